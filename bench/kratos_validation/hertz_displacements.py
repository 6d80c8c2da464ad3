#!/usr/bin/env python3
"""Compare contact_fem's displacements on Kratos' Hertz mesh with Kratos' own
stored results (shared/validation/kratos/hertz_simple_test).

Kratos' regression test checks DISPLACEMENT_X/Y of the 152 nodes of its
Contact_Part (hertz_simple_test_results.json). This script reads those nodes'
coordinates and bodies from the .mdpa, runs prm/hertz_kratos_mesh.prm with
every node as an `Output/Displacement probes` entry, and prints the largest
differences, absolute and relative to the largest Kratos displacement, per
body. Usage:
  bench/kratos_validation/hertz_displacements.py [--binary FILE] [--keep DIR]
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", ".."))
DATA = os.path.abspath(os.path.join(REPO, "..", "shared", "validation", "kratos",
                                    "hertz_simple_test"))


def read_mdpa(path):
    """Node coordinates by Kratos id, and the body (material id of
    prm/hertz_kratos_mesh.prm: 1 hemisphere, 2 plate) of every node."""
    nodes, body, section, part = {}, {}, None, None
    bodies = {"Parts_parts_hemisphere": 1, "Parts_parts_plate": 2}
    for line in open(path):
        words = line.split()
        if not words:
            continue
        if words[0] == "Begin":
            section = words[1]
            if words[1] == "SubModelPart":
                part = words[2]
            continue
        if words[0] == "End":
            if words[1] == "SubModelPart":
                part = None
            section = None
            continue
        if section == "Nodes":
            nodes[int(words[0])] = (float(words[1]), float(words[2]))
        elif section == "SubModelPartNodes" and part in bodies:
            body[int(words[0])] = bodies[part]
    return nodes, body


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default=os.path.join(REPO, "build", "contact_fem"))
    parser.add_argument("--keep", help="output directory of the run (default: temporary)")
    args = parser.parse_args()

    reference = json.load(open(os.path.join(DATA, "hertz_simple_test_results.json")))
    nodes, body = read_mdpa(os.path.join(DATA, "hertz_simple_test.mdpa"))
    ids = sorted(int(k.split("_")[1]) for k in reference if k.startswith("NODE_"))
    probes = "; ".join("%d @ %.10g, %.10g" % (body[i], *nodes[i]) for i in ids)

    out = args.keep or tempfile.mkdtemp(prefix="kratos-hertz-")
    cmd = [args.binary, os.path.join(REPO, "prm", "hertz_kratos_mesh.prm"),
           "--set", "Output/Displacement probes=" + probes,
           "--set", "Output/Write VTU=false", "--output-directory", out]
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit("contact_fem failed (exit %d):\n%s" % (run.returncode, run.stdout[-2000:]))
    probes_out = json.load(open(os.path.join(out, "summary.json")))["cycles"][-1]["displacement_probes"]

    worst = {}
    scale = max(math.hypot(reference["NODE_%d" % i]["DISPLACEMENT_X"][0],
                           reference["NODE_%d" % i]["DISPLACEMENT_Y"][0]) for i in ids)
    rows = []
    for i, probe in zip(ids, probes_out):
        ref = reference["NODE_%d" % i]
        ux, uy = probe["displacement"]
        rx, ry = ref["DISPLACEMENT_X"][0], ref["DISPLACEMENT_Y"][0]
        d = math.hypot(ux - rx, uy - ry)
        rows.append((d, i, body[i], nodes[i], (ux, uy), (rx, ry)))
        w = worst.setdefault(body[i], [0., None, 0])
        w[2] += 1
        if d > w[0]:
            w[0], w[1] = d, i
    print("Kratos hertz_simple_test: %d Contact_Part nodes, largest Kratos |u| = %.6g" %
          (len(ids), scale))
    for b, (d, i, n) in sorted(worst.items()):
        print("body %d (%s, %d nodes): largest |u - u_Kratos| = %.3g (%.3g %% of the largest |u|) "
              "at node %d %s" % (b, "hemisphere" if b == 1 else "plate", n, d, 100 * d / scale, i,
                                 nodes[i]))
    print("five largest differences:")
    for d, i, b, x, u, r in sorted(rows, reverse=True)[:5]:
        print("  node %5d body %d at (%.5g, %.5g): u = (%.6g, %.6g), Kratos (%.6g, %.6g)" %
              (i, b, x[0], x[1], u[0], u[1], r[0], r[1]))

    # Contact pressure at Kratos' active nodes (its augmented normal contact
    # pressure is negative there; positive values on open nodes are not
    # pressures). Ours from pressure_profile.csv, whose x is the deformed
    # position of the slave node.
    kratos_p = json.load(open(os.path.join(DATA, "hertz_simple_test_results_LM.json")))
    profile = [tuple(map(float, line.split(",")[:3]))
               for line in open(os.path.join(out, "pressure_profile.csv")).readlines()[1:]]
    u_of = {i: probe["displacement"] for i, probe in zip(ids, probes_out)}
    active = sorted((nodes[i][0], i) for i in ids
                    if kratos_p["NODE_%d" % i]["AUGMENTED_NORMAL_CONTACT_PRESSURE"][0] < 0)
    print("contact pressure at Kratos' %d active nodes (x, Kratos, contact_fem, Hertz):" %
          len(active))
    largest = 0.
    for x, i in active:
        x_def = x + u_of[i][0]
        row = min(profile, key=lambda r: abs(r[0] - x_def))
        pk = -kratos_p["NODE_%d" % i]["AUGMENTED_NORMAL_CONTACT_PRESSURE"][0]
        largest = max(largest, abs(row[1] - pk))
        print("  %8.5f  %7.4f  %7.4f  %7.4f" % (x, pk, row[1], row[2]))
    print("largest |p - p_Kratos| on them: %.3g" % largest)
    print("output: %s" % out)


if __name__ == "__main__":
    main()
