#!/usr/bin/env python3
"""Tresca friction at large deformation in 3D (Contact/Kinematics = current).

Usage: check_current_tresca_3d.py CONTACT_FEM SCENE.prm

SCENE is tests/scenes/current_kinematics_friction_3d_01.prm (a neo-Hookean
block pressed by 22 % onto a rigid flat base, non-matching, then pulled in
the plane at 30 degrees from x) run to t = 7 with Contact/Friction = tresca
5 instead of Coulomb. The slip bound is 5 per unit area of the current
configuration, whatever the pressure. From forces.csv (the pair's force and
its contact area on the current configuration), the pressure profile of
the last step and the Newton tables:

- every step converges without a split, quadratically once the sets are
  fixed (r_k <= 10 r_(k-1)^2);
- t = 7: every active node slips, its tangential traction is 5 to 1e-8
  (the exact bound), against its slip;
- in the steps where every active node slips (t = 4 to 7) the pair's
  |F_t| tends to the exact 5 A (A the contact area): |F_t| = 5 A once all
  slip directions agree, which the steady slide reaches step by step (the
  press made the rim slip outward); the relative error falls by at least
  10 per step and is below 2e-8 at t = 7 (measured 2.3e-3, 3.2e-5,
  4.6e-7, 7.1e-9), and F_t points against the pull within 1e-5 rad;
- t = 3 (pulled by 0.03): stick nodes, and |F_t| below 5 A.

CONTACT_FEM_PERTURBATION_SEED, if set, renumbers the DoFs.
"""
import csv
import math
import sys

from scene_run import check_quadratic, converged_sets, newton_table, perturbation, run_scene

BOUND = 5.0
PULL = math.radians(30.0)


def report(name, good, detail):
    print(f"{name}: {'ok' if good else 'FAILED'} ({detail})")
    return good


contact_fem, scene = sys.argv[1:3]
output = run_scene(contact_fem, scene, f"Contact/Friction=tresca {BOUND:g}",
                   "Load stepping/End time=7", "Load stepping/Number of load steps=7",
                   "Output/Write pressure profile=true", *perturbation())
attempts = newton_table(output)
ok = report("every step converged without a split",
            len(attempts) == 7 and all(converged for _, converged in attempts),
            f"{len(attempts)} attempts, Newton iterations {[len(r) - 1 for r, _ in attempts]}")
ok = check_quadratic("Tresca block 3D", output, 10.0) and ok

with open("results/forces.csv") as f:
    rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
sets = converged_sets(output)
ok = report("steps with their sets", len(sets) == len(rows) == 7, f"{len(sets)}") and ok
errors, angle = [], None
for (active, stick, slip), row in zip(sets, rows):
    tx, ty = row["pair_3_4_tangential_x"], row["pair_3_4_tangential_y"]
    limit = BOUND * row["pair_3_4_area"]
    if row["t"] == 3:
        ok = report("t = 3: stick nodes, |F_t| below 5 A", stick > 0 and
                    0 < math.hypot(tx, ty) < (1 - 1e-6) * limit,
                    f"{stick} of {active} stick, |F_t| = {math.hypot(tx, ty) / limit:.4f} of 5 A") and ok
    if row["t"] >= 4:
        if not (active > 0 and slip == active):
            ok = report(f"t = {row['t']:g}: every active node slips", False,
                        f"{slip} of {active}")
        errors.append(abs(math.hypot(tx, ty) - limit) / limit)
        # The base holds the block back: F_t (master on slave) against the pull.
        angle = abs(math.remainder(math.atan2(ty, tx) - PULL - math.pi, 2 * math.pi))
falling = len(errors) == 4 and all(b < a / 10 for a, b in zip(errors, errors[1:]))
ok = report("full slip, t = 4 to 7: |F_t| -> 5 A, error falling by 10 per step, < 2e-8 at "
            "t = 7; F_t against the pull within 1e-5 rad", falling and errors[-1] < 2e-8 and
            angle < 1e-5, f"errors {', '.join(f'{e:.1e}' for e in errors)}, angle {angle:.1e}") and ok

with open("results/pressure_profile.csv") as f:
    nodes = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f) if r["active"] == "1"]
off = max(abs(math.hypot(n["tangential_traction_x"], n["tangential_traction_y"]) - BOUND)
          for n in nodes) / BOUND
opposed = all(n["tangential_traction_x"] * n["slip_increment_x"] +
              n["tangential_traction_y"] * n["slip_increment_y"] < 0 for n in nodes)
every = all(n["stick"] == 0 for n in nodes)
ok = report("t = 7: every active node slips, |t_j| = 5 to 1e-8, against its slip",
            len(nodes) > 0 and every and off < 1e-8 and opposed,
            f"{len(nodes)} nodes, |t_j| off 5 by {off:.1e}") and ok
sys.exit(0 if ok else 1)
