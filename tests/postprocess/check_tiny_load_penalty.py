#!/usr/bin/env python3
"""Penalty friction at a load near the round-off of the geometry is never a
wrong "converged" result (doc/metamorphic.md, "tiny loads").

Usage: check_tiny_load_penalty.py CONTACT_FEM MESH

MESH is meshes/contact_blocks_3d_3_2.msh: the 3D patch (E = 100 and 200)
pressed by 2 and pulled by (0.5, 0.3) with penalty frictional, Coulomb
0.2, once at these loads and once at loads x 1e-9 (a positively
homogeneous problem: every stress and force scales by 1e-9). At x 1e-9 the
penalty's penetration p / eps (about 7e-16) is two units of the round-off
of the coordinates: the run used to end "converged" after one iteration
on its absolute tolerances (the whole load's residual 7.8e-10 below 1e-9)
with a stick/slip change pending and its pressures 2.6 % off. Checks:
either the x 1e-9 run converges and its p_max, normal force and stick /
slip counts are the unit run's (to 1e-4, the 5e4 units of round-off the
bodies move by), or it fails (exit code 2) naming the penalty's
penetration at the round-off of the coordinates as the likely cause.
"""
import json
import os
import subprocess
import sys

from scene_run import ENVIRONMENT

SCENE = """set Dimension = 3
set Output directory = {out}
subsection Geometry
  set Type      = mesh file
  set Mesh file = {mesh}
end
subsection Materials
  set Material ids     = 1, 2
  set Young's moduli   = 100, 200
  set Poisson's ratios = 0.3, 0.2
end
subsection Boundary conditions
  set Fixed    = 2: z; 5: x; 6: y
  set Pressure = 1: {pressure!r}
  set Traction = 1: {tx!r}, {ty!r}, 0
end
subsection Contact
  set Pairs       = 3: 4
  set Formulation = penalty frictional
  set Friction    = coulomb 0.2
end
subsection Output
  set Write VTU = false
  set Write pressure profile = false
  set Print timing = false
end
"""


def run(contact_fem, mesh, scale):
    name = f"load_{scale:g}"
    with open(name + ".prm", "w") as f:
        f.write(SCENE.format(out=name, mesh=mesh, pressure=2 * scale, tx=0.5 * scale,
                             ty=0.3 * scale))
    result = subprocess.run([contact_fem, name + ".prm"], env=ENVIRONMENT, capture_output=True,
                            text=True)
    summary = None
    if result.returncode == 0:
        with open(os.path.join(name, "summary.json")) as f:
            contact = json.load(f)["cycles"][-1]["contact"]
        summary = {key: contact[key] for key in
                   ["max_contact_pressure", "total_contact_force", "stick_nodes", "slip_nodes"]}
    return result.returncode, result.stdout, summary


def main():
    contact_fem, mesh = sys.argv[1:3]
    code, _, unit = run(contact_fem, mesh, 1.0)
    if code != 0:
        sys.exit("the unit-load scene failed")
    code, output, tiny = run(contact_fem, mesh, 1e-9)
    if code == 0:
        worst = max(abs(tiny[k] / 1e-9 / unit[k] - 1.)
                    for k in ["max_contact_pressure", "total_contact_force"])
        good = worst <= 1e-4 and all(tiny[k] == unit[k] for k in ["stick_nodes", "slip_nodes"])
        print(f"loads x 1e-9 converged: {'ok' if good else 'FAILED'} (largest relative change "
              f"{worst:.1e}, stick / slip {tiny['stick_nodes']} / {tiny['slip_nodes']} against "
              f"{unit['stick_nodes']} / {unit['slip_nodes']})")
    else:
        named = "penalty's penetration" in output and "round-off of the coordinates" in output
        good = code == 2 and named
        print(f"loads x 1e-9 not converged: {'ok' if good else 'FAILED'} (exit code {code}, "
              f"{'names' if named else 'does not name'} the penalty's penetration at round-off)")
    sys.exit(0 if good else 1)


if __name__ == "__main__":
    main()
