#!/usr/bin/env python3
"""The guide's example (doc/own_scene.md) against the numbers it must meet.

Usage: check_pin.py CONTACT_FEM SCENE.prm

SCENE is prm/pin.prm (a steel pin pressed into a matching groove of an
aluminium plate by a prescribed displacement of its top). At every load
step, from summary.json: the reaction of the pin's top (boundary 1, K u - f
at its held DoFs), the normal force of the contact pair (from the
multipliers) and the reaction of the plate's base (boundary 2) must be one
force to 1e-9, and frictionless contact must carry no tangential force. At
the end, the contact width and p_max must be within 5 % of Hertz' solution
for that force with the relative curvature of the pin in the groove
(R* = R1 R2 / (R2 - R1) = 21, a / R1 = 0.22): an estimate the run does not
use.
"""
import json
import math
import sys

from scene_run import run_scene

contact_fem, scene = sys.argv[1:3]
run_scene(contact_fem, scene, "Output directory=results", "Output/Write VTU=false")
with open("results/summary.json") as f:
    summary = json.load(f)
failures, checked = [], 0
for cycle in summary["cycles"]:
    for step in cycle["load_steps"]:
        forces = step["forces"]
        reaction = {r["support"]: r["force"] for r in forces["reactions"]}
        pair = forces["pairs"][0]
        top, base, contact = reaction["boundary 1"], reaction["boundary 2"], pair["normal_force"]
        scale = math.hypot(*contact)
        where = f"cycle {cycle['cycle']}, t = {step['time']}"
        for d in range(2):
            if abs(top[d] - contact[d]) > 1e-9 * scale:
                failures.append(f"{where}: pin top {top} != contact force {contact}")
            if abs(base[d] + contact[d]) > 1e-9 * scale:
                failures.append(f"{where}: plate base {base} != -contact force {contact}")
            if abs(pair["tangential_force"][d]) > 1e-9 * scale:
                failures.append(f"{where}: tangential force {pair['tangential_force']}")
        checked += 1

# Hertz, plane strain: a = sqrt(4 P R* / (pi E*)), p0 = 2 P / (pi a).
E1, nu1, E2, nu2, R1, R2 = 210000.0, 0.3, 70000.0, 0.33, 1.0, 1.05
E_star = 1.0 / ((1 - nu1 ** 2) / E1 + (1 - nu2 ** 2) / E2)
R_star = R1 * R2 / (R2 - R1)
last = summary["cycles"][-1]
P = math.hypot(*last["load_steps"][-1]["forces"]["pairs"][0]["normal_force"])
a = math.sqrt(4 * P * R_star / (math.pi * E_star))
p0 = 2 * P / (math.pi * a)
width = last["load_steps"][-1]["forces"]["pairs"][0]["contact_length"]
p_max = last["contact"]["max_contact_pressure"]
for name, value, hertz in [("contact width", width, 2 * a), ("p_max", p_max, p0)]:
    if abs(value / hertz - 1) > 0.05:
        failures.append(f"{name} {value:.4g}, Hertz {hertz:.4g}: more than 5 % apart")
if failures or checked == 0:
    print("\n".join(failures) or "no load step in summary.json")
    sys.exit(1)
print(f"{checked} load steps: pin top reaction = contact force = -plate base reaction; "
      f"P = {P:.4g}, width {width:.4g} (Hertz {2 * a:.4g}), p_max {p_max:.4g} (Hertz {p0:.4g})")
