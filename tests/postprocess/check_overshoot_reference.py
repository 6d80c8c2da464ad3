#!/usr/bin/env python3
"""A converged step balances its forces even when one Newton iterate
overshoots (NewtonMonitor's reference, doc/design.md "ALM semi-smooth
Newton").

Usage: check_overshoot_reference.py CONTACT_FEM SCENE.prm

SCENE is tests/scenes/frictional_hertz_3d_penalty_01.prm (penalty
frictional, Coulomb mu = 0.2, Q1 on the quarter Hertz sphere), run here at
Sphere refinements 2 with Kinematics = updated in 4 load steps and at the
default Newton tolerance (Displacement relative 1e-4). From step 2 on the
first slip solve overshoots: its residual is 1e4 times the step's initial
one. With the reference of the relative test the largest residual of the
step, that spike accepted the later steps at 4e-7 / 6e-8 of it while the
load and the reactions were out of balance by 4.2e-5 of the forces (and
tangential / normal 0.143432 against 0.143492 at tolerances 1e-10).
Checks:
- the run overshoots (some iterate's residual above 100 times its step's
  initial one), so that the case is exercised;
- the load and the support reactions balance to 1e-6 of the forces (the
  tolerance of the run's balance warning; measured 3.8e-8), and the run
  prints no balance warning.

CONTACT_FEM_PERTURBATION_SEED, if set, renumbers the DoFs.
"""
import json
import re
import sys

from scene_run import perturbation, run_scene

ROW = re.compile(r"^\s*\|\s*(\d+)\s*\|[^|]+\|\s*([^|]+)\|")


def largest_overshoot(output):
    """The largest residual of an iterate over its step's initial one."""
    largest, initial = 0., None
    for line in output.splitlines():
        match = ROW.match(line)
        if not match:
            continue
        try:
            value = float(match.group(2))
        except ValueError:  # at the absolute tolerance or round-off
            continue
        if int(match.group(1)) == 0:
            initial = value
        elif initial:
            largest = max(largest, value / initial)
    return largest


def report(name, good, detail):
    print(f"{name}: {'ok' if good else 'FAILED'} ({detail})")
    return good


def main():
    contact_fem, scene = sys.argv[1:3]
    output = run_scene(contact_fem, scene, "Contact/Kinematics=updated",
                       "Load stepping/Number of load steps=4",
                       "Geometry/Hertz sphere/Sphere refinements=2",
                       "Newton/Displacement relative tolerance=1e-4",
                       "Output directory=results", *perturbation())
    with open("results/summary.json") as f:
        imbalance = json.load(f)["cycles"][-1]["reaction"]["relative_imbalance"]
    overshoot = largest_overshoot(output)
    ok = report("an iterate overshoots its step's initial residual", overshoot > 100.,
                f"by {overshoot:.3g}")
    ok = report("load and reactions balance to 1e-6", imbalance <= 1e-6,
                f"{imbalance:.2e}") and ok
    ok = report("no balance warning", "out of balance" not in output, "") and ok
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
