#!/usr/bin/env python3
"""A chain of contact pairs through one node, checked by each body's balance.

Usage: check_contact_chain.py CONTACT_FEM SCENE.prm

SCENE is tests/scenes/frictional_chain_02.prm (meshes/contact_chain_2d.geo:
a base L, a block M on its left half, pair 3: 2, and a block R pressed onto
M's right side, pair 5: 4; M's corner node (1, 0.5) is a slave of the first
pair and a master of the second). It is run frictionless, with Coulomb and
with Tresca friction, R's right side moved up, not at all or down along M:
the corner stays in contact in each of these runs. At every load step,
from summary.json, the forces the pairs report (from the multipliers, which
the chain mixes at the corner) must balance the support reactions (K u - f
at the held DoFs, which no multiplier enters), body by body, to 1e-8 of
the forces:
  L: reaction of boundary 1 = force of pair 3: 2 (on M, from L);
  R: reaction of boundary 7 = -force of pair 5: 4 (on R, from M);
  M: reaction of boundary 8 + force of pair 3: 2 - force of pair 5: 4
     + the load on its top (0, -0.3) = 0.
Frictionless, pair 3: 2 then carries exactly M's load (0.3) (a run that
cannot tell a mixed recovery apart here: M's corner takes its pressure from
its vertical residual, and R's frictionless forces on it are horizontal;
the frictional runs, with only the recovery's first pass, cycle and fail). With Coulomb
friction and R moved down, the ALM's pair forces (recovered from the
residual, pass by pass along the chain) must be those of the penalty
formulation (from the penetrations, no recovery) to 1e-3 (measured 5e-5,
the penalty's regularisation). Also: M's whole bottom in contact at the
end (contact length 1 of pair 3: 2, the corner too), the gap closed on the
active nodes (< 1e-10 h), and no penetration (< 1e-3 h, pointwise), but
for the penalty.
"""
import json
import math
import sys

from scene_run import run_scene

contact_fem, scene = sys.argv[1:3]
LOAD = (0.0, -0.3)
cases = {
    "frictionless, R down": ["Contact/Formulation=alm frictionless", "Contact/Friction=",
                             "Boundary conditions/Prescribed displacement="
                             "7: x = -0.01*t; 7: y = -0.02*t"],
    "Coulomb, R down": [],
    "Coulomb, R down, penalty": ["Contact/Formulation=penalty frictional"],
    "Coulomb, R held": ["Boundary conditions/Prescribed displacement="
                        "7: x = -0.01*t; 7: y = 0"],
    "Tresca, R up": ["Contact/Friction=5: tresca 0.05; 3: tresca 0.02",
                     "Boundary conditions/Prescribed displacement="
                     "7: x = -0.01*t; 7: y = 0.02*t"],
}
failures, lines, pair_forces = [], [], {}
for name, settings in cases.items():
    run_scene(contact_fem, scene, "Output directory=results", *settings)
    with open("results/summary.json") as f:
        summary = json.load(f)
    worst = 0.0
    for cycle in summary["cycles"]:
        for step in cycle["load_steps"]:
            forces = step["forces"]
            support = {r["support"]: r["force"] for r in forces["reactions"]}
            pair = {(p["slave"], p["master"]): [p["normal_force"][d] + p["tangential_force"][d]
                                                for d in range(2)] for p in forces["pairs"]}
            pair_lengths = {(p["slave"], p["master"]): p["contact_length"] for p in forces["pairs"]}
            p3, p5 = pair[(3, 2)], pair[(5, 4)]
            scale = max(math.hypot(*p3), math.hypot(*p5), math.hypot(*LOAD))
            for d in range(2):
                residuals = {
                    "L": support["boundary 1"][d] - p3[d],
                    "R": support["boundary 7"][d] + p5[d],
                    "M": support["boundary 8"][d] + p3[d] - p5[d] + LOAD[d],
                }
                if "frictionless" in name:
                    residuals["M's load through pair 3: 2"] = p3[d] + LOAD[d]
                for body, r in residuals.items():
                    worst = max(worst, abs(r) / scale)
                    if abs(r) > 1e-8 * scale:
                        failures.append(f"{name}, t = {step['time']}: {body} off balance in "
                                        f"{'xy'[d]} by {r:.3e} (forces {scale:.3e})")
    contact = summary["cycles"][-1]["contact"]
    # M's whole bottom (length 1) in contact at the end: the corner too.
    closed = pair_lengths[(3, 2)]
    if abs(closed - 1.0) > 1e-9:
        failures.append(f"{name}: contact length of pair 3: 2 {closed}, not 1 (the corner opened)")
    if "penalty" not in name and not contact["max_gap_over_h_on_active_nodes"] < 1e-10:
        failures.append(f"{name}: gap/h {contact['max_gap_over_h_on_active_nodes']}")
    # Pointwise, against the whole master surface: the weighted gaps are
    # zero, a node's own distance is not (5.6e-5 h with R held, 0 in the
    # other runs; the program's own tolerance is 0.05 h).
    if "penalty" not in name and not contact["largest_unexplained_penetration_over_h"] < 1e-3:
        failures.append(f"{name}: penetration/h "
                        f"{contact['largest_unexplained_penetration_over_h']}")
    pair_forces[name] = (p3, p5)
    lines.append(f"{name}: every body balances (< 1e-8 of the forces)"
                 if worst < 1e-8 else f"{name}: imbalance {worst:.1e}")
# The penalty formulation takes its forces from the penetration, not from
# the residual: an independent value of the chain's forces (measured 5e-5
# apart, the penalty's regularisation).
alm, penalty = pair_forces["Coulomb, R down"], pair_forces["Coulomb, R down, penalty"]
apart = max(math.hypot(a[0] - b[0], a[1] - b[1]) / math.hypot(*a) for a, b in zip(alm, penalty))
lines.append(f"Coulomb, R down: ALM and penalty pair forces {'within' if apart < 1e-3 else 'beyond'} "
             "1e-3 of each other")
if apart >= 1e-3:
    failures.append(f"ALM and penalty pair forces {apart:.2e} apart: {alm} against {penalty}")
print("\n".join(lines))
if failures:
    print("\n".join(failures))
    sys.exit(1)
