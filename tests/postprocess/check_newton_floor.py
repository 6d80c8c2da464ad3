#!/usr/bin/env python3
"""A Newton tolerance below the round-off floor of the residual: the
failure names the floor and a tolerance that is reachable, and it is.

Usage: check_newton_floor.py CONTACT_FEM SOURCE_DIR

prm/hertz_3d.prm, coarse (Q1, Sphere refinements 1), neo-Hookean on the
current configuration, Active check factor 1e-2, at 1e-8 of its load, with
Newton/Displacement relative tolerance 1e-10 and absolute 1e-12: |r_u|
stays at about 1e-8 (3e-7 of the step's initial residual) with the active
set settled, a floor that does not scale with the load (doc/design.md,
"What a failed step names").
- the run fails (non-zero exit), once (no split: a smaller step does not
  lower the floor), with "did not converge" and "|r_u| stagnated at F ...
  Reachable: Newton/Displacement absolute tolerance = A (or a relative
  tolerance of R)", F within a factor 2 of the last |r_u| printed, A above F;
- the same run with Newton/Displacement absolute tolerance = A converges,
  and so does the one with Newton/Displacement relative tolerance = R.
The numbers are round-off: only these relations are checked.
"""
import re
import subprocess
import sys

from scene_run import ENVIRONMENT, perturbation

contact_fem, source_dir = sys.argv[1:3]
SETTINGS = ["Materials/Models=neo-hookean, linear", "Contact/Kinematics=current",
            "Finite element/Degree=1", "Geometry/Hertz sphere/Sphere refinements=1",
            "Geometry/Hertz sphere/Contact refinements=0", "Contact/Active check factor=1e-2",
            "Boundary conditions/Pressure=1: 1e-8*5e5*t",
            "Newton/Displacement relative tolerance=1e-10",
            "Newton/Displacement absolute tolerance=1e-12", "Newton/Maximum iterations=7",
            "Load stepping/Maximum step splits=2", "Output/Write VTU=false",
            "Output/Print timing=false", "Output directory=results"]


def run(*extra):
    command = [contact_fem, f"{source_dir}/prm/hertz_3d.prm"]
    for setting in SETTINGS + list(perturbation()) + list(extra):
        command += ["--set", setting]
    return subprocess.run(command, env=ENVIRONMENT, capture_output=True, text=True)


failures = []
tight = run()
text = tight.stdout + tight.stderr
floor = re.search(r"\|r_u\| = ([0-9.e+-]+), \|r_lambda\| [^)]*\)\. \|r_u\| stagnated at "
                  r"([0-9.e+-]+) over the last \d+ iterations .* Reachable: Newton/Displacement "
                  r"absolute tolerance = ([0-9.e+-]+) \(or a relative tolerance of "
                  r"([0-9.e+-]+)\)\.", text)
if tight.returncode == 0 or "did not converge" not in text:
    failures.append(f"the tight run did not fail as not converged (exit {tight.returncode})")
if "Splitting the step" in text:
    failures.append("the tight run split its step")
if floor is None:
    failures.append("no floor in the failure:\n" + text[-2000:])
else:
    last, stated, absolute, relative = (float(x) for x in floor.groups())
    if not 0.5 * last <= stated <= 2 * last:
        failures.append(f"floor {stated} not within a factor 2 of the last |r_u| {last}")
    if not absolute > stated:
        failures.append(f"reachable tolerance {absolute} not above the floor {stated}")
    for key, value in (("absolute", absolute), ("relative", relative)):
        again = run(f"Newton/Displacement {key} tolerance={value:g}")
        if again.returncode != 0 or "| converged" not in again.stdout:
            failures.append(f"with the {key} tolerance {value:g} the run did not converge:\n"
                            + again.stdout[-1500:])
        else:
            print(f"{key} tolerance {value:g} (the floor {stated:g}): converged")
if failures:
    print("\n".join(failures))
    sys.exit(1)
