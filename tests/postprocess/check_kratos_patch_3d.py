#!/usr/bin/env python3
"""Kratos' 3D patch test with its bulk model (tests/scenes/kratos_patch_3d_02:
Saint Venant-Kirchhoff, tight Newton tolerance) against two references, by
the 10 digits of summary.json's displacement probes.

Usage: check_kratos_patch_3d.py CONTACT_FEM SCENE.prm

- The independent two-element solver bench/kratos_validation/patch_3d.py,
  case (c) (the same model, interface in equilibrium), to 1e-9 relative.
- Kratos' stored u_y (ALM_frictionless_3D_contact_simplest_patch_matching_
  test, results.json), to 3e-6 relative: the solver's case (d) shows that
  the remaining 2e-6 is Kratos' interface left out of equilibrium by its
  Newton tolerance (1e-4 relative residual).
"""
import json
import sys

from scene_run import run_scene

# (probe, u_x, u_y, u_z) of case (c); probes as in the scene, body 2 = lower.
INDEPENDENT = {
    "lower top": (2.05572541208e-03, -1.00049489844e-02),
    "upper base": (2.05572781718e-03, -9.99494898443e-03),
}
KRATOS_UY = {"lower top": 2.0557214043e-03, "upper base": 2.0557318811e-03}

contact_fem, scene = sys.argv[1:3]
run_scene(contact_fem, scene)
with open("results/summary.json") as f:
    probes = json.load(f)["cycles"][-1]["displacement_probes"]

failures = []


def check(name, computed, expected, tolerance, reference):
    error = abs(computed - expected) / abs(expected)
    verdict = "ok" if error <= tolerance else "FAILED"
    print(f"{name}: {computed:.10e} against {reference} {expected:.10e}: "
          f"relative {error:.1e} (tolerance {tolerance:g}) {verdict}")
    if error > tolerance:
        failures.append(name)


for probe in probes:
    side = "lower top" if probe["point"].startswith("2 @") else "upper base"
    ux, uy, uz = probe["displacement"]
    lateral, axial = INDEPENDENT[side]
    where = f"{side} {probe['point']}"
    # u_x = +-u_y = +-lateral at the corners (symmetry).
    check(f"{where} |u_x|", abs(ux), lateral, 1e-9, "independent")
    check(f"{where} |u_y|", abs(uy), lateral, 1e-9, "independent")
    check(f"{where} u_z", uz, axial, 1e-9, "independent")
    check(f"{where} |u_y|", abs(uy), KRATOS_UY[side], 3e-6, "Kratos")

if len(probes) != 8:
    failures.append(f"{len(probes)} probes, expected 8")
if failures:
    sys.exit("failed: " + ", ".join(failures))
print("all checks passed")
