#!/usr/bin/env python3
"""Audit round 4: forces.csv of metamorphic.py's variants (run directory
DIR/results-NAME) turned back into the scene's frame and scaled, against the
identity run's; and per row the balance of the master body: the reaction of
its support equals the pair's normal + tangential force.
usage: compare_forces.py DIR SPEC... (the same NAME=RULES as metamorphic.py)"""
import csv, os, sys
sys.path.insert(0, "/work/wt/audit4/tests/metamorphic")
from metamorphic import Variant

def rows(d):
    with open(os.path.join(d, "forces.csv")) as f:
        return list(csv.DictReader(f))

def vectors(row):
    out = {}
    for k, v in row.items():
        if k[-2:] in ("_x", "_y", "_z"):
            out.setdefault(k[:-2], [0.0] * 3)["xyz".index(k[-1])] = float(v)
    return out

base_dir = sys.argv[1]
ref = rows(os.path.join(base_dir, "results-identity"))
scale = max(abs(float(v)) for r in ref for k, v in r.items() if k[-2:] in ("_x", "_y", "_z"))
worst_balance = 0.0
for r in ref:
    v = vectors(r)
    pair = [k for k in v if k.endswith("_normal")][0][: -len("_normal")]
    b = [v[pair + "_normal"][i] + v[pair + "_tangential"][i] - v["boundary_2"][i] for i in range(3)]
    worst_balance = max(worst_balance, max(abs(x) for x in b) / scale)
print(f"identity: support of the master body against the pair force: {worst_balance:.1e} of the largest force")
for spec in sys.argv[2:]:
    var = Variant(spec, 3, 1.0)
    R = var.matrix()
    k = var.moduli * var.load * var.length ** 2
    try:
        got = rows(os.path.join(base_dir, "results-" + var.name))
    except FileNotFoundError:
        print(f"{var.name}: no forces.csv"); continue
    worst, where = 0.0, ""
    for a, b in zip(ref, got):
        va, vb = vectors(a), vectors(b)
        for name, vec in va.items():
            w = vb[name]
            back = [sum(R[j][i] * w[j] for j in range(3)) / k for i in range(3)]  # R^T w
            d = max(abs(back[i] - vec[i]) for i in range(3)) / scale
            if d > worst:
                worst, where = d, f"t = {a['t']}, {name}"
        if 'pair_3_4_area' in a:
            d = abs(float(b['pair_3_4_area']) / var.length ** 2 - float(a['pair_3_4_area'])) / float(a['pair_3_4_area'])
            if d > worst:
                worst, where = d, f"t = {a['t']}, area"
    print(f"{var.name}: {len(got)} rows (identity {len(ref)}), largest difference {worst:.1e} of the largest force ({where})")
