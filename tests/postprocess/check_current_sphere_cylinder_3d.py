#!/usr/bin/env python3
"""Curved 3D faces on the current configuration with an answer that is not
plane (issue 29): checks that do not depend on stored numbers.

Usage: check_current_sphere_cylinder_3d.py CONTACT_FEM SCENE.prm MESH_SCRIPT MODE
       [EXPECTED NUMDIFF NORMALIZE_PL]

SCENE is tests/scenes/current_kinematics_sphere_cylinder_3d_01.prm (a
neo-Hookean block with a spherical bottom pressed by 0.05 onto a neo-Hookean
block with a cylindrical top whose axis is turned by 30 degrees from x,
then its top slid along x by 0.5, then along y by 0.5; Q1 on the quadratic
mapping: 9-node curved contact faces; alm frictional, coulomb 0.3),
MESH_SCRIPT meshes/sphere_on_cylinder_3d.py (its mesh, turned for the
objectivity check). Every run: Newton relative tolerance 1e-10.

MODE 'frictionless' (alm frictionless):
1. path independence: the top driven x then y (3 steps), y then x (3 steps)
   and along the diagonal (2 steps) ends in the same state: the reactions of
   the slave's top and the master's bottom and the pair's contact force of
   the three runs agree to 1e-8 of |F_n| (Newton's tolerance; the equations
   of a load step on the current configuration hold no history: operators,
   pairs and active set are those of the iterate). The same runs with
   `Kinematics = updated` (operators of the step's start) must differ by
   more than 100 times that, or the check could not see operators that
   follow the path (printed).
2. every step converges; Newton quadratic once the active set has settled
   (r_k <= 10 r_(k-1)^2 in every run); global balance at every step: the
   reaction on the slave's top, on the master's bottom and the pair's force
   one force to 1e-8 of |F_n|.

MODE 'frictional' (the scene as it is):
0. with EXPECTED (the scene test's stored output), the scene's perturbed
   twin: the run on DoFs renumbered by seed 1 prints EXPECTED (normalize.pl,
   then numdiff as tests/run_perturbed.sh);
3. the same Newton and balance checks;
4. at t = 2 and t = 3 every active node slips (no stick); at t = 3, per
   active node of pressure_profile.csv, the tangential traction opposes the
   node's slip increment and |t_j| = mu p_j: |t_j + mu p_j s_j / |s_j||
   below 1e-8 of mu max p (the alm imposes the Coulomb law exactly; no
   regularisation); the pair's tangential force points against the slide
   (x at t = 2, y at t = 3) within 25 degrees (the curved faces tilt it),
   and turns by more than 60 degrees between the two;
5. objectivity: the whole scene turned about the origin by a rotation R of
   50 degrees about the axis (1, 2, 3) (mesh, manifolds and prescribed
   displacements; the fixed support is the same): the same active, stick
   and slip counts at every step, and R^T F of every reaction and pair
   force equal to the unturned run's to 1e-8 of |F_n|; at t = 3 per node
   the same active flags, p_j and R^T t_j to 1e-8 of max p.

CONTACT_FEM_PERTURBATION_SEED, if set, renumbers the DoFs.
"""
import importlib.util
import math
import os
import sys

from scene_run import (check_quadratic, converged_sets, csv_numbers, newton_table, perturbation,
                       prints_stored_output, run_scene, twin_renumbering)

TOLERANCE = 1e-8
MU = 0.3
PRESS = "-0.05*min(t,1)"


def ramp(start):
    return f"0.5*min(max(t-{start},0),1)"


# (x, y, z) of the top's displacement, end time (= number of steps)
PATHS = {"x then y": ((ramp(1), ramp(2), PRESS), 3),
         "y then x": ((ramp(2), ramp(1), PRESS), 3),
         "diagonal": ((ramp(1), ramp(1), PRESS), 2)}


def report(name, good, detail=""):
    print(f"{name}: {'ok' if good else 'FAILED'}" + (f" ({detail})" if detail else ""))
    return good


def vector(row, prefix):
    return [row[f"{prefix}_{c}"] for c in "xyz"]


FORCES = ("boundary_1", "boundary_2", "pair_3_4_normal", "pair_3_4_tangential")


def rotation():
    """50 degrees about (1, 2, 3) (Rodrigues)."""
    n = [1.0, 2.0, 3.0]
    s = math.sqrt(sum(x * x for x in n))
    n = [x / s for x in n]
    a = math.radians(50.0)
    c, s = math.cos(a), math.sin(a)
    K = [[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]]
    return [[(1 - c) * n[i] * n[j] + (c if i == j else 0.0) + s * K[i][j] for j in range(3)]
            for i in range(3)]


def back(R, v):
    return [sum(R[i][j] * v[i] for i in range(3)) for j in range(3)]


def run(contact_fem, scene, path, extra=(), R=None, mesh_script=None):
    motion, end = PATHS[path]
    if R is None:
        driven = [f"1: {c} = {e}" for c, e in zip("xyz", motion)]
    else:
        driven = [f"1: {c} = " + " + ".join(f"({R[i][j]!r})*({motion[j]})" for j in range(3))
                  for i, c in enumerate("xyz")]
    settings = [*extra, *perturbation(), f"Load stepping/End time={end}",
                f"Load stepping/Number of load steps={end}",
                "Boundary conditions/Prescribed displacement=" + "; ".join(driven)]
    if R is not None:
        manifolds = mesh_script.write(os.path.abspath("turned.msh"), R)
        settings += [f"Geometry/Mesh file={os.path.abspath('turned.msh')}", f"Geometry/Manifolds={manifolds}"]
    output = run_scene(contact_fem, scene, *settings)
    return output, csv_numbers("results/forces.csv"), csv_numbers("results/pressure_profile.csv")


def newton_and_balance(name, output, rows, steps):
    table = newton_table(output)
    ok = report(f"{name}: {steps} load steps, each converged at the first attempt",
                len(table) == steps and all(c for _, c in table))
    ok = check_quadratic(name, output, 10.0) and ok
    for ratios, _ in table:
        print("    displacement ratios: " + ", ".join("-" if r is None else f"{r:.1e}"
                                                     for r in ratios))
    worst = 0.0
    for r in rows:
        pair = [a + b for a, b in zip(vector(r, "pair_3_4_normal"), vector(r, "pair_3_4_tangential"))]
        scale = math.sqrt(sum(x * x for x in vector(r, "pair_3_4_normal")))
        worst = max(worst, max(abs(a + b) for a, b in zip(vector(r, "boundary_1"), pair)) / scale,
                    max(abs(a - b) for a, b in zip(vector(r, "boundary_2"), pair)) / scale)
    return report(f"{name}: reactions of top and bottom = the pair's force at every step",
                  worst < TOLERANCE, f"largest difference {worst:.1e} of |F_n|") and ok


def final_difference(a, b):
    scale = math.sqrt(sum(x * x for x in vector(a, "pair_3_4_normal")))
    return max(math.dist(vector(a, f), vector(b, f)) for f in FORCES) / scale


def frictionless(contact_fem, scene):
    ok, final = True, {}
    for kinematics in ("current", "updated"):
        for path in PATHS:
            # updated: the small-strain range check refuses its answer (it
            # is a comparison only)
            extra = ("Contact/Formulation=alm frictionless", "Contact/Friction=",
                     f"Contact/Kinematics={kinematics}",
                     "Model range/Accept results outside the small-strain range=true")
            output, rows, _ = run(contact_fem, scene, path, extra)
            if kinematics == "current":
                ok = newton_and_balance(f"frictionless, {path}", output, rows,
                                        PATHS[path][1]) and ok
            final[kinematics, path] = rows[-1]
    reference = final["current", "x then y"]
    print("frictionless, x then y, at t = 3: " + ", ".join(
        f"{f} ({', '.join(f'{x:.9g}' for x in vector(reference, f))})" for f in FORCES[:3]))
    for kinematics in ("current", "updated"):
        differences = [final_difference(final[kinematics, "x then y"], final[kinematics, p])
                       for p in ("y then x", "diagonal")]
        detail = (f"y then x {differences[0]:.1e}, diagonal {differences[1]:.1e} of |F_n| "
                  f"from x then y")
        if kinematics == "current":
            ok = report("frictionless, current: the three paths end in the same forces "
                        f"(bound {TOLERANCE:g})", max(differences) < TOLERANCE, detail) and ok
        else:
            ok = report("frictionless, updated (operators of each step's start): the paths "
                        f"differ by more than {100 * TOLERANCE:g}",
                        min(differences) > 100 * TOLERANCE, detail) and ok
    return ok


def angle(u, v):
    c = sum(a * b for a, b in zip(u, v)) / math.sqrt(sum(a * a for a in u) * sum(b * b for b in v))
    return math.degrees(math.acos(max(-1.0, min(1.0, c))))


def same_as_stored(output, twin):
    """The scene's perturbed twin, run here (scene_run.prints_stored_output)."""
    good = prints_stored_output(output, twin)
    return report("Coulomb, x then y, on renumbered DoFs: the scene's stored output "
                  "(numdiff as the perturbed twins)", good, "" if good else "see diff and output")


def frictional(contact_fem, scene, mesh_script, twin=None):
    # With twin, the run is renumbered (seed 1, or the environment's) and
    # must print the scene's stored output: the scene's perturbed twin.
    renumbered = twin_renumbering(twin)
    output, rows, nodes = run(contact_fem, scene, "x then y", renumbered)
    ok = same_as_stored(output, twin) if twin else True
    ok = newton_and_balance("Coulomb, x then y", output, rows, 3) and ok
    sets = converged_sets(output)
    ok = report("Coulomb: every active node slips at t = 2 and 3",
                len(sets) == 3 and all(s[1] == 0 and s[2] == s[0] > 0 for s in sets[1:]),
                f"(active, stick, slip) per step {sets}") and ok
    active = [n for n in nodes if n["active"] == 1]
    scale = MU * max(n["pressure"] for n in active)
    worst = 0.0
    for n in active:
        s, t = vector(n, "slip_increment"), vector(n, "tangential_traction")
        length = math.sqrt(sum(x * x for x in s))
        worst = max(worst, math.dist(t, [-MU * n["pressure"] * x / length for x in s]) / scale)
    ok = report("Coulomb, t = 3: per active node t_j = -mu p_j s_j / |s_j|",
                len(active) > 0 and worst < TOLERANCE,
                f"{len(active)} nodes, largest difference {worst:.1e} of mu max p") and ok
    turns = [vector(r, "pair_3_4_tangential") for r in rows[1:]]
    against = [angle(turns[0], (-1, 0, 0)), angle(turns[1], (0, -1, 0))]
    ratios = [math.sqrt(sum(x * x for x in v)) /
              math.sqrt(sum(x * x for x in vector(r, "pair_3_4_normal")))
              for v, r in zip(turns, rows[1:])]
    ok = report("Coulomb: the pair's tangential force against the slide (-x at t = 2, -y at "
                "t = 3) within 25 degrees, turned by more than 60 degrees",
                max(against) < 25 and angle(*turns) > 60,
                f"angles {against[0]:.2f}, {against[1]:.2f}; turned by {angle(*turns):.2f}; "
                f"|F_t| / |F_n| {ratios[0]:.6f}, {ratios[1]:.6f}") and ok

    R = rotation()
    turned_output, turned_rows, turned_nodes = run(contact_fem, scene, "x then y", R=R,
                                                   mesh_script=mesh_script)
    turned_sets = converged_sets(turned_output)
    ok = report("turned: the same (active, stick, slip) at every step", turned_sets == sets,
                f"{turned_sets}") and ok
    per_step = []
    for a, b in zip(rows, turned_rows):
        scale_n = math.sqrt(sum(x * x for x in vector(a, "pair_3_4_normal")))
        per_step.append(max(math.dist(vector(a, f), back(R, vector(b, f))) for f in FORCES) /
                        scale_n)
    ok = report(f"turned: R^T F of the reactions and pair forces equal to {TOLERANCE:g} of |F_n|",
                len(per_step) == 3 and max(per_step) < TOLERANCE,
                "per step " + ", ".join(f"{e:.1e}" for e in per_step)) and ok

    # The nodes by their reference positions (R^T X of the turned run; the
    # file prints 10 digits, so the nearest one within 1e-6).
    pmax = max(n["pressure"] for n in nodes)
    flags, pressure, traction = len(turned_nodes) == len(nodes), 0.0, 0.0
    for n in turned_nodes:
        X = back(R, vector(n, "reference"))
        m = min(nodes, key=lambda m: math.dist(vector(m, "reference"), X))
        if math.dist(vector(m, "reference"), X) > 1e-6:
            flags = False
            continue
        flags = flags and n["active"] == m["active"]
        pressure = max(pressure, abs(n["pressure"] - m["pressure"]) / pmax)
        traction = max(traction, math.dist(vector(m, "tangential_traction"),
                                           back(R, vector(n, "tangential_traction"))) / pmax)
    ok = report(f"turned, t = 3: per node the same active flags, p_j and R^T t_j to {TOLERANCE:g} "
                "of max p", flags and pressure < TOLERANCE and traction < TOLERANCE,
                f"p off {pressure:.1e}, t off {traction:.1e}") and ok
    return ok


def main():
    contact_fem, scene, script, mode = sys.argv[1:5]
    twin = sys.argv[5:8] if len(sys.argv) >= 8 else None
    sys.dont_write_bytecode = True  # no __pycache__ in the source tree's meshes/
    spec = importlib.util.spec_from_file_location("sphere_on_cylinder_3d", script)
    mesh_script = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mesh_script)
    ok = frictionless(contact_fem, scene) if mode == "frictionless" else \
        frictional(contact_fem, scene, mesh_script, twin)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
