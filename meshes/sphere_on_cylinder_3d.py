#!/usr/bin/env python3
"""A block with a spherical bottom on a block with a cylindrical top whose
axis is turned by 30 degrees from x about z (MSH 2.2 ASCII, hexahedra):
curved 3D contact faces whose contact under sliding along x and y is not
plane (tests/scenes/current_kinematics_sphere_cylinder_3d_01).

- body 1 (the slave, material id 1): x, y in [-1, 1] (8 x 8 cells), the top
  z = 1 (boundary 1), the bottom on the sphere of radius 3 about (0, 0, 3),
  so its lowest point is the origin: its central 4 x 4 faces (|x|, |y| <
  0.5) boundary 3 (the contact surface: every contact face pair costs an AD
  linearisation per Newton iteration), the others and the sides boundary 5;
  3 cell layers in z;
- body 2 (the master, material id 2): x, y in [-1.5, 1.5] (6 x 6 cells), the
  bottom z = -2 (boundary 2), the top (boundary 4) on the cylinder of
  radius 4 about the axis through (0, 0, -4) along (cos 30, sin 30, 0), so
  its highest line passes through the origin; 2 cell layers; sides 6.

The two touch at the origin. The manifolds of boundaries 3 and 4 are
MANIFOLDS (Geometry/Manifolds). With a rotation matrix (write(path, R)) every
vertex, the sphere's centre and the cylinder's point and axis are turned
by R about the origin (the objectivity check).

    python3 meshes/sphere_on_cylinder_3d.py meshes/sphere_on_cylinder_3d.msh
"""
import math
import sys

SPHERE_RADIUS, CYLINDER_RADIUS = 3.0, 4.0
AXIS = (math.cos(math.radians(30.0)), math.sin(math.radians(30.0)), 0.0)


def turn(R, p):
    return tuple(sum(R[i][j] * p[j] for j in range(3)) for i in range(3))


def manifolds(R=None):
    R = R or [[1.0 if i == j else 0.0 for j in range(3)] for i in range(3)]
    s, c, a = turn(R, (0, 0, SPHERE_RADIUS)), turn(R, (0, 0, -CYLINDER_RADIUS)), turn(R, AXIS)
    f = lambda v: ", ".join(repr(x) for x in v)
    return f"3: sphere {f(s)}, {SPHERE_RADIUS!r}; 4: cylinder {f(c)}, {f(a)}, {CYLINDER_RADIUS!r}"


def block(nodes, elements, size, n, layers, bottom, top, ids, central=None):
    """Hexahedra on [-size, size]^2 x [bottom(x, y), top(x, y)], linear in z
    between; ids = (material, bottom face, top face, sides); with central =
    (c, id) the bottom faces with |x|, |y| > c get the id instead."""
    first = len(nodes) + 1

    def index(i, j, k):
        return first + i + (n + 1) * (j + (n + 1) * k)

    for k in range(layers + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                x, y = -size + 2 * size * i / n, -size + 2 * size * j / n
                zb, zt = bottom(x, y), top(x, y)
                nodes.append((x, y, zb + (zt - zb) * k / layers))
    material, low, high, sides = ids
    for k in range(layers):
        for j in range(n):
            for i in range(n):
                v = [index(i, j, k), index(i + 1, j, k), index(i + 1, j + 1, k), index(i, j + 1, k)]
                elements.append((5, material, v + [w + (n + 1) ** 2 for w in v]))
    for j in range(n):
        for i in range(n):
            outer = central and max(abs(-size + 2 * size * (m + 0.5) / n) for m in (i, j)) > central[0]
            elements.append((3, central[1] if outer else low, [index(i, j, 0), index(i, j + 1, 0), index(i + 1, j + 1, 0),
                                      index(i + 1, j, 0)]))
            elements.append((3, high, [index(i, j, layers), index(i + 1, j, layers),
                                       index(i + 1, j + 1, layers), index(i, j + 1, layers)]))
    for k in range(layers):
        for m in range(n):
            for a, b in (((m, 0), (m + 1, 0)), ((n, m), (n, m + 1)), ((m + 1, n), (m, n)),
                         ((0, m + 1), (0, m))):
                elements.append((3, sides, [index(*a, k), index(*b, k), index(*b, k + 1),
                                            index(*a, k + 1)]))


def write(path, R=None):
    nodes, elements = [], []
    block(nodes, elements, 1.0, 8, 3,
          lambda x, y: SPHERE_RADIUS - math.sqrt(SPHERE_RADIUS**2 - x * x - y * y),
          lambda x, y: 1.0, (1, 3, 1, 5), (0.5, 5))

    def cylinder(x, y):
        d = -AXIS[1] * x + AXIS[0] * y
        return -CYLINDER_RADIUS + math.sqrt(CYLINDER_RADIUS**2 - d * d)

    block(nodes, elements, 1.5, 6, 2, lambda x, y: -2.0, cylinder, (2, 2, 4, 6))
    if R is not None:
        nodes = [turn(R, p) for p in nodes]
    with open(path, "w") as out:
        out.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
        for k, p in enumerate(nodes, 1):
            out.write("%d %.17g %.17g %.17g\n" % (k, *p))
        out.write("$EndNodes\n$Elements\n%d\n" % len(elements))
        for e, (kind, physical, v) in enumerate(elements, 1):
            out.write("%d %d 2 %d %d %s\n" % (e, kind, physical, physical, " ".join(map(str, v))))
        out.write("$EndElements\n")
    return manifolds(R)


if __name__ == "__main__":
    print(write(sys.argv[1]))
