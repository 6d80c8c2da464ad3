#!/usr/bin/env python3
"""Coulomb friction at large deformation (Contact/Kinematics = current).

Usage: check_current_friction.py CONTACT_FEM SCENE.prm

SCENE is tests/scenes/current_kinematics_friction_01.prm: a neo-Hookean
block pressed by 25 % onto a non-matching one (whose top is held
vertically: the interface stays flat) and pulled along x until it slides,
mu = 0.3. From forces.csv (the reaction on the pulled top, F_x and F_y)
and the Newton tables (the active, stick and slip counts of the converged
iterate):

- every step converges, and Newton's displacement ratios fall
  quadratically once r_(k-1) <= 0.1 (r_k <= 10 r_(k-1)^2, over the
  iterations without active or stick/slip set changes);
- at least two steps have every active node slipping, and there |F_x| =
  0.3 |F_y| to 1e-8 (the slip condition t_j = mu p_j on a flat interface);
- at least two pull steps have every active node sticking, with 0 < |F_x|
  < 0.3 |F_y| (below the limit).

And the stick condition is objective and exact: on a rigid flat master
(its top held in x and y) the objective slip of a slave node j reduces to
D_j^n / D_j (x_j - x_j^n) . tau, so a node that sticks through a load step keeps
its position. The scene is run to t = 1.25 and to t = 1.5 (the same
steps); every node that sticks at t = 1.5 must be where it was at t =
1.25, to 1e-10 of the block's width, and a node that slips must have
moved.
"""
import csv
import sys

from scene_run import check_quadratic, converged_sets, run_scene

MU = 0.3


def top_reactions():
    with open("results/forces.csv") as f:
        return [(float(r["t"]), float(r["boundary_1_x"]), float(r["boundary_1_y"]))
                for r in csv.DictReader(f)]


def profile(contact_fem, scene, end_time, steps):
    run_scene(contact_fem, scene, "Output/Write pressure profile=true",
              "Boundary conditions/Fixed=2: xy; 4: xy", f"Load stepping/End time={end_time}",
              f"Load stepping/Number of load steps={steps}")
    with open("results/pressure_profile.csv") as f:
        return {r["reference_x"]: r for r in csv.DictReader(f)}


contact_fem, scene = sys.argv[1:3]
output = run_scene(contact_fem, scene)
ok = check_quadratic("sliding block", output, 10.0)
sets, reactions = converged_sets(output), top_reactions()
good = len(sets) == len(reactions) == output.count("  Load step ")
print(f"steps: {len(reactions)}, converged: {len(sets)}: {'ok' if good else 'FAILED'}")
ok = good and ok
sliding, sticking = [], []
for (active, stick, slip), (t, fx, fy) in zip(sets, reactions):
    if active > 0 and slip == active:
        sliding.append(abs(abs(fx / fy) - MU) / MU)
    if t > 1 and active > 0 and stick == active:
        sticking.append(abs(fx / fy))
good = len(sliding) >= 2 and max(sliding) < 1e-8
print(f"steps with every active node slipping: {len(sliding)}, |F_x / F_y| = {MU} to 1e-8: "
      f"{'ok' if good else 'FAILED'} (largest relative error {max(sliding, default=1):.1e})")
ok = good and ok
good = len(sticking) >= 2 and all(1e-6 < r < MU for r in sticking)
print(f"pull steps with every active node sticking: {len(sticking)}, 0 < |F_x / F_y| < {MU}: "
      f"{'ok' if good else 'FAILED'} ({', '.join(f'{r:.4f}' for r in sticking)})")
ok = good and ok

before, after = profile(contact_fem, scene, 1.25, 5), profile(contact_fem, scene, 1.5, 6)
width = 4.0
moved = {key: abs(float(after[key]["x"]) - float(before[key]["x"])) / width for key in after}
stuck = [moved[key] for key in after if after[key]["stick"] == "1" and after[key]["active"] == "1"]
slid = [moved[key] for key in after if after[key]["stick"] == "0" and after[key]["active"] == "1"]
good = len(stuck) >= 2 and max(stuck) < 1e-10 and all(m > 1e-6 for m in slid)
print(f"rigid master, t = 1.25 -> 1.5: {len(stuck)} stick nodes kept their place to 1e-10 "
      f"(largest move {max(stuck, default=1):.1e}), {len(slid)} slip nodes moved: "
      f"{'ok' if good else 'FAILED'}")
ok = good and ok
sys.exit(0 if ok else 1)
