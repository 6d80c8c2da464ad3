#!/usr/bin/env python3
"""The penalty on the current configuration ('penalty frictionless' with
Contact/Kinematics = current).

Usage: check_current_penalty.py CONTACT_FEM PATCH_2D.prm PATCH_3D.prm SLIDING.prm

PATCH_2D and PATCH_3D are the large-deformation patch tests of
check_current_kinematics.py and check_current_kinematics_3d.py (two
non-matching neo-Hookean blocks, E = 100, nu = 0.3, of total height H = 2
in 2D and 1 in 3D, compressed by 0.3 H), run with the penalty. The
deformation stays homogeneous, but the blocks overlap by delta = p / eps
(eps the pair's penalty from summary.json), so the bodies are compressed
by 0.3 H - delta: the pressure at every slave node must be the fixed point
p = sigma(0.7 + p / (eps H)) of the law's Cauchy stress, to 1e-8 relative;
and every node's gap must be -p / eps. Newton's displacement ratios must
fall quadratically (C = 10): the tangent holds the derivatives of D_j,
M_jl, n_j and of the pressure lambda_j = eps (-G_j) / D_j.

SLIDING is the 2D large-sliding scene (check_current_kinematics.py): pairs
change during Newton; every step converges with a quadratic tail (C = 100).
It runs at 1e-4 of the automatic penalty: at the automatic one (1e4 E / h)
a change of pairs, a kink the tangent cannot see, is amplified by the
penalty, and this scene's slide of half a master face per step fails
(1e-3: 21 steps after splits; doc/finite_strain.md).

The penalty's overlap leaves the displacement ratio at a round-off floor
above the scenes' tolerance 1e-12: the runs here take 1e-10.
"""
import csv
import json
import sys

from check_current_kinematics import cauchy_pressure
from scene_run import check_quadratic, run_scene

PENALTY = ("Contact/Formulation=penalty frictionless",
           "Newton/Displacement relative tolerance=1e-10")


def expected_pressure(eps, height, dim):
    """The fixed point p = sigma(0.7 + p / (eps height)), by iteration (a
    contraction: d sigma / d p = sigma' / (eps height) is tiny)."""
    p = cauchy_pressure(100.0, 0.3, 0.7, dim)
    for _ in range(50):
        p = cauchy_pressure(100.0, 0.3, 0.7 + p / (eps * height), dim)
    return p


def check_patch(name, output, height, dim):
    ok = check_quadratic(name, output, 10.0)
    with open("results/summary.json") as f:
        eps = json.load(f)["cycles"][-1]["contact"]["penalty"]
    expected = expected_pressure(eps, height, dim)
    with open("results/pressure_profile.csv") as f:
        rows = list(csv.DictReader(f))
    pressure_error = max((abs(float(r["pressure"]) - expected) / expected for r in rows),
                         default=1.0)
    gap_error = max((abs(float(r["gap"]) * eps + expected) / expected for r in rows),
                    default=1.0)
    inactive = [r for r in rows if r["active"] != "1"]
    good = len(rows) > 0 and not inactive and pressure_error < 1e-8 and gap_error < 1e-6
    print(f"{name}: {len(rows)} slave nodes, penalty {eps:.6g}, pressure against the fixed "
          f"point {expected:.9g} (nominal stretch 0.7: {cauchy_pressure(100.0, 0.3, 0.7, dim):.9g})"
          f" to 1e-8 and gap -p/eps to 1e-6: {'ok' if good else 'FAILED'} (largest relative "
          f"errors {pressure_error:.1e}, {gap_error:.1e}; inactive {len(inactive)})")
    return ok and good


def main():
    contact_fem, patch_2d, patch_3d, sliding = sys.argv[1:5]
    profile = "Output/Write pressure profile=true"
    ok = check_patch("patch 2D Q1", run_scene(contact_fem, patch_2d, *PENALTY, profile), 2.0, 2)
    ok = check_patch("patch 3D Q1",
                     run_scene(contact_fem, patch_3d, *PENALTY, profile,
                               "Output/Print Newton iterations=true"), 1.0, 3) and ok
    output = run_scene(contact_fem, sliding, *PENALTY, "Contact/Stiffness factor=1e-4")
    ok = check_quadratic("sliding, 1e-4 of the automatic penalty", output, 100.0) and ok
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
