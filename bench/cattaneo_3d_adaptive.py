#!/usr/bin/env python3
"""Mindlin's sphere with the adaptive loop: does the refinement go to the
stick/slip boundary? (doc/validation.md, "3D Cattaneo-Mindlin", issue 28
item 4).

prm/cattaneo_3d.prm (Q2, the whole path up to Q/(mu P) = 0.875) from a
coarser mesh (Contact refinements 1 by default, the box of Local
refinements refined as often), with Refinement/Estimator = spr contact and
several cycles; each cycle re-solves the whole load path (friction is path
dependent) and the marking sees the state at Q/(mu P) = 0.875, where
Mindlin's stick radius is c = a / 2.

Per cycle:
  - cells, DoFs and the cycle's wall time (summary.json),
  - per load step c_h/a (c/a), |c_h - c| / h and the tangential L2 error
    against Mindlin (cattaneo.load_steps),
  - the slave nodal spacing by radius r from the axis (the median distance
    of a paired slave node to its nearest other slave node, reference
    configuration, pressure_profile_cycle_K.csv) in bands: the stick core
    r < 0.6 c, the stick/slip boundary 0.75 c < r < 1.25 c, the slip
    annulus 1.4 c < r < 0.85 a, the rim 0.9 a < r < 1.1 a and outside
    1.3 a < r < 2 a (node counts in brackets).
Refinement that concentrates at the stick/slip boundary shows as a smaller
spacing in its band than in the core and the annulus. With the default
Refinement/Contact layers along the surface = true the layers also spread
each flagged cell sideways along the contact surface; --set "Refinement/
Contact layers along the surface=false" makes the refinement follow the
marking (doc/validation.md, "Which rule spreads the refinement"): the
grading toward r ~ c was shown with
  --level 2 --cycles 3 --fraction 0.1
  --set "Refinement/Contact layers along the surface=false"
  --set "Model range/Accept results outside the small-strain range=true"
(cycle 2: spacing 0.134 in the stick core, 0.067 at r ~ c, 0.132 outside).

With --indicator (one cycle, Write VTU = true): where the marking goes on
the mesh of --level. The error indicator of every cell (error_indicators
VTU, at Q/(mu P) = 0.875), the cells the fixed-fraction marking
would refine (the largest indicators eta_K summing to the refine fraction
of the sum of eta_K, as deal.II's fixed fraction with its L1 norm does:
not of eta_K^2), and per band of r (of the cell centre; the sphere's cells
on the contact surface, the lowest layer above the flat within 2 a) the
cells, the marked cells and the share of the total squared error.

Usage:
  python3 bench/cattaneo_3d_adaptive.py [--binary B] [--level 1] [--cycles 3]
          [--fraction 0.3] [--results DIR] [--reuse] [--indicator]
          [--set "Section/Key=value" ...]
"""
import argparse
import csv
import math
import statistics
import sys
from pathlib import Path

import cattaneo_study

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO / "tests/postprocess"))
import vtu_files  # noqa: E402
BOX = "-1.2, 0, 1.5, 1.2, 1.2, 2.1"
# Of prm/cattaneo_3d.prm: the flat's top (Plate thickness) and the sphere's
# radius.
PLATE_TOP = 2.
RADIUS = 6.1237


def spacings(path):
    """(r, nearest-neighbour distance) of the paired slave nodes."""
    with open(path) as f:
        points = [(float(r["reference_x"]), float(r["reference_y"]), float(r["reference_z"]))
                  for r in csv.DictReader(f)]
    return [(math.hypot(p[0], p[1]),
             min(math.dist(p, q) for j, q in enumerate(points) if j != i))
            for i, p in enumerate(points)]


def bands(a, c):
    return [("r < 0.6 c", 0., 0.6 * c), ("r ~ c", 0.75 * c, 1.25 * c),
            ("slip annulus", 1.4 * c, 0.85 * a), ("r ~ a", 0.9 * a, 1.1 * a),
            ("outside", 1.3 * a, 2. * a)]


def indicator_bands(directory, a, c, fraction, degree=2):
    """Per band of r: the sphere's contact-surface cells, how many the
    fixed-fraction marking takes, and their share of the squared error."""
    name = sorted(directory.glob("error_indicators*.pvtu"))[-1].name
    points, fields = vtu_files.read_volume(name, str(directory))
    per_cell = (degree + 1) ** 3  # the points of one cell's patch
    cells = []
    for k in range(0, len(points), per_cell):
        patch = points[k:k + per_cell]
        centre = [sum(p[d] for p in patch) / per_cell for d in range(3)]
        cells.append((fields["error_indicator"][k][0], centre, min(p[2] for p in patch)))
    # The program's fixed fraction (deal.II's L1 norm): the largest eta_K
    # summing to the fraction of the sum of eta_K (not of eta_K^2).
    total = sum(e * e for e, _, _ in cells)
    total_eta = sum(e for e, _, _ in cells)
    marked, held = set(), 0.
    for k in sorted(range(len(cells)), key=lambda k: -cells[k][0]):
        if held >= fraction * total_eta:
            break
        marked.add(k)
        held += cells[k][0]
    # The sphere's cells on the contact surface: above the plate's top z =
    # PLATE_TOP, their lowest point on the sphere (z = PLATE_TOP + r^2 / 2R)
    # rather than a layer up, near the axis.
    surface = set(k for k, (_, x, z) in enumerate(cells)
                  if z > PLATE_TOP - 1e-6 and math.hypot(x[0], x[1]) < 2. * a
                  and z < PLATE_TOP + 0.1 * a + math.hypot(x[0], x[1]) ** 2 / (2. * RADIUS))
    rows = []
    for label, low, high in bands(a, c) + [("r > 2 a or not on the surface", None, None)]:
        if low is None:
            chosen = [k for k in range(len(cells)) if k not in surface]
        else:
            chosen = [k for k in surface if low <= math.hypot(*cells[k][1][:2]) < high]
        rows.append((label, len(chosen), sum(k in marked for k in chosen),
                     sum(cells[k][0] ** 2 for k in chosen) / total))
    return len(cells), len(marked), rows


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", type=Path, default=REPO / "build/contact_fem")
    parser.add_argument("--level", type=int, default=1)
    parser.add_argument("--cycles", type=int, default=3)
    parser.add_argument("--fraction", type=float, default=0.3)
    parser.add_argument("--results", type=Path, default=Path("results-cattaneo-3d-adaptive"))
    parser.add_argument("--reuse", action="store_true")
    parser.add_argument("--indicator", action="store_true")
    parser.add_argument("--set", action="append", default=[], dest="extra",
                        help="further --set of the program (repeatable)")
    args = parser.parse_args()
    d = args.results.resolve()
    sets = [f"Geometry/Hertz sphere/Contact refinements={args.level}",
            f"Geometry/Local refinements={args.level}: {BOX}",
            "Refinement/Estimator=spr contact",
            f"Refinement/Number of cycles={args.cycles}",
            f"Refinement/Refine fraction={args.fraction}"] + args.extra
    if args.indicator:
        # Two cycles, the mesh kept (Maximum cells): the estimate of the
        # first cycle is written (error_indicators_*.pvtu), then the run ends.
        sets += ["Refinement/Number of cycles=2", "Refinement/Maximum cells=1",
                 "Output/Write VTU=true"]
    if args.indicator:
        cattaneo_study.QUIET = [q for q in cattaneo_study.QUIET if "VTU" not in q]
    summary = cattaneo_study.run(args.binary.resolve(), sets, d, args.reuse,
                                 "prm/cattaneo_3d.prm")
    print(f"Contact refinements {args.level}, spr contact, refine fraction {args.fraction}")
    print("| cycle | cells | DoFs | per step: c_h/a (c/a), |c_h - c| / h, L2 vs Mindlin | "
          "slave spacing: " + ", ".join(n for n, _, _ in bands(1., 1.)) + " | wall |")
    print("|---:|---:|---:|---|---|---:|")
    for cycle in summary["cycles"]:
        cattaneo = cycle["analytical"]["cattaneo"]
        steps = [s for s in cattaneo["load_steps"] if s.get("Q_over_mu_P", 0.) > 1e-3]
        text = "; ".join(f"{s['Q_over_mu_P']:.3f}: {s['c_h_over_a']:.3f} ({s['c_over_a']:.3f}), "
                         f"{s['c_error_in_slave_elements']:.2f}, "
                         f"{s['tangential_l2_relative_error']:.3f}" for s in steps)
        a = cattaneo["a"]
        c = cattaneo["c_over_a"] * a
        nodes = spacings(d / f"pressure_profile_cycle_{cycle['cycle']}.csv")
        band_text = []
        for _, low, high in bands(a, c):
            inside = [h for r, h in nodes if low <= r < high]
            band_text.append(f"{statistics.median(inside):.3f} ({len(inside)})" if inside else "-")
        print(f"| {cycle['cycle']} | {cycle['n_cells']} | {cycle['n_dofs']} | {text} | "
              f"{', '.join(band_text)} | {cycle['wall_time']:.0f} s |")
    print(f"total wall {summary['wall_time']:.0f} s", file=sys.stderr)
    if args.indicator:
        cattaneo = summary["cycles"][-1]["analytical"]["cattaneo"]
        n, n_marked, rows = indicator_bands(d, cattaneo["a"], cattaneo["c_over_a"] * cattaneo["a"],
                                            args.fraction)
        print(f"{n} cells, {n_marked} marked (fixed fraction {args.fraction})")
        print("| band | sphere surface cells | marked | share of eta^2 |")
        print("|---|---:|---:|---:|")
        for label, count, hit, share in rows:
            print(f"| {label} | {count} | {hit} | {share:.3f} |")


if __name__ == "__main__":
    main()
