#!/usr/bin/env python3
"""3D ironing with Coulomb friction (mu = 0.3) on the current configuration.

Usage: check_ironing_3d_friction.py CONTACT_FEM SOURCE_DIR IRONING.prm

IRONING is tests/postprocess/ironing_3d_friction_01.prm.in: prm/ironing_3d.prm
(Puso and Laursen's slab and die, stored mesh) with alm frictional and
coulomb 0.3, pressed 1.4 in 4 load steps and slid 2 in 8, from x = -2 to
the slab's middle, through 4 steps of the plateau (the die's axis within
0.75 of the middle, as check_ironing_3d.py). Before the fix, load step 11
(x = -0.75 to -0.5) failed after 4 splits: one slave node behind the die,
slipping, stuck after the step's first iterate and slipped again after the
second, and the check for cycling sets took that return to the step's
starting sets for a period-2 cycle (doc/finite_strain.md).

- the run reaches the end of the slide (on the whole surfaces of the
  stored mesh, read since 9819f39, the step control splits a few steps
  whose active set cycles: their number is printed);
- the die's reaction balances the pair's contact force (to 1e-6 of F_n);
- on the plateau every active slave node slips (no stick node once a step
  converged), and at the last step every slip node is on the slip bound
  (|t - T(p) d| / max T < 1e-8, the run's cone check);
- printed, not bounded: the die's F_t / F_n per plateau step (not mu: the
  normal pressure on the curved die has a resultant along the slide, and
  the slip directions differ from node to node), the pair's |T| / |N|, and
  the chatter of F_n (doc/finite_strain.md has the whole slide).
"""
import csv
import math
import os
import re
import sys

from scene_run import perturbation, run_scene

contact_fem, source_dir, scene = sys.argv[1:4]
sys.path.insert(0, os.path.join(source_dir, "bench", "finite_strain"))
from ironing_3d import PLATEAU_HALF_WIDTH, PRESS_END, die_forces  # noqa: E402

MU = 0.3
STEPS = 12

output = run_scene(contact_fem, scene, "Output directory=results", *perturbation())
steps, converged = output.count("  Load step "), output.count("| converged")

# Per converged step: (stick, slip) of the last row of its Newton table.
sets = [(int(m.group(1)), int(m.group(2)))
        for m in re.finditer(r"\|\s*\d+\s*\|\s*(\d+)\s*\|\s*(\d+)\s*\|\s*\d+\s*\|\s*converged", output)]
rows = die_forces("results/forces.csv")
with open("results/forces.csv") as f:
    pair = []
    for r in csv.DictReader(f):
        normal = [float(r["pair_4_3_normal_" + c]) for c in "xyz"]
        tangential = [float(r["pair_4_3_tangential_" + c]) for c in "xyz"]
        pair.append(math.sqrt(sum(v * v for v in tangential)) / math.sqrt(sum(v * v for v in normal)))

plateau = [k for k, (t, x, _, _) in enumerate(rows)
           if t > PRESS_END and abs(x) <= PLATEAU_HALF_WIDTH + 1e-12]
balance = max(max(abs(f[i] - p[i]) for i in range(3)) / abs(f[2]) for _, _, f, p in rows)
for k in plateau:
    t, x, f, _ = rows[k]
    print(f"x = {x:5.2f}: F_n {abs(f[2]):.4f}, die F_t / F_n {math.hypot(f[0], f[1]) / abs(f[2]):.4f}, "
          f"pair |T| / |N| {pair[k]:.4f}, stick / slip nodes {sets[k][0]} / {sets[k][1]}")
normal = [abs(rows[k][2][2]) for k in plateau]
mean = sum(normal) / len(normal)
print(f"F_n on the plateau: mean {mean:.4f}, max |F_n - mean| / mean "
      f"{100 * max(abs(v - mean) for v in normal) / mean:.2f} %")

on_bound = re.search(r"slip nodes off the slip bound: ok \(< 1e-08\)", output) is not None
checks = {
    f"the slide converged to its end ({steps - converged} failed attempts split)":
        "Results at t = 12" in output and converged >= STEPS,
    "4 plateau steps": len(plateau) == 4,
    "the die's reaction balances the contact force to 1e-6 of F_n": balance < 1e-6,
    "every active node slips on the plateau": len(sets) == len(rows) and all(
        sets[k][0] == 0 and sets[k][1] > 0 for k in plateau),
    "slip nodes on the slip bound at the last step": on_bound,
}
for name, ok in checks.items():
    print(f"{name}: {'ok' if ok else 'FAILED'}")
sys.exit(0 if all(checks.values()) else 1)
