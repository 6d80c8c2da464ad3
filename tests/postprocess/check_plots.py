#!/usr/bin/env python3
"""Runs scenes, then bench/plot_results.py on their output, and checks both.

Usage: check_plots.py CONTACT_FEM PLOT_SCRIPT ADAPTIVE_SCENE.prm PATCH_SCENE.prm

1. ADAPTIVE_SCENE (three adaptive cycles with an analytical solution and a
   reference energy): convergence.csv has one row per cycle with the DoFs,
   the wall times, the error measures, p_max and the pair's normal force,
   which must equal the magnitude of the normal force of the cycle's last
   row of forces.csv to 1e-9; the plot script writes its three PNGs.
2. PATCH_SCENE with a displacement probe, in two load steps: forces.csv
   carries the probe's displacement, equal to summary.json's to 1e-9 (the
   column a force-displacement curve takes), and the plot script draws the
   force against it.
"""
import csv
import json
import math
import os
import shutil
import sys

from scene_run import run, run_scene

contact_fem, plot_script, adaptive_scene, patch_scene = sys.argv[1:5]
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)


def rows(directory, name):
    with open(os.path.join(directory, name)) as f:
        return list(csv.DictReader(f))


def plots(directory):
    print(run([plot_script, directory]).strip())
    for name in ("error_vs_dofs.png", "error_vs_time.png", "force_vs_displacement.png"):
        path = os.path.join(directory, name)
        check(os.path.isfile(path) and os.path.getsize(path) > 1000, f"{path} missing or empty")


# 1. The adaptive scene.
shutil.rmtree("adaptive", ignore_errors=True)
run_scene(contact_fem, adaptive_scene, "Output directory=adaptive")
convergence = rows("adaptive", "convergence.csv")
forces = rows("adaptive", "forces.csv")
check(len(convergence) == 3, f"convergence.csv: {len(convergence)} rows, expected 3")
for row in convergence:
    cycle = row["cycle"]
    for column in ("dofs", "wall_time", "cumulative_wall_time", "relative_estimated_error",
                   "energy_error", "pressure_l2_relative_error", "max_contact_pressure",
                   "pair_3_4_normal_force", "pair_3_4_contact_length"):
        value = float(row[column]) if row.get(column) else math.nan
        check(math.isfinite(value) and value > 0, f"cycle {cycle}: {column} = {row.get(column)!r}")
    last = [r for r in forces if r["cycle"] == cycle][-1]
    normal = math.hypot(float(last["pair_3_4_normal_x"]), float(last["pair_3_4_normal_y"]))
    check(abs(float(row["pair_3_4_normal_force"]) - normal) <= 1e-9 * normal,
          f"cycle {cycle}: normal force {row['pair_3_4_normal_force']} in convergence.csv, "
          f"{normal} in forces.csv")
plots("adaptive")

# 2. The patch test with a probe.
shutil.rmtree("patch", ignore_errors=True)
run_scene(contact_fem, patch_scene, "Output directory=patch",
          "Output/Displacement probes=2 @ 1, 1", "Load stepping/Number of load steps=2")
with open(os.path.join("patch", "summary.json")) as f:
    probe = json.load(f)["cycles"][-1]["displacement_probes"][0]["displacement"]
last = rows("patch", "forces.csv")[-1]
for d, axis in enumerate("xy"):
    column = f"probe_1_u{axis}"
    value = float(last[column]) if column in last else math.nan
    check(abs(value - probe[d]) <= 1e-9 * max(abs(probe[d]), 1e-12),
          f"forces.csv {column} = {last.get(column)!r}, summary.json {probe[d]}")
plots("patch")

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("convergence.csv, forces.csv and the plots agree")
