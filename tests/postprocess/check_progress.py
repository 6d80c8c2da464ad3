#!/usr/bin/env python3
"""The progress lines of a run with Output/Print timing (timings vary, so
the scene tests switch them off).

Usage: check_progress.py CONTACT_FEM SCENE.prm

SCENE in 4 load steps: after each converged step a line
'Progress: load step k of 4 of cycle 0 done, T s in this cycle' with
k = 1..4 in order, T not decreasing, and ', about R s to go' on every line
but the last.
"""
import re
import sys

from scene_run import run_scene

contact_fem, scene = sys.argv[1:3]
stdout = run_scene(contact_fem, scene, "Output directory=results", "Output/Print timing=true",
                   "Load stepping/Number of load steps=4")
pattern = re.compile(r"  Progress: load step (\d+) of (\d+) of cycle 0 done, ([0-9.e+-]+) s "
                     r"in this cycle(, about ([0-9.e+-]+) s to go)?$")
lines = [pattern.match(line) for line in stdout.splitlines() if "Progress:" in line]
failures = []
if any(m is None for m in lines):
    failures.append("a progress line of another form:\n" +
                    "\n".join(l for l in stdout.splitlines() if "Progress:" in l))
else:
    steps = [(int(m.group(1)), int(m.group(2))) for m in lines]
    if steps != [(k, 4) for k in range(1, 5)]:
        failures.append(f"steps {steps}, expected (k, 4) for k = 1..4")
    times = [float(m.group(3)) for m in lines]
    if times != sorted(times):
        failures.append(f"elapsed times {times} decrease")
    to_go = [m.group(4) is not None for m in lines]
    if to_go != [True, True, True, False]:
        failures.append(f"'to go' on lines {to_go}, expected on all but the last")
if failures:
    print("\n".join(failures))
    sys.exit(1)
print("4 progress lines, steps 1 to 4 of 4")
