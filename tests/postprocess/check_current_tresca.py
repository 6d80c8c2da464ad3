#!/usr/bin/env python3
"""Tresca friction at large deformation (Contact/Kinematics = current).

Usage: check_current_tresca.py CONTACT_FEM SCENE.prm

SCENE is tests/scenes/current_kinematics_friction_01.prm (a neo-Hookean
block pressed by 25 % onto a non-matching one and pulled along x) run with
Contact/Friction = tresca 5 instead of Coulomb. From forces.csv (the pair's
force and its contact length on the current configuration) and the Newton
tables (active, stick and slip counts of the converged iterate):

- every step converges without a split, in at most 8 Newton iterations,
  quadratically once the sets are fixed (the slave's end node leaving the
  master made the stick/slip set cycle and the steps split to 1/32);
- at least two steps have every active node slipping on a flat interface
  (the pair's normal force along y), and there the pair's tangential force
  is 5 times the contact length to 1e-8;
- every pull step with a stick node stays below that bound.

CONTACT_FEM_PERTURBATION_SEED, if set, renumbers the DoFs (as
tests/run_perturbed.sh does; seeds 1-3 pass).
"""
import csv
import sys

from scene_run import check_quadratic, converged_sets, newton_table, perturbation, run_scene

BOUND = 5.0

contact_fem, scene = sys.argv[1:3]
output = run_scene(contact_fem, scene, f"Contact/Friction=tresca {BOUND:g}", *perturbation())
iterations = [len(ratios) - 1 for ratios, _ in newton_table(output)]
ok = ("Newton failed" not in output and "Splitting" not in output and iterations
      and max(iterations) <= 8)
print(f"load steps {iterations} Newton iterations, every one converged without a split "
      f"in at most 8: {'ok' if ok else 'FAILED'}")
ok = check_quadratic("Tresca block", output, 10.0) and ok
with open("results/forces.csv") as f:
    rows = list(csv.DictReader(f))
sets = converged_sets(output)
good = len(sets) == len(rows)
print(f"steps: {len(rows)}, with their sets: {len(sets)}: {'ok' if good else 'FAILED'}")
ok = good and ok
sliding, sticking = [], []
for (active, stick, slip), row in zip(sets, rows):
    force = abs(float(row["pair_3_4_tangential_x"]))
    limit = BOUND * float(row["pair_3_4_length"])
    flat = abs(float(row["pair_3_4_normal_x"])) <= 1e-10 * abs(float(row["pair_3_4_normal_y"]))
    if active > 0 and slip == active and flat:
        sliding.append(abs(force - limit) / limit)
    if float(row["t"]) > 1 and stick > 0:
        sticking.append(force / limit)
good = len(sliding) >= 2 and max(sliding) < 1e-8
print(f"flat steps with every active node slipping: {len(sliding)}, tangential force = "
      f"{BOUND:g} x contact length to 1e-8: {'ok' if good else 'FAILED'} "
      f"(largest relative error {max(sliding, default=1):.1e})")
ok = good and ok
good = len(sticking) >= 2 and all(0 < r < 1 - 1e-6 for r in sticking)
print(f"pull steps with stick nodes: {len(sticking)}, tangential force below the bound: "
      f"{'ok' if good else 'FAILED'} ({', '.join(f'{r:.4f}' for r in sticking)} of it)")
ok = good and ok
sys.exit(0 if ok else 1)
