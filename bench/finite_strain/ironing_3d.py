#!/usr/bin/env python3
"""3D ironing, frictionless, on the current configuration (issue 29, item 4):
the die's force on its sliding plateau under refinement.

The scene is prm/ironing_3d.prm (Puso and Laursen's slab 9 x 4 x 3, E = 1,
and half-cylinder die of radius 3 and width 5.2, E = 1000, both
neo-Hookean; pressed 1.4 in 4 load steps, slid 4 along x in 16, from x = -2
to 2), on meshes/ironing_3d.geo made by Gmsh with the element length h =
2^-LEVEL (slab top and die arc) and 2^(LEVEL+1) slab cells across (level 0
is the stored mesh of tests/postprocess/ironing_3d_01). Not Geometry/Global
refinements of the stored mesh: refined once that way, the press stalls at
about 0.95 in an active-set cycle (doc/finite_strain.md). From forces.csv, the reaction on
the die's driven top per load step: F_n = |F_z| normal, F_t = |(F_x, F_y)|
tangential. The plateau is the part of the slide where the die's axis
stays within PLATEAU_HALF_WIDTH of the slab's middle: the slab is only 9
long and the contact about 5, so nearer its ends the stored energy varies
with the die's position and the frictionless die feels a real horizontal
force (-dE/dx, towards the nearer end: 3.6 % of F_n at the start of the
slide; doc/finite_strain.md). Per level:

- the largest F_t / F_n on the plateau (and its y part, which symmetry
  makes zero);
- the chatter of the normal force: the largest deviation of F_n from the
  least-squares parabola in the die's position over the plateau (the
  smooth trend of the finite slab removed), relative to the mean F_n, and
  the peak-to-peak of the raw F_n;
- DoFs, wall time, Newton iterations.

Usage: bench/finite_strain/ironing_3d.py [--binary B] [--levels N] [--out DIR]
       (levels 0 and 1 took 50 s and 5.3 minutes of wall time on the loaded
       shared machine, 2026-11-27, commit 4b98c04: doc/finite_strain.md)
"""

import argparse
import csv
import os
import re
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
SCENE = os.path.join(REPO, "prm", "ironing_3d.prm")

START_X = -2.            # the die's axis at the start of the slide
SLIDE_PER_TIME = 0.25    # die top x = 0.25 (t - 4) for t > 4
PRESS_END = 4.           # t at the end of the press
PLATEAU_HALF_WIDTH = 0.75


def die_forces(forces_csv):
    """Per load step: (t, die axis x, reaction of the die top, pair force on the slave)."""
    rows = []
    with open(forces_csv) as f:
        for r in csv.DictReader(f):
            t = float(r["t"])
            reaction = [float(r["boundary_1_" + c]) for c in "xyz"]
            pair = [float(r["pair_4_3_normal_" + c]) + float(r["pair_4_3_tangential_" + c])
                    for c in "xyz"]
            x = START_X + SLIDE_PER_TIME * max(t - PRESS_END, 0.)
            rows.append((t, x, reaction, pair))
    return rows


def parabola_residuals(xs, ys):
    """ys minus their least-squares parabola a + b x + c x^2."""
    n = 3
    A = [[sum(x ** (i + j) for x in xs) for j in range(n)] for i in range(n)]
    b = [sum(y * x ** i for x, y in zip(xs, ys)) for i in range(n)]
    for k in range(n):  # Gaussian elimination, partial pivoting
        p = max(range(k, n), key=lambda i: abs(A[i][k]))
        A[k], A[p], b[k], b[p] = A[p], A[k], b[p], b[k]
        for i in range(k + 1, n):
            f = A[i][k] / A[k][k]
            A[i] = [a - f * c for a, c in zip(A[i], A[k])]
            b[i] -= f * b[k]
    c = [0.] * n
    for k in reversed(range(n)):
        c[k] = (b[k] - sum(A[k][j] * c[j] for j in range(k + 1, n))) / A[k][k]
    return [y - (c[0] + c[1] * x + c[2] * x * x) for x, y in zip(xs, ys)]


def plateau_statistics(rows):
    """The plateau's numbers (see the module's doc) from die_forces()."""
    plateau = [r for r in rows if r[0] > PRESS_END and abs(r[1]) <= PLATEAU_HALF_WIDTH + 1e-12]
    xs = [x for _, x, _, _ in plateau]
    normal = [abs(f[2]) for _, _, f, _ in plateau]
    mean = sum(normal) / len(normal)
    return {
        "steps": len(plateau),
        "mean_normal": mean,
        "ratio": max((f[0] ** 2 + f[1] ** 2) ** 0.5 / abs(f[2]) for _, _, f, _ in plateau),
        "ratio_y": max(abs(f[1] / f[2]) for _, _, f, _ in plateau),
        "chatter": max(abs(d) for d in parabola_residuals(xs, normal)) / mean,
        "peak_to_peak": (max(normal) - min(normal)) / mean,
        # The die's support balances the contact force on it (every step).
        "balance": max(max(abs(f[i] - p[i]) for i in range(3)) / abs(f[2])
                       for _, _, f, p in rows),
    }


def mesh(level, out):
    """The Gmsh mesh of the level in out (Gmsh on PATH)."""
    path = os.path.join(out, "ironing_3d.msh")
    geo = os.path.join(REPO, "meshes", "ironing_3d.geo")
    subprocess.run(["gmsh", "-3", "-format", "msh22", geo, "-setnumber", "h", str(0.5 ** level),
                    "-setnumber", "ny", str(2 ** (level + 1)), "-o", path],
                   check=True, capture_output=True)
    return path


def run(binary, scene, level, out, mesh_file=None):
    """Runs the scene on the level's mesh (mesh_file: the scene's own) in
    out; returns the plateau statistics with DoFs, wall time, steps and
    Newton iterations."""
    os.makedirs(out, exist_ok=True)
    command = [binary, scene, "--set", "Geometry/Global refinements=0",
               "--set", f"Output directory={out}", "--set", "Output/Write VTU=false",
               "--set", "Output/Print timing=false"]
    if mesh_file != "scene":
        command += ["--set", f"Geometry/Mesh file={mesh(level, out)}"]
    start = time.time()
    result = subprocess.run(command, capture_output=True, text=True)
    wall = time.time() - start
    if result.returncode != 0:
        raise SystemExit(f"{' '.join(command)} failed:\n{result.stdout}{result.stderr}")
    output = result.stdout
    stats = plateau_statistics(die_forces(os.path.join(out, "forces.csv")))
    stats.update({
        "level": level, "wall": wall,
        "dofs": int(re.search(r"(\d+) DoFs", output).group(1)),
        "steps_run": output.count("  Load step "),
        "converged": output.count("| converged"),
        "iterations": len(re.findall(r"^\s*\|\s*[1-9]\d*\s*\|", output, re.M)),
    })
    return stats


def report(s):
    return (f"level {s['level']}: {s['dofs']} DoFs, {s['wall']:.1f} s, "
            f"{s['converged']} of {s['steps_run']} load step attempts converged, "
            f"{s['iterations']} Newton iterations; plateau of {s['steps']} steps: "
            f"mean F_n {s['mean_normal']:.5g}, max F_t / F_n {100 * s['ratio']:.3f} % "
            f"(y part {100 * s['ratio_y']:.3f} %), normal-force chatter "
            f"{100 * s['chatter']:.3f} % (peak to peak {100 * s['peak_to_peak']:.3f} %), "
            f"support against contact force {s['balance']:.1e}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default=os.path.join(REPO, "build", "contact_fem"))
    parser.add_argument("--levels", type=int, default=2)
    parser.add_argument("--out", default="ironing_3d_bench")
    args = parser.parse_args()
    for level in range(args.levels):
        print(report(run(args.binary, SCENE, level,
                         os.path.abspath(os.path.join(args.out, f"level{level}")))), flush=True)


if __name__ == "__main__":
    main()
