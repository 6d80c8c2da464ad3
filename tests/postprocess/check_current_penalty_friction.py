#!/usr/bin/env python3
"""'penalty frictional' on the current configuration (Contact/Kinematics =
current).

Usage: check_current_penalty_friction.py CONTACT_FEM SCENE_2D.prm SCENE_3D.prm
       [EXPECTED_3D NUMDIFF NORMALIZE_PL]

SCENE_2D is tests/scenes/current_kinematics_penalty_friction_01.prm: a
neo-Hookean block pressed by 25 % onto a non-matching one and pulled along
x until it slides, mu = 0.3, automatic penalties. From forces.csv and the
Newton tables:

- every step converges without a split, Newton's displacement ratios fall
  quadratically (r_k <= 10 r_(k-1)^2 once r_(k-1) <= 0.1, over the
  iterations without set changes): the tangent holds the derivatives of
  the operators, of the objective slip, of the transported history
  traction and of the pressure eps_n (-G_j) / D_j in the slip bound;
- at least two steps have every active node slipping, and there the
  pair's |F_t| = 0.3 |F_n| to 1e-8 (F_n = sum_j D_j p_j n_j, F_t = sum_j
  D_j t_j tau_j: exact in 2D, where tau_j is n_j turned, once every t_j =
  mu p_j one way; the top's reaction F_x / F_y is 2e-4 off, since the
  slave normals tilt by about 1e-4 with the penetration p / eps_n, varying
  from node to node);
- at least two pull steps have every active node sticking, with 0 < |F_t|
  < 0.3 |F_n|.

And the stick nodes move by the penalty's elastic slip, the model's exact
answer: on a rigid flat master (the lower top held in x and y) the
objective slip of slave node j is xi_j = D_j^n / D_j (x_j - x_j^n) . tau,
and a stick node carries t_j = t_j^n - eps_t xi_j, so over a load step it
moves by x_j - x_j^n = (D_j / D_j^n) (t_j^n - t_j) / eps_t. The scene is
run to t = 1.25 and to t = 1.5 (the same steps of 0.25); for every interior
node that sticks at t = 1.5 (D_j from the current positions: half the
lengths of its two slave faces) the move must match to 1e-3 of the
largest move (the profile's 10 digits of x near x = 4 resolve 5e-10, 2.6e-4
of the moves of 1.9e-6), and |t_j| < mu p_j.

SCENE_3D is tests/scenes/current_kinematics_penalty_friction_3d_01.prm: a
block pressed by 22 % on a rigid base (two steps), pulled at 30 degrees by
0.03 (t = 3) and by 0.125 more (t = 4):

- every step converges without a split; in the full-slip step Newton is
  quadratic (C = 10); in the steps where nodes stick and slip the rim's slip
  nodes lie just outside the cone (T / |t*| near 1), where the slip
  direction t* / |t*| turns sharply under the stiff penalty: the contraction
  is there that of Contact/Kinematics = small on the same steps (its
  contact terms linear in u, only the return mapping curved), so each
  step must take the same iterations as the small path, and each quadratic
  constant r_k / r_(k-1)^2 (r_(k-1) <= 0.1, no set change) be within a
  factor 2 of the small path's (measured: 4.9 and 36 in the first step,
  2.6e3 in the third, a linear error in the tangent would leave r_k /
  r_(k-1) constant instead);
- t = 4: every active node slips, |t_j| = mu p_j to 1e-8 (of the largest
  mu p), t_j against the node's slip, and 0 < |F_t| / F_n <= mu;
- t = 3 (step 3 of the same run: its contact-surface VTU, the same 10
  digits as the pressure profile of a run that ends there): stick nodes
  inside the cone (|t_j| < mu p_j), slip nodes on it to 1e-8, 0 < |F_t| /
  F_n < mu.

With EXPECTED_3D (the 3D scene test's stored output) the 3D run is the
scene's perturbed twin: it runs on DoFs renumbered by seed 1 and must print
EXPECTED_3D (normalize.pl, then numdiff as tests/run_perturbed.sh; writing
the VTU and the pressure profile changes no line of the console).
"""
import csv
import json
import math
import shutil
import sys

from scene_run import (check_quadratic, converged_sets, newton_ratios, prints_stored_output,
                       run_scene, twin_renumbering)
from vtu_files import active_nodes, collection, read_surface

MU = 0.3


def report(name, good, detail):
    print(f"{name}: {'ok' if good else 'FAILED'} ({detail})")
    return good


def forces():
    with open("results/forces.csv") as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def profile():
    with open("results/pressure_profile.csv") as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def tangential_penalty():
    with open("results/summary.json") as f:
        return json.load(f)["cycles"][-1]["contact"]["tangential_penalty"]


def check_2d(contact_fem, scene):
    output = run_scene(contact_fem, scene)
    ok = check_quadratic("2D sliding block", output, 10.0)
    sets, reactions = converged_sets(output), forces()
    ok = report("2D: every step converged, no split",
                len(sets) == len(reactions) == output.count("  Load step ") and
                "Splitting" not in output, f"{len(reactions)} steps") and ok
    sliding, sticking = [], []
    for (active, stick, slip), r in zip(sets, reactions):
        ratio = math.hypot(r["pair_3_4_tangential_x"], r["pair_3_4_tangential_y"]) / math.hypot(
            r["pair_3_4_normal_x"], r["pair_3_4_normal_y"])
        if active > 0 and slip == active:
            sliding.append(abs(ratio - MU) / MU)
        if r["t"] > 1 and active > 0 and stick == active:
            sticking.append(ratio)
    ok = report(f"2D: steps with every active node slipping, |F_t| / |F_n| = {MU} to 1e-8",
                len(sliding) >= 2 and max(sliding) < 1e-8,
                f"{len(sliding)} steps, largest relative error {max(sliding, default=1):.1e}") and ok
    ok = report(f"2D: pull steps with every active node sticking, 0 < |F_t| / |F_n| < {MU}",
                len(sticking) >= 2 and all(1e-6 < r < MU for r in sticking),
                ", ".join(f"{r:.4f}" for r in sticking)) and ok

    def rigid_master(end_time, steps):
        run_scene(contact_fem, scene, "Output/Write pressure profile=true",
                  "Boundary conditions/Fixed=2: xy; 4: xy", f"Load stepping/End time={end_time}",
                  f"Load stepping/Number of load steps={steps}")
        return sorted(profile(), key=lambda n: n["reference_x"])

    before, after = rigid_master(1.25, 5), rigid_master(1.5, 6)
    eps_t = tangential_penalty()

    def D(nodes, j):
        return 0.5 * (math.dist((nodes[j - 1]["x"], nodes[j - 1]["y"]),
                                (nodes[j + 1]["x"], nodes[j + 1]["y"])))

    moves, errors, inside = [], [], True
    for j in range(1, len(after) - 1):
        n, m = after[j], before[j]
        if n["stick"] != 1 or n["active"] != 1 or m["active"] != 1:
            continue
        move = n["x"] - m["x"]
        elastic = D(after, j) / D(before, j) * (m["tangential_traction"] -
                                               n["tangential_traction"]) / eps_t
        moves.append(abs(move))
        errors.append(abs(move - elastic))
        inside = inside and abs(n["tangential_traction"]) < MU * n["pressure"]
    worst = max(errors, default=1.0) / max(moves, default=1.0)
    ok = report("2D rigid master, t = 1.25 -> 1.5: stick nodes move by (D / D^n) (t^n - t) / "
                "eps_t to 1e-3, inside the cone",
                len(moves) >= 3 and worst < 1e-3 and inside,
                f"{len(moves)} interior stick nodes, moves up to {max(moves, default=0):.3e}, "
                f"largest error {worst:.1e} of the largest move, eps_t {eps_t:.4g}") and ok
    return ok


def pair(row):
    """(F_n, |F_t|) of the pair (master on slave)."""
    return row["pair_3_4_normal_z"], math.hypot(row["pair_3_4_tangential_x"],
                                                 row["pair_3_4_tangential_y"])


def traction(n):
    return math.hypot(n["tangential_traction_x"], n["tangential_traction_y"])


def check_3d(contact_fem, scene, twin=None):
    write_profile = "Output/Write pressure profile=true"
    # The 2D runs' files gone first: the program would name them in the
    # output ("removed ... of an earlier run"), which the twin compares.
    shutil.rmtree("results", ignore_errors=True)
    output = run_scene(contact_fem, scene, write_profile, "Output/Write VTU=true",
                       *twin_renumbering(twin))
    ok = True
    if twin:
        good = prints_stored_output(output, twin)
        ok = report("3D on renumbered DoFs: the scene's stored output (numdiff as the perturbed "
                    "twins)", good, "the same" if good else "see diff and output")
    rows = forces()
    ok = report("3D: every step converged, no split",
                len(rows) == 4 == output.count("| converged") and "Splitting" not in output,
                f"{len(rows)} steps") and ok
    current = newton_ratios(output)
    ok = check_quadratic("3D full-slip step (t = 4)", output[output.index("  Load step 4,"):],
                         10.0) and ok
    nodes = [n for n in profile() if n["active"] == 1]
    bound = max(MU * n["pressure"] for n in nodes)
    off = max(abs(traction(n) - MU * n["pressure"]) for n in nodes) / bound
    opposed = all(n["tangential_traction_x"] * n["slip_increment_x"] +
                  n["tangential_traction_y"] * n["slip_increment_y"] < 0 for n in nodes)
    normal, tangential = pair(rows[-1])
    ok = report("3D t = 4: every active node slips, |t_j| = mu p_j to 1e-8, against its slip, "
                "0 < |F_t| / F_n <= mu",
                all(n["stick"] == 0 for n in nodes) and off < 1e-8 and opposed and
                0 < tangential / normal <= MU * (1 + 1e-12),
                f"{len(nodes)} nodes, |t| off mu p {off:.1e}, |F_t| / F_n = "
                f"{tangential / normal:.6f}") and ok

    # t = 3: step 3 of the run (the same steps as a run to t = 3).
    normal, tangential = pair(rows[2])
    _, _, surface, _ = read_surface(dict(collection("contact_surface.pvd"))[3.0])
    nodes = active_nodes(surface)
    stick = [n for n in nodes if n["stick"] == 1]
    inside = all(traction(n) < MU * n["pressure"] for n in stick)
    off = max((abs(traction(n) - MU * n["pressure"]) for n in nodes if n["stick"] == 0),
              default=0.0) / bound
    ok = report("3D t = 3: stick nodes inside the cone, slip nodes on it to 1e-8, "
                "0 < |F_t| / F_n < mu",
                0 < len(stick) < len(nodes) and inside and off < 1e-8 and
                0 < tangential / normal < MU,
                f"{len(stick)} of {len(nodes)} stick, |F_t| / F_n = {tangential / normal:.4f}") and ok

    short = ("Load stepping/End time=3", "Load stepping/Number of load steps=3")
    small = newton_ratios(run_scene(contact_fem, scene, "Contact/Kinematics=small", *short))

    def constants(ratios):
        return [b / a**2 for a, b in zip(ratios, ratios[1:])
                if a is not None and b is not None and a <= 0.1]

    # The current run's first update of a step keeps every stick node
    # sticking (PenaltyFrictional: its predictor is too far off to decide
    # the slip): one iteration more, then those of Kinematics = small.
    held = [r[1:] for r in current[:3]]
    same = [len(r) for r in held] == [len(r) for r in small]
    pairs = [(c, d) for a, b in zip(held, small)
             for c, d in zip(constants(a), constants(b))]
    ok = report("3D steps with stick and slip nodes: after the held first update the iterations "
                "of Kinematics = small, each r_k / r_(k-1)^2 within a factor 2 of its",
                same and pairs and all(0.5 < c / d < 2 for c, d in pairs),
                f"iterations {[len(r) - 1 for r in held]} and "
                f"{[len(r) - 1 for r in small]}, constants (current, small) "
                f"{', '.join(f'({c:.3g}, {d:.3g})' for c, d in pairs)}") and ok
    return ok


def main():
    contact_fem, scene_2d, scene_3d = sys.argv[1:4]
    twin = sys.argv[4:7] if len(sys.argv) >= 7 else None
    ok = check_2d(contact_fem, scene_2d)
    ok = check_3d(contact_fem, scene_3d, twin) and ok
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
