#!/usr/bin/env python3
"""Audit round 4: the 2D patch (tests/metamorphic/blocks_2d.msh ids) with
the upper block a strip of thickness H (argv[1]) in 5 x 1 cells on the
lower unit block in 3 x 3: aspect ratios 0.2 / H. Writes thin_H.msh."""
import sys
H = float(sys.argv[1])
nodes, quads, lines = [], [], []
def block(nx, ny, y0, height, material, ids):
    base = len(nodes)
    for j in range(ny + 1):
        for i in range(nx + 1):
            nodes.append((i / nx, y0 + height * j / ny))
    idx = lambda i, j: base + j * (nx + 1) + i + 1
    for j in range(ny):
        for i in range(nx):
            quads.append((material, [idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)]))
    bottom, top, left, right = ids
    for i in range(nx):
        lines.append((bottom, [idx(i, 0), idx(i + 1, 0)]))
        lines.append((top, [idx(i, ny), idx(i + 1, ny)]))
    for j in range(ny):
        lines.append((left, [idx(0, j), idx(0, j + 1)]))
        lines.append((right, [idx(nx, j), idx(nx, j + 1)]))
block(3, 3, 0.0, 1.0, 2, (2, 4, 5, 7))
block(5, 1, 1.0, H, 1, (3, 1, 6, 7))
with open(f"thin_{sys.argv[1]}.msh", "w") as f:
    f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
    for k, (x, y) in enumerate(nodes):
        f.write(f"{k + 1} {x!r} {y!r} 0\n")
    f.write("$EndNodes\n$Elements\n%d\n" % (len(lines) + len(quads)))
    k = 0
    for tag, v in lines:
        k += 1; f.write(f"{k} 1 2 {tag} {tag} {v[0]} {v[1]}\n")
    for tag, v in quads:
        k += 1; f.write(f"{k} 3 2 {tag} {tag} " + " ".join(map(str, v)) + "\n")
    f.write("$EndElements\n")
