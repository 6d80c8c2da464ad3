#!/usr/bin/env python3
"""3D ironing with Coulomb friction: the energy balance of the die's work and
the pair's force ratio on the plateau (issue 29, item 4; doc/finite_strain.md,
"3D ironing under friction: the proposed clause").

The scene is prm/ironing_3d.prm (Puso and Laursen's slab 9 x 4 x 3, E = 1,
and half-cylinder die of radius 3, width 5.2, E = 1000; pressed 1.4, slid
along x by 0.25 per unit of t from x = -2) with alm frictional, coulomb
MU, stopped at x = 0.75 (t = 15), with K load steps per unit of t (K = 1:
the scene's steps). The plateau is the die's axis within 0.75 of the slab's
middle (t in [9, 15]); the balance is taken over the slide from x = -1 (t
= 8) to 0.75, i.e. over the load steps ending in (8, 15]:

    sum_n |F_x^n| dx_n = W(15) - W(8) + sum_n sum_j D_j mu p_j |s_j^n|

F_x the reaction of the die's driven top (forces.csv), W the stored energy
of both bodies (summary.json of the run and of one stopped at t = 8 with the
same steps), D_j the integral of node j's bilinear shape function over its
deformed slab-top faces (2 x 2 Gauss points; the lumped dual weight, the
same as the code's where the node's faces lie wholly under the die: their
sum over the active nodes is printed against the pair's area of
forces.csv), p_j the pressure and s_j^n the slip of the step against the
die taken as rigid, (x_j^n - x_j^(n-1) - dx_n e_x) projected onto the
tangent plane of the node's averaged face normal (contact_surface_NNN.vtu),
or the code's objective slip increment. Backward Euler: the balance closes
to first order in dx.

Also per run: the die's F_t / F_n and the pair's |T| / |N| on the plateau,
the stick nodes on the plateau, the lean of the pair's normal force and the
die's offset from mu it implies, -(1 + mu^2) N_x / (mu N_n), and the chatter
of F_n (from its least-squares parabola in x, relative to the mean).

Usage: bench/ironing/ironing_3d_energy.py [--per-unit K...] [--level L]
       [--binary B] [--out DIR]
"""

import argparse
import csv
import json
import math
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
SCENE = os.path.join(REPO, "prm", "ironing_3d.prm")
sys.path.insert(0, os.path.join(REPO, "tests", "postprocess"))
sys.path.insert(0, os.path.join(REPO, "bench", "finite_strain"))
sys.path.insert(0, os.path.join(REPO, "bench"))
from bench_run import run_or_exit  # noqa: E402
from vtu_files import read_surface  # noqa: E402
from ironing_3d import parabola_residuals  # noqa: E402

MU = 0.3
START_X, SLIDE_PER_TIME, PRESS_END = -2., 0.25, 4.
T_BEFORE, T_END, T_PLATEAU = 8., 15., 9.


def mesh(out, level):
    if level == 0:
        return []
    path = os.path.join(out, "ironing_3d.msh")
    if not os.path.exists(path):
        subprocess.run(["gmsh", "-3", "-format", "msh22", os.path.join(REPO, "meshes", "ironing_3d.geo"),
                        "-setnumber", "h", str(0.5 ** level), "-setnumber", "ny",
                        str(2 ** (level + 1)), "-o", path], check=True, capture_output=True)
    # Not refined, mapping degree 1: the cylinder manifold plays no part.
    return ["--set", f"Geometry/Mesh file={path}", "--set", "Geometry/Manifolds="]


REUSE = False   # --reuse: analyse the runs already in --out


def run(binary, out, level, end_time, steps, vtu, mu=MU):
    if REUSE and os.path.exists(os.path.join(out, "summary.json")):
        with open(os.path.join(out, "console.txt")) as f:
            return f.read(), 0.
    os.makedirs(out, exist_ok=True)
    command = [binary, SCENE] + mesh(os.path.dirname(out), level)
    law = ("Contact/Formulation=alm frictional", f"Contact/Friction=coulomb {mu}") if mu > 0 \
        else ("Contact/Formulation=alm frictionless",)
    for setting in (f"Output directory={out}", *law, f"Load stepping/End time={end_time}",
                    f"Load stepping/Number of load steps={steps}",
                    f"Output/Write VTU={'true' if vtu else 'false'}", "Output/Print timing=false"):
        command += ["--set", setting]
    return run_or_exit(command, out)


def stored_energy(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)["cycles"][-1]["strain_energy"]


def slide(t):
    return SLIDE_PER_TIME * max(t - PRESS_END, 0.)


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def step_dissipation(out, step, dx):
    """sum_j D_j mu p_j |s_j| (rigid die's slip), the same with the code's
    objective slip, the work of the whole contact traction on the slave's
    motion relative to the rigid die, -sum_j D_j t_j . d_j (d_j = x_j^n -
    x_j^(n-1) - dx e_x, not projected: it counts the normal traction's work
    on the relative normal motion too), sum_j D_j over the active nodes, and
    the largest |t_j| / (mu p_j) - 1 of the active nodes."""
    points, cells, fields, wrong = read_surface(f"contact_surface_{step:03d}.vtu", out)
    before = read_surface(f"contact_surface_{step - 1:03d}.vtu", out)[0]
    if wrong:
        sys.exit("\n".join(wrong))
    faces = [cells["connectivity"][i:i + 4] for i in range(0, len(cells["connectivity"]), 4)]
    weight = [0.] * len(points)
    normal = [[0., 0., 0.] for _ in points]
    g = 1. / math.sqrt(3.)
    for face in faces:
        x = [points[v] for v in face]   # VTK quad order: (0,0), (1,0), (1,1), (0,1)
        for xi in ((-g, -g), (g, -g), (g, g), (-g, g)):
            shape = [(1 - xi[0]) * (1 - xi[1]) / 4, (1 + xi[0]) * (1 - xi[1]) / 4,
                     (1 + xi[0]) * (1 + xi[1]) / 4, (1 - xi[0]) * (1 + xi[1]) / 4]
            d0 = [(-(1 - xi[1]) * x[0][c] + (1 - xi[1]) * x[1][c] + (1 + xi[1]) * x[2][c] -
                   (1 + xi[1]) * x[3][c]) / 4 for c in range(3)]
            d1 = [(-(1 - xi[0]) * x[0][c] - (1 + xi[0]) * x[1][c] + (1 + xi[0]) * x[2][c] +
                   (1 - xi[0]) * x[3][c]) / 4 for c in range(3)]
            n = cross(d0, d1)
            jacobian = math.sqrt(sum(v * v for v in n))
            for v, s in zip(face, shape):
                weight[v] += s * jacobian
                for c in range(3):
                    normal[v][c] += s * n[c]
    rigid = objective = traction = length = 0.
    cone = 0.
    for j, w in enumerate(weight):
        if fields["active"][j][0] != 1:
            continue
        n = normal[j]
        norm = math.sqrt(sum(v * v for v in n))
        n = [v / norm for v in n]
        d = [points[j][0] - before[j][0] - dx, points[j][1] - before[j][1],
             points[j][2] - before[j][2]]
        dn = sum(a * b for a, b in zip(d, n))
        s = math.sqrt(max(sum(v * v for v in d) - dn * dn, 0.))
        p = fields["contact_pressure"][j][0]
        xi = math.sqrt(sum(fields[f"slip_increment_{c}"][j][0] ** 2 for c in "xyz"))
        t = math.sqrt(sum(fields[f"tangential_traction_{c}"][j][0] ** 2 for c in "xyz"))
        traction -= w * sum(a * b for a, b in zip(fields["traction"][j], d))
        rigid += w * MU * p * s
        objective += w * MU * p * xi
        length += w
        cone = max(cone, abs(t / (MU * p) - 1.))
    return rigid, objective, traction, length, cone


def analyse(out, stdout):
    with open(os.path.join(out, "forces.csv")) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    sets = [(int(m.group(1)), int(m.group(2))) for m in re.finditer(
        r"\|\s*\d+\s*\|\s*(\d+)\s*\|\s*(\d+)\s*\|\s*\d+\s*\|\s*converged", stdout)]
    plateau = [k for k, r in enumerate(rows) if r["t"] >= T_PLATEAU - 1e-9]
    fn = [abs(rows[k]["boundary_1_z"]) for k in plateau]
    ratio = [math.hypot(rows[k]["boundary_1_x"], rows[k]["boundary_1_y"]) / fn[i]
             for i, k in enumerate(plateau)]
    pair = [math.sqrt(sum(rows[k][f"pair_4_3_tangential_{c}"] ** 2 for c in "xyz")) /
            math.sqrt(sum(rows[k][f"pair_4_3_normal_{c}"] ** 2 for c in "xyz")) for k in plateau]
    lean = [-rows[k]["pair_4_3_normal_x"] / abs(rows[k]["pair_4_3_normal_z"]) for k in plateau]
    lean_error = max(abs((q / MU - 1.) + (1. + MU * MU) * l / MU) for q, l in zip(ratio, lean))
    # Exactly, if T were normal to N with |T| = q |N| (q the pair's ratio) and
    # along x: the die's ratio is (q - l) / (1 + q l), l = the lean above.
    exact_error = max(abs(r - (q - l) / (1. + q * l)) / MU for r, q, l in zip(ratio, pair, lean))
    xs = [START_X + slide(rows[k]["t"]) for k in plateau]
    mean = sum(fn) / len(fn)
    stick = [sets[k][0] for k in plateau] if len(sets) == len(rows) else None
    return {"rows": rows, "plateau": plateau, "ratio": ratio, "pair": pair, "lean": lean,
            "lean_error": lean_error, "exact_error": exact_error, "F_n": mean, "stick": stick,
            "chatter": max(abs(v) for v in parabola_residuals(xs, fn)) / mean,
            "steps": stdout.count("  Load step "), "converged": stdout.count("| converged"),
            "newton": len(re.findall(r"^\s*\|\s*\d+\s*\|", stdout, re.M)) -
            stdout.count("  Load step ")}


def frictionless(args):
    """The die's work over the balance's slide against W(15) - W(8), without
    friction: what the contact forces' non-variational part leaves."""
    print("| h | slide step | die work | stored energy change | difference | difference / "
          "(mean F_n x slide) |\n|" + "---|" * 6, flush=True)
    for k in args.per_unit:
        base = os.path.join(args.out, f"frictionless_level_{args.level}_k{k}")
        full, before = os.path.join(base, "full"), os.path.join(base, "before")
        run(args.binary, full, args.level, T_END, int(T_END * k), False, mu=0.)
        run(args.binary, before, args.level, T_BEFORE, int(T_BEFORE * k), False, mu=0.)
        with open(os.path.join(full, "forces.csv")) as f:
            rows = [{key: float(v) for key, v in r.items()} for r in csv.DictReader(f)]
        work = normal = 0.
        for i, r in enumerate(rows):
            if r["t"] > T_BEFORE + 1e-9:
                dx = slide(r["t"]) - slide(rows[i - 1]["t"])
                work += r["boundary_1_x"] * dx
                normal += abs(r["boundary_1_z"]) * dx
        stored = stored_energy(full) - stored_energy(before)
        print(f"| {0.5 ** args.level} | {SLIDE_PER_TIME / k:.4g} | {work:+.5f} | {stored:+.5f} | "
              f"{work - stored:+.5f} | {(work - stored) / normal:+.2e} |", flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default=os.path.join(REPO, "build", "contact_fem"))
    parser.add_argument("--out", default="/tmp/ironing_3d_energy")
    parser.add_argument("--level", type=int, default=0,
                        help="0: the stored mesh (h = 1); L > 0: Gmsh's h = 2^-L mesh")
    parser.add_argument("--per-unit", type=int, nargs="*", default=[1, 2, 4],
                        help="load steps per unit of t (1: 0.25 of slide per step)")
    parser.add_argument("--frictionless", action="store_true",
                        help="alm frictionless: the die's work against the stored energy's "
                             "change alone (the non-variational part of the contact forces)")
    parser.add_argument("--reuse", action="store_true",
                        help="analyse the runs already in --out instead of running them")
    args = parser.parse_args()
    global REUSE
    REUSE = args.reuse
    if args.frictionless:
        frictionless(args)
        return
    print(f"# 3D ironing energy, level {args.level}, "
          f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, load {os.getloadavg()[0]:.1f}")
    print("| h | slide step | converged / attempts | Newton its | die work | stored energy change / "
          "work | imbalance, rigid die's slip | imbalance, objective slip | imbalance, the contact "
          "traction's work on the relative motion | sum D_j / pair area - 1 "
          "(max) | die F_t / F_n (plateau) | pair abs(T) / abs(N) | stick nodes | offset + (1 + "
          "mu^2) lean / mu (max) | die ratio - (q - l) / (1 + q l), / mu (max) | mean F_n | "
          "chatter of F_n | wall |\n|" + "---|" * 18, flush=True)
    for k in args.per_unit:
        base = os.path.join(args.out, f"level_{args.level}_k{k}")
        full, before = os.path.join(base, "full"), os.path.join(base, "before")
        stdout, wall = run(args.binary, full, args.level, T_END, int(T_END * k), True)
        _, wall_before = run(args.binary, before, args.level, T_BEFORE, int(T_BEFORE * k), False)
        a = analyse(full, stdout)
        rows = a["rows"]
        work = rigid = objective = traction = 0.
        weight_error, cone = 0., 0.
        for i, r in enumerate(rows):
            if r["t"] <= T_BEFORE + 1e-9:
                continue
            dx = slide(r["t"]) - slide(rows[i - 1]["t"])
            work += math.hypot(r["boundary_1_x"], r["boundary_1_y"]) * dx
            d, o, f, length, c = step_dissipation(full, int(r["step"]), dx)
            rigid, objective, traction = rigid + d, objective + o, traction + f
            weight_error = max(weight_error, abs(length / r["pair_4_3_area"] - 1.))
            cone = max(cone, c)
        stored = stored_energy(full) - stored_energy(before)
        print(f"| {0.5 ** args.level} | {SLIDE_PER_TIME / k:.4g} | {a['converged']} / {a['steps']} | "
              f"{a['newton']} | {work:.5f} | {100 * stored / work:+.3f} % | "
              f"{100 * (work - stored - rigid) / work:+.3f} % | "
              f"{100 * (work - stored - objective) / work:+.3f} % | "
              f"{100 * (work - stored - traction) / work:+.3f} % | {weight_error:.1e} | "
              f"{min(a['ratio']):.4f} to {max(a['ratio']):.4f} | {min(a['pair']):.4f} to "
              f"{max(a['pair']):.4f} | {max(a['stick']) if a['stick'] else '?'} | "
              f"{a['lean_error']:.1e} | {a['exact_error']:.1e} | {a['F_n']:.4f} | {100 * a['chatter']:.2f} % | "
              f"{wall + wall_before:.0f} s |", flush=True)
        print(f"  (largest |t_j| / (mu p_j) - 1 of the active nodes over the balance: {cone:.1e})",
              flush=True)


if __name__ == "__main__":
    main()
