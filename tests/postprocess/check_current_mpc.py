#!/usr/bin/env python3
"""The multipoint-constraint formulations on the current configuration
(Contact/Formulation = mpc frictionless | mpc frictional, Contact/Kinematics
= current) against the closed form and against the alm formulations.

Usage: check_current_mpc.py CONTACT_FEM 2d PATCH.prm SLIDING.prm FRICTION.prm PATCH_3D.prm
       check_current_mpc.py CONTACT_FEM 3d MPIEXEC,ARG... FRICTION_3D.prm

2d:
- PATCH (tests/scenes/current_kinematics_patch_01.prm) and PATCH_3D
  (current_kinematics_patch_3d_01.prm) with 'mpc frictionless': two
  non-matching neo-Hookean blocks compressed by 30 %, homogeneous
  deformation: the contact pressure at every slave node is the Cauchy
  stress of the law to 1e-8 (check_current_kinematics.cauchy_pressure()),
  Newton quadratic (r_k <= 10 r_(k-1)^2).
- SLIDING (current_kinematics_sliding_01.prm, frictionless, pairs changing
  during Newton) and FRICTION (current_kinematics_friction_01.prm, Coulomb
  0.3 to full slip): 'alm KIND' and 'mpc KIND' reach the same converged
  state (below), mpc's Newton quadratic (C = 100 for SLIDING, whose pairs
  change, 10 for FRICTION: the bounds of check_current_kinematics.py and
  check_current_friction.py).

3d: FRICTION_3D (current_kinematics_friction_3d_01.prm: a neo-Hookean block
pressed by 22 % on a rigid base and pulled at 30 degrees, mu = 0.3; stick
and slip nodes, then full slip), 'alm frictional' serially and 'mpc
frictional' on 2 MPI ranks (under the launcher MPIEXEC,ARG..., its words
separated by commas): the same converged state; mpc's full-slip steps
(t = 4, 5) quadratic (C = 10). In the steps with stick and slip nodes the
mpc slip direction -xi / |xi| turns sharply at the nodes with little slip
(its derivative T / |xi|: doc/design.md, "MPC contact"), so the last
displacement ratio of the first step falls only from 8e-8 to 7e-9. That is
the mpc law, not the current configuration: with Contact/Kinematics =
small (whose contact terms are linear in u) the first two steps take the
same iterations and each r_k / r_(k-1)^2 is within a factor 2 of the
current one's (the rule of check_current_penalty_friction.py).

The same converged state: every load step converged, at the same load
times; every force of forces.csv (support reactions, the pair's normal
and tangential force and its contact length) within 1e-7 of the largest
force of the scene (measured: 0 in 2D, where alm and mpc take the same
Newton path, 3.4e-9 in 3D); the converged active (and stick, slip) counts
of every step equal.
"""
import csv
import os
import sys

from check_current_kinematics import (cauchy_pressure, cauchy_pressure_3d, check_cauchy_pressure,
                                      check_quadratic)
from scene_run import newton_ratios, run_scene

TOLERANCE = 1e-7


def report(name, good, detail):
    print(f"{name}: {'ok' if good else 'FAILED'} ({detail})")
    return good


def converged_counts(output):
    """Per converged load step: the active (and stick, slip) counts of the
    Newton table's converged row."""
    counts = []
    for line in output.splitlines():
        if line.rstrip().endswith("| converged"):
            cells = [c.strip() for c in line.split("|")][7:-1]
            counts.append(cells[:3] if len(cells) == 4 else cells)
    return counts


def run(contact_fem, scene, formulation, launcher=()):
    """Runs scene with formulation; returns its console output and forces.csv rows."""
    directory = f"{os.path.splitext(os.path.basename(scene))[0]}-{formulation.replace(' ', '-')}"
    output = run_scene(contact_fem, scene, f"Contact/Formulation={formulation}",
                       f"Output directory={directory}", launcher=launcher)
    with open(os.path.join(directory, "forces.csv")) as f:
        return output, list(csv.DictReader(f))


def same_state(name, alm, mpc):
    """alm and mpc: (output, forces) of the same scene."""
    (alm_output, alm_rows), (mpc_output, mpc_rows) = alm, mpc
    steps = [alm_output.count("| converged"), mpc_output.count("| converged")]
    times = [r["t"] for r in alm_rows] == [r["t"] for r in mpc_rows]
    forces = [k for k in alm_rows[0] if k not in ("cycle", "step", "t")]
    scale = max(abs(float(r[k])) for r in alm_rows for k in forces if not k.endswith("_length"))
    worst = max(abs(float(a[k]) - float(m[k])) for a, m in zip(alm_rows, mpc_rows)
                for k in forces) / scale
    counts = converged_counts(alm_output) == converged_counts(mpc_output)
    return report(f"{name}: alm and mpc converge to the same state",
                  steps[0] == steps[1] == len(alm_rows) and times and worst <= TOLERANCE and
                  counts, f"{len(alm_rows)} steps, forces {worst:.1e} of the largest apart "
                  f"(bound {TOLERANCE}), converged counts {converged_counts(mpc_output)} "
                  f"{'equal' if counts else 'differ from alm ' + str(converged_counts(alm_output))}")


def check_2d(contact_fem, patch, sliding, friction, patch_3d):
    ok = True
    for name, scene, expected, settings in (
            ("patch Q1, mpc", patch, cauchy_pressure(100.0, 0.3, 0.7), ()),
            ("patch 3D Q1, mpc", patch_3d, cauchy_pressure_3d(100.0, 0.3, 0.7),
             ("Output/Print Newton iterations=true",))):
        output = run_scene(contact_fem, scene, "Contact/Formulation=mpc frictionless",
                           "Output/Write pressure profile=true", *settings)
        ok = check_quadratic(name, output, 10.0) and ok
        ok = check_cauchy_pressure(name, expected) and ok
    for name, scene, kind, bound in (("sliding", sliding, "frictionless", 100.0),
                                     ("friction", friction, "frictional", 10.0)):
        alm = run(contact_fem, scene, f"alm {kind}")
        mpc = run(contact_fem, scene, f"mpc {kind}")
        ok = check_quadratic(f"{name}, mpc", mpc[0], bound) and ok
        ok = same_state(name, alm, mpc) and ok
    return ok


def check_3d(contact_fem, launcher, scene):
    alm = run(contact_fem, scene, "alm frictional")
    mpc = run(contact_fem, scene, "mpc frictional", launcher=launcher)
    ok = same_state("friction 3D (mpc on 2 ranks)", alm, mpc)
    output = mpc[0]
    ok = check_quadratic("friction 3D, mpc, full-slip steps (t = 4, 5)",
                         output[output.index("  Load step 4,"):], 10.0) and ok

    short = ("Load stepping/End time=2", "Load stepping/Number of load steps=2")
    small = newton_ratios(run_scene(contact_fem, scene, "Contact/Formulation=mpc frictional",
                                    "Contact/Kinematics=small", "Output directory=small",
                                    "Model range/Accept results outside the small-strain range=true",
                                    *short))
    current = newton_ratios(output)[:2]

    def constants(ratios):
        return [b / a**2 for a, b in zip(ratios, ratios[1:])
                if a is not None and b is not None and a <= 0.1]

    same = [len(r) for r in current] == [len(r) for r in small]
    pairs = [(c, d) for a, b in zip(current, small) for c, d in zip(constants(a), constants(b))]
    ok = report("friction 3D, mpc, steps t = 1, 2 (stick and slip nodes): the iterations of "
                "Kinematics = small, each r_k / r_(k-1)^2 within a factor 2 of its",
                same and pairs and all(0.5 < c / d < 2 for c, d in pairs),
                f"iterations {[len(r) - 1 for r in current]} and {[len(r) - 1 for r in small]}, "
                f"constants (current, small) "
                f"{', '.join(f'({c:.3g}, {d:.3g})' for c, d in pairs)}") and ok
    return ok


def main():
    contact_fem, mode = sys.argv[1:3]
    if mode == "2d":
        ok = check_2d(contact_fem, *sys.argv[3:7])
    else:
        ok = check_3d(contact_fem, sys.argv[3].split(","), sys.argv[4])
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
