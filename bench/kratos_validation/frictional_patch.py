#!/usr/bin/env python3
"""Independent solver for Kratos' frictional "hyper simple patch test"
(shared/validation/kratos/ALM_frictional_2D_hyper_simple_patch_test) under
contact_fem's model, to validate `Contact/Formulation = alm frictional`.

Pure Python (no numpy, nothing from contact_fem): two bilinear plane-strain
elements, 2D dual mortar on straight faces, Coulomb friction with the slip
measured incrementally from the last converged load step. The contact
problem of each load step is solved by ENUMERATION of the states of the two
slave nodes (inactive / stick / slip +t / slip -t; frictionless: inactive /
active): every combination is one linear system, and a combination is a
solution when all its inequalities hold (gap >= 0 where inactive, pressure
>= 0 where active, |t.lambda| <= mu p where stick, slip along +-t where
slip). The script reports how many combinations are solutions (1 = unique).

Model (contact_fem, Contact/Kinematics = small):
  * small-strain linear elasticity, plane strain, Q1, 2x2 Gauss;
  * mortar operators on the reference configuration: D_j = int N_j,
    M_jl = int Phi_j N_l (dual basis Phi_1 = 2 N_1 - N_2, ...);
  * weighted gap g_j = n.(sum_l M_jl x_l - D_j x_j) / D_j >= 0;
  * traction lambda_j on the slave (force D_j lambda_j on slave node j,
    -sum_j M_jl lambda_j on master node l), p_j = -n.lambda_j;
  * slip increment xi_j = t.((u_j - u_j_old) - sum_l M_jl/D_j (u_l - u_l_old));
    Coulomb: |t.lambda_j| <= mu p_j, stick if xi_j = 0, otherwise
    t.lambda_j = -mu p_j sign(xi_j) (the friction opposes the slip).

Kratos' scene (its parameters JSON), read by this script: lower block
(Parts_Parts_Auto2, slave) clamped at y = 0; upper block's top (nodes 7, 8)
displaced by (0.04, -0.04); mu = 0.01; E = 2.069e11, nu = 0.29, rho = 1000;
solver_type "Dynamic" (Bossak by default), ONE time step of 1.1e-3 (end time
1e-3): Kratos' stored result at TIME 0.0011 is that one step.

Cases printed:
  (a0) sanity: the frictionless twin scene (ALM_frictionless_2D_..., top
       displaced by (0, -0.01)): must give Kratos' and tests/scenes/
       kratos_patch_01's +-1.28426035e-03, -4.50229204e-03, ...;
  (a)  the frictional scene's load without friction;
  (b)  mu = 0.01, static, one load step: what `alm frictional` must give
       (tests/scenes/kratos_frictional_patch_01);
  (c)  the same in N load steps (linear ramp; --steps): path independence;
  (d)  (b) plus Kratos' inertia: one Bossak step (alpha_m = -0.3, beta =
       0.25 (1 - alpha_m)^2, consistent mass) of 1.1e-3 from rest, the top
       nodes already at their imposed value at t = 0 (Kratos' assign process
       sets constant values before the solution loop);
  (e)  (d) with the mortar operators, normal and gap on the deformed
       configuration X + u (fixed point; dual basis on the overlap), as
       Kratos' conditions do: Kratos' model, with exact Coulomb slip;
  (f)  Kratos' stored displacements analysed: the nodal forces K u + inertia
       they imply (the action-reaction balance of the interface confirms the
       inertia model), their gaps and tangential-to-normal traction ratio;
  (g)  (e) with the traction ratio found in (f) instead of Coulomb's mu:
       reproduces Kratos' stored displacements.
(d) to (g) are not our model: they explain the difference from Kratos.

Usage: bench/kratos_validation/frictional_patch.py [--steps N]
"""
import argparse
import itertools
import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.abspath(os.path.join(HERE, "..", "..", "..", "shared", "validation", "kratos"))

# Kratos node ids 1..8 (index = id - 1); the .mdpa of both patch tests.
X = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0),
     (0.0, 1.001), (1.0, 1.001), (1.0, 2.0), (0.0, 2.0)]
CELLS = [(0, 1, 2, 3), (4, 5, 6, 7)]        # counter-clockwise
SLAVE = (3, 2)      # lower block top face, Kratos nodes 4 (x = 0), 3 (x = 1)
MASTER = (4, 5)     # upper block base, Kratos nodes 5 (x = 0), 6 (x = 1)
NDOF = 16


# ---------------------------------------------------------------- linear algebra
def solve(A, b):
    """Gaussian elimination with partial pivoting (dense, small)."""
    n = len(b)
    M = [row[:] + [b[i]] for i, row in enumerate(A)]
    for k in range(n):
        p = max(range(k, n), key=lambda i: abs(M[i][k]))
        if abs(M[p][k]) < 1e-300:
            raise ZeroDivisionError("singular system")
        M[k], M[p] = M[p], M[k]
        for i in range(k + 1, n):
            f = M[i][k] / M[k][k]
            if f:
                for j in range(k, n + 1):
                    M[i][j] -= f * M[k][j]
    x = [0.0] * n
    for i in reversed(range(n)):
        x[i] = (M[i][n] - sum(M[i][j] * x[j] for j in range(i + 1, n))) / M[i][i]
    return x


def zeros(n, m=None):
    return [0.0] * n if m is None else [[0.0] * m for _ in range(n)]


def matvec(A, x):
    return [sum(a * b for a, b in zip(row, x)) for row in A]


# ---------------------------------------------------------------- bulk
def bulk_matrices(E, nu, rho):
    """Global stiffness K and consistent mass M (Q1, plane strain, 2x2 Gauss)."""
    c = E / ((1 + nu) * (1 - 2 * nu))
    C = [[c * (1 - nu), c * nu, 0.0], [c * nu, c * (1 - nu), 0.0], [0.0, 0.0, c * (1 - 2 * nu) / 2]]
    K, M = zeros(NDOF, NDOF), zeros(NDOF, NDOF)
    ref = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
    g = 1 / 3 ** 0.5
    for cell in CELLS:
        xy = [X[i] for i in cell]
        for qx, qy in [(-g, -g), (g, -g), (g, g), (-g, g)]:
            N = [(1 + a * qx) * (1 + b * qy) / 4 for a, b in ref]
            dN = [(a * (1 + b * qy) / 4, b * (1 + a * qx) / 4) for a, b in ref]
            J = [[sum(dN[k][i] * xy[k][j] for k in range(4)) for j in range(2)] for i in range(2)]
            det = J[0][0] * J[1][1] - J[0][1] * J[1][0]
            Ji = [[J[1][1] / det, -J[0][1] / det], [-J[1][0] / det, J[0][0] / det]]
            dx = [(Ji[0][0] * d[0] + Ji[0][1] * d[1], Ji[1][0] * d[0] + Ji[1][1] * d[1]) for d in dN]
            B = zeros(3, 8)
            for k in range(4):
                B[0][2 * k], B[1][2 * k + 1] = dx[k][0], dx[k][1]
                B[2][2 * k], B[2][2 * k + 1] = dx[k][1], dx[k][0]
            CB = [[sum(C[i][m] * B[m][j] for m in range(3)) for j in range(8)] for i in range(3)]
            dofs = [2 * n + d for n in cell for d in (0, 1)]
            for a in range(8):
                for b in range(8):
                    K[dofs[a]][dofs[b]] += det * sum(B[m][a] * CB[m][b] for m in range(3))
            for a in range(4):
                for b in range(4):
                    for d in (0, 1):
                        M[2 * cell[a] + d][2 * cell[b] + d] += det * rho * N[a] * N[b]
    return K, M


# ---------------------------------------------------------------- mortar
def mortar(x, whole_face_dual=True):
    """Dual mortar operators of the straight slave face SLAVE against the
    straight master face MASTER at the nodal positions x.
    Returns n, t (slave normal, tangent), D[j], M[j][l]."""
    xa, xb = x[SLAVE[0]], x[SLAVE[1]]
    e = (xb[0] - xa[0], xb[1] - xa[1])
    L = (e[0] ** 2 + e[1] ** 2) ** 0.5
    # outward normal of the lower block's top: the face runs 3 -> 4 counter-
    # clockwise, i.e. against e; outward = right of (xa - xb) = (-e_y, e_x).
    n = (-e[1] / L, e[0] / L)
    t = (n[1], -n[0])                       # (1, 0) on the reference interface
    # master nodes projected along n onto the slave line: parameters s in [0, 1]
    s = [((x[m][0] - xa[0]) * e[0] + (x[m][1] - xa[1]) * e[1]) / L ** 2 for m in MASTER]
    lo, hi = max(0.0, min(s)), min(1.0, max(s))
    if hi <= lo:
        return n, t, [0.0, 0.0], [[0.0, 0.0], [0.0, 0.0]]
    gauss = [(-(3 / 5) ** 0.5, 5 / 9), (0.0, 8 / 9), ((3 / 5) ** 0.5, 5 / 9)]

    def points(a, b):
        return [((a + b) / 2 + (b - a) / 2 * q, w * (b - a) / 2 * L) for q, w in gauss]

    # dual basis Phi_j = sum_k A_jk N_k, A = De Me^-1 on the face (or on the overlap)
    a, b = (0.0, 1.0) if whole_face_dual else (lo, hi)
    De, Me = [0.0, 0.0], [[0.0, 0.0], [0.0, 0.0]]
    for sp, w in points(a, b):
        N = (1 - sp, sp)
        for j in range(2):
            De[j] += w * N[j]
            for k in range(2):
                Me[j][k] += w * N[j] * N[k]
    det = Me[0][0] * Me[1][1] - Me[0][1] * Me[1][0]
    Mi = [[Me[1][1] / det, -Me[0][1] / det], [-Me[1][0] / det, Me[0][0] / det]]
    A = [[De[j] * Mi[j][k] for k in range(2)] for j in range(2)]
    D, Mm = [0.0, 0.0], [[0.0, 0.0], [0.0, 0.0]]
    for sp, w in points(lo, hi):
        N = (1 - sp, sp)
        Phi = [A[j][0] * N[0] + A[j][1] * N[1] for j in range(2)]
        eta = (sp - s[0]) / (s[1] - s[0])          # master parameter (affine map)
        Nm = (1 - eta, eta)
        for j in range(2):
            D[j] += w * Phi[j]                         # row-sum form
            for l in range(2):
                Mm[j][l] += w * Phi[j] * Nm[l]
    return n, t, D, Mm


# ---------------------------------------------------------------- one load step
def contact_rows(j, n, t, D, Mm):
    """Rows n.(D_j u_j - sum_l M_jl u_l) and t.(...) over the 16 DoFs."""
    rn, rt = zeros(NDOF), zeros(NDOF)
    for d in (0, 1):
        rn[2 * SLAVE[j] + d] += D[j] * n[d]
        rt[2 * SLAVE[j] + d] += D[j] * t[d]
        for l in range(2):
            rn[2 * MASTER[l] + d] -= Mm[j][l] * n[d]
            rt[2 * MASTER[l] + d] -= Mm[j][l] * t[d]
    return rn, rt


def solve_step(K, prescribed, u_old, mu, ops, inertia=None):
    """All consistent contact states of one step.
    prescribed: {dof: value}; ops = (n, t, D, Mm), fixed in the step (the
    weighted gap n.(sum_l M_jl (X_l + u_l) - D_j (X_j + u_j)) is then affine
    in u); inertia = (Meff, f_in): Meff u is added to K u, f_in to the load.
    Returns a list of (states, u, lam, gaps, slips)."""
    n, t, D, Mm = ops
    rows = [contact_rows(j, n, t, D, Mm) for j in range(2)]
    # weighted gap of node j times D_j: n.(sum_l M_jl x_l - D_j x_j)
    # = n.(sum_l M_jl X_l - D_j X_j) - rn . u
    g0 = []
    for j in range(2):
        v = [sum(Mm[j][l] * X[MASTER[l]][d] for l in range(2)) - D[j] * X[SLAVE[j]][d]
             for d in (0, 1)]
        g0.append(n[0] * v[0] + n[1] * v[1])
    Kt = [row[:] for row in K]
    f = zeros(NDOF)
    if inertia:
        Meff, f_in = inertia
        for i in range(NDOF):
            for k in range(NDOF):
                Kt[i][k] += Meff[i][k]
            f[i] += f_in[i]
    choices = ["inactive", "stick", "slip+", "slip-"] if mu is not None else ["inactive", "active"]
    found = []
    for states in itertools.product(choices, repeat=2):
        nz = NDOF + 4
        A, b = zeros(nz, nz), zeros(nz)
        for i in range(NDOF):
            if i in prescribed:
                A[i][i], b[i] = 1.0, prescribed[i]
                continue
            A[i][:NDOF] = Kt[i][:]
            b[i] = f[i]
            # contact force on the DoF: sum_j (rn_j n + rt_j t)-weighted lambda;
            # force on slave DoF = D_j lambda_j, on master DoF = -M_jl lambda_j,
            # i.e. the transpose of the rows in the Cartesian basis
            for j in range(2):
                for d in (0, 1):
                    # coefficient of lambda_j[d] in the force on DoF i
                    node, comp = divmod(i, 2)
                    if comp != d:
                        continue
                    if node == SLAVE[j]:
                        A[i][NDOF + 2 * j + d] -= D[j]
                    for l in range(2):
                        if node == MASTER[l]:
                            A[i][NDOF + 2 * j + d] += Mm[j][l]
        for j, s in enumerate(states):
            r0, r1 = NDOF + 2 * j, NDOF + 2 * j + 1
            rn, rt = rows[j]
            if s == "inactive":
                A[r0][r0], A[r1][r1] = 1.0, 1.0
                continue
            A[r0][:NDOF], b[r0] = rn[:], g0[j]                 # weighted gap = 0
            if s == "stick":                                   # no slip increment
                A[r1][:NDOF] = rt[:]
                b[r1] = sum(a * v for a, v in zip(rt, u_old))
            else:                                              # t.lam = -sgn mu p = sgn mu n.lam
                sg = {"active": 0.0, "slip+": 1.0, "slip-": -1.0}[s]
                m = mu or 0.0
                A[r1][r0], A[r1][r1] = t[0] - sg * m * n[0], t[1] - sg * m * n[1]
        try:
            z = solve(A, b)
        except ZeroDivisionError:
            continue
        u, lam = z[:NDOF], [(z[NDOF + 2 * j], z[NDOF + 2 * j + 1]) for j in range(2)]
        ok, gaps, slips = True, [], []
        for j, s in enumerate(states):
            rn, rt = rows[j]
            gap = (g0[j] - sum(a * v for a, v in zip(rn, u))) / D[j]
            xi = sum(a * (v - w) for a, v, w in zip(rt, u, u_old)) / D[j]
            p = -(n[0] * lam[j][0] + n[1] * lam[j][1])
            lt = t[0] * lam[j][0] + t[1] * lam[j][1]
            gaps.append(gap)
            slips.append(xi)
            tol_g, tol_p = 1e-12, 1e-9 * (abs(p) + 1e-30) + 1e-300
            if s == "inactive":
                ok &= gap >= -tol_g
            else:
                ok &= p >= -tol_p
                if s == "stick":
                    ok &= abs(lt) <= (mu or 0.0) * p * (1 + 1e-12) + 1e-300
                elif s == "slip+":
                    ok &= xi >= -1e-15
                elif s == "slip-":
                    ok &= xi <= 1e-15
        if ok:
            found.append((states, u, lam, gaps, slips))
    return found


# ---------------------------------------------------------------- drivers
def dirichlet(top, scale):
    """Nodes 1, 2 clamped; nodes 7, 8 displaced by scale * top."""
    pres = {0: 0.0, 1: 0.0, 2: 0.0, 3: 0.0}
    for node in (6, 7):
        pres[2 * node], pres[2 * node + 1] = scale * top[0], scale * top[1]
    return pres


def check_unique(found, where):
    """Several consistent state combinations are accepted only when they give
    the same displacement (a node exactly at zero gap and zero pressure, or
    exactly at the stick limit, satisfies two state sets)."""
    if not found:
        raise RuntimeError("%s: no consistent state combination" % where)
    u0 = found[0][1]
    scale = max(abs(v) for v in u0)
    for f in found[1:]:
        if max(abs(a - b) for a, b in zip(f[1], u0)) > 1e-12 * scale:
            raise RuntimeError("%s: %d consistent states with different displacements" %
                               (where, len(found)))


def run_static(K, top, mu, steps):
    u = zeros(NDOF)
    ops = mortar(X)
    for k in range(1, steps + 1):
        found = solve_step(K, dirichlet(top, k / steps), u, mu, ops)
        check_unique(found, "step %d" % k)
        states, u, lam, gaps, slips = found[0]
    return found, u, lam, gaps, slips, states


def run_dynamic(K, Mass, top, mu, dt, alpha_m=-0.3, newmark_beta=0.25, updated=False,
                top_preset=True):
    """One Bossak step of dt from rest (v_n = a_n = 0), Kratos' default scheme:
    beta = newmark_beta (1 - alpha_m)^2, inertia M ((1 - alpha_m) a_n+1 + alpha_m a_n)
    with a_n+1 = (u - u_n) / (beta dt^2); u_n = 0 except, with top_preset, at
    the top nodes, which Kratos has already moved to their imposed value at
    t = 0 (so they do not accelerate in the step). updated: mortar operators
    on X + u, iterated to a fixed point."""
    beta = newmark_beta * (1 - alpha_m) ** 2
    c0 = (1 - alpha_m) / (beta * dt ** 2)
    Meff = [[c0 * m for m in row] for row in Mass]
    u_old = zeros(NDOF)
    if top_preset:              # u_n of nodes 7, 8 = the imposed value already
        for i, v in dirichlet(top, 1.0).items():
            u_old[i] = v
    f_in = matvec(Meff, u_old)  # M (1 - alpha_m) a_n+1 = Meff (u - u_n)
    u = u_old
    for it in range(100):
        x = [(X[i][0] + u[2 * i], X[i][1] + u[2 * i + 1]) for i in range(8)] if updated else X
        ops = mortar(x, whole_face_dual=not updated)
        found = solve_step(K, dirichlet(top, 1.0), u_old, mu, ops, inertia=(Meff, f_in))
        check_unique(found, "Bossak step")
        u_new = found[0][1]
        change = max(abs(a - b) for a, b in zip(u_new, u))
        u = u_new
        if not updated or change < 1e-15:
            break
    states, u, lam, gaps, slips = found[0]
    return found, u, lam, gaps, slips, states, ops


def table(title, found, u, lam, gaps, slips, states, ref=None):
    print("%s\n  consistent state combinations: %d; slave node 4: %s, node 3: %s" %
          (title, len(found), states[0], states[1]))
    for node in (3, 4, 5, 6):
        i = node - 1
        line = "  node %d (%g, %g): u_x = %+.10e  u_y = %+.10e" % (node, X[i][0], X[i][1],
                                                               u[2 * i], u[2 * i + 1])
        if ref:
            r = ref["NODE_%d" % node]
            line += "   Kratos %+.6e %+.6e" % (r["DISPLACEMENT_X"][0], r["DISPLACEMENT_Y"][0])
        print(line)
    for j, node in enumerate((4, 3)):
        print("  slave node %d: traction (%+.6e, %+.6e), gap %+.3e, slip increment %+.6e" %
              (node, lam[j][0], lam[j][1], gaps[j], slips[j]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=40, help="load steps of case (c)")
    args = parser.parse_args()
    folder = os.path.join(DATA, "ALM_frictional_2D_hyper_simple_patch_test")
    params = json.load(open(os.path.join(folder, "hyper_simple_patch_test_parameters.json")))
    mat = json.load(open(os.path.join(folder, "hyper_simple_patch_test_materials.json")))
    ref = json.load(open(os.path.join(folder, "hyper_simple_patch_test_results.json")))
    var = mat["properties"][0]["Material"]["Variables"]
    E, nu, rho, mu = (var["YOUNG_MODULUS"], var["POISSON_RATIO"], var["DENSITY"],
                      var["FRICTION_COEFFICIENT"])
    top = next(p["Parameters"]["value"][:2] for p in params["processes"]["constraints_process_list"]
               if p["Parameters"]["model_part_name"].endswith("IMPOSE_DISP_Auto1"))
    dt = params["solver_settings"]["time_stepping"]["time_step"]
    end = params["problem_data"]["end_time"]
    print("Kratos scene: E = %g, nu = %g, rho = %g, mu = %g, top displacement %s, "
          "solver %s, dt = %g, end time %g -> %d step(s), stored TIME %s" %
          (E, nu, rho, mu, top, params["solver_settings"]["solver_type"], dt, end,
           -int(-end // dt), ref["TIME"]))
    K, Mass = bulk_matrices(E, nu, rho)

    twin = json.load(open(os.path.join(DATA, "ALM_frictionless_2D_hyper_simple_patch_test",
                                       "hyper_simple_patch_test_results.json")))
    table("(a0) sanity: frictionless twin scene (top (0, -0.01)), static, 1 step",
          *run_static(K, (0.0, -0.01), None, 1), ref=twin)
    table("(a) frictionless, Kratos' frictional load, static, 1 step",
          *run_static(K, top, None, 1), ref=ref)
    table("(b) mu = %g, static, 1 step  [our model: alm frictional, small kinematics]" % mu,
          *run_static(K, top, mu, 1), ref=ref)
    table("(c) mu = %g, static, %d load steps (linear ramp)" % (mu, args.steps),
          *run_static(K, top, mu, args.steps), ref=ref)
    res = run_dynamic(K, Mass, top, mu, dt)
    table("(d) mu = %g, one Bossak step of %g from rest (top preset), reference-configuration "
          "mortar" % (mu, dt), *res[:6], ref=ref)
    res = run_dynamic(K, Mass, top, mu, dt, updated=True)
    table("(e) as (d), mortar operators, normal and gap on X + u (Kratos' model, Coulomb slip)",
          *res[:6], ref=ref)
    ratio = analyse_kratos(K, Mass, top, dt, ref)
    # slip along -t: the "slip-" state imposes t.lambda = mu p, so mu = ratio (< 0)
    res = run_dynamic(K, Mass, top, ratio, dt, updated=True)
    table("(g) as (e), tangential traction t.lambda = %.5f p (the ratio Kratos' result implies) "
          "instead of Coulomb's" % ratio, *res[:6], ref=ref)
    u = res[1]
    print("  (g) largest |u - u_Kratos| = %.2e" % max(
        abs(u[2 * (n - 1) + c] - ref["NODE_%d" % n]["DISPLACEMENT_" + "XY"[c]][0])
        for n in (3, 4, 5, 6) for c in (0, 1)))


def analyse_kratos(K, Mass, top, dt, ref, alpha_m=-0.3, newmark_beta=0.25):
    """(f): the nodal forces that Kratos' stored displacements imply."""
    u, un = dirichlet(top, 1.0), dirichlet(top, 1.0)
    u = [u.get(i, 0.0) for i in range(NDOF)]
    un = [un.get(i, 0.0) if i >= 12 else 0.0 for i in range(NDOF)]
    for node in (3, 4, 5, 6):
        for c in (0, 1):
            u[2 * (node - 1) + c] = ref["NODE_%d" % node]["DISPLACEMENT_" + "XY"[c]][0]
    fk = matvec(K, u)
    fm = matvec(Mass, [a - b for a, b in zip(u, un)])
    beta = newmark_beta * (1 - alpha_m) ** 2
    print("(f) Kratos' stored displacements: interface forces f = K u + c0 M (u - u_n)")
    for comp in (0, 1):
        sk = sum(fk[2 * (n - 1) + comp] for n in (3, 4, 5, 6))
        sm = sum(fm[2 * (n - 1) + comp] for n in (3, 4, 5, 6))
        print("  %s: the interface forces cancel (action = reaction) for c0 dt^2 = %.5f; "
              "Bossak (1 - alpha_m) / beta = %.5f; static (c0 = 0) leaves %.3e" %
              ("xy"[comp], -sk / sm * dt ** 2, (1 - alpha_m) / beta, sk))
    c0 = (1 - alpha_m) / (beta * dt ** 2)
    f = [a + c0 * b for a, b in zip(fk, fm)]
    x = [(X[i][0] + u[2 * i], X[i][1] + u[2 * i + 1]) for i in range(8)]
    n, t, D, Mm = mortar(x, whole_face_dual=False)
    lam = [(f[2 * s] / D[j], f[2 * s + 1] / D[j]) for j, s in enumerate(SLAVE)]
    ratios = []
    for j, s in enumerate(SLAVE):
        p = -(n[0] * lam[j][0] + n[1] * lam[j][1])
        lt = t[0] * lam[j][0] + t[1] * lam[j][1]
        gap = sum(n[d] * (sum(Mm[j][l] * x[MASTER[l]][d] for l in range(2)) - D[j] * x[s][d])
                  for d in (0, 1)) / D[j]
        ratios.append(lt / p)
        print("  slave node %d: force (%+.6e, %+.6e), p = %.6e, t.lambda / p = %+.5f, "
              "gap on X + u = %+.1e" % (s + 1, f[2 * s], f[2 * s + 1], p, lt / p, gap))
    for l, m in enumerate(MASTER):
        pred = [-sum(Mm[j][l] * lam[j][d] for j in range(2)) for d in (0, 1)]
        print("  master node %d: force (%+.6e, %+.6e), -sum_j M_jl lambda_j on X + u = "
              "(%+.6e, %+.6e)" % (m + 1, f[2 * m], f[2 * m + 1], pred[0], pred[1]))
    print("  slip of the slave relative to the master is along -t (t = (%.5f, %.5f)): Coulomb "
          "needs t.lambda / p = +%g; Kratos' state has %+.5f (%.2f mu, along the slip)" %
          (t[0], t[1], 0.01, sum(ratios) / 2, sum(ratios) / 2 / 0.01))
    return sum(ratios) / 2


if __name__ == "__main__":
    main()
