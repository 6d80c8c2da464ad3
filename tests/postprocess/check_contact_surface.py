#!/usr/bin/env python3
"""Runs a contact patch scene with its VTU output and checks what the files say.

Usage: check_contact_surface.py CONTACT_FEM SCENE.prm

The scene is a 2D patch test under a uniform pressure p = 2 (exact for the
mortar method): every active slave node of contact_surface_NNN.vtu must
show the pressure 2 and the traction (0, 2) on the slave to 1e-10, the
traction integrated over the surface's cells (exact for a uniform traction
on straight cells) must equal the pair force of forces.csv to 1e-10, and
solution.pvd and contact_surface.pvd must list the two load steps at their
load times 0.5 and 1; pressure_profile.csv must hold the same slave nodes
at the same current and reference positions.
"""
import csv
import os
import sys

from scene_run import run_scene
from vtu_files import collection, read_surface

contact_fem, scene = sys.argv[1:3]
run_scene(contact_fem, scene, "Output directory=results", "Output/Write VTU=true",
          "Output/Write pressure profile=true", "Load stepping/Number of load steps=2")

failures = []


def check(condition, what):
    if not condition:
        failures.append(what)


# The collections: the load steps at their load times.
for name in ("solution.pvd", "contact_surface.pvd", "contact_surface_cycle_0.pvd"):
    times = [t for t, _ in collection(name)]
    check(times == [0.5, 1.0], f"{name}: times {times}, expected [0.5, 1.0]")

points, cells, fields, wrong = read_surface(collection("contact_surface.pvd")[-1][1])
failures += wrong
n_points = len(points)
check(set(cells["types"]) == {3}, f"cell types {set(cells['types'])}, expected lines (3)")
check(cells["offsets"][-1] == len(cells["connectivity"]), "offsets do not end at the connectivity")

for k in range(n_points):
    if fields["active"][k][0] != 1.0:
        failures.append(f"node {k} is not active")
        continue
    p = fields["contact_pressure"][k][0]
    t = fields["traction"][k]
    check(abs(p - 2.0) < 2e-10, f"node {k}: pressure {p!r}, expected 2")
    check(abs(t[0]) < 2e-10 and abs(abs(t[1]) - 2.0) < 2e-10,
          f"node {k}: traction {t}, expected (0, +-2)")

# Integrated traction (trapezoid rule: exact for a uniform traction) over
# the reference cells (points less displacement), where the mortar weights
# of the pair force are measured (Contact/Kinematics = small).
points = [[x[d] - u[d] for d in range(3)] for x, u in zip(points, fields["displacement"])]
force = [0.0, 0.0]
start = 0
for end in cells["offsets"]:
    a, b = cells["connectivity"][start:start + 2]
    start = end
    length = sum((points[a][d] - points[b][d]) ** 2 for d in range(2)) ** 0.5
    for d in range(2):
        force[d] += 0.5 * length * (fields["traction"][a][d] + fields["traction"][b][d])
with open(os.path.join("results", "forces.csv")) as f:
    last = list(csv.DictReader(f))[-1]
pair = [float(last["pair_3_4_normal_x"]) + float(last["pair_3_4_tangential_x"]),
        float(last["pair_3_4_normal_y"]) + float(last["pair_3_4_tangential_y"])]
for d in range(2):
    check(abs(force[d] - pair[d]) <= 1e-10 * max(1.0, abs(pair[1])),
          f"integrated traction {force} differs from the pair force {pair} of forces.csv")

# pressure_profile.csv (the latest cycle's, equal to pressure_profile_cycle_0.csv):
# the same slave nodes, at the same current and reference positions, with
# the pressure 2.
with open(os.path.join("results", "pressure_profile.csv")) as f:
    profile = list(csv.DictReader(f))
with open(os.path.join("results", "pressure_profile_cycle_0.csv")) as f:
    check(list(csv.DictReader(f)) == profile, "pressure_profile_cycle_0.csv differs from pressure_profile.csv")
check(len(profile) == n_points, f"pressure_profile.csv: {len(profile)} rows, {n_points} slave nodes")
current = [[x[d] + u[d] for d in range(2)] for x, u in zip(points, fields["displacement"])]
reference = [x[:2] for x in points]


def near(p, candidates):
    return min(max(abs(p[d] - q[d]) for d in range(2)) for q in candidates) < 1e-9


for row in profile:
    here = [float(row["x"]), float(row["y"])]
    there = [float(row["reference_x"]), float(row["reference_y"])]
    check(near(here, current), f"profile row at {here}: no slave node of the VTU there")
    check(near(there, reference), f"profile row at reference {there}: no slave node there")
    check(abs(float(row["pressure"]) - 2.0) < 2e-10 and row["pair"] == "0",
          f"profile row at {here}: pressure {row['pressure']}, pair {row['pair']}")

if failures:
    print("\n".join(failures))
    sys.exit(1)
print(f"{n_points} slave nodes: pressure 2 and traction (0, 2) at each; integrated "
      f"traction = pair force {pair}; load times 0.5 and 1")
