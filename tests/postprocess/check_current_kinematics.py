#!/usr/bin/env python3
"""Contact on the current configuration (Contact/Kinematics = current).

Usage: check_current_kinematics.py CONTACT_FEM PATCH.prm SLIDING.prm

PATCH is tests/scenes/current_kinematics_patch_01.prm, run with Q1 and
with Q2 elements: two non-matching neo-Hookean blocks (E = 100, nu = 0.3) compressed by 30 %. The deformation
is homogeneous plane-strain uniaxial stress, so the contact pressure at
every slave node must be the Cauchy stress of the law, sigma_yy = stretch_y
S_yy / a (a the lateral stretch from S_xx = 0), to 1e-8 relative.

Both scenes: every load step converges, and Newton's displacement ratios
r_k fall quadratically once r_(k-1) <= 0.1: r_k <= C r_(k-1)^2, with C =
10 for the patch (no pair or active-set changes) and C = 100 for SLIDING
(tests/scenes/current_kinematics_sliding_01.prm: a slave node passes over
about 3 master faces per step; pairs change during Newton). A linearly
converging Newton (a tangent without the operators' derivatives) breaks
these bounds.
"""
import csv
import math
import sys

from scene_run import check_quadratic, run_scene


def cauchy_pressure(E, nu, stretch, dim=2):
    """-sigma along the stretch of S = mu (I - C^-1) + lambda ln J C^-1
    under uniaxial stress (plane strain in 2D): the lateral stretch a from
    S_xx = 0 by bisection, J = a^(dim-1) stretch."""
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))

    def S(s, a):
        return mu * (1 - 1 / s**2) + lam * math.log(a ** (dim - 1) * stretch) / s**2

    lo, hi = 0.5, 2.0
    for _ in range(200):
        a = 0.5 * (lo + hi)
        if S(a, a) > 0:
            hi = a
        else:
            lo = a
    return -stretch * S(stretch, a) / a ** (dim - 1)


def cauchy_pressure_3d(E, nu, stretch):
    return cauchy_pressure(E, nu, stretch, dim=3)


def check_cauchy_pressure(name, expected):
    """Every slave node of results/pressure_profile.csv active, at the
    pressure expected to 1e-8 relative."""
    with open("results/pressure_profile.csv") as f:
        rows = list(csv.DictReader(f))
    errors = [abs(float(r["pressure"]) - expected) / expected for r in rows]
    inactive = [r for r in rows if r["active"] != "1"]
    good = len(rows) > 0 and not inactive and max(errors) < 1e-8
    print(f"{name}: {len(rows)} slave nodes, pressure against the Cauchy stress "
          f"{expected:.9g} of the law to 1e-8: {'ok' if good else 'FAILED'} "
          f"(largest relative error {max(errors, default=0.0):.1e}, inactive {len(inactive)})")
    return good


def main():
    contact_fem, patch, sliding = sys.argv[1:4]
    ok = True

    expected = cauchy_pressure(100.0, 0.3, 0.7)
    for degree in (1, 2):
        name = f"patch Q{degree}"
        output = run_scene(contact_fem, patch, "Output/Write pressure profile=true",
                           f"Finite element/Degree={degree}")
        ok = check_quadratic(name, output, 10.0) and ok
        ok = check_cauchy_pressure(name, expected) and ok

    output = run_scene(contact_fem, sliding)
    ok = check_quadratic("sliding", output, 100.0) and ok
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
