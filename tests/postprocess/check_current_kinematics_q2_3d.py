#!/usr/bin/env python3
"""Q2 faces on the current configuration in 3D (Contact/Kinematics =
current, Finite element/Degree = 2).

Usage: check_current_kinematics_q2_3d.py CONTACT_FEM PATCH.prm MESH.msh

PATCH is tests/scenes/current_kinematics_patch_3d_01.prm (two neo-Hookean
blocks, E = 100, nu = 0.3, compressed by 30 %), here on MESH =
meshes/contact_blocks_3d_3_2.msh (a 3 x 3 slave face against a 2 x 2
master, non-matching; 26 cells) with Degree = 2 and the compression in
one load step, which keeps the run to seconds. The deformation is
homogeneous uniaxial stress, which Q2 represents exactly: the contact
pressure at every slave node (vertices, edge midpoints and face centres of
the 9-node faces) must be the Cauchy stress of the law on the deformed
interface, 33.0121409 (check_current_kinematics.cauchy_pressure_3d(), by
bisection on S_xx = 0), to 1e-8 relative, against 40.5 nominal; Newton
converges quadratically (C = 10; measured 6.6e-3, 1.1e-4, 3.2e-8 on
2026-11-27): the linearisation of the mortar operators of 9-node faces on
the current configuration is consistent.
"""
import sys

from check_current_kinematics import cauchy_pressure_3d, check_cauchy_pressure, check_quadratic
from scene_run import perturbation, run_scene

contact_fem, patch, mesh = sys.argv[1:4]
expected = cauchy_pressure_3d(100.0, 0.3, 0.7)
output = run_scene(contact_fem, patch, *perturbation(), f"Geometry/Mesh file={mesh}",
                   "Finite element/Degree=2", "Load stepping/Number of load steps=1",
                   "Output/Write pressure profile=true", "Output/Print Newton iterations=true")
ok = check_quadratic("patch 3D Q2", output, 10.0)
ok = check_cauchy_pressure("patch 3D Q2", expected) and ok
sys.exit(0 if ok else 1)
