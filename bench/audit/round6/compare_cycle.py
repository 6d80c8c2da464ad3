#!/usr/bin/env python3
"""Compares cycle K of an adaptive study's summary.json with the first cycle
of a fresh run (same mesh made by initial refinement): every number, each
against the largest magnitude among the numbers of its key (a force against
the forces), so round-off of values near zero does not count.
Usage: compare_cycle.py STUDY/summary.json K FRESH/summary.json [tol]"""
import json
import re
import sys

SKIP = re.compile(r"wall_time|timing|estimat|linear_solver|^cycle$|dofs_per_rank|"
                  r"recovered|solution_energy_norm|newton_iterations")


def flatten(node, path, out):
    if isinstance(node, dict):
        for k, v in node.items():
            if not SKIP.search(k):
                flatten(v, path + [k], out)
    elif isinstance(node, list):
        for i, v in enumerate(node):
            flatten(v, path + [str(i)], out)
    elif isinstance(node, (int, float)) and not isinstance(node, bool):
        out["/".join(path)] = float(node)
    else:
        out["/".join(path)] = node


study = json.load(open(sys.argv[1]))["cycles"][int(sys.argv[2])]
fresh = json.load(open(sys.argv[3]))["cycles"][0]
tol = float(sys.argv[4]) if len(sys.argv) > 4 else 1e-7
a, b = {}, {}
flatten(study, [], a)
flatten(fresh, [], b)
scale = {}
for k, v in list(a.items()) + list(b.items()):
    if isinstance(v, float):
        key = re.sub(r"/[0-9]+", "", k)
        scale[key] = max(scale.get(key, 0.0), abs(v))
worst, bad = 0.0, []
for k in sorted(set(a) | set(b)):
    if k not in a or k not in b:
        bad.append(f"only in {'study' if k in a else 'fresh'}: {k}")
        continue
    x, y = a[k], b[k]
    if isinstance(x, float) and isinstance(y, float):
        s = scale[re.sub(r"/[0-9]+", "", k)] or 1.0
        d = abs(x - y) / s
        worst = max(worst, d)
        if d > tol:
            bad.append(f"{k}: study {x!r} fresh {y!r} ({d:.1e} of the key's scale)")
    elif x != y:
        bad.append(f"{k}: study {x!r} fresh {y!r}")
for line in bad[:25]:
    print("  " + line)
print(f"largest relative change {worst:.1e}, {len(bad)} differences")
