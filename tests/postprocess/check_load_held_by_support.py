#!/usr/bin/env python3
"""A load that a support on the same boundary takes whole is named in a
warning, and only such a load (outside-user audit, doc/metamorphic.md).

Usage: check_load_held_by_support.py CONTACT_FEM

The built-in contact blocks (pressure 2 on the top, boundary 1). With the
top also Fixed in y (the pressure's only component) the support takes the
whole load: the run used to "converge" without a word, contact force 9e-15
and 3 of 6 slave nodes active at pressures of round-off. Checks: that case
(and a Prescribed displacement in y on the top, and a Traction whose every
component is held) prints the warning; the scene as shipped and a top held
in x only (the pressure still loads the blocks) do not.
"""
import subprocess
import sys

from scene_run import ENVIRONMENT

SCENE = """subsection Geometry
  set Type = contact blocks
end
subsection Boundary conditions
  set Fixed    = 2: y; 5: x; 6: x{fixed}
  set Pressure = {pressure}
  set Traction = {traction}
  set Prescribed displacement = {prescribed}
end
subsection Contact
  set Pairs = 3: 4
end
"""
WARNING = "the support takes the whole load"

CASES = [
    # name, extra Fixed, Pressure, Traction, Prescribed displacement, warned
    ("shipped", "", "1: 2", "", "", False),
    ("held_x", "; 1: x", "1: 2", "", "", False),
    ("held_y", "; 1: y", "1: 2", "", "", True),
    ("prescribed_y", "", "1: 2", "", "1: y = -0.01*t", True),
    ("traction_held", "; 1: xy", "", "1: 0.1, -0.2", "", True),
]

failures = 0
for name, fixed, pressure, traction, prescribed, warned in CASES:
    with open(name + ".prm", "w") as f:
        f.write(SCENE.format(fixed=fixed, pressure=pressure, traction=traction,
                             prescribed=prescribed))
    result = subprocess.run([sys.argv[1], name + ".prm", "--validate", "--output-directory",
                             "results-" + name], env=ENVIRONMENT, capture_output=True, text=True)
    printed = WARNING in result.stdout + result.stderr
    ok = result.returncode == 0 and printed == warned
    failures += not ok
    print(f"{name}: exit {result.returncode}, warning {'printed' if printed else 'not printed'}"
          f" ({'expected' if ok else 'WRONG'})")
sys.exit(1 if failures else 0)
