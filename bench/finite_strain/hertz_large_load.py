#!/usr/bin/env python3
"""Large-load 2D Hertz at finite strain against an overkill of the same
model (issue 29, item 4, last bullet).

The scene (tests/scenes/hertz_large_load_01.prm.in): prm/hertz.prm at 100 x its load (p = 20 on the flat top, Hertz
a = 3.85 = 0.48 R), the half-disc neo-Hookean (E = 200, nu = 0.3), the
plate linear and 1e10 x stiffer, contact on the current configuration
(Contact/Kinematics = current), 5 load steps, Newton tolerances 1e-10. A
coarse base mesh (Cylinder refinements 1, Contact refinements 2 within
|x| < 4.5, Plate contact refinements 0: slave faces 1.31 at the contact)
is refined uniformly (Geometry/Global refinements = 0 ... LEVELS - 1); the
overkill is the same scene one global refinement beyond the finest level.

Per level: DoFs, wall time, and the error against the overkill of
- p_max (the largest nodal Cauchy pressure),
- the contact half-width: summary.json contact_half_width (the outermost
  active node: resolved to one element only), and a_m = 2 sqrt(int x^2 p dx
  / int p dx) (trapezoid over the slave nodes; = a for a Hertz profile), a
  width that converges with the pressure,
- the pressure profile: L2 over the overkill's contact zone (deformed x) of
  p_h - p_ref, p_h interpolated linearly between its slave nodes, relative
  to |p_ref|_L2,
- the energy: e = sqrt(|Pi_h - Pi_ref| / W_ref), Pi the potential energy
  (int W dV - work of the dead load), W_ref the overkill's strain energy.
  For a Galerkin solution of a minimum problem Pi_h - Pi = |u - u_h|^2 / 2
  in the energy norm of the tangent, so e is a relative energy-norm error
  (O(h) for Q1 away from the contact edges' singularity).
and the observed order between successive levels (h halves).

Usage: bench/finite_strain/hertz_large_load.py [--binary B] [--levels N]
       [--out DIR] [--reuse]   (nice -n 10 on a shared machine)
"""

import argparse
import bisect
import csv
import json
import math
import os
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

# The scene of the test (tests/scenes/hertz_large_load_01.prm.in, which
# includes prm/hertz.prm): one definition for the bench and the test.
SCENE_IN = os.path.join(REPO, "tests", "scenes", "hertz_large_load_01.prm.in")


def scene_file(out):
    path = os.path.join(out, "hertz_large_load.prm")
    with open(SCENE_IN) as f:
        text = f.read().replace("@SOURCE_DIR@", os.path.join(REPO, "tests", "scenes"))
    with open(path, "w") as f:
        f.write(text)
    return path


def run(binary, scene, level, out, reuse):
    summary = os.path.join(out, "summary.json")
    if not (reuse and os.path.exists(summary)):
        cmd = [binary, scene, "--output-directory", out,
               "--set", "Geometry/Global refinements=%d" % level]
        env = dict(os.environ, OMP_NUM_THREADS="1", DEAL_II_NUM_THREADS="1")
        with open(os.path.join(out + ".log"), "w") as log:
            subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, env=env, check=True)
    with open(summary) as f:
        s = json.load(f)
    c = s["cycles"][0]
    with open(os.path.join(out, "pressure_profile.csv")) as f:
        prof = sorted((float(r["x"]), float(r["pressure"])) for r in csv.DictReader(f))
    return {"level": level, "dofs": c["n_dofs"], "wall": s["wall_time"],
            "h": c["contact"]["slave_element_size"], "status": s["status"],
            "p_max": c["contact"]["max_contact_pressure"],
            "a": c["contact"]["contact_half_width"],
            "W": c["strain_energy"], "Pi": c["potential_energy"],
            "its": [st["newton_iterations"] for st in c["load_steps"]], "profile": prof}


def interpolate(profile, x):
    xs = [p[0] for p in profile]
    i = bisect.bisect_left(xs, x)
    if i == 0 or i == len(xs):
        return 0.
    (x0, p0), (x1, p1) = profile[i - 1], profile[i]
    return p0 + (p1 - p0) * (x - x0) / (x1 - x0)


def moment_width(profile):
    """2 sqrt(m2 / m0) of the nodal pressures (trapezoid, deformed x)."""
    m0 = m2 = 0.
    for (x0, p0), (x1, p1) in zip(profile, profile[1:]):
        m0 += 0.5 * (x1 - x0) * (p0 + p1)
        m2 += 0.5 * (x1 - x0) * (x0 * x0 * p0 + x1 * x1 * p1)
    return 2. * math.sqrt(m2 / m0)


def pressure_l2_error(r, ref):
    """Trapezoid rule on the overkill's nodes in its contact zone."""
    pts = [(x, p) for x, p in ref["profile"] if p > 0.]
    num = den = 0.
    for (x0, p0), (x1, p1) in zip(pts, pts[1:]):
        e0, e1 = interpolate(r["profile"], x0) - p0, interpolate(r["profile"], x1) - p1
        num += 0.5 * (x1 - x0) * (e0 * e0 + e1 * e1)
        den += 0.5 * (x1 - x0) * (p0 * p0 + p1 * p1)
    return math.sqrt(num / den)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--binary", default=os.path.join(REPO, "build", "contact_fem"))
    ap.add_argument("--levels", type=int, default=4)
    ap.add_argument("--out", default="/tmp/hertz_large_load")
    ap.add_argument("--reuse", action="store_true", help="read runs already in --out")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    load, start = os.getloadavg()[0], time.time()
    scene = scene_file(args.out)
    runs = [run(args.binary, scene, g, os.path.join(args.out, "g%d" % g), args.reuse)
            for g in range(args.levels + 1)]
    ref, levels = runs[-1], runs[:-1]
    print("load average (1 min) %.2f at start, %.2f at end, %.0f s" %
          (load, os.getloadavg()[0], time.time() - start))
    print("overkill: Global refinements %d, %d DoFs, h %.4g, %.0f s, p_max %.6g, a %.6g, "
          "a_m %.6g, Pi %.8g, W %.8g, Newton its %s, %s" %
          (ref["level"], ref["dofs"], ref["h"], ref["wall"], ref["p_max"], ref["a"],
           moment_width(ref["profile"]), ref["Pi"], ref["W"], ref["its"], ref["status"]))
    print()
    print("| level | DoFs | h at contact | wall [s] | Newton its per step | p_max | err p_max "
          "| a (node) | err a | a_m | err a_m | err p (L2) | err energy | order (energy) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    previous = None
    ref_am = moment_width(ref["profile"])
    for r in levels:
        e = math.sqrt(abs(r["Pi"] - ref["Pi"]) / ref["W"])
        order = "-" if previous is None else "%.2f" % math.log2(previous / e)
        am = moment_width(r["profile"])
        print("| %d | %d | %.4g | %.1f | %s | %.6g | %+.2e | %.5g | %+.2e | %.6g | %+.2e | %.2e "
              "| %.2e | %s |" %
              (r["level"], r["dofs"], r["h"], r["wall"], " ".join(map(str, r["its"])), r["p_max"],
               r["p_max"] / ref["p_max"] - 1., r["a"], r["a"] / ref["a"] - 1., am,
               am / ref_am - 1., pressure_l2_error(r, ref), e, order))
        previous = e


if __name__ == "__main__":
    main()
