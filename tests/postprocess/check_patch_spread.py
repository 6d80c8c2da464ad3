#!/usr/bin/env python3
"""The 3D contact patch test on general quadrilateral faces, to 1e-10.

Usage: check_patch_spread.py CONTACT_FEM SCENE.prm

SCENE is tests/scenes/contact_patch_3d_04 (its slave block meshed with
unstructured quadrilaterals at arbitrary angles, trapezoids among them):
the exact contact pressure is uniform, so (p_max - p_min) / p_max over the
active slave nodes and max |gap| / h must be below 1e-10 (the console
prints them only against 1e-8). With the mortar quadrature of
parallelograms plus two points per direction on other faces the spread
was 5e-10; plus four it is at round-off.
"""
import json
import os
import sys

from scene_run import run_scene

contact_fem, scene = sys.argv[1:3]
run_scene(contact_fem, scene, "Output directory=results")
with open(os.path.join("results", "summary.json")) as f:
    contact = json.load(f)["cycles"][-1]["contact"]
p_max = contact["max_contact_pressure"]
spread = (p_max - contact["min_active_contact_pressure"]) / p_max
gap = contact["max_gap_over_h_on_active_nodes"]
print(f"p_max {p_max!r}, spread {spread:.3e}, max |gap|/h {gap:.3e}, "
      f"{contact['active_slave_nodes']} active slave nodes")
if not (abs(p_max - 2.0) < 2e-10 and spread < 1e-10 and gap < 1e-10):
    sys.exit("the patch test on general quadrilateral faces is not passed to 1e-10")
