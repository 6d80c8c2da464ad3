#!/usr/bin/env python3
"""Print, per physical tag of boundary elements, the material of the cells that own its nodes (MSH 2.2)."""
import sys, collections
lines = open(sys.argv[1]).read().split("\n")
i = lines.index("$Elements"); n = int(lines[i+1])
bnd = collections.defaultdict(set); cellnodes = collections.defaultdict(set)
for l in lines[i+2:i+2+n]:
    t = l.split(); typ = int(t[1]); nt = int(t[2]); phys = int(t[3]); nodes = t[3+nt:]
    if typ in (1, 2, 3, 8, 9, 10, 16) and typ in (1, 8) or (typ in (2, 3, 9, 10, 16) and sys.argv[2:] == ["3d"]):
        bnd[phys].update(nodes)
    else:
        for v in nodes: cellnodes[v].add(phys)
for p, ns in sorted(bnd.items()):
    mats = collections.Counter(m for v in ns for m in cellnodes[v])
    print(p, len(ns), dict(mats))
