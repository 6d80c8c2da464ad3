#!/usr/bin/env python3
"""The residual floor of a contact scene is the round-off of the residual's
terms, set by the rigid motion that closes an initial gap, not by the load.

Usage: check_newton_floor_gap.py CONTACT_FEM PATCH_PRM

The 2D contact patch (tests/scenes/contact_patch_01.prm) with both blocks at
E = 1e8, linear elastic, small kinematics, in 3 load steps of a small
pressure L, Newton tolerance 1e-15 (relative): the upper block closes an
initial gap g by a rigid motion, which costs no force but makes the
residual's terms E h g. |r_u| cannot fall below machine epsilon times
|K| |u| (measured 0.3 to 0.5 of it), whatever the load
(doc/design.md, "What a failed step names").
- g = 0: the residual, the matrix and the multipliers are consistent to
  the round-off of the load: the run converges at a relative tolerance of
  1e-12 (the floor there is about 7e-15 of the load);
- g = 0.1, L = 1e-3: step 2 (the multipliers at round-off from its start)
  fails with the floor named (not split: a smaller step does not lower
  it), the floor F between 1/20 and 1.5 times the round-off scale S stated;
  without the scale the flat run, at 1.5e-4 of the step's residual, was
  split twice and got the hint "more load steps";
- the floor in proportion to the gap: F(g = 0.1) / F(g = 1e-3) in [20, 500];
- and not to the load: F(L = 0.1) / F(L = 1e-3) in [0.25, 4] at g = 0.1.
The floors are round-off: only these relations, far from their noise
(a factor 2), are checked.
"""
import re
import subprocess
import sys

from scene_run import ENVIRONMENT, perturbation

contact_fem, patch = sys.argv[1:3]
SETTINGS = ["Materials/Young's moduli=1e8, 1e8", "Materials/Poisson's ratios=0.3, 0.3",
            "Contact/Active check factor=1", "Load stepping/Number of load steps=3",
            "Load stepping/Maximum step splits=2", "Newton/Maximum iterations=6",
            "Newton/Displacement relative tolerance=1e-15",
            "Newton/Displacement absolute tolerance=1e-30", "Output directory=results"]
FLOOR = re.compile(r"\|r_u\| stagnated at ([0-9.e+-]+) over the last \d+ iterations .*"
                   r"machine epsilon times \|K\| \|u\| = ([0-9.e+-]+)")


def run(gap, load, *extra):
    command = [contact_fem, patch]
    for setting in (SETTINGS + [f"Geometry/Contact blocks/Initial gap={gap}",
                                f"Boundary conditions/Pressure=1: {load}*t"]
                    + list(perturbation()) + list(extra)):
        command += ["--set", setting]
    result = subprocess.run(command, env=ENVIRONMENT, capture_output=True, text=True)
    return result.returncode, result.stdout + result.stderr


failures = []
code, text = run(0, 1e-3, "Newton/Displacement relative tolerance=1e-12")
if code != 0 or "linear-solver accuracy" in text or text.count("| converged") != 3:
    failures.append("gap 0: the run did not converge at 1e-12 in each step:\n" + text[-1500:])
else:
    print("gap 0: converged at a relative tolerance of 1e-12 in each of the 3 steps")

floors = {}
for gap, load in ((0.1, 1e-3), (1e-3, 1e-3), (0.1, 0.1)):
    code, text = run(gap, load)
    found = FLOOR.search(text)
    if code == 0 or "did not converge" not in text or found is None:
        failures.append(f"gap {gap}, load {load}: no floor named:\n" + text[-1500:])
        continue
    if "Splitting the step" in text:
        failures.append(f"gap {gap}, load {load}: the step was split at its floor")
    floor, scale = (float(x) for x in found.groups())
    if not scale / 20 <= floor <= 1.5 * scale:
        failures.append(f"gap {gap}, load {load}: floor {floor:g} not within [1/20, 1.5] "
                        f"of the round-off scale {scale:g}")
    floors[(gap, load)] = floor

if len(floors) == 3:
    by_gap = floors[(0.1, 1e-3)] / floors[(1e-3, 1e-3)]
    by_load = floors[(0.1, 0.1)] / floors[(0.1, 1e-3)]
    if not 20 <= by_gap <= 500:
        failures.append(f"floors at gaps 0.1 and 1e-3 in the ratio {by_gap:g}, not ~100")
    else:
        print("the floor grows with the gap (x100 in [20, 500]): yes")
    if not 0.25 <= by_load <= 4:
        failures.append(f"floors at loads 0.1 and 1e-3 in the ratio {by_load:g}, not ~1")
    else:
        print("the floor is the same at loads 100 times apart (within a factor 4): yes")
    print("each floor named, not split, within [1/20, 1.5] of eps |K| |u|: "
          + ("yes" if len(failures) == 0 else "no"))
if failures:
    print("\n".join(failures))
    sys.exit(1)
