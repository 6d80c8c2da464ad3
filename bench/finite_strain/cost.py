#!/usr/bin/env python3
"""Cost of finite strain (issue 29, item 7): time per Newton iteration and
Newton iterations per load step of the same scene with

  linear         linear bulk, Contact/Kinematics = small (the default)
  nh-small       neo-Hookean body, small kinematics
  nh-current     neo-Hookean body, Contact/Kinematics = current
  linear-current linear bulk, current kinematics (the contact's share alone)

on the 2D Hertz scene (prm/hertz.prm, Contact refinements 4, 5, 6) and the
3D Hertz sphere (prm/hertz_3d.prm, Q2, small kinematics: the first
measurement); with --3d instead on the 3D Hertz sphere with Q1 on the
quadratic mapping (Sphere refinements 2 and 3, at its load) and the 3D
patch (build/tests/scenes/current_kinematics_patch_3d_01.prm, as cmake
configures it; refined once, 30 %
compression in 6 steps), every variant. Every
run uses Newton tolerances 1e-10 (the finite-strain bulk needs them for
reactions to many digits; the same for all so that iterations compare).

Time per iteration = sum of the load steps' wall times / sum of their
Newton iterations (summary.json), so it holds the assembly, the contact
update (search, integration, linearisation) and the solve, not the setup.
The CPU time
(user + system) of each whole run, start-up included, is less sensitive
to a loaded machine than the wall times. CPU per iteration = the run's CPU
time times the load steps' share of its wall time, over the Newton
iterations: the wall times of a loaded machine stretch every part alike,
their share does not (an estimate: the program times wall clocks only). The variants run interleaved (one repetition of every variant, then the
next), REPEATS times; the median is reported. With --baseline BINARY, the
linear scene also runs with that binary (e.g. one built before finite
strain landed), to show that a small-strain scene pays nothing.

Usage: bench/finite_strain/cost.py [--binary B] [--baseline B] [--repeats N]
       [--out DIR] [--quick] [--3d]
Run at low priority on a shared machine: nice -n 10 bench/finite_strain/cost.py
"""

import argparse
import json
import os
import resource
import statistics
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

TIGHT = ["Newton/Displacement relative tolerance=1e-10",
         "Newton/Displacement absolute tolerance=1e-12"]
VARIANTS = {
    "linear": [],
    "nh-small": ["Materials/Models=neo-hookean, linear"],
    "nh-current": ["Materials/Models=neo-hookean, linear", "Contact/Kinematics=current"],
    "linear-current": ["Contact/Kinematics=current"],
}


# The 3D patch sets its own bodies (neo-Hookean) and kinematics (current).
PATCH_VARIANTS = {
    "linear": ["Materials/Models=", "Contact/Kinematics=small"],
    "nh-small": ["Contact/Kinematics=small"],
    "nh-current": [],
    "linear-current": ["Materials/Models="],
}
ALL = ("linear", "nh-small", "nh-current", "linear-current")
# Linear bodies at 11 % (Hertz) or 30 % (patch) strain end with exit code 3.
ACCEPT = ["Model range/Accept results outside the small-strain range=true"]


def scenes_3d():
    for level in (2, 3):
        yield ("hertz-3d-q1-sr%d" % level, os.path.join(REPO, "prm", "hertz_3d.prm"),
               ["Finite element/Degree=1", "Geometry/Hertz sphere/Sphere refinements=%d" % level,
                "Geometry/Hertz sphere/Contact refinements=0"], ALL)
    yield ("patch-3d-r1", os.path.join(REPO, "build", "tests", "scenes",
                                       "current_kinematics_patch_3d_01.prm"),
           ["Geometry/Global refinements=1"], ALL)


def scenes(quick):
    levels = (4, 5) if quick else (4, 5, 6)
    for level in levels:
        yield ("hertz-2d-r%d" % level, os.path.join(REPO, "prm", "hertz.prm"),
               ["Geometry/Hertz cylinder/Contact refinements=%d" % level],
               ("linear", "nh-small", "nh-current", "linear-current"))
    yield ("hertz-3d-q2", os.path.join(REPO, "prm", "hertz_3d.prm"),
           ["Geometry/Hertz sphere/Sphere refinements=2",
            "Geometry/Hertz sphere/Contact refinements=0"],
           ("linear", "nh-small"))


def run(binary, prm, sets, out):
    cmd = [binary, prm, "--set", "Output/Write VTU=false", "--set", "Output/Print timing=false",
           "--output-directory", out]
    for kv in sets:
        cmd += ["--set", kv]
    env = dict(os.environ, OMP_NUM_THREADS="1", DEAL_II_NUM_THREADS="1")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    rc = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                        env=env).returncode
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    c = s["cycles"][0]
    steps = c["load_steps"]
    its = [st["newton_iterations"] for st in steps]
    step_time = sum(st["wall_time"] for st in steps)
    timing = c.get("timing", {})
    cpu_per_it = cpu * step_time / s["wall_time"] / max(sum(its), 1)
    return {"rc": rc, "dofs": c["n_dofs"], "its": its, "per_it": step_time / max(sum(its), 1),
            "cpu_per_it": cpu_per_it,
            "wall": s["wall_time"], "cpu": cpu, "p_max": c["contact"]["max_contact_pressure"],
            "search_per_it": timing.get("Contact: search", 0.) / max(sum(its), 1),
            "solve_per_it": timing.get("Solve: linear", 0.) / max(sum(its), 1)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--binary", default=os.path.join(REPO, "build", "contact_fem"))
    ap.add_argument("--baseline", default=None)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--out", default="/tmp/finite_strain_cost")
    ap.add_argument("--quick", action="store_true", help="levels 4 and 5 only")
    ap.add_argument("--3d", dest="three_d", action="store_true",
                    help="the 3D scenes with every variant (Q1 Hertz sphere, patch)")
    args = ap.parse_args()

    load = os.getloadavg()[0]
    start = time.time()
    runs = {}
    loads = []
    for rep in range(args.repeats):
        for name, prm, base, variants in (scenes_3d() if args.three_d else scenes(args.quick)):
            table = PATCH_VARIANTS if name.startswith("patch") else VARIANTS
            jobs = [(v, args.binary, table[v] + (ACCEPT if args.three_d else [])) for v in variants]
            if args.baseline and not name.endswith("3d-q2"):
                jobs.append(("linear (baseline binary)", args.baseline, jobs[0][2]))
            for v, binary, sets in jobs:
                out = os.path.join(args.out, name, v.split()[0] + ("-base" if "baseline" in v else ""))
                r = run(binary, prm, base + sets + TIGHT, out)
                runs.setdefault((name, v), []).append(r)
                loads.append(os.getloadavg()[0])
    print("load average (1 min) %.2f at start, %.2f at end, %.2f-%.2f after the runs; %.0f s; "
          "%d repetitions, medians" % (load, os.getloadavg()[0], min(loads), max(loads),
                                      time.time() - start, args.repeats))
    print()
    print("| scene | variant | DoFs | exit | Newton its per step | ms per iteration, median (min) | "
          "of which search+linearisation | of which linear solve | CPU s per run, median (min) "
          "| CPU ms per iteration, median (min) | p_max |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for (name, v), rs in runs.items():
        r = rs[0]
        med = lambda k: statistics.median(x[k] for x in rs)
        print("| %s | %s | %d | %d | %s | %.1f (%.1f) | %.1f | %.1f | %.3f (%.3f) | %.1f (%.1f) "
              "| %.6g |"
              % (name, v, r["dofs"], r["rc"], ", ".join(str(i) for i in r["its"]),
                 1e3 * med("per_it"), 1e3 * min(x["per_it"] for x in rs),
                 1e3 * med("search_per_it"), 1e3 * med("solve_per_it"), med("cpu"),
                 min(x["cpu"] for x in rs), 1e3 * med("cpu_per_it"),
                 1e3 * min(x["cpu_per_it"] for x in rs), r["p_max"]))


if __name__ == "__main__":
    main()
