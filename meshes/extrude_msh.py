#!/usr/bin/env python3
"""Extrudes a 2D Gmsh mesh (MSH 2.2 ASCII, quadrilaterals and boundary
lines) by one layer of hexahedra, z from 0 to 1: every quadrilateral becomes
a hexahedron of the same physical id, every boundary line a quadrilateral
face of the same physical id, and the faces z = 0 and z = 1 get the ids 5
and 6 (or the two ids given after the file names). With u_z = 0 on both,
the 3D problem is the plane-strain 2D one, so the 3D contact code can be
checked against the 2D one on curved surfaces.

    python3 meshes/extrude_msh.py meshes/two_cylinders.msh meshes/two_cylinders_extruded.msh
    python3 meshes/extrude_msh.py meshes/tied_ring_6_8.msh meshes/tied_ring_3d_6_8.msh 7 8
"""
import sys

bottom, top_id = sys.argv[3:5] if len(sys.argv) > 3 else ('5', '6')
lines = open(sys.argv[1]).read().split('\n')
i = lines.index('$Nodes')
nodes = {}
for line in lines[i + 2:i + 2 + int(lines[i + 1])]:
    t = line.split()
    nodes[int(t[0])] = (float(t[1]), float(t[2]))
offset = max(nodes)  # node k at z = 1 is k + offset
j = lines.index('$Elements')
elements = []
for line in lines[j + 2:j + 2 + int(lines[j + 1])]:
    t = line.split()
    kind, physical, v = t[1], t[3], [int(x) for x in t[3 + int(t[2]):]]
    top = [w + offset for w in v]
    if kind == '1':    # boundary line -> quadrilateral face
        elements.append(('3', physical, [v[0], v[1], top[1], top[0]]))
    elif kind == '3':  # quadrilateral -> hexahedron and its two end faces
        elements.append(('5', physical, v + top))
        elements.append(('3', bottom, v[::-1]))
        elements.append(('3', top_id, top))
with open(sys.argv[2], 'w') as out:
    out.write('$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n' % (2 * len(nodes)))
    for z, shift in ((0., 0), (1., offset)):
        for k, (x, y) in sorted(nodes.items()):
            out.write('%d %.17g %.17g %.17g\n' % (k + shift, x, y, z))
    out.write('$EndNodes\n$Elements\n%d\n' % len(elements))
    for e, (kind, physical, v) in enumerate(elements, 1):
        out.write('%d %s 2 %s %s %s\n' % (e, kind, physical, physical, ' '.join(map(str, v))))
    out.write('$EndElements\n')
