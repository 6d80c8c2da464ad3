#!/usr/bin/env python3
"""Independent solver for Kratos' 3D frictionless patch test
(shared/validation/kratos/ALM_frictionless_3D_contact_simplest_patch_matching_test),
to explain tests/scenes/kratos_patch_3d_01 and its difference from Kratos.

Pure Python (no numpy, nothing from contact_fem). The scene: two stacked
unit hexahedra, one trilinear element each, read from the .msh beside
Kratos' files; the lower one (z in [0, 1]) clamped at z = 0, the upper one
(z in [0.99999, 2], 1e-5 of initial overlap) displaced by (0, 0, -0.02) at
z = 2; E = 2.069e11 (the answer does not depend on E), nu = 0.29;
frictionless contact on the matching interface.

Which loading: the stored results (TIME 1.1, u_y = +-2.0557e-3) were made
with an older parameters file (Kratos commit 077ba6fd: one static step of
dt = 1.1, top displaced by the constant (0, 0, -0.02), lower block the
slave); the stored parameters (commit 6d8af783: dt = 0.5, end time 0.99,
top displaced by -1.0*t) give neither TIME 1.1 nor a displacement of this
size (and their check never fires: its counter must exceed
time_frequency = 1.0). Kratos' elements are UpdatedLagrangianElement3D8N
with HyperElastic3DLaw (materials JSON): finite strain.

Contact on this interface: the two faces are flat, parallel and matching,
and the deformation is symmetric (x <-> 1 - x, y <-> 1 - y, x <-> y), so
the interface stays a horizontal plane and the dual-mortar weighted gap of
each node pair reduces to z_upper - z_lower = 0 in the deformed
configuration (for Kratos' operators on X + u as for ours on X), with equal
and opposite normal forces and no tangential ones. The script imposes that
with a Lagrange multiplier per pair (and checks that each is compressive).

Cases printed:
  (a) small-strain linear elasticity (contact_fem's model): what
      tests/scenes/kratos_patch_3d_01 must print;
  (b) compressible neo-Hookean at finite strain (HyperElastic3DLaw of the
      stored materials JSON: P = mu (F - F^-T) + lambda ln(J) F^-T), total
      Lagrangian (equivalent to Kratos' updated Lagrangian for a
      hyperelastic law);
  (c) finite strain with the linear law on the Green-Lagrange strain (Saint
      Venant-Kirchhoff: what a linear elastic law gives in Kratos' finite
      strain elements): reproduces Kratos' stored u_y to 4e-9 (2e-6);
  (d) (c) with the interface left out of equilibrium by a small residual
      force (equal and opposite on the two blocks, as a Newton iteration
      stopped at Kratos' relative tolerance 1e-4 may leave it), fitted to
      Kratos' lower node: predicts the upper node to 6e-11.
All with 2 x 2 x 2 Gauss points (Kratos' and ours). (b) to (d) are not our
model: they explain the difference from Kratos.

Usage: bench/kratos_validation/patch_3d.py
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
KRATOS = os.path.join(HERE, '..', '..', '..', 'shared', 'validation', 'kratos',
                      'ALM_frictionless_3D_contact_simplest_patch_matching_test')
MESH = os.path.join(KRATOS, '3D_contact_simplest_patch_matching_test.msh')
RESULTS = os.path.join(KRATOS, '3D_contact_simplest_patch_matching_test_results.json')

E, NU = 206.9, 0.29  # GPa; displacement-driven: the answer does not depend on E
LAMBDA = E * NU / ((1 + NU) * (1 - 2 * NU))
MU = E / (2 * (1 + NU))
TOP_DISPLACEMENT = (0., 0., -0.02)


def read_msh(path):
    """Nodes {gmsh id: (x, y, z)} and hexahedra [(material, [8 ids])]."""
    nodes, hexes = {}, []
    with open(path) as f:
        lines = [l.strip() for l in f]
    i = lines.index('$Nodes') + 1
    for l in lines[i + 1:i + 1 + int(lines[i])]:
        v = l.split()
        nodes[int(v[0])] = tuple(float(c) for c in v[1:4])
    i = lines.index('$Elements') + 1
    for l in lines[i + 1:i + 1 + int(lines[i])]:
        v = [int(c) for c in l.split()]
        if v[1] == 5:
            hexes.append((v[3], v[3 + v[2]:]))
    return nodes, hexes


# Gmsh's hexahedron: the first four nodes one face, the last four the
# opposite one, in the same order.
CORNERS = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
           (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]
GAUSS = [(a / math.sqrt(3.), b / math.sqrt(3.), c / math.sqrt(3.))
         for a in (-1, 1) for b in (-1, 1) for c in (-1, 1)]


def shape_gradients(xi):
    return [[0.125 * c[d] * math.prod(1 + c[e] * xi[e] for e in range(3) if e != d)
             for d in range(3)] for c in CORNERS]


def inverse3(a):
    det = (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
           - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
           + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))
    inv = [[(a[(j + 1) % 3][(i + 1) % 3] * a[(j + 2) % 3][(i + 2) % 3]
             - a[(j + 1) % 3][(i + 2) % 3] * a[(j + 2) % 3][(i + 1) % 3]) / det
            for j in range(3)] for i in range(3)]
    return inv, det


def reference_gradients(X):
    """Per Gauss point: dN/dX of the 8 nodes and the weight |det J|."""
    points = []
    for xi in GAUSS:
        dN = shape_gradients(xi)
        J = [[sum(X[a][i] * dN[a][j] for a in range(8)) for j in range(3)] for i in range(3)]
        Jinv, det = inverse3(J)
        points.append(([[sum(dN[a][k] * Jinv[k][j] for k in range(3)) for j in range(3)]
                        for a in range(8)], abs(det)))
    return points


def linear_stress(H):
    """Small strain: P = sigma(eps(H)) and dP/dH."""
    eps = [[0.5 * (H[i][j] + H[j][i]) for j in range(3)] for i in range(3)]
    tr = eps[0][0] + eps[1][1] + eps[2][2]
    P = [[LAMBDA * tr * (i == j) + 2 * MU * eps[i][j] for j in range(3)] for i in range(3)]
    A = [[[[LAMBDA * (i == j) * (k == l) + MU * ((i == k) * (j == l) + (i == l) * (j == k))
            for l in range(3)] for k in range(3)] for j in range(3)] for i in range(3)]
    return P, A


def neo_hookean_stress(H):
    """P = mu (F - F^-T) + lambda ln J F^-T and dP/dF."""
    F = [[(i == j) + H[i][j] for j in range(3)] for i in range(3)]
    Finv, J = inverse3(F)
    lnJ = math.log(J)
    P = [[MU * (F[i][j] - Finv[j][i]) + LAMBDA * lnJ * Finv[j][i] for j in range(3)]
         for i in range(3)]
    A = [[[[MU * (i == k) * (j == l) + (MU - LAMBDA * lnJ) * Finv[j][k] * Finv[l][i]
            + LAMBDA * Finv[j][i] * Finv[l][k]
            for l in range(3)] for k in range(3)] for j in range(3)] for i in range(3)]
    return P, A


def saint_venant_kirchhoff_stress(H):
    """The linear law on the Green-Lagrange strain E: P = F (lambda tr(E) I
    + 2 mu E) and dP/dF."""
    F = [[(i == j) + H[i][j] for j in range(3)] for i in range(3)]
    E_gl = [[0.5 * (sum(F[k][i] * F[k][j] for k in range(3)) - (i == j)) for j in range(3)]
            for i in range(3)]
    tr = E_gl[0][0] + E_gl[1][1] + E_gl[2][2]
    S = [[LAMBDA * tr * (i == j) + 2 * MU * E_gl[i][j] for j in range(3)] for i in range(3)]
    P = [[sum(F[i][k] * S[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    FFt = [[sum(F[i][m] * F[k][m] for m in range(3)) for k in range(3)] for i in range(3)]
    A = [[[[(i == k) * S[l][j] + LAMBDA * F[i][j] * F[k][l] + MU * F[i][l] * F[k][j]
            + MU * FFt[i][k] * (j == l)
            for l in range(3)] for k in range(3)] for j in range(3)] for i in range(3)]
    return P, A


def assemble(u, elements, material, n):
    """Internal force vector and tangent (dense)."""
    f = [0.] * n
    K = [[0.] * n for _ in range(n)]
    for dofs, points in elements:
        for dNdX, w in points:
            H = [[sum(u[dofs[a][i]] * dNdX[a][j] for a in range(8)) for j in range(3)]
                 for i in range(3)]
            P, A = material(H)
            for a in range(8):
                for i in range(3):
                    f[dofs[a][i]] += w * sum(P[i][J] * dNdX[a][J] for J in range(3))
                    for b in range(8):
                        for k in range(3):
                            K[dofs[a][i]][dofs[b][k]] += w * sum(
                                A[i][J][k][L] * dNdX[a][J] * dNdX[b][L]
                                for J in range(3) for L in range(3))
    return f, K


def solve_dense(A, b):
    """Gaussian elimination with partial pivoting."""
    n = len(b)
    M = [row[:] + [b[i]] for i, row in enumerate(A)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(M[r][c]))
        M[c], M[p] = M[p], M[c]
        for r in range(c + 1, n):
            factor = M[r][c] / M[c][c]
            if factor:
                for k in range(c, n + 1):
                    M[r][k] -= factor * M[c][k]
    x = [0.] * n
    for r in reversed(range(n)):
        x[r] = (M[r][n] - sum(M[r][k] * x[k] for k in range(r + 1, n))) / M[r][r]
    return x


def solve(material, nodes, hexes, imbalance=0.):
    ids = sorted(nodes)
    index = {node: k for k, node in enumerate(ids)}
    n = 3 * len(ids)
    elements = [([[3 * index[v] + i for i in range(3)] for v in vertices],
                 reference_gradients([nodes[v] for v in vertices]))
                for _, vertices in hexes]
    body = {v: material_id for material_id, vertices in hexes for v in vertices}
    z_max = max(p[2] for p in nodes.values())
    # Dirichlet values: clamped base, displaced top.
    fixed = {}
    for v, p in nodes.items():
        if p[2] == 0.:
            fixed.update({3 * index[v] + i: 0. for i in range(3)})
        if p[2] == z_max:
            fixed.update({3 * index[v] + i: TOP_DISPLACEMENT[i] for i in range(3)})
    # Contact pairs: the nodes of the two bodies at the same (x, y) near z = 1.
    interface = [v for v, p in nodes.items() if 0. < p[2] < z_max]
    pairs = []
    for s in interface:
        for m in interface:
            if body[s] != body[m] and nodes[s][2] > nodes[m][2] and \
                    nodes[s][:2] == nodes[m][:2]:
                pairs.append((s, m))  # s: lower (slave), m: upper (master)
    free = [d for d in range(n) if d not in fixed]
    u = [fixed.get(d, 0.) for d in range(n)]
    lam = [0.] * len(pairs)
    for iteration in range(30):
        f, K = assemble(u, elements, material, n)
        # Residual of [f + B^T lam = 0 on free dofs; gap = 0], B u = u_z,m - u_z,s.
        r = [f[d] for d in range(n)]
        gaps = []
        for k, (s, m) in enumerate(pairs):
            r[3 * index[m] + 2] += lam[k]
            r[3 * index[s] + 2] -= lam[k]
            # An unbalanced interface: the lower node pushed down by more
            # than the upper one is pushed up.
            r[3 * index[s] + 2] += imbalance
            gaps.append(nodes[m][2] + u[3 * index[m] + 2] - nodes[s][2] - u[3 * index[s] + 2])
        norm = math.sqrt(sum(r[d] ** 2 for d in free) + sum(g ** 2 for g in gaps))
        if norm < 1e-13:
            break
        size = len(free) + len(pairs)
        A = [[0.] * size for _ in range(size)]
        rhs = [0.] * size
        where = {d: k for k, d in enumerate(free)}
        for a, d in enumerate(free):
            rhs[a] = -r[d]
            for b, e in enumerate(free):
                A[a][b] = K[d][e]
        for k, (s, m) in enumerate(pairs):
            row = len(free) + k
            for node, sign in ((m, 1.), (s, -1.)):
                d = 3 * index[node] + 2
                A[row][where[d]] = A[where[d]][row] = sign
            rhs[row] = -gaps[k]
        x = solve_dense(A, rhs)
        for a, d in enumerate(free):
            u[d] += x[a]
        for k in range(len(pairs)):
            lam[k] += x[len(free) + k]
    displacement = {v: tuple(u[3 * index[v] + i] for i in range(3)) for v in ids}
    return displacement, lam, iteration, norm, pairs


def print_case(name, solution, nodes, kratos):
    u, lam, iterations, norm, _ = solution
    print(f'{name}: {iterations} Newton iteration(s), residual {norm:.1e}; '
          f'normal force per node pair {-max(lam):.6g} to {-min(lam):.6g} '
          f'({"compressive" if max(lam) < 0 else "NOT compressive"})')
    print('  node  (x, y, z)          u_x                u_y                u_z'
          '                Kratos u_y         u_y - Kratos')
    for v in sorted(kratos):
        p = nodes[v]
        print(f'  {v:4d}  ({p[0]:g}, {p[1]:g}, {p[2]:.5f})  '
              + '  '.join(f'{c:+.11e}' for c in u[v])
              + f'  {kratos[v]:+.11e}  {u[v][1] - kratos[v]:+.2e}')
    worst = max(abs(u[v][1] - kratos[v]) for v in kratos)
    print(f'  largest |u_y - Kratos u_y| = {worst:.2e} '
          f'({worst / max(abs(k) for k in kratos.values()):.1e} of |u_y|)\n')


def main():
    nodes, hexes = read_msh(MESH)
    with open(RESULTS) as f:
        stored = json.load(f)
    kratos = {int(k[5:]): v['DISPLACEMENT_Y'][0] for k, v in stored.items() if k != 'TIME'}
    print_case('(a) small strain, linear elastic (contact_fem)',
               solve(linear_stress, nodes, hexes), nodes, kratos)
    print_case('(b) finite strain, neo-Hookean (HyperElastic3DLaw as named in the '
               'materials JSON)', solve(neo_hookean_stress, nodes, hexes), nodes, kratos)
    svk = solve(saint_venant_kirchhoff_stress, nodes, hexes)
    print_case('(c) finite strain, linear law on the Green-Lagrange strain '
               '(Saint Venant-Kirchhoff)', svk, nodes, kratos)
    # (d): Kratos' upper and lower nodes differ from (c) by equal and
    # opposite amounts, as if the Newton iteration had stopped with the
    # interface not quite in equilibrium (its tolerance: relative 1e-4).
    # One such residual force, fitted to the lower node 5, predicts the upper
    # node 2.
    lower = 5  # (0, 1, 1), a node of the lower block
    trial = 1e-5
    shifted = solve(saint_venant_kirchhoff_stress, nodes, hexes, trial)
    force = trial * (kratos[lower] - svk[0][lower][1]) / \
        (shifted[0][lower][1] - svk[0][lower][1])
    fitted = solve(saint_venant_kirchhoff_stress, nodes, hexes, force)
    print_case(f'(d) (c) with an unbalanced interface: residual force {force:.3g} per '
               f'node pair ({abs(force / fitted[1][0]):.2g} of the normal force) '
               f'fitted to node {lower}', fitted, nodes, kratos)


if __name__ == '__main__':
    main()
