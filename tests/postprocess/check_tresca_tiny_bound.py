#!/usr/bin/env python3
"""A Tresca bound far below the pressures: the friction conditions are
measured against what the tractions can resolve (outside-user audit,
rounds 2 and 6, doc/metamorphic.md).

Usage: check_tresca_tiny_bound.py CONTACT_FEM SCENE

SCENE is tests/scenes/frictional_block_tresca_01.prm (the block pressed
by 1 and slid along x, 'alm frictional'), run with the bound 1e-12 and
1e-300 in 2 steps, and with its own 0.15. The tractions carry the
round-off of the pressures (about 1e-16 of p ~ 1), so a bound of 1e-12
cannot be met closer than 1e-4 of itself: the check read "the friction
conditions hold to 2.2e-04 (1e-300: 1.65e+284) of the largest slip bound"
and blamed Newton's tolerances. Checks: the tiny bounds are measured
against 1e-6 of the largest pressure (said in a line) and met ('ok'),
without the warning; every node slips; the tangential force vanishes
against the normal one; the bound 0.15 is measured against itself as
before (no such line) and gives F_t = 0.15 A.
"""
import sys

from scene_run import run_scene


def results(output):
    """The lines after the last 'Results at' of output."""
    return output[output.rindex("Results at"):].splitlines()


def value(lines, label):
    line = next(line for line in lines if line.strip().startswith(label))
    return line.split(":", 1)[1].split()[0]


def main():
    contact_fem, scene = sys.argv[1], sys.argv[2]
    failures = []
    for bound in ["1e-12", "1e-300", "0.15"]:
        output = run_scene(contact_fem, scene, f"Contact/Friction=tresca {bound}",
                           "Load stepping/Number of load steps=2",
                           "Output directory=out_" + bound)
        lines = results(output)
        tiny = float(bound) < 1e-6
        said = any("slip bounds below 1e-6 of the largest pressure" in line for line in lines)
        if said != tiny:
            failures.append(f"tresca {bound}: the resolution line is {'missing' if tiny else 'there'}")
        for label in ["slip nodes off the slip bound", "stick nodes outside the cone"]:
            if value(lines, label) != "ok":
                failures.append(f"tresca {bound}: {label}: {value(lines, label)}")
        if "Warning: the friction conditions" in output:
            failures.append(f"tresca {bound}: warns about the friction conditions")
        if value(lines, "stick / slip nodes") != "0":
            failures.append(f"tresca {bound}: a node sticks")
        tangential = float(value(lines, "tangential contact force"))
        length = float(value(lines, "active contact length"))
        expected = 0. if tiny else float(bound) * length
        if abs(abs(tangential) - expected) > 1e-8:
            failures.append(f"tresca {bound}: tangential force {tangential}, expected {expected}")
        print(f"tresca {bound}: resolution line {said}, tangential force {tangential:.6g}")
    if failures:
        sys.exit("\n".join(failures))
    print("OK")


if __name__ == "__main__":
    main()
