#!/usr/bin/env python3
"""Writes blocks_2d.msh (Gmsh MSH 2.2): the 2D contact patch of two stacked
unit blocks with non-matching meshes, the lower [0, 1] x [0, 1] in 3 x 3
cells (material 2), the upper [0, 1] x [1, 2] in 5 x 5 (material 1).
Boundary ids: 1 top, 2 bottom, 3 underside of the upper block (slave),
4 top of the lower block (master), 5 left side of the lower block, 6 left
side of the upper block, 7 right sides.

Also blocks_wide_2d.msh (friction_current_2d.prm.in): the upper block
[0, 4] x [1, 2] in 8 x 8 cells on the lower [-1, 5] x [0, 1] in 6 x 6, with
the same ids."""


def block(n, y0, material, ids, x0=0, width=1):
    base = len(nodes)
    for j in range(n + 1):
        for i in range(n + 1):
            nodes.append((x0 + width * i / n if width != 1 else i / n, y0 + j / n))
    index = lambda i, j: base + j * (n + 1) + i + 1
    for j in range(n):
        for i in range(n):
            quads.append((material, [index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)]))
    bottom, top, left, right = ids
    for i in range(n):
        lines.append((bottom, [index(i, 0), index(i + 1, 0)]))
        lines.append((top, [index(i, n), index(i + 1, n)]))
    for j in range(n):
        lines.append((left, [index(0, j), index(0, j + 1)]))
        lines.append((right, [index(n, j), index(n, j + 1)]))


def write(name):
    with open(name, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
        for k, (x, y) in enumerate(nodes):
            f.write(f"{k + 1} {x!r} {y!r} 0\n")
        f.write("$EndNodes\n$Elements\n%d\n" % (len(lines) + len(quads)))
        k = 0
        for tag, v in lines:
            k += 1
            f.write(f"{k} 1 2 {tag} {tag} {v[0]} {v[1]}\n")
        for tag, v in quads:
            k += 1
            f.write(f"{k} 3 2 {tag} {tag} {' '.join(map(str, v))}\n")
        f.write("$EndElements\n")


for name, lower, upper in [("blocks_2d.msh", (3,), (5,)), ("blocks_wide_2d.msh", (6, -1, 6), (8, 0, 4))]:
    nodes, quads, lines = [], [], []
    block(lower[0], 0.0, 2, (2, 4, 5, 7), *lower[1:])
    block(upper[0], 1.0, 1, (3, 1, 6, 7), *upper[1:])
    write(name)
