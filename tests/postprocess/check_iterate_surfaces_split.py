#!/usr/bin/env python3
"""A Newton iterate whose contact surfaces fail the segmentation's check is
split, not fatal (Contact/Kinematics = current).

Usage: check_iterate_surfaces_split.py CONTACT_FEM SCENE.prm

SCENE is tests/scenes/current_kinematics_friction_3d_01.prm (a neo-Hookean
block pressed by 22 % onto a base, then pulled at 30 degrees in the plane)
run with `penalty frictional` at Stiffness factor 3e-1 to t = 4. The slide
step's first iterates switch every node from stick to slip, a jump the
tangent cannot see; the stiff penalty turns it into a force error whose
next iterate distorts a slave face until its facing master faces no longer
tile it (about 0.82 of it). With current kinematics the operators are
rebuilt on every iterate, so that is a property of a bad iterate, not of
the scene: the step must be split (before, the check stopped the run).
(At Stiffness factor 1e-1, the factor until 2026-11-28, the slide step no
longer reaches such an iterate since the penalty's frame is the interface
normal with current kinematics too: it converges without the failure; at
3e-1 the check fails at t = 4 and t = 3.75 and the split steps converge.
Contact/Entry depth factor = 0 keeps the re-entry step limit off: with it
the slide step no longer reaches the bad iterate either, and is split
once, on a stick/slip cycle, instead of twice.)
Checks: the output names the failed check as a Newton failure of an
iterate followed by a split; the run ends converged at t = 4 with every
active node slipping and the pair's tangential / normal force at mu = 0.3
within 1e-2 (the penalty's penetration tilts the normals by about 1e-3).

CONTACT_FEM_PERTURBATION_SEED, if set, renumbers the DoFs.
"""
import re
import sys

from scene_run import perturbation, run_scene


def report(name, good, detail):
    print(f"{name}: {'ok' if good else 'FAILED'} ({detail})")
    return good


contact_fem, scene = sys.argv[1:3]
output = run_scene(contact_fem, scene, "Contact/Formulation=penalty frictional",
                   "Contact/Stiffness factor=3e-1", "Load stepping/End time=4",
                   "Load stepping/Number of load steps=4",
                   "Contact/Entry depth factor=0", *perturbation())
lines = output.splitlines()
failed = [i for i, line in enumerate(lines)
          if "Newton failed at" in line and "its contact surfaces: Contact pair" in line
          and "master faces cover" in line]
split = bool(failed) and failed[0] + 1 < len(lines) and \
    lines[failed[0] + 1].strip().startswith("Splitting the step")
ok = report("the segmentation check of an iterate fails and the step is split", split,
            f"{len(failed)} such failures")
results = output[output.rfind("Results at t = 4"):] if "Results at t = 4" in output else ""
sets = re.search(r"stick / slip nodes:\s+(\d+) / (\d+)", results)
ratio = re.search(r"tangential / normal force:\s+([-0-9.e+]+)", results)
ok = report("converged at t = 4, every active node slipping, F_t / F_n = 0.3 within 1e-2",
            bool(sets and ratio) and int(sets.group(1)) == 0 and int(sets.group(2)) > 0 and
            abs(float(ratio.group(1)) - 0.3) < 1e-2,
            f"stick / slip {sets.groups() if sets else '-'}, "
            f"ratio {ratio.group(1) if ratio else '-'}") and ok
sys.exit(0 if ok else 1)
