#!/usr/bin/env python3
"""Contact on the current configuration in 3D (Contact/Kinematics = current).

Usage: check_current_kinematics_3d.py CONTACT_FEM PATCH.prm SLIDING.prm

PATCH is tests/scenes/current_kinematics_patch_3d_01.prm: two non-matching
neo-Hookean blocks (E = 100, nu = 0.3) compressed by 30 %. The deformation
is homogeneous uniaxial stress, so the contact pressure at every slave node
must be the Cauchy stress of the law, sigma_zz = stretch_z S_zz / a^2 (a
the lateral stretch from S_xx = 0), to 1e-8 relative; every load step
converges, Newton's displacement ratios falling quadratically
(check_current_kinematics.check_quadratic(), C = 10).

SLIDING is tests/scenes/current_kinematics_sliding_3d_01.prm: the upper
block pressed and slid over about two master faces in 3 steps, pairs and
active set changing during Newton; every step converges with a quadratic
tail (C = 10).
"""
import sys

from check_current_kinematics import cauchy_pressure_3d, check_cauchy_pressure, check_quadratic
from scene_run import run_scene


contact_fem, patch, sliding = sys.argv[1:4]
expected = cauchy_pressure_3d(100.0, 0.3, 0.7)
output = run_scene(contact_fem, patch, "Output/Write pressure profile=true",
                   "Output/Print Newton iterations=true")
ok = check_quadratic("patch 3D Q1", output, 10.0)
ok = check_cauchy_pressure("patch 3D Q1", expected) and ok
ok = check_quadratic("sliding 3D Q1", run_scene(contact_fem, sliding), 10.0) and ok
sys.exit(0 if ok else 1)
