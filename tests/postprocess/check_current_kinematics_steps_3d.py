#!/usr/bin/env python3
"""The 3D current-kinematics patch in few, large load steps.

Usage: check_current_kinematics_steps_3d.py CONTACT_FEM PATCH.prm

PATCH is tests/scenes/current_kinematics_patch_3d_01.prm (two neo-Hookean
blocks compressed by 30 %, homogeneous), run here in 2 and in 3 load steps
(15 % and 10 % of the height per step). Each step must converge without a
split, quadratically (C = 10), to the Cauchy pressure of the law at every
slave node to 1e-8. Before the tangential predictor at the step start and
the bounded derivative of the clipping where the blocks' rims coincide,
2 steps split into inverted elements and 3 steps stopped with a
"singular" linear system at the first solve of step 2.
"""
import sys

from check_current_kinematics import cauchy_pressure_3d, check_cauchy_pressure, check_quadratic
from scene_run import newton_table, run_scene

contact_fem, patch = sys.argv[1:3]
expected = cauchy_pressure_3d(100.0, 0.3, 0.7)
ok = True
for steps in (2, 3):
    name = f"patch 3D Q1 in {steps} load steps"
    output = run_scene(contact_fem, patch, f"Load stepping/Number of load steps={steps}",
                       "Output/Write pressure profile=true", "Output/Print Newton iterations=true")
    attempts = newton_table(output)
    unsplit = len(attempts) == steps and all(converged for _, converged in attempts)
    print(f"{name}: {len(attempts)} step attempts, every one converged without a split: "
          f"{'ok' if unsplit else 'FAILED'}")
    ok = check_quadratic(name, output, 10.0) and unsplit and ok
    ok = check_cauchy_pressure(name, expected) and ok
sys.exit(0 if ok else 1)
