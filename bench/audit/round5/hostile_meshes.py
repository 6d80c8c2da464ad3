#!/usr/bin/env python3
"""Hostile variants of a 2D MSH 2.2 mesh (round 5): usage hostile_meshes.py
MESH OUTDIR. Writes z5.msh (every node at z = 5), unused.msh (3 nodes no
element uses), point.msh (a physical point group), xz.msh (the mesh in the
x-z plane), tangled.msh (an interior node moved above the top: 3 triangles
inverted and overlapping their neighbours), degenerate.msh (a node moved
onto the opposite edge of its triangle)."""
import os, sys
src, out = sys.argv[1], sys.argv[2]
lines = open(src).read().split("\n")
i = lines.index("$Nodes"); n = int(lines[i + 1])
j = lines.index("$Elements"); m = int(lines[j + 1])
nodes = lines[i + 2:i + 2 + n]
xy = {l.split()[0]: (float(l.split()[1]), float(l.split()[2])) for l in nodes}
def write(name, text_lines):
    open(os.path.join(out, name), "w").write("\n".join(text_lines))
def with_nodes(f):
    a = lines[:]
    for k in range(i + 2, i + 2 + n):
        a[k] = f(a[k].split())
    return a
write("z5.msh", with_nodes(lambda t: " ".join(t[:3] + ["5"])))
write("xz.msh", with_nodes(lambda t: " ".join([t[0], t[1], "0", t[2]])))
u = lines[:]; u[i + 1] = str(n + 3)
write("unused.msh", u[:i + 2 + n] + [f"{100000 + k} {7 + k} -3 0" for k in range(3)] + u[i + 2 + n:])
p = lines[:]; p[j + 1] = str(m + 1)
write("point.msh", p[:j + 2] + [f"1000000 15 2 7 7 {lines[j + 2].split()[-1]}"] + p[j + 2:])
boundary = set()
for l in lines[j + 2:j + 2 + m]:
    t = l.split()
    if t[1] == "1":
        boundary.update(t[5:])
inner = next(t for t in (l.split() for l in nodes) if t[0] not in boundary and float(t[2]) > 0.6)
write("tangled.msh", with_nodes(lambda t: f"{t[0]} {t[1]} 1.3 0" if t[0] == inner[0] else " ".join(t)))
for l in lines[j + 2:j + 2 + m]:
    t = l.split()
    if t[1] == "2" and t[5] not in boundary:
        a, b, c = t[5:]
        mid = ((xy[b][0] + xy[c][0]) / 2, (xy[b][1] + xy[c][1]) / 2)
        write("degenerate.msh", with_nodes(
            lambda s: f"{a} {mid[0]!r} {mid[1]!r} 0" if s[0] == a else " ".join(s)))
        break
