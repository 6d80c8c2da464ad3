#!/usr/bin/env python3
"""2D ironing, frictionless, on the current configuration (issue 29, item 4).

Usage: check_ironing.py CONTACT_FEM IRONING.prm

IRONING is tests/scenes/ironing_2d_01.prm: a stiff half-disc die pressed
0.2 into a soft neo-Hookean block (t in [0, 1]) and slid 1.5 along x (t in
[1, 9]; the block top's element length is 0.25), run on its mesh and once
refined globally. From forces.csv, the reaction on the die's driven top
(the force the die needs: F_x tangential, F_y normal) per load step. The
sliding plateau is the slide beyond 0.5 (two coarse element lengths, past
the start-up of the slide). On it:

- every step converges, and F_x balances the pair's contact force (to 1e-8
  of F_n);
- frictionless: |F_x| / |F_y| < 1e-2 at every plateau step, on both meshes;
- the chatter of the normal force, max |F_y - mean| / |mean| over the
  plateau, is printed per mesh and must fall under refinement (by at least
  a factor 1.5: the chatter comes from the slave nodes entering and leaving
  the contact zone, one element length apart).
"""
import csv
import sys

from scene_run import run_scene

SLIDE_PER_TIME = 0.1875   # die top x = 0.1875 (t - 1) for t > 1
PLATEAU_START = 0.5       # slide from which the plateau counts


def plateau_forces(contact_fem, scene, refinements):
    output = run_scene(contact_fem, scene, f"Geometry/Global refinements={refinements}")
    steps, converged = output.count("  Load step "), output.count("| converged")
    with open("results/forces.csv") as f:
        rows = list(csv.DictReader(f))
    plateau = []
    for r in rows:
        slide = SLIDE_PER_TIME * max(float(r["t"]) - 1., 0.)
        if slide >= PLATEAU_START - 1e-12:
            reaction = (float(r["boundary_1_x"]), float(r["boundary_1_y"]))
            pair = (float(r["pair_4_3_normal_x"]) + float(r["pair_4_3_tangential_x"]),
                    float(r["pair_4_3_normal_y"]) + float(r["pair_4_3_tangential_y"]))
            plateau.append((slide, reaction, pair))
    return steps, converged, plateau


contact_fem, scene = sys.argv[1:3]
ok = True
chatter = []
for refinements in (0, 1):
    steps, converged, plateau = plateau_forces(contact_fem, scene, refinements)
    normal = [abs(r[1]) for _, r, _ in plateau]
    mean = sum(normal) / len(normal) if normal else 0.
    ratio = max((abs(r[0]) / abs(r[1]) for _, r, _ in plateau), default=1.)
    # The die's reaction is minus the contact force the block exerts on it
    # (the pair force acts on the slave, the block).
    balance = max((abs(r[0] - p[0]) / abs(r[1]) for _, r, p in plateau), default=1.)
    amplitude = max(abs(f - mean) for f in normal) / mean if normal else 1.
    chatter.append(amplitude)
    good = (converged == steps and len(plateau) >= 8 and ratio < 1e-2 and balance < 1e-8)
    print(f"refinements {refinements}: {converged} of {steps} load steps converged, "
          f"{len(plateau)} on the plateau; mean normal force {mean:.4g}; "
          f"|F_t| / F_n < 1e-2: {'ok' if ratio < 1e-2 else 'FAILED'} (largest {ratio:.1e}); "
          f"F_t equals the pair's: {'ok' if balance < 1e-8 else 'FAILED'}; "
          f"normal-force chatter {100 * amplitude:.2f} % of the mean")
    ok = good and ok
falling = chatter[1] * 1.5 <= chatter[0]
print(f"chatter falls under refinement by at least 1.5: {'ok' if falling else 'FAILED'} "
      f"({100 * chatter[0]:.2f} % -> {100 * chatter[1]:.2f} %)")
sys.exit(0 if ok and falling else 1)
