#!/usr/bin/env python3
"""'mpc frictionless' against 'alm frictionless' on frictionless scenes.

Usage: check_mpc_vs_alm.py CONTACT_FEM SCENE.prm...

Each scene runs with both formulations (Contact/Formulation set on the
command line, nothing else changed). Both must converge; the total contact
force, the largest contact pressure and the contact half-width
(summary.json's contact_half_width) of the last cycle must agree within
the Newton tolerance: relative 1e-4 (Newton/Displacement and Multiplier
relative tolerance, their defaults, which these scenes keep), and the
number of active slave nodes exactly. The two formulations impose the
same constraints and reach the same complementarity conditions; only the
active-set rule differs (reactions and gap, against lambda - eps g).
"""
import json
import os
import sys

from scene_run import run_scene

TOLERANCE = 1e-4
KEYS = ["total_contact_force", "max_contact_pressure", "contact_half_width"]


def contact_results(contact_fem, scene, formulation):
    """The status and the contact results of the last cycle of scene."""
    name = os.path.splitext(os.path.basename(scene))[0]
    directory = f"{name}-{formulation.replace(' ', '-')}"
    run_scene(contact_fem, scene, f"Contact/Formulation={formulation}",
              f"Output directory={directory}", "Output/Write VTU=false")
    with open(os.path.join(directory, "summary.json")) as f:
        summary = json.load(f)
    return summary["status"], summary["cycles"][-1]["contact"]


contact_fem, scenes = sys.argv[1], sys.argv[2:]
failures = []
for scene in scenes:
    alm_status, alm = contact_results(contact_fem, scene, "alm frictionless")
    mpc_status, mpc = contact_results(contact_fem, scene, "mpc frictionless")
    name = os.path.basename(scene)
    if alm_status != "converged" or mpc_status != "converged":
        failures.append(f"{name}: status alm {alm_status}, mpc {mpc_status}")
        continue
    cells = []
    for key in KEYS:
        a, m = alm[key], mpc[key]
        difference = abs(m - a) / max(abs(a), 1e-300)
        cells.append(f"{key} {m:.6g} (alm {a:.6g})")
        if not difference <= TOLERANCE:
            failures.append(f"{name}: {key} mpc {m!r}, alm {a!r}: relative difference "
                            f"{difference:.2e} > {TOLERANCE}")
    if alm["active_slave_nodes"] != mpc["active_slave_nodes"]:
        failures.append(f"{name}: active slave nodes mpc {mpc['active_slave_nodes']}, "
                        f"alm {alm['active_slave_nodes']}")
    print(f"{name}: " + ", ".join(cells))
if failures:
    print("\n".join(failures))
    sys.exit(1)
print(f"{len(scenes)} scenes: mpc = alm within {TOLERANCE} relative")
