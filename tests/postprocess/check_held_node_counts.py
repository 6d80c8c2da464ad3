#!/usr/bin/env python3
"""Stick and slip counts of a node a support holds tangentially (issue 28).

Usage: check_held_node_counts.py CONTACT_FEM SCENE.prm

SCENE is tests/scenes/frictional_hertz_3d_01.prm: a quarter sphere on a
plate, symmetry planes x = 0 and y = 0, Coulomb mu = 0.2. The slave node on
the axis x = y = 0 is held in x and y by the two planes: it carries no
friction, so it neither sticks nor slips (a node on one plane only slips
along the plane and counts). Run with 'alm frictional' and 'penalty
frictional', each must give:

- the contact summary (summary.json, as the console's "stick / slip
  nodes"): stick + slip = active slave nodes - the active nodes on the axis
  (counted from pressure_profile.csv's coordinates, 1 here);
- stick = the active nodes pressure_profile.csv marks stick (stick = 1);
- the last step's per-pair counts equal the contact summary's.

'penalty frictional' counted every active node that did not stick as
slipping, the node on the axis too.
"""
import csv
import json
import sys

from scene_run import perturbation, run_scene


def check(contact_fem, scene, formulation):
    directory = formulation.replace(" ", "_")
    output = run_scene(contact_fem, scene, f"Contact/Formulation={formulation}",
                       f"Output directory={directory}", "Output/Write pressure profile=true",
                       *perturbation())
    with open(f"{directory}/pressure_profile.csv") as f:
        rows = [r for r in csv.DictReader(f) if r["active"] == "1"]
    with open(f"{directory}/summary.json") as f:
        summary = json.load(f)
    size = max(max(abs(float(r["reference_x"])), abs(float(r["reference_y"]))) for r in rows)
    on_axis = [r for r in rows if abs(float(r["reference_x"])) <= 1e-12 * size and
               abs(float(r["reference_y"])) <= 1e-12 * size]
    stick_in_profile = sum(r["stick"] == "1" for r in rows)
    contact = summary["cycles"][-1]["contact"]
    pair = summary["cycles"][-1]["load_steps"][-1]["forces"]["pairs"][0]
    active, stick, slip = contact["active_slave_nodes"], contact["stick_nodes"], contact["slip_nodes"]
    console = f"stick / slip nodes:           {stick} / {slip}" in output
    good = (len(on_axis) == 1 and active == len(rows) and stick + slip == active - len(on_axis)
            and stick == stick_in_profile and console and
            (pair["stick_nodes"], pair["slip_nodes"]) == (stick, slip))
    print(f"{formulation}: stick + slip = active - on the axis, stick as in the profile, the "
          f"pair's counts and the console's the same: {'ok' if good else 'FAILED'} (active "
          f"{active}, on the axis {len(on_axis)}, stick {stick} (profile {stick_in_profile}), "
          f"slip {slip}, pair {pair['stick_nodes']} / {pair['slip_nodes']})")
    return good


def main():
    contact_fem, scene = sys.argv[1:3]
    ok = check(contact_fem, scene, "alm frictional")
    ok = check(contact_fem, scene, "penalty frictional") and ok
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
