#!/usr/bin/env python3
"""Cattaneo-Mindlin: discretisation error or model error? (doc/validation.md,
"Cattaneo-Mindlin").

prm/cattaneo.prm is solved at Global refinements 0..4 and at an overkill
level (5 by default). For every level the tangential traction of
pressure_profile.csv is compared
  - with Cattaneo's half-space q(x) (the program's own number, summary.json),
  - with the overkill run of the same discrete scene (same finite bodies,
    supports and loads), interpolated linearly in x (zero outside its range).
The first is the program's (mortar weights D_j, each node at its reference
position, as the half-space solution is posed). The second is measured here
as the relative L2 error over the paired slave nodes with the nodal
tributary lengths as weights, each node at its deformed x (the only
position pressure_profile.csv holds; both runs are compared at the same
deformed positions). An error against the overkill run that falls level by
level while the one against Cattaneo levels off is model error (finite
bodies against half-spaces), not discretisation.

With --adaptive N it instead runs tests/scenes/cattaneo_adaptive_01's setup
(the unrefined mesh, N cycles of SPR-contact refinement) and prints the
Cattaneo error and c_h/a per cycle.

Usage:
  python3 bench/cattaneo_study.py [--binary B] [--levels 0,1,2,3,4]
          [--reference-level 5] [--adaptive N] [--results DIR] [--reuse]

--reuse takes the runs already in DIR (summary.json present) as they are.
"""
import argparse
import csv
import json
import math
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
QUIET = ["Output/Write VTU=false", "Output/Write pressure profile=true",
         "Output/Print timing=false"]


def run(binary, sets, directory, reuse=False, prm="prm/cattaneo.prm"):
    if reuse and (directory / "summary.json").exists():
        return json.load(open(directory / "summary.json"))
    directory.mkdir(parents=True, exist_ok=True)
    cmd = [str(binary), str(REPO / prm)]
    for s in sets + QUIET:
        cmd += ["--set", s]
    cmd += ["--output-directory", str(directory)]
    with open(directory / "stdout.txt", "w") as out:
        rc = subprocess.call(cmd, stdout=out, stderr=subprocess.STDOUT, cwd=REPO)
    if rc != 0:
        sys.exit(f"{' '.join(cmd)} failed ({rc}), see {directory}/stdout.txt")
    return json.load(open(directory / "summary.json"))


def profile(directory):
    """Sorted (x, tangential traction) of the paired slave nodes."""
    with open(directory / "pressure_profile.csv") as f:
        rows = [(float(r["x"]), float(r["tangential_traction"])) for r in csv.DictReader(f)]
    return sorted(rows)


def interpolate(rows, x):
    if x < rows[0][0] or x > rows[-1][0]:
        return 0.
    for (x0, t0), (x1, t1) in zip(rows, rows[1:]):
        if x0 <= x <= x1:
            return t0 if x1 == x0 else t0 + (x - x0) / (x1 - x0) * (t1 - t0)
    return rows[-1][1]


def tributary(rows):
    xs = [x for x, _ in rows]
    return [0.5 * ((xs[min(i + 1, len(xs) - 1)]) - xs[max(i - 1, 0)]) for i in range(len(xs))]


def relative_l2(rows, exact):
    w = tributary(rows)
    error = sum(wi * (t - exact(x)) ** 2 for wi, (x, t) in zip(w, rows))
    norm = sum(wi * exact(x) ** 2 for wi, (x, _) in zip(w, rows))
    return math.sqrt(error / norm)


def global_study(args):
    levels = [int(v) for v in args.levels.split(",")]
    results = {}
    for level in levels + [args.reference_level]:
        d = args.results / f"level_{level}"
        summary = run(args.binary, [f"Geometry/Global refinements={level}"], d, args.reuse)
        wall = summary["wall_time"]
        c = summary["cycles"][-1]["analytical"]["cattaneo"]
        results[level] = (profile(d), c, wall)
        print(f"level {level}: {wall:.1f} s", file=sys.stderr)
    reference = results[args.reference_level][0]
    print(f"| Global refinements | paired slave nodes | c_h/a (c/a) | L2 vs Cattaneo "
          f"| L2 vs level {args.reference_level} | wall |")
    print("|---|---|---|---|---|---|")
    for level in levels + [args.reference_level]:
        rows, c, wall = results[level]
        against_reference = ("-" if level == args.reference_level else
                             f"{relative_l2(rows, lambda x: interpolate(reference, x)):.4f}")
        print(f"| {level} | {len(rows)} | {c['c_h_over_a']:.4f} ({c['c_over_a']:.4f}) | "
              f"{c['tangential_l2_relative_error']:.4f} | {against_reference} | {wall:.1f} s |")


def adaptive_study(args):
    d = args.results / f"adaptive_{args.adaptive}"
    summary = run(args.binary, [
        "Geometry/Global refinements=0", f"Refinement/Number of cycles={args.adaptive}",
        "Refinement/Estimator=spr contact"], d)
    print("| cycle | cells | DoFs | stick / slip | c_h/a (c/a) | L2 vs Cattaneo |")
    print("|---|---|---|---|---|---|")
    for i, cycle in enumerate(summary["cycles"]):
        c = cycle["analytical"]["cattaneo"]
        print(f"| {i} | {cycle['n_cells']} | {cycle['n_dofs']} | "
              f"{c['stick_nodes']} / {c['slip_nodes']} | "
              f"{c['c_h_over_a']:.4f} ({c['c_over_a']:.4f}) | "
              f"{c['tangential_l2_relative_error']:.4f} |")
    print(f"wall {summary['wall_time']:.1f} s", file=sys.stderr)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", type=Path, default=REPO / "build/contact_fem")
    parser.add_argument("--levels", default="0,1,2,3,4")
    parser.add_argument("--reference-level", type=int, default=5)
    parser.add_argument("--adaptive", type=int, default=0)
    parser.add_argument("--results", type=Path, default=Path("results-cattaneo-study"))
    parser.add_argument("--reuse", action="store_true")
    args = parser.parse_args()
    args.binary = args.binary.resolve()
    args.results = args.results.resolve()
    if args.adaptive:
        adaptive_study(args)
    else:
        global_study(args)


if __name__ == "__main__":
    main()
