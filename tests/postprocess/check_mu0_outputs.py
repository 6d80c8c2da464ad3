#!/usr/bin/env python3
"""Coulomb mu = 0 is the frictionless formulation: the expected output of a
frictional scene with mu = 0 must hold every line of the expected output of
the same scene run frictionless (issue 28: "mu = 0 reproduces the 3D
frictionless results to round-off").

The frictional output has more: the stick/slip columns of the Newton table
(cut to the frictionless table's cells here) and the friction lines of the
results (skipped). Every other line, Newton residuals, active sets,
pressures, forces and the Hertz comparison as printed, must appear in the
same order. Each output is checked against its own run by its scene test;
this checks that the two stored outputs agree, so that neither can be
updated away from the other.

Usage: check_mu0_outputs.py CONTACT_FEM FRICTIONAL.output FRICTIONLESS.output
(CONTACT_FEM, passed to every postprocess test, is not run.)
"""
import sys


def normalised(path):
    """The lines after the first (which names the scene), Newton table rows
    cut to their first seven cells, without the trailing 'converged'."""
    lines = []
    with open(path) as f:
        for line in f.read().splitlines()[1:]:
            if line.lstrip().startswith("|"):
                cells = line.split("|")
                line = "|".join(cells[:8]) + "|"
            lines.append(line.rstrip())
    return lines


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    frictional = normalised(sys.argv[2])
    frictionless = normalised(sys.argv[3])
    position = 0
    for number, line in enumerate(frictionless, start=2):
        try:
            position = frictional.index(line, position) + 1
        except ValueError:
            sys.exit(f"line {number} of {sys.argv[3]} is not in {sys.argv[2]} "
                     f"(after its line {position + 1}):\n  {line}")
    print(f"{len(frictionless)} lines of the frictionless output found in order "
          f"among the {len(frictional)} of the frictional one")


if __name__ == "__main__":
    main()
