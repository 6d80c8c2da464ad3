#!/usr/bin/env python3
"""The accumulated slip of pressure_profile.csv and summary.json's stick and
slip counts per pair.

Usage: check_accumulated_slip.py CONTACT_FEM BLOCK.prm UNLOADING.prm
       [EXPECTED NUMDIFF NORMALIZE_PL]

BLOCK (frictional_block_coulomb_01: pressed, then pulled along +x by a
prescribed displacement) pulled monotonically, 0.05 (t - 1) to t = 2:
every active node's accumulated_slip (the path length) equals
|accumulated_tangential_displacement| (each slides one way; the inactive
corner node slid inward under the normal load first) and is at least its
last-step slip_increment. UNLOADING (cattaneo_unloading_01:
Mindlin-Deresiewicz, the tangential load raised to 0.8 mu P and turned
back): the path length is never below |accumulated_tangential_displacement|
and exceeds it at the nodes of the reverse-slip annulus, which slid both
ways. Both: the pair's stick_nodes + slip_nodes in summary.json = its
active slave nodes.

With EXPECTED (the unloading scene test's stored output) the UNLOADING run
is that scene's perturbed twin: it runs on DoFs renumbered by seed 1 and
must print EXPECTED (normalize.pl, then numdiff as tests/run_perturbed.sh;
the pressure profile changes no line of the console).
"""
import csv
import json
import shutil
import sys

from scene_run import prints_stored_output, run_scene, twin_renumbering


def run(contact_fem, scene, directory, displacement, end_time, steps):
    run_scene(contact_fem, scene, f"Output directory={directory}",
              "Output/Write pressure profile=true",
              f"Boundary conditions/Prescribed displacement=1: x = {displacement}",
              f"Load stepping/End time={end_time}",
              f"Load stepping/Number of load steps={steps}")
    with open(f"{directory}/pressure_profile.csv") as f:
        rows = list(csv.DictReader(f))
    with open(f"{directory}/summary.json") as f:
        summary = json.load(f)
    return rows, summary


def check_counts(summary, name, failures):
    cycle = summary["cycles"][-1]
    step = cycle["load_steps"][-1]
    pair = step["forces"]["pairs"][0]
    if pair["stick_nodes"] + pair["slip_nodes"] != step["active_slave_nodes"]:
        failures.append(f"{name}: stick {pair['stick_nodes']} + slip {pair['slip_nodes']} "
                        f"!= active {step['active_slave_nodes']}")


contact_fem, scene, unloading = sys.argv[1:4]
twin = sys.argv[4:7] if len(sys.argv) >= 7 else None
failures = []
monotone, summary = run(contact_fem, scene, "monotone", "0.05*max(t-1, 0)", 2, 4)
check_counts(summary, "monotone", failures)
scale = max(float(r["accumulated_slip"]) for r in monotone)
if scale <= 0.:
    failures.append("monotone: no slip")
for r in (r for r in monotone if r["active"] == "1"):
    length, along = float(r["accumulated_slip"]), float(r["accumulated_tangential_displacement"])
    last = abs(float(r["slip_increment"]))
    if abs(length - abs(along)) > 1e-12 * scale or last > length + 1e-12 * scale:
        failures.append(f"monotone node x = {r['x']}: path {length}, accumulated {along}, "
                        f"last step {last}")

shutil.rmtree("reversed", ignore_errors=True)  # no "removed ... of an earlier run" line
output = run_scene(contact_fem, unloading, "Output directory=reversed",
                   "Output/Write pressure profile=true", *twin_renumbering(twin))
if twin and not prints_stored_output(output, twin):
    failures.append("unloading on renumbered DoFs: not the scene's stored output (see diff)")
with open("reversed/pressure_profile.csv") as f:
    reversed_rows = list(csv.DictReader(f))
with open("reversed/summary.json") as f:
    summary = json.load(f)
check_counts(summary, "unloading", failures)
scale = max(float(r["accumulated_slip"]) for r in reversed_rows)
slid_back = 0
for r in reversed_rows:
    length, along = float(r["accumulated_slip"]), float(r["accumulated_tangential_displacement"])
    if length < abs(along) - 1e-12 * scale:
        failures.append(f"reversed node x = {r['x']}: path {length} < |accumulated| {along}")
    if length > abs(along) + 0.01 * scale:
        slid_back += 1
if slid_back == 0:
    failures.append("reversed: no node slid back")
if failures:
    print("\n".join(failures))
    sys.exit(1)
print(f"monotone: path = |accumulated| at {len(monotone)} nodes; unloading: {slid_back} nodes "
      "slid both ways (path > |accumulated|); stick + slip = active")
