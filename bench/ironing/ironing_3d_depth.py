#!/usr/bin/env python3
"""3D ironing with mu = 0.3 (prm/ironing_3d.prm, the stored mesh h = 1) at
other indentation depths: the die's F_t / F_n on the plateau against mu
(doc/finite_strain.md, "2D ironing: the die's force ratio under friction").

The scene presses the die 1.4 (d / R = 0.47) in 4 load steps and slides it
4 in 16; here the depth is d (the same 4 steps) and the run stops at x =
0.75 (15 steps). Plateau: the die's axis within 0.75 of the slab's middle
(x = -0.75 .. 0.75, 7 steps), as bench/finite_strain/ironing_3d.py. Per
depth: the die's mean F_t / F_n, its offset from mu, the lean of the
pair's normal force along the slide over F_n, the pair's |T| / |N|, and
the Newton iterations.

Usage: bench/ironing/ironing_3d_depth.py [--depths D...] [--level L] [--refine N]
       [--binary B] [--out DIR]
"""

import argparse
import csv
import math
import os
import sys
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "bench"))
from bench_run import run_logged  # noqa: E402
SCENE = os.path.join(REPO, "prm", "ironing_3d.prm")
MU = 0.3


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default=os.path.join(REPO, "build", "contact_fem"))
    parser.add_argument("--out", default="/tmp/ironing_3d_depth")
    parser.add_argument("--depths", type=float, nargs="*", default=[0.7, 0.35])
    parser.add_argument("--level", type=int, default=0,
                        help="0: the stored mesh (h = 1); 1: Gmsh's h = 0.5 mesh, as "
                             "bench/finite_strain/ironing_3d.py makes it")
    parser.add_argument("--refine", type=int, default=0,
                        help="global refinements of that mesh (the die's new vertices on its "
                             "cylinder). Gmsh's h = 0.25 mesh is not all hexahedra (20 prisms "
                             "in the die), which contact_fem splits with every other cell: "
                             "91,806 DoFs; level 1 refined once has the slab's h = 0.25")
    args = parser.parse_args()
    print(f"# 3D ironing depths, {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, load "
          f"{os.getloadavg()[0]:.1f}")
    print("| d | d / R | h | converged / attempts | Newton its | mean F_n | die F_t / F_n | offset | "
          "lean / F_n | pair abs(T) / abs(N) | wall |\n|" + "---|" * 11, flush=True)
    for depth in args.depths:
        out = os.path.join(args.out, f"d_{depth}_level_{args.level}_refine_{args.refine}")
        os.makedirs(out, exist_ok=True)
        command = [args.binary, SCENE]
        if args.level > 0:
            path = os.path.join(out, "ironing_3d.msh")
            subprocess.run(["gmsh", "-3", "-format", "msh22",
                            os.path.join(REPO, "meshes", "ironing_3d.geo"), "-setnumber", "h",
                            str(0.5 ** args.level), "-setnumber", "ny",
                            str(2 ** (args.level + 1)), "-o", path],
                           check=True, capture_output=True)
            command += ["--set", f"Geometry/Mesh file={path}"]
        for setting in (f"Output directory={out}", f"Geometry/Global refinements={args.refine}",
                        "Contact/Formulation=alm frictional", "Contact/Friction=coulomb 0.3",
                        "Boundary conditions/Prescribed displacement=die top: x = "
                        f"0.25*max(t-4, 0); die top: y = 0; die top: z = -{depth / 4}*min(t, 4)",
                        "Load stepping/End time=15", "Load stepping/Number of load steps=15",
                        "Output/Write VTU=false", "Output/Print timing=false"):
            command += ["--set", setting]
        result, wall = run_logged(command, out)
        if result.returncode != 0:
            print(f"| {depth} | failed ({result.returncode}) |")
            continue
        with open(os.path.join(out, "forces.csv")) as f:
            rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
        rows = [r for r in rows if r["t"] >= 9 - 1e-9]  # x = 0.25 (t - 4) - 2 >= -0.75
        fn = [abs(r["boundary_1_z"]) for r in rows]
        ratio = [math.hypot(r["boundary_1_x"], r["boundary_1_y"]) / abs(r["boundary_1_z"])
                 for r in rows]
        lean = [-r["pair_4_3_normal_x"] / abs(r["pair_4_3_normal_z"]) for r in rows]
        pair = [math.sqrt(sum(r[f"pair_4_3_tangential_{c}"]**2 for c in "xyz")) /
                math.sqrt(sum(r[f"pair_4_3_normal_{c}"]**2 for c in "xyz")) for r in rows]
        mean = lambda v: sum(v) / len(v)
        its = sum(1 for line in result.stdout.splitlines()
                  if line.strip().startswith("|") and line.split("|")[1].strip().isdigit()) \
            - result.stdout.count("  Load step ")
        print(f"| {depth} | {depth / 3:.3f} | {0.5 ** (args.level + args.refine)} | {result.stdout.count('| converged')} / "
              f"{result.stdout.count('  Load step ')} | {its} | {mean(fn):.4f} | "
              f"{mean(ratio):.4f} | {100 * (mean(ratio) / MU - 1):+.1f} % | "
              f"{100 * mean(lean):+.2f} % | {min(pair):.4f} to {max(pair):.4f} | {wall:.0f} s |",
              flush=True)


if __name__ == "__main__":
    main()
