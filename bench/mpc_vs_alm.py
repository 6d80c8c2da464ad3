#!/usr/bin/env python3
"""mpc frictionless against alm frictionless: Newton iterations and wall
time (doc/performance.md, "MPC contact against ALM").

Serial runs of each scene with Contact/Formulation = alm frictionless and
mpc frictionless, nothing else changed, REPS times each, interleaved (rep 1
of both, then rep 2, ...) so that a change of machine load hits both alike.
Reported per scene and formulation: Newton iterations per load step
(summary.json), the median and min program wall time (summary.json
"wall_time"), and p_max and the total contact force (which must agree).

  hertz2d     prm/hertz.prm as shipped (Contact refinements 6)
  hertz2d_r8  prm/hertz.prm, Contact refinements 8
  hertz3d     prm/hertz_3d.prm on tests/scenes/hertz_3d_01's mesh (Q2,
              Sphere refinements 2, Contact refinements 0, pole patch 20
              degrees: 8,124 DoFs)
  hertz3d_r3  the same with Sphere refinements 3 (the quick look of
              prm/hertz_3d.prm's header, Pole patch angle as shipped)
  friction2d  prm/hertz_frictional.prm as shipped (Coulomb 0.2, 8 load
              steps): alm frictional against mpc frictional
  friction3d  prm/hertz_3d.prm as tests/scenes/frictional_hertz_3d_01 runs
              it (Q1, Sphere refinements 3, Contact refinements 0, Coulomb
              0.2): alm frictional against mpc frictional

Usage:
  python3 bench/mpc_vs_alm.py [--binary B] [--reps N] [--scenes a,b,...]
Run it on a quiet machine; results go to bench/results-mpc-vs-alm/.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SMALL_3D = ["Geometry/Hertz sphere/Sphere refinements=2",
            "Geometry/Hertz sphere/Contact refinements=0",
            "Geometry/Hertz sphere/Pole patch angle=20"]
QUICK_3D = ["Geometry/Hertz sphere/Sphere refinements=3",
            "Geometry/Hertz sphere/Contact refinements=0"]
# name: (scene, settings, kind of the two formulations)
SCENES = {
    "hertz2d": ("prm/hertz.prm", [], "frictionless"),
    "hertz2d_r8": ("prm/hertz.prm", ["Geometry/Hertz cylinder/Contact refinements=8"],
                   "frictionless"),
    "hertz3d": ("prm/hertz_3d.prm", SMALL_3D, "frictionless"),
    "hertz3d_r3": ("prm/hertz_3d.prm", QUICK_3D, "frictionless"),
    "friction2d": ("prm/hertz_frictional.prm", [], "frictional"),
    "friction3d": ("prm/hertz_3d.prm", QUICK_3D + ["Finite element/Degree=1",
                                                   "Contact/Friction=coulomb 0.2"], "frictional"),
}


def run(binary, scene, settings, formulation, directory):
    command = [binary, os.path.join(ROOT, scene), "--output-directory", directory,
               "--set", f"Contact/Formulation={formulation}",
               "--set", "Output/Write VTU=false"]
    for setting in settings:
        command += ["--set", setting]
    env = dict(os.environ, OMP_NUM_THREADS="1", DEAL_II_NUM_THREADS="1",
               OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    result = subprocess.run(command, env=env, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"{' '.join(command)} failed:\n{result.stdout[-2000:]}{result.stderr}")
    with open(os.path.join(directory, "summary.json")) as f:
        summary = json.load(f)
    cycle = summary["cycles"][-1]
    return {"iterations": [s["newton_iterations"] for s in cycle["load_steps"]],
            "wall_time": summary["wall_time"],
            "p_max": cycle["contact"]["max_contact_pressure"],
            "force": cycle["contact"]["total_contact_force"],
            "dofs": cycle["n_dofs"]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "contact_fem"))
    parser.add_argument("--reps", type=int, default=3)
    parser.add_argument("--scenes", default=",".join(SCENES))
    args = parser.parse_args()
    out_root = os.path.join(ROOT, "bench", "results-mpc-vs-alm")
    print(f"load average before: {open('/proc/loadavg').read().split()[:3]}")
    print(f"{'scene':<11} {'formulation':<17} {'DoFs':>7} {'its/step':<10} "
          f"{'wall med [s]':>12} {'wall min [s]':>12} {'p_max':>14} {'contact force':>14}")
    for name in args.scenes.split(","):
        scene, settings, kind = SCENES[name]
        formulations = [f"alm {kind}", f"mpc {kind}"]
        runs = {f: [] for f in formulations}
        for rep in range(args.reps):
            for formulation in formulations:
                directory = os.path.join(out_root, f"{name}-{formulation.split()[0]}-{rep}")
                runs[formulation].append(run(args.binary, scene, settings, formulation,
                                             directory))
        for formulation in formulations:
            r = runs[formulation]
            times = [x["wall_time"] for x in r]
            print(f"{name:<11} {formulation:<17} {r[0]['dofs']:>7} "
                  f"{','.join(map(str, r[0]['iterations'])):<10} "
                  f"{statistics.median(times):>12.3f} {min(times):>12.3f} "
                  f"{r[0]['p_max']:>14.8g} {r[0]['force']:>14.8g}")
    print(f"load average after: {open('/proc/loadavg').read().split()[:3]}")


if __name__ == "__main__":
    main()
