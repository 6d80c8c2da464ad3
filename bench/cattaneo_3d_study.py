#!/usr/bin/env python3
"""Mindlin's sphere: discretisation error or model error? (doc/validation.md,
"3D Cattaneo-Mindlin").

prm/cattaneo_3d.prm (the scene: Q2, the whole path, Q/(mu P) = 0.25, 0.5,
0.75, 0.875) is solved at several Contact refinements (the box of Local
refinements refined as often, so that the flat follows the sphere) and at
an overkill level. For every level:
  - the program's comparison with Mindlin at every step (summary.json,
    cattaneo.load_steps: c_h/a against c/a, |c_h - c| in slave nodal
    spacings h, the traction's L2 error against the half-space solution),
  - the tangential traction vector (tangential_traction_x, _y of
    pressure_profile.csv) at the last step against the overkill run of the
    same scene: each node of the level against the nearest node of the
    overkill in the reference configuration (the meshes are nested, so
    that is the same point: the largest distance is printed), relative L2
    over the nodes with r < a, equal weights (a nodal RMS: the mesh is
    uniform there, but the Q2 nodes' areas differ by their kind),
  - |c_h - c_h(overkill)| / h at every step, and the DoFs, the run's wall
    time (summary.json) and the CPU time of the process (getrusage).
An error against the overkill that falls level by level while the one
against Mindlin levels off is model error (finite bodies, the curved slave
frame), not discretisation.

Usage:
  python3 bench/cattaneo_3d_study.py [--binary B] [--levels 1,2]
          [--reference-level 3] [--degree 2] [--up-to 0.875]
          [--results DIR] [--reuse]
The Q1 study of 2026-11-26 (doc/validation.md): --degree 1 --levels 2,3
--reference-level 4 --up-to 0.75.
"""
import argparse
import csv
import math
import resource
import sys
from pathlib import Path

import cattaneo_study

REPO = Path(__file__).resolve().parent.parent
# The load steps up to Q/(mu P) = 0.75 or 0.875 (the scene's whole path);
# cattaneo_study.run() adds the quiet outputs.
STEPS = {"0.75": ["Load stepping/End time=0.8", "Load stepping/Number of load steps=4"],
         "0.875": []}


def run(binary, level, degree, up_to, directory, reuse):
    """The summary of the run and the CPU seconds of its process (kept in
    cpu_seconds.txt for --reuse)."""
    sets = STEPS[up_to] + [f"Geometry/Hertz sphere/Contact refinements={level}",
                           f"Geometry/Local refinements={level}: -1.2, 0, 1.5, 1.2, 1.2, 2.1",
                           f"Finite element/Degree={degree}"]
    cpu_file = directory / "cpu_seconds.txt"
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    summary = cattaneo_study.run(binary, sets, directory, reuse, "prm/cattaneo_3d.prm")
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
    if cpu > 0.:
        cpu_file.write_text(f"{cpu:.2f}\n")
    return summary, float(cpu_file.read_text()) if cpu_file.exists() else float("nan")


def profile(directory):
    """(X, Y, t_x, t_y) of the paired slave nodes at the last step, X, Y in
    the reference configuration (where the nested meshes share nodes)."""
    with open(directory / "pressure_profile.csv") as f:
        return [(float(r["reference_x"]), float(r["reference_y"]),
                 float(r["tangential_traction_x"]), float(r["tangential_traction_y"]))
                for r in csv.DictReader(f)]


def error_against(rows, reference, radius):
    """The relative nodal L2 error of rows against reference over r < radius,
    and the largest distance from a node to its reference node."""
    error = norm = distance = 0.
    for x, y, tx, ty in rows:
        if math.hypot(x, y) >= radius:
            continue
        rx0, ry0, rx, ry = min(reference, key=lambda r: (r[0] - x) ** 2 + (r[1] - y) ** 2)
        distance = max(distance, math.hypot(rx0 - x, ry0 - y))
        error += (tx - rx) ** 2 + (ty - ry) ** 2
        norm += rx * rx + ry * ry
    return (math.sqrt(error / norm) if norm > 0. else float("nan")), distance


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", type=Path, default=REPO / "build/contact_fem")
    parser.add_argument("--levels", default="1,2")
    parser.add_argument("--reference-level", type=int, default=3)
    parser.add_argument("--degree", type=int, default=2)
    parser.add_argument("--up-to", choices=sorted(STEPS), default="0.875")
    parser.add_argument("--results", type=Path, default=Path("results-cattaneo-3d-study"))
    parser.add_argument("--reuse", action="store_true")
    args = parser.parse_args()
    args.binary = args.binary.resolve()
    args.results = args.results.resolve()
    levels = [int(v) for v in args.levels.split(",")]
    results = {}
    for level in levels + [args.reference_level]:
        d = args.results / f"level_{level}"
        summary, cpu = run(args.binary, level, args.degree, args.up_to, d, args.reuse)
        cycle = summary["cycles"][-1]
        results[level] = (profile(d), cycle, summary["wall_time"], cpu)
        print(f"level {level}: {summary['wall_time']:.1f} s", file=sys.stderr)
    reference = results[args.reference_level]
    a = reference[1]["analytical"]["cattaneo"]["a"]

    def steps(cycle):
        return [s for s in cycle["analytical"]["cattaneo"]["load_steps"]
                if s.get("Q_over_mu_P", 0.) > 1e-3]

    print(f"Q{args.degree}, up to Q/(mu P) = {args.up_to}, overkill L = {args.reference_level}; "
          f"per step: c_h/a (c/a), |c_h - c| / h, |c_h - c_h(overkill)| / h, L2 vs Mindlin")
    print(f"| L | DoFs | slave h | per step | L2 vs L = {args.reference_level} at the last step "
          f"(node distance) | wall | CPU |")
    print("|---|---:|---:|---|---:|---:|---:|")
    for level in levels + [args.reference_level]:
        rows, cycle, wall, cpu = results[level]
        h = cycle["contact"]["slave_element_size"]
        text = "; ".join(
            f"{s['Q_over_mu_P']:.3f}: {s['c_h_over_a']:.3f} ({s['c_over_a']:.3f}), "
            f"{s['c_error_in_slave_elements']:.2f}, "
            f"{abs(s['c_h_over_a'] - r['c_h_over_a']) * a / h:.2f}, "
            f"{s['tangential_l2_relative_error']:.3f}"
            for s, r in zip(steps(cycle), steps(reference[1])))
        if level == args.reference_level:
            against = "-"
        else:
            error, distance = error_against(rows, reference[0], a)
            against = f"{error:.4f} ({distance:.1e})"
        print(f"| {level} | {cycle['n_dofs']} | {h:.4f} | {text} | {against} | "
              f"{wall:.0f} s | {cpu:.0f} s |")


if __name__ == "__main__":
    main()
