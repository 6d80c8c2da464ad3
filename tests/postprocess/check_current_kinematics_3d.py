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
import csv
import math
import sys

from check_current_kinematics import check_quadratic
from scene_run import run_scene


def cauchy_pressure_3d(E, nu, stretch):
    """-sigma_zz of S = mu (I - C^-1) + lambda ln J C^-1 under uniaxial
    stress: stretch along z, a along x and y with S_xx = 0."""
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))

    def S(s, a):
        return mu * (1 - 1 / s**2) + lam * math.log(a * a * stretch) / s**2

    lo, hi = 0.5, 2.0
    for _ in range(200):
        a = 0.5 * (lo + hi)
        if S(a, a) > 0:
            hi = a
        else:
            lo = a
    return -stretch * S(stretch, a) / a**2


contact_fem, patch, sliding = sys.argv[1:4]
expected = cauchy_pressure_3d(100.0, 0.3, 0.7)
output = run_scene(contact_fem, patch, "Output/Write pressure profile=true",
                   "Output/Print Newton iterations=true")
ok = check_quadratic("patch 3D Q1", output, 10.0)
with open("results/pressure_profile.csv") as f:
    rows = list(csv.DictReader(f))
errors = [abs(float(r["pressure"]) - expected) / expected for r in rows]
inactive = [r for r in rows if r["active"] != "1"]
good = len(rows) > 0 and not inactive and max(errors) < 1e-8
print(f"patch 3D Q1: {len(rows)} slave nodes, pressure against the Cauchy stress "
      f"{expected:.9g} of the law to 1e-8: {'ok' if good else 'FAILED'} "
      f"(largest relative error {max(errors):.1e}, inactive {len(inactive)})")
ok = check_quadratic("sliding 3D Q1", run_scene(contact_fem, sliding), 10.0) and ok
sys.exit(0 if ok and good else 1)
