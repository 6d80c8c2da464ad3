#!/usr/bin/env python3
"""Newton on a slave surface with hanging vertices under Contact/Kinematics =
current (issue 29).

Usage: check_current_hanging.py CONTACT_FEM SCENE_3D.prm

SCENE_3D is tests/scenes/current_kinematics_penalty_friction_3d_01.prm (a
neo-Hookean block pressed onto a wider base), run here frictionless
(`penalty frictionless`) in one load step to t = 1 (the top pressed by
0.055), with the block's cells at its base on x < 0 refined once
(`Geometry/Local refinements`): the slave surface then has hanging
vertices, whose faces carry the owners' dual basis. Checks:

- the run reports hanging slave vertices;
- the step converges without a split, and Newton is quadratic once the
  active set is fixed: r_k <= 10 r_(k-1)^2 (r_(k-1) <= 0.1). Before the
  faces with hanging vertices were linearised in the owners' basis the
  displacement ratios fell linearly, by 0.2 per iteration (r_k / r_(k-1)^2
  from 5.7 up to 5e4), in 12 iterations.
"""
import re
import sys

from scene_run import check_quadratic, newton_ratios, perturbation, run_scene


def main():
    contact_fem, scene = sys.argv[1:3]
    output = run_scene(contact_fem, scene, "Geometry/Local refinements=1: -0.6, -0.6, 0.3, 0, 0.6, 0.45",
                       "Contact/Formulation=penalty frictionless", "Contact/Friction=",
                       "Load stepping/End time=1", "Load stepping/Number of load steps=1",
                       *perturbation())
    match = re.search(r"(\d+) hanging slave vertices", output)
    hanging = int(match.group(1)) if match else 0
    ok = hanging > 0
    print(f"hanging slave vertices: {hanging} ({'ok' if ok else 'FAILED'})")
    steps = newton_ratios(output)
    converged = len(steps) == 1 and "Splitting" not in output
    print(f"one converged load step, no split: {'ok' if converged else 'FAILED'}")
    ok = check_quadratic("3D block on hanging slave vertices", output, 10.0) and ok and converged
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
