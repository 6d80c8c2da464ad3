#!/usr/bin/env python3
"""Mindlin's sphere: why is the discrete stick zone smaller than Mindlin's?
(doc/validation.md, "3D Cattaneo-Mindlin", "The stick radius at
Q/(mu P) = 0.875").

Runs prm/cattaneo_3d.prm (the whole path, Q/(mu P) = 0.25, 0.5, 0.75,
0.875) in variants that each shrink one suspected cause:
  - base-L3, base-L4: the shipped scene at Contact refinements 3 and 4 (the
    box of Local refinements refined as often);
  - q2-L1, q2-L2: Finite element/Degree = 2 (the Q1 surface strain under the
    normal load is the suspect of the radial traction the normal step
    locks in);
  - small-L4: the load / 8 (a / R halved, 0.055: the slave normals' tilt
    r / R, the curvature of the reference surface and the finite bodies
    shrink by half), Refinement radius 0.4 and one more contact round, so
    that about as many slave elements span a as in base-L3;
  - steps-L3: twice the load steps (load-path effect);
  - thick-L3: the flat twice as thick and wide (finite-layer effect).
Per variant and load step: c_h/a against c/a, |c_h - c| in slave
elements, the stick zone's centre along the load in slave elements, the
traction's L2 error against Mindlin; after the normal step, the slip nodes
and the tangential force across the load (the half model's y force: the
resultant of the radial traction the normal step leaves, over mu P / 2).
From pressure_profile.csv at the last step: the largest radius of a stick
node. (The nodes on the symmetry plane y = 0 carried no friction until
2026-11-27 (branch symfric): doc/validation.md, "The stick radius: Q1
against Q2".)

Usage:
  python3 bench/cattaneo_3d_stick_zone.py [--binary B] [--variants a,b]
          [--results DIR] [--reuse]
"""
import argparse
import csv
import json
import math
import sys
from pathlib import Path

import cattaneo_study

REPO = Path(__file__).resolve().parent.parent
BOX = "-1.2, 0, 1.5, 1.2, 1.2, 2.1"


def level(L, box=BOX):
    return [f"Geometry/Hertz sphere/Contact refinements={L}",
            f"Geometry/Local refinements={L}: {box}"]


# Load / 8: pressure, its moment part and the traction scale alike.
SMALL = ["Boundary conditions/Pressure=1: 5e3*min(5*t, 1) - 1633.0075*x*"
         "(1.25*max(t - 0.2, 0) - 0.625*max(t - 0.8, 0))",
         "Boundary conditions/Traction=1: 2.5e3*(1.25*max(t - 0.2, 0) - "
         "0.625*max(t - 0.8, 0)), 0, 0",
         "Geometry/Hertz sphere/Refinement radius=0.4",
         "Geometry/Hertz sphere/Contact refinements=4",
         f"Geometry/Local refinements=3: {BOX}; 1: -0.6, 0, 1.8, 0.6, 0.6, 2.1"]

VARIANTS = {
    "base-L3": level(3),
    "base-L4": level(4),
    "q2-L1": level(1) + ["Finite element/Degree=2"],
    "q2-L2": level(2) + ["Finite element/Degree=2"],
    "small-L4": SMALL,
    "steps-L3": level(3) + ["Load stepping/Number of load steps=10"],
    # The flat twice as thick and wide (its clamped base 6 a below the
    # contact instead of 3 a): the finite layer's part.
    "thick-L3": level(3, "-1.2, 0, 3.4, 1.2, 1.2, 4.1") + [
        "Geometry/Hertz sphere/Plate thickness=4", "Geometry/Hertz sphere/Plate width=8",
        "Geometry/Hertz sphere/Plate refinements=2"],
}


def largest_stick_radius(directory):
    """The largest reference radius of a stick node, from the profile."""
    with open(directory / "pressure_profile.csv") as f:
        rows = [r for r in csv.DictReader(f) if float(r["active"]) > 0.5]
    return max((math.hypot(float(r["reference_x"]), float(r["reference_y"]))
                for r in rows if float(r["stick"]) > 0.5), default=0.)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", type=Path, default=REPO / "build/contact_fem")
    parser.add_argument("--variants", default="base-L3,thick-L3,small-L4,q2-L2")
    parser.add_argument("--results", type=Path, default=Path("results-cattaneo-3d-stick"))
    parser.add_argument("--reuse", action="store_true")
    args = parser.parse_args()
    for name in args.variants.split(","):
        d = args.results.resolve() / name
        summary = cattaneo_study.run(args.binary.resolve(), VARIANTS[name], d, args.reuse,
                                     "prm/cattaneo_3d.prm")
        cycle = summary["cycles"][-1]
        first = cycle["load_steps"][0]["forces"]["pairs"][0]
        steps = cycle["analytical"]["cattaneo"]["load_steps"]
        last = steps[-1]
        mu_P_half = 0.5 * last["mu"] * last["P"] if "mu" in last else float("nan")
        h = last["stick_end_spacing"]
        a = last["a"]
        print(f"{name}: {cycle['n_dofs']} DoFs, slave h {h:.4f} (a/h {a / h:.1f}), "
              f"a {a:.4f} (a/R {a / 6.1237:.3f}), {summary['wall_time']:.0f} s")
        print(f"  normal step: stick / slip {first.get('stick_nodes')} / {first.get('slip_nodes')}, "
              f"tangential force y {first['tangential_force'][1]:.4g}"
              + (f" = {first['tangential_force'][1] / mu_P_half:.4f} mu P/2" if mu_P_half == mu_P_half else ""))
        for s in steps:
            if s.get("Q_over_mu_P", 0.) < 1e-3:
                continue
            print(f"  Q/(mu P) {s['Q_over_mu_P']:.4f}: c_h/a {s['c_h_over_a']:.4f} (c/a {s['c_over_a']:.4f}), "
                  f"{s['c_error_in_slave_elements']:.2f} el, centre {s['stick_zone_center'] / h:+.2f} el, "
                  f"L2 {s['tangential_l2_relative_error']:.3f}, stick/slip {s['stick_nodes']}/{s['slip_nodes']}")
        largest = largest_stick_radius(d)
        print(f"  last step: largest stick radius / a {largest / a:.4f} "
              f"({(largest - last['c']) / h:+.2f} spacings off c)")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
