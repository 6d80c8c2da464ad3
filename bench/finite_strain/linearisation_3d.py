#!/usr/bin/env python3
"""Cost of the 3D mortar linearisation (Contact/Kinematics = current) of two
builds, run alternately: the 3D ironing scene (prm/ironing_3d.prm) pressed
in its first STEPS load steps, and the scene of tests/postprocess/
ironing_3d_01 (15 steps). Per run: Newton iterations (exact), the CPU time
(user + system, less sensitive to a loaded machine than the wall time),
the wall time and the "Contact: search" timer (wall; it holds the
linearisation); per Newton iteration: CPU and search time.

Each build is a directory holding contact_fem and libcontact_fem_lib.so
(its own library is loaded through LD_LIBRARY_PATH), e.g. a copy of the
build directory's two files before the change.

Usage: bench/finite_strain/linearisation_3d.py --build A DIR --build B DIR
       [--repeats N] [--steps S] [--out DIR] [--no-test]
"""

import argparse
import os
import re
import resource
import statistics
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))


def scenes(steps, test):
    yield ("ironing_3d press %d steps" % steps, os.path.join(REPO, "prm", "ironing_3d.prm"),
           ["Load stepping/End time=%d" % steps, "Load stepping/Number of load steps=%d" % steps])
    if test:
        yield ("ironing_3d_01 (15 steps)", os.path.join(REPO, "prm", "ironing_3d.prm"),
               ["Load stepping/End time=15", "Load stepping/Number of load steps=15"])


def run(directory, scene, sets, out):
    command = [os.path.join(directory, "contact_fem"), scene, "--set", f"Output directory={out}",
               "--set", "Output/Write VTU=false", "--set", "Output/Write pressure profile=false",
               "--set", "Output/Print timing=true"]
    for s in sets:
        command += ["--set", s]
    env = dict(os.environ, LD_LIBRARY_PATH=directory)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.time()
    result = subprocess.run(command, capture_output=True, text=True, env=env)
    wall = time.time() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if result.returncode != 0:
        raise SystemExit(f"{' '.join(command)} failed:\n{result.stdout}{result.stderr}")
    output = result.stdout
    search = sum(float(t) for t in re.findall(r"Contact: search\s+([\d.]+) s", output))
    return {
        "cpu": (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime),
        "wall": wall,
        "search": search,
        "iterations": len(re.findall(r"^\s*\|\s*[1-9]\d*\s*\|", output, re.M)),
        "converged": output.count("| converged"),
    }


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", nargs=2, action="append", metavar=("NAME", "DIR"),
                        required=True)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--steps", type=int, default=2)
    parser.add_argument("--out", default="/tmp/linearisation_3d_bench")
    parser.add_argument("--no-test", action="store_true")
    args = parser.parse_args()
    results = {}
    for name, scene, sets in scenes(args.steps, not args.no_test):
        for r in range(args.repeats):
            for build, directory in args.build:
                s = run(os.path.abspath(directory), scene, sets,
                        os.path.join(args.out, build, str(r)))
                results.setdefault((name, build), []).append(s)
                print(f"{name} | {build} | run {r}: {s['iterations']} Newton iterations, "
                      f"{s['converged']} steps converged, CPU {s['cpu']:.2f} s, "
                      f"wall {s['wall']:.2f} s, Contact: search {s['search']:.2f} s", flush=True)
    print("\n| scene | build | Newton its | CPU per it (median) | search per it (median) "
          "| CPU of the run (min-max) |")
    print("|---|---|---:|---:|---:|---:|")
    for (name, build), runs in results.items():
        its = runs[0]["iterations"]
        cpu = [s["cpu"] / s["iterations"] for s in runs]
        search = [s["search"] / s["iterations"] for s in runs]
        print(f"| {name} | {build} | {its} | {statistics.median(cpu):.3f} s | "
              f"{statistics.median(search):.3f} s | {min(s['cpu'] for s in runs):.1f}-"
              f"{max(s['cpu'] for s in runs):.1f} s |")


if __name__ == "__main__":
    main()
