#!/usr/bin/env python3
"""Runs a scene with tied pairs and checks the tying traction of its volume VTU.

Usage: check_tied_volume.py CONTACT_FEM [--launcher=MPIEXEC,ARG...] SCENE.prm [SETTING...]

The scene runs with its VTU output and tying_profile.csv and the
'Section/Key=value' SETTINGs. In the volume VTU of the last load step
(solution_NNN.pvtu), tying_traction and tying_normal_traction must be, at
every tied slave node (matched by its reference position) in the slave
body's cells, the traction and normal traction tying_profile.csv has for
that node, to the VTU's single precision, and zero elsewhere (vtu_files.py
tied_volume()). The traction must vary along the interface (a uniform one
could not show a node mixed up with another), and released nodes (tied
flag 0) must show what the CSV has for them. With --launcher, contact_fem
runs under that MPI launcher (its words separated by commas), so the
volume has a piece per rank.
"""
import csv
import os
import sys

from scene_run import run_scene
from vtu_files import collection, read_surface, tied_volume

arguments = sys.argv[1:]
launcher = arguments.pop(1)[len("--launcher="):].split(",") \
    if arguments[1].startswith("--launcher=") else []
contact_fem, scene = arguments[:2]
run_scene(contact_fem, scene, "Output directory=results", "Output/Write VTU=true",
          "Output/Write pressure profile=true", *arguments[2:], launcher=launcher)
failures = []

# Every tied slave node (hanging vertices too) from the tied surface VTU.
points, _, fields, failures = read_surface(collection("tied_surface.pvd")[-1][1])
references = [[x[d] - u[d] for d in range(3)] for x, u in zip(points, fields["displacement"])]
volume = collection("solution.pvd")[-1][1]
values, wrong = tied_volume(volume, references)
failures += wrong
if launcher:
    import xml.etree.ElementTree as ET
    pieces = len(list(ET.parse(os.path.join("results", volume)).getroot().iter("Piece")))
    if pieces < 2:
        failures.append(f"{volume}: {pieces} piece(s) from the MPI run")

with open(os.path.join("results", "tying_profile.csv")) as f:
    rows = list(csv.DictReader(f))
dim = 3 if "traction_z" in rows[0] else 2
tractions = [[float(row["traction_" + a]) for a in "xyz"[:dim]] for row in rows]
scale = max(abs(t) for traction in tractions for t in traction)
size = max(abs(x) for p in references for x in p)
spread = max(max(t[d] for t in tractions) - min(t[d] for t in tractions) for d in range(dim))
if spread < 1e-3 * scale:
    failures.append(f"the traction is uniform ({spread} spread): nodes could be mixed up")
checked = 0
for row, traction in zip(rows, tractions):
    x = [float(row["reference_" + a]) for a in "xyz"[:dim]] + [0.0] * (3 - dim)
    r = next((r for r, y in enumerate(references)
              if all(abs(x[d] - y[d]) <= 1e-6 * size for d in range(3))), None)
    if r is None:
        failures.append(f"tying_profile.csv node at {x} not on the tied surface VTU")
        continue
    for t, p in values[r] if r < len(values) else []:
        checked += 1
        if any(abs(t[d] - traction[d]) > 1e-6 * scale for d in range(dim)) or \
           abs(p - float(row["normal_traction"])) > 1e-6 * scale:
            failures.append(f"{volume} at {x}: tying traction {t[:dim]}, normal {p}; "
                            f"tying_profile.csv: {traction}, {row['normal_traction']}")

if failures:
    print("\n".join(failures))
    sys.exit(1)
released = sum(row["tied"] == "0" for row in rows)
print(f"{volume}: the tying traction of tying_profile.csv at its {len(rows)} nodes ({released} "
      f"released), {checked} points of the slave cells, zero elsewhere; the traction ranges over "
      f"{spread:.3g} (largest {scale:.3g})")
