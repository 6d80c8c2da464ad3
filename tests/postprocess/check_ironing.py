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

Newton converges quadratically once the sets hold (scene_run.check_quadratic:
r_k <= C r_(k-1)^2; C = 100 on the scene, 1e4 refined or in 9 steps).

And the coarse mesh in 9 load steps (pressed in one, slid 0.75 element
lengths per step; this stopped with "does not project onto the master
face" before Mortar::overlap() rejected distant flanks): frictionless
elasticity does not depend on the path, so at the times both runs share
the die's force equals that of the 36 steps to 1e-6 of F_n.
"""
import csv
import sys

from scene_run import check_quadratic, run_scene

SLIDE_PER_TIME = 0.1875   # die top x = 0.1875 (t - 1) for t > 1
PLATEAU_START = 0.5       # slide from which the plateau counts
quadratic = True


def plateau_forces(contact_fem, scene, refinements, *settings):
    output = run_scene(contact_fem, scene, f"Geometry/Global refinements={refinements}",
                       *settings)
    steps, converged = output.count("  Load step "), output.count("| converged")
    # Quadratic Newton once the sets hold, r_k <= C r_(k-1)^2: C = 100 on the
    # scene as it is (measured 2026-11-28: passes at 100, not at 10); the
    # refined mesh and the 9 longer steps have larger constants (measured
    # 838 and 1510, quadratic: 1.9e-5, 5.6e-7, 1.3e-10), bounded by 1e4
    # (a linear tail of rate 0.01 from 1e-6 gives C = 1e4).
    bound = 100. if refinements == 0 and not settings else 1e4
    global quadratic
    quadratic = check_quadratic(f"refinements {refinements}, {steps} load steps", output,
                                bound) and quadratic
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
reference = {}
for refinements in (0, 1):
    steps, converged, plateau = plateau_forces(contact_fem, scene, refinements)
    if refinements == 0:
        reference = {slide: r for slide, r, _ in plateau}
    normal = [abs(r[1]) for _, r, _ in plateau]
    mean = sum(normal) / len(normal) if normal else 0.
    ratio = max((abs(r[0]) / abs(r[1]) for _, r, _ in plateau), default=1.)
    # The support's reaction on the die balances the contact force on the
    # die, so it equals the pair's force on the slave (the block).
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

steps, converged, plateau = plateau_forces(contact_fem, scene, 0,
                                           "Load stepping/Number of load steps=9")
shared = [(reference[slide], r) for slide, r, _ in plateau if slide in reference]
difference = max((max(abs(a[0] - b[0]), abs(a[1] - b[1])) / abs(a[1]) for a, b in shared),
                 default=1.)
same = converged == steps and len(shared) >= 4 and difference < 1e-6
print(f"9 load steps (0.75 element lengths per slide step): {converged} of {steps} converged; "
      f"the die's force at the {len(shared)} shared plateau times equals that of 36 steps "
      f"to 1e-6 of F_n: {'ok' if same else 'FAILED'} (largest difference {difference:.1e})")
sys.exit(0 if ok and falling and same and quadratic else 1)
