#!/usr/bin/env python3
"""2D ironing with Coulomb friction: why the die's force ratio is not mu
(issue 29, item 4; doc/finite_strain.md, "2D ironing: the die's force
ratio under friction").

The scene is tests/postprocess/ironing_2d_friction.prm (a half-disc die of
radius R = 1, E = 1000, pressed into a neo-Hookean block 10 x 2, E = 1, then
slid 1.5 along x; alm frictional, coulomb MU, current kinematics), with the
indentation depth d, the block's Poisson ratio, the die's Young modulus,
mu, the global refinements and the number of load steps set on the command
line. On the sliding plateau (slide >= 0.5, as the tests) per run, from
forces.csv:

- ratio: the die's |F_x| / |F_y| (its driven top's reaction), its mean and
  offset = mean / mu - 1;
- lean: the pair's normal force on the die along the slide over F_n (the
  pressure resultant's horizontal part; > 0 pushes the die forward);
- pair: the pair's |T| / |N| (sums of D_j t_j and D_j p_j n_j);
- the contact length (sum of D_j) and the number of active slave nodes;
- chatter: max |F_y - mean| / mean and the same of the ratio.

Studies (--study):

- depth: d = 0.2, 0.1, 0.05, 0.025 on refinements 1, 2, 3 (h = 0.125,
  0.0625, 0.03125 on the block top);
- material: d = 0.1 on refinement 2, block nu = 0, 0.2, 0.3, 0.4, 0.45 and
  die E = 1000, 1e4, 1e5;
- energy: the work of the die over the plateau against the change of the
  stored energy plus the frictional dissipation sum_j D_j mu p_j |s_j|
  (D_j from the deformed slave edges of contact_surface_NNN.vtu, s_j the
  slip increment of the step), refinements 0, 1, 2 at d = 0.2;
- energy_steps: the same balance per plateau step (h = 0.25, 36 steps; W
  from a run stopped at every step);
- chatter: the die's force with 4 slide steps per block element length
  (frictionless and mu = 0.3), refinements 0, 1, 2.

Linear theory (a rigid cylinder sliding on an elastic half-plane, the
coupling of the tangential traction and the normal displacement, Johnson,
Contact Mechanics, 7.2; first order in beta mu, derived in the doc): the
pressure centroid lies behind the die's axis by e = (8 / (3 pi)) beta mu
a, beta = (1 - 2 nu) / (2 (1 - nu)); the pressure resultant then pushes
the die forward by e / R of F_n and the friction's vertical part adds mu e /
R to F_n, so the die's ratio is mu (1 - (8 / (3 pi)) beta (1 + mu^2) a /
R): printed as 'linear theory' beside each run (a = contact length / 2).

Usage: bench/ironing/ironing_2d_plough.py --study S [--binary B] [--out DIR]
"""

import argparse
import csv
import json
import math
import os
import re
import sys
import time
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "bench"))
from bench_run import run_or_exit  # noqa: E402
SCENE = os.path.join(REPO, "tests", "postprocess", "ironing_2d_friction.prm")

SLIDE_PER_TIME = 0.1875  # die top x = 0.1875 (t - 1) for t > 1
END_TIME = 9.
PLATEAU_START = 0.5
RADIUS = 1.


def beta(nu):
    """Dundurs' second constant of a rigid die on an elastic body."""
    return (1. - 2. * nu) / (2. * (1. - nu))


def run(binary, out, refinements=0, depth=0.2, nu=0.3, e_die=1000., mu=0.3, steps=36,
        vtu=False, end_time=END_TIME, frictionless=False):
    os.makedirs(out, exist_ok=True)
    settings = {
        "Output directory": out,
        "Geometry/Global refinements": refinements,
        "Boundary conditions/Prescribed displacement":
            f"die top: x = {SLIDE_PER_TIME}*max(t-1, 0); die top: y = -{depth}*min(t, 1)",
        "Materials/Young's moduli": f"{e_die}, 1",
        "Materials/Poisson's ratios": f"0.3, {nu}",
        "Load stepping/End time": end_time,
        "Load stepping/Number of load steps": steps,
        "Output/Write VTU": "true" if vtu else "false",
    }
    if frictionless:
        settings["Contact/Formulation"] = "alm frictionless"
        settings["Contact/Friction"] = ""
    else:
        settings["Contact/Friction"] = f"coulomb {mu}"
    command = [binary, SCENE]
    for key, value in settings.items():
        command += ["--set", f"{key}={value}"]
    return run_or_exit(command, out)


def plateau_rows(out):
    with open(os.path.join(out, "forces.csv")) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    return [r for r in rows
            if SLIDE_PER_TIME * max(r["t"] - 1., 0.) >= PLATEAU_START - 1e-12]


def analyse(out, stdout, mu):
    rows = plateau_rows(out)
    fx = [abs(r["boundary_1_x"]) for r in rows]
    fy = [abs(r["boundary_1_y"]) for r in rows]
    ratio = [a / b for a, b in zip(fx, fy)]
    lean = [-r["pair_4_3_normal_x"] / abs(r["pair_4_3_normal_y"]) for r in rows]
    pair = [math.hypot(r["pair_4_3_tangential_x"], r["pair_4_3_tangential_y"]) /
            math.hypot(r["pair_4_3_normal_x"], r["pair_4_3_normal_y"]) for r in rows]
    length = [r["pair_4_3_length"] for r in rows]
    mean = lambda v: sum(v) / len(v)
    chatter = lambda v: max(abs(x - mean(v)) for x in v) / abs(mean(v))
    active = [int(m.group(1)) for m in re.finditer(
        r"\|\s*\d+\s*\|[^\n]*?\|\s*(\d+)\s*\|\s*\d+\s*\|\s*\d+\s*\|[^|\n]*\| converged", stdout)]
    its = len(re.findall(r"^\s*\|\s*\d+\s*\|", stdout, re.M)) - stdout.count("  Load step ")
    steps, converged = stdout.count("  Load step "), stdout.count("| converged")
    return {
        "plateau_steps": len(rows), "steps": steps, "converged": converged, "newton": its,
        "F_y": mean(fy), "ratio": mean(ratio), "offset": mean(ratio) / mu - 1. if mu else None,
        "ratio_min": min(ratio), "ratio_max": max(ratio),
        "lean": mean(lean), "pair": mean(pair), "pair_error": max(abs(q - mu) for q in pair) / mu
        if mu else None,
        "length": mean(length), "active": (min(active[-len(rows):]), max(active[-len(rows):]))
        if active else None,
        "chatter_F_y": chatter(fy), "peak_to_peak_F_y": (max(fy) - min(fy)) / mean(fy),
        "chatter_ratio": chatter(ratio) if mu else None,
        "max_abs_ratio": max(ratio),
    }


def surface(name):
    piece = ET.parse(name).getroot().find(".//Piece")
    raw = [float(x) for x in piece.find("Points/DataArray").text.split()]
    points = [raw[i:i + 2] for i in range(0, len(raw), 3)]
    cells = {e.get("Name"): [int(x) for x in e.text.split()] for e in piece.find("Cells")}
    fields = {e.get("Name"): [float(x) for x in e.text.split()] for e in piece.find("PointData")
              if e.get("NumberOfComponents", "1") == "1"}
    return points, cells["connectivity"], fields


def dissipation(name, previous, dx, mu):
    """Of the active slip nodes of a step: sum_j D_j mu p_j |xi_j| (xi_j the
    objective slip increment of the step, the code's), the same with the
    kinematic slip of a rigid die instead, (x_j - x_j^(n-1) - dx e_x) . tau_j
    (tau_j along the chord of node j's neighbours), sum_j D_j p_j and sum_j
    D_j (checks D_j against the pair's contact length of forces.csv). D_j is
    half the deformed lengths of the node's slave edges (every active node's
    edges lie under the die's arc, so the dual weights are the lumped ones of
    the whole edges)."""
    points, connectivity, fields = surface(name)
    before, _, _ = surface(previous)
    weight = [0.] * len(points)
    neighbours = [[] for _ in points]
    for a, b in zip(connectivity[0::2], connectivity[1::2]):
        half = 0.5 * math.dist(points[a], points[b])
        weight[a] += half
        weight[b] += half
        neighbours[a].append(b)
        neighbours[b].append(a)
    work, kinematic, normal, length = 0., 0., 0., 0.
    for j, w in enumerate(weight):
        if fields["active"][j] != 1:
            continue
        a, b = sorted(neighbours[j], key=lambda k: points[k][0])
        chord = [points[b][0] - points[a][0], points[b][1] - points[a][1]]
        slip = ((points[j][0] - before[j][0] - dx) * chord[0] +
                (points[j][1] - before[j][1]) * chord[1]) / math.hypot(*chord)
        p = fields["contact_pressure"][j]
        work += w * mu * p * abs(fields["slip_increment"][j])
        kinematic += w * mu * p * abs(slip)
        normal += w * p
        length += w
    return work, kinematic, normal, length


def strain_energy(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)["cycles"][-1]["strain_energy"]


def energy_balance(binary, out, refinements, depth=0.2, mu=0.3, steps=36, nu=0.3):
    """The plateau's steps k0..N: the die's work sum |F_x^n| dx (the
    backward-Euler work of the step, as the step's dissipation) against
    W(N) - W(k0 - 1) plus the dissipation of the steps k0..N."""
    full = os.path.join(out, "full")
    stdout, wall = run(binary, full, refinements, depth, nu=nu, mu=mu, steps=steps, vtu=True)
    rows = plateau_rows(full)
    first = int(rows[0]["step"])
    dt = END_TIME / steps
    before = os.path.join(out, "before")
    run(binary, before, refinements, depth, nu=nu, mu=mu, steps=first - 1,
        end_time=dt * (first - 1))
    dx = SLIDE_PER_TIME * dt
    work = sum(abs(r["boundary_1_x"]) * dx for r in rows)
    normal_work = sum(abs(r["boundary_1_y"]) * dx for r in rows)
    dissipated, kinematic, weight_errors = 0., 0., []
    slip_over_advance = 0.
    for r in rows:
        name = os.path.join(full, f"contact_surface_{int(r['step']):03d}.vtu")
        previous = os.path.join(full, f"contact_surface_{int(r['step']) - 1:03d}.vtu")
        d, k, normal, length = dissipation(name, previous, dx, mu)
        dissipated += d
        kinematic += k
        slip_over_advance += d / (mu * normal * dx) / len(rows)
        weight_errors.append(abs(length - r["pair_4_3_length"]) / length)
    stored = strain_energy(full) - strain_energy(before)
    return {
        "work": work, "stored": stored, "dissipated": dissipated,
        "imbalance": (work - stored - dissipated) / work,
        "kinematic_imbalance": (work - stored - kinematic) / work,
        "ratio_from_energy": (stored + dissipated) / (mu * normal_work),
        "ratio_measured": work / (mu * normal_work),
        "slip_over_advance": slip_over_advance,
        "weight_check": max(weight_errors), "wall": wall,
    }


def linear_offset(length, nu, mu=0.3):
    """The die's ratio / mu - 1 of the linear theory (docstring), a = length / 2."""
    return -(8. / (3. * math.pi)) * beta(nu) * (1. + mu * mu) * 0.5 * length / RADIUS


def row(label, a, nu, wall, mu=0.3):
    return (f"| {label} | {a['converged']}/{a['steps']} | {a['newton']} | {a['active'][0]}-"
            f"{a['active'][1]} | {a['length']:.4f} | {a['F_y']:.5f} | {a['ratio']:.5f} | "
            f"{100 * a['offset']:+.2f} % | {100 * linear_offset(a['length'], nu, mu):+.2f} % | "
            f"{100 * a['lean']:+.3f} % | {a['pair_error']:.1e} | {100 * a['chatter_F_y']:.3f} % | "
            f"{100 * a['chatter_ratio']:.3f} % | {wall:.0f} s |")


HEADER = ("| run | converged | Newton its | active nodes | contact length | mean F_y | "
          "die abs(F_x)/F_y | offset from mu | linear theory | lean of the pressure "
          "resultant / F_n | pair abs(T)/abs(N) - mu, rel. | chatter F_y | chatter ratio | "
          "wall |\n|" + "---|" * 14)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default=os.path.join(REPO, "build", "contact_fem"))
    parser.add_argument("--out", default="/tmp/ironing_2d_plough")
    parser.add_argument("--study", required=True,
                        choices=["depth", "material", "energy", "energy_steps", "chatter", "mu"])
    parser.add_argument("--refinements", type=int, nargs="*")
    parser.add_argument("--depths", type=float, nargs="*")
    parser.add_argument("--steps", type=int, nargs="*", default=[36],
                        help="energy study: load steps of the whole run (36: 0.047 per slide step)")
    args = parser.parse_args()
    print(f"# {args.study}, {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, load "
          f"{os.getloadavg()[0]:.1f}", flush=True)
    if args.study == "depth":
        print(HEADER, flush=True)
        for refinements in args.refinements or (1, 2, 3):
            for depth in args.depths or (0.2, 0.1, 0.05, 0.025):
                out = os.path.join(args.out, f"depth_{refinements}_{depth}")
                stdout, wall = run(args.binary, out, refinements, depth)
                print(row(f"h = {0.25 / 2**refinements}, d = {depth}",
                          analyse(out, stdout, 0.3), 0.3, wall), flush=True)
    elif args.study == "material":
        print(HEADER, flush=True)
        refinements = (args.refinements or [2])[0]
        depth = (args.depths or [0.1])[0]
        for nu, e_die in ((0.0, 1e3), (0.2, 1e3), (0.3, 1e3), (0.4, 1e3), (0.45, 1e3),
                          (0.3, 1e4), (0.3, 1e5)):
            out = os.path.join(args.out, f"material_{nu}_{e_die:g}")
            stdout, wall = run(args.binary, out, refinements, depth, nu=nu, e_die=e_die)
            print(row(f"nu = {nu}, E_die = {e_die:g}", analyse(out, stdout, 0.3), nu, wall),
                  flush=True)
    elif args.study == "mu":
        print(HEADER, flush=True)
        refinements = (args.refinements or [2])[0]
        depth = (args.depths or [0.1])[0]
        for mu in (0.1, 0.2, 0.3, 0.5):
            out = os.path.join(args.out, f"mu_{mu}")
            stdout, wall = run(args.binary, out, refinements, depth, mu=mu)
            print(row(f"mu = {mu}", analyse(out, stdout, mu), 0.3, wall, mu), flush=True)
    elif args.study == "energy":
        print("| h | d | load steps | die work | stored energy change | dissipation | imbalance / work | "
              "imbalance with the rigid die's slip | "
              "die ratio / mu | (stored + dissipation) / (mu int F_y dx) | p-weighted slip per "
              "die advance | sum D_j against the contact length |\n|" + "---|" * 12, flush=True)
        for refinements in args.refinements or (0, 1, 2):
            for depth, steps in ((d, n) for d in args.depths or (0.2,) for n in args.steps):
                e = energy_balance(args.binary, os.path.join(args.out, f"energy_{refinements}_"
                                                              f"{depth}_{steps}"), refinements,
                                   depth, steps=steps)
                print(f"| {0.25 / 2**refinements} | {depth} | {steps} | {e['work']:.6g} | "
                      f"{e['stored']:+.3e} | {e['dissipated']:.6g} | {e['imbalance']:+.2e} | "
                      f"{e['kinematic_imbalance']:+.2e} | "
                      f"{e['ratio_measured']:.5f} | {e['ratio_from_energy']:.5f} | "
                      f"{e['slip_over_advance']:.5f} | {e['weight_check']:.1e} |", flush=True)
    elif args.study == "energy_steps":
        steps = args.steps[0]
        dt = END_TIME / steps
        dx = SLIDE_PER_TIME * dt
        full = os.path.join(args.out, "energy_steps", "full")
        run(args.binary, full, 0, 0.2, steps=steps, vtu=True)
        rows = plateau_rows(full)
        energy = {}
        for n in range(int(rows[0]["step"]) - 1, steps + 1):
            out = os.path.join(args.out, "energy_steps", str(n))
            run(args.binary, out, 0, 0.2, steps=n, end_time=dt * n)
            energy[n] = strain_energy(out)
        print("| step | slide | die F_x / F_y | stored energy change / work | dissipation / "
              "work | imbalance / work |\n|" + "---|" * 6, flush=True)
        for r in rows:
            n = int(r["step"])
            _, dissipated, _, _ = dissipation(
                os.path.join(full, f"contact_surface_{n:03d}.vtu"),
                os.path.join(full, f"contact_surface_{n - 1:03d}.vtu"), dx, 0.3)
            work = abs(r["boundary_1_x"]) * dx
            stored = energy[n] - energy[n - 1]
            print(f"| {n} | {SLIDE_PER_TIME * (r['t'] - 1.):.4f} | "
                  f"{abs(r['boundary_1_x'] / r['boundary_1_y']):.5f} | "
                  f"{100 * stored / work:+.3f} % | {100 * dissipated / work:.3f} % | "
                  f"{100 * (work - stored - dissipated) / work:+.3f} % |", flush=True)
    elif args.study == "chatter":
        print("| run | h | slide step / h | plateau steps | Newton its | mean F_y | chatter F_y "
              "(max dev. / mean) | peak to peak / mean | die ratio (mean) | chatter ratio | "
              "wall |\n|" + "---|" * 11, flush=True)
        for frictionless in (True, False):
            for refinements in args.refinements or (0, 1, 2):
                h = 0.25 / 2**refinements
                steps = int(round(END_TIME * SLIDE_PER_TIME / (h / 4)))  # h / 4 per step
                out = os.path.join(args.out, f"chatter_{refinements}_{int(frictionless)}")
                stdout, wall = run(args.binary, out, refinements, 0.2, steps=steps,
                                   frictionless=frictionless)
                a = analyse(out, stdout, 0. if frictionless else 0.3)
                ratio = (f"{a['max_abs_ratio']:.1e} (max)" if frictionless else
                         f"{a['ratio']:.5f}")
                chat = "-" if frictionless else f"{100 * a['chatter_ratio']:.3f} %"
                print(f"| {'frictionless' if frictionless else 'mu = 0.3'} | {h} | "
                      f"{SLIDE_PER_TIME * END_TIME / steps / h:.2f} | {a['plateau_steps']} | "
                      f"{a['newton']} | {a['F_y']:.5f} | {100 * a['chatter_F_y']:.3f} % | "
                      f"{100 * a['peak_to_peak_F_y']:.3f} % | {ratio} | {chat} | {wall:.0f} s |",
                      flush=True)


if __name__ == "__main__":
    main()
