#!/usr/bin/env python3
"""Writes a quarter of a thick-walled cylinder (Lame's problem) as hexahedra
in Gmsh's MSH 2.2 ASCII format: radii 1 and 2, x, y >= 0, z from 0 to the
given thickness; NR cells across the wall, NT around the quarter, NZ along
z, the nodes on the circles (so that Geometry/Manifolds accepts them).
One body (physical id 1). Boundary ids: 1 the inner face r = 1, 2 the outer
face r = 2, 5 the plane y = 0, 6 the plane x = 0, 7 z = 0, 8 z = thickness
(those of meshes/tied_ring.geo extruded by extrude_msh.py).

    python3 meshes/ring_3d.py NR NT NZ THICKNESS OUT.msh
    python3 meshes/ring_3d.py 4 6 1 0.25 meshes/ring_3d_4_6_1.msh
"""
import math
import sys

nr, nt, nz = (int(a) for a in sys.argv[1:4])
thickness, out = float(sys.argv[4]), sys.argv[5]


def node(i, j, k):
    """Number of the node i-th across the wall, j-th around, k-th along z (from 1)."""
    return 1 + i + (nr + 1) * (j + (nt + 1) * k)


nodes = []
for k in range(nz + 1):
    for j in range(nt + 1):
        angle = 0.5 * math.pi * j / nt
        # exact zeros and ones on the symmetry planes
        c, s = (1., 0.) if j == 0 else (0., 1.) if j == nt else (math.cos(angle), math.sin(angle))
        for i in range(nr + 1):
            r = 1. + i / nr
            nodes.append((r * c, r * s, thickness * k / nz))

elements = []  # (Gmsh type, physical id, nodes)
for k in range(nz):
    for j in range(nt):
        for i in range(nr):
            # counter-clockwise seen from +z (e_r x e_theta = e_z), then the
            # layer above: a hexahedron of positive volume
            base = [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k)]
            top = [v + (nr + 1) * (nt + 1) for v in base]
            elements.append((5, 1, base + top))
            if k == 0:
                elements.append((3, 7, base))
            if k == nz - 1:
                elements.append((3, 8, top))
            if i == 0:
                elements.append((3, 1, [base[0], base[3], top[3], top[0]]))
            if i == nr - 1:
                elements.append((3, 2, [base[1], base[2], top[2], top[1]]))
            if j == 0:
                elements.append((3, 5, [base[0], base[1], top[1], top[0]]))
            if j == nt - 1:
                elements.append((3, 6, [base[3], base[2], top[2], top[3]]))

with open(out, "w") as f:
    f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
    for n, (x, y, z) in enumerate(nodes, 1):
        f.write("%d %.17g %.17g %.17g\n" % (n, x, y, z))
    f.write("$EndNodes\n$Elements\n%d\n" % len(elements))
    for e, (kind, physical, v) in enumerate(elements, 1):
        f.write("%d %d 2 %d %d %s\n" % (e, kind, physical, physical, " ".join(map(str, v))))
    f.write("$EndElements\n")
