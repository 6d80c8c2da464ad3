#!/usr/bin/env python3
"""Mindlin's sphere: discretisation error or model error? (doc/validation.md,
"3D Cattaneo-Mindlin").

prm/cattaneo_3d.prm is solved up to Q/(mu P) = 0.75 (End time 0.8, 4 load
steps: the normal step, then 0.25, 0.5, 0.75) at several Contact
refinements (the box of Local refinements refined as often, so that the
flat follows the sphere) and at an overkill level. For every level:
  - the program's comparison with Mindlin at every step (summary.json,
    cattaneo.load_steps: c_h/a against c/a, |c_h - c| in slave elements,
    the traction's L2 error against the half-space solution),
  - the tangential traction vector (tangential_traction_x, _y of
    pressure_profile.csv) at the last step against the overkill run of the
    same scene: each node of the level against the nearest node of the
    overkill (within a fraction of the level's element size, so that the
    lookup error is below the level's own), relative L2 over the nodes
    with r < a (equal weights: the mesh is uniform there).
An error against the overkill that falls level by level while the one
against Mindlin levels off is model error (finite bodies, the curved slave
frame, Q1), not discretisation.

Usage:
  python3 bench/cattaneo_3d_study.py [--binary B] [--levels 2,3]
          [--reference-level 4] [--degree 1] [--results DIR] [--reuse]
"""
import argparse
import csv
import math
import sys
from pathlib import Path

import cattaneo_study

REPO = Path(__file__).resolve().parent.parent
# Up to Q/(mu P) = 0.75 (cattaneo_study.run() adds the quiet outputs).
STEPS = ["Load stepping/End time=0.8", "Load stepping/Number of load steps=4"]


def run(binary, level, degree, directory, reuse):
    sets = STEPS + [f"Geometry/Hertz sphere/Contact refinements={level}",
                    f"Geometry/Local refinements={level}: -1.2, 0, 1.5, 1.2, 1.2, 2.1",
                    f"Finite element/Degree={degree}"]
    return cattaneo_study.run(binary, sets, directory, reuse, "prm/cattaneo_3d.prm")


def profile(directory):
    """(x, y, t_x, t_y) of the paired slave nodes at the last step."""
    with open(directory / "pressure_profile.csv") as f:
        return [(float(r["x"]), float(r["y"]), float(r["tangential_traction_x"]),
                 float(r["tangential_traction_y"])) for r in csv.DictReader(f)]


def error_against(rows, reference, radius):
    error = norm = 0.
    for x, y, tx, ty in rows:
        if math.hypot(x, y) >= radius:
            continue
        _, _, rx, ry = min(reference, key=lambda r: (r[0] - x) ** 2 + (r[1] - y) ** 2)
        error += (tx - rx) ** 2 + (ty - ry) ** 2
        norm += rx * rx + ry * ry
    return math.sqrt(error / norm) if norm > 0. else float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", type=Path, default=REPO / "build/contact_fem")
    parser.add_argument("--levels", default="2,3")
    parser.add_argument("--reference-level", type=int, default=4)
    parser.add_argument("--degree", type=int, default=1)
    parser.add_argument("--results", type=Path, default=Path("results-cattaneo-3d-study"))
    parser.add_argument("--reuse", action="store_true")
    args = parser.parse_args()
    args.binary = args.binary.resolve()
    args.results = args.results.resolve()
    levels = [int(v) for v in args.levels.split(",")]
    results = {}
    for level in levels + [args.reference_level]:
        d = args.results / f"level_{level}"
        summary = run(args.binary, level, args.degree, d, args.reuse)
        cycle = summary["cycles"][-1]
        results[level] = (profile(d), cycle, summary["wall_time"])
        print(f"level {level}: {summary['wall_time']:.1f} s", file=sys.stderr)
    reference = results[args.reference_level][0]
    a = results[args.reference_level][1]["analytical"]["cattaneo"]["a"]
    print(f"| Contact refinements | DoFs | slave h | Q/(mu P): c_h/a (c/a), |c_h - c|/h, "
          f"L2 vs Mindlin | L2 vs level {args.reference_level} at 0.75 | wall |")
    print("|---|---|---|---|---|---|")
    for level in levels + [args.reference_level]:
        rows, cycle, wall = results[level]
        steps = cycle["analytical"]["cattaneo"]["load_steps"]
        text = "; ".join(
            f"{s['Q_over_mu_P']:.2f}: {s['c_h_over_a']:.3f} ({s['c_over_a']:.3f}), "
            f"{s['c_error_in_slave_elements']:.2f}, {s['tangential_l2_relative_error']:.3f}"
            for s in steps if s.get("Q_over_mu_P", 0.) > 1e-3)
        against = ("-" if level == args.reference_level else
                   f"{error_against(rows, reference, a):.4f}")
        print(f"| {level} | {cycle['n_dofs']} | {cycle['contact']['slave_element_size']:.4f} | "
              f"{text} | {against} | {wall:.0f} s |")


if __name__ == "__main__":
    main()
