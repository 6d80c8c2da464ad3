#!/usr/bin/env python3
"""'mpc frictionless' / 'mpc frictional' against the ALM formulations.

Usage: check_mpc_vs_alm.py CONTACT_FEM frictionless|frictional SCENE.prm...

Each scene runs with 'alm KIND' and 'mpc KIND' (Contact/Formulation set on
the command line, nothing else changed). Both must converge, and the last
cycle's results must agree within the Newton tolerance, relative 1e-4
(Newton/Displacement and Multiplier relative tolerance, their defaults,
which these scenes keep): the total contact force (and, with friction, the
tangential contact force, relative to the total one, since it vanishes on
symmetric scenes), the largest contact pressure and the contact half-width
(summary.json's contact_half_width); the active count exactly, and with
friction the stick and slip counts. The two formulations impose the same
constraints and reach the same conditions; only the rules that pick the
sets differ (reactions, gap and slip against the augmented tests).
"""
import json
import os
import sys

from scene_run import run_scene

TOLERANCE = 1e-4


def contact_results(contact_fem, scene, formulation):
    """The status and the contact results of the last cycle of scene."""
    name = os.path.splitext(os.path.basename(scene))[0]
    directory = f"{name}-{formulation.replace(' ', '-')}"
    run_scene(contact_fem, scene, f"Contact/Formulation={formulation}",
              f"Output directory={directory}", "Output/Write VTU=false")
    with open(os.path.join(directory, "summary.json")) as f:
        summary = json.load(f)
    return summary["status"], summary["cycles"][-1]["contact"]


def compare(name, alm, mpc, frictional):
    """The failures of one scene; prints its numbers."""
    failures = []
    scales = {"total_contact_force": alm["total_contact_force"],
              "max_contact_pressure": alm["max_contact_pressure"],
              "contact_half_width": alm["contact_half_width"]}
    if frictional:
        scales["total_tangential_contact_force"] = alm["total_contact_force"]
    cells = []
    for key, scale in scales.items():
        a, m = alm[key], mpc[key]
        difference = abs(m - a) / max(abs(scale), 1e-300)
        cells.append(f"{key} {m:.6g} (alm {a:.6g})")
        if not difference <= TOLERANCE:
            failures.append(f"{name}: {key} mpc {m!r}, alm {a!r}: relative difference "
                            f"{difference:.2e} > {TOLERANCE}")
    counts = ["active_slave_nodes"] + (["stick_nodes", "slip_nodes"] if frictional else [])
    for key in counts:
        if alm[key] != mpc[key]:
            failures.append(f"{name}: {key} mpc {mpc[key]}, alm {alm[key]}")
    print(f"{name}: " + ", ".join(cells))
    return failures


contact_fem, kind, scenes = sys.argv[1], sys.argv[2], sys.argv[3:]
failures = []
for scene in scenes:
    alm_status, alm = contact_results(contact_fem, scene, f"alm {kind}")
    mpc_status, mpc = contact_results(contact_fem, scene, f"mpc {kind}")
    name = os.path.basename(scene)
    if alm_status != "converged" or mpc_status != "converged":
        failures.append(f"{name}: status alm {alm_status}, mpc {mpc_status}")
        continue
    failures += compare(name, alm, mpc, kind == "frictional")
if failures:
    print("\n".join(failures))
    sys.exit(1)
print(f"{len(scenes)} scenes: mpc {kind} = alm {kind} within {TOLERANCE} relative")
