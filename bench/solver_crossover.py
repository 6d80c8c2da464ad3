#!/usr/bin/env python3
"""Direct (MUMPS) against iterative (CG + ML multigrid) linear solver on the
Hertz scene at increasing uniform refinement, serial, one run after the
other; optionally `mpirun -np 2` at the largest levels.

Per run it reads summary.json (timing sections, Newton and Krylov
iterations, DoFs) and the peak resident memory (/usr/bin/time), and prints
one markdown table: solve time per Newton iteration, multigrid set-up per
Newton iteration, Krylov iterations, whole-run time, peak memory. The
crossover is the smallest size at which the iterative solve per Newton
iteration is the faster.

Usage: bench/solver_crossover.py [--binary B] [--levels 0 1 2 3 4]
                                 [--mpi-levels 3 4] [--results DIR]
                                 [--scene prm/hertz.prm]
Results go to bench/results-solver/ (ignored by git). Timings are
wall-clock: run it on a quiet machine.
"""
import argparse
import json
import os
import pathlib
import subprocess
import sys

repo = pathlib.Path(__file__).resolve().parent.parent


def run(binary, scene, level, solver, np, results):
    name = f"level{level}-{solver}-np{np}"
    out = results / name
    out.mkdir(parents=True, exist_ok=True)
    # The scene is run as it is (relative mesh paths resolve from its own
    # directory), with the bench's settings as command-line overrides.
    sets = [f"Geometry/Global refinements={level}", f"Linear solver/Type={solver}",
            "Output/Write VTU=false", "Output/Write pressure profile=false"]
    command = ["/usr/bin/time", "-f", "peak_kb %M"]
    if np > 1:
        command += ["mpirun", "-np", str(np)]
    command += [str(binary), str(scene), "--output-directory", str(out)]
    for s in sets:
        command += ["--set", s]
    env = dict(os.environ, OMP_NUM_THREADS="1", DEAL_II_NUM_THREADS="1",
               OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    done = subprocess.run(command, cwd=out, env=env, capture_output=True, text=True)
    (out / "console.txt").write_text(done.stdout + done.stderr)
    if done.returncode != 0:
        sys.exit(f"{name} failed (exit {done.returncode}); see {out}/console.txt")
    # With MPI, /usr/bin/time reports the largest resident set of mpirun and
    # the ranks it waited for: the peak of one rank, not of the job.
    peak_kb = int(done.stderr.strip().splitlines()[-1].split()[-1])
    summary = json.loads((out / "summary.json").read_text())
    cycle = summary["cycles"][0]
    steps = cycle["load_steps"]
    newton = sum(step["newton_iterations"] for step in steps)
    krylov = [n for step in steps for n in step.get("linear_iterations", [])]
    timing = cycle["timing"]
    return {
        "dofs": int(cycle["n_dofs"]),
        "newton": newton,
        "solve": timing["Solve: linear"],
        "setup": timing.get("Solve: multigrid setup", 0.0),
        "assembly": timing["Assembly: system"] + timing["Assembly: residual"],
        # Search and mortar operators, active set, penetration check.
        "contact": sum(v for k, v in timing.items() if k.startswith("Contact:")),
        "wall": cycle["wall_time"],
        "krylov_mean": sum(krylov) / len(krylov) if krylov else None,
        "krylov_max": max(krylov) if krylov else None,
        "peak_mb": peak_kb / 1024.0,
        "p_max": cycle["contact"]["max_contact_pressure"] if "contact" in cycle else None,
    }


def detail(level, np, r, solver):
    """Seconds per Newton iteration of each part, the contact share and the
    memory per DoF."""
    n = r["newton"]
    return (f"| {level} | {np} | {solver} | {r['dofs']:,} | {r['solve'] / n:.3f} | "
            f"{r['assembly'] / n:.3f} | {r['contact'] / n:.4f} | "
            f"{100 * r['contact'] / r['wall']:.1f} % | {1024 * r['peak_mb'] / r['dofs']:.2f} |")


def row(level, np, direct, iterative):
    def per(r, key):
        return r[key] / r["newton"]
    krylov = (f"{iterative['krylov_mean']:.0f} (max {iterative['krylov_max']})"
              if iterative["krylov_mean"] is not None else "-")
    return (f"| {level} | {np} | {direct['dofs']:,} | {direct['newton']} / {iterative['newton']} | "
            f"{per(direct, 'solve'):.3f} | {per(iterative, 'solve'):.3f} | "
            f"{per(iterative, 'setup'):.3f} | {krylov} | "
            f"{direct['wall']:.1f} | {iterative['wall']:.1f} | "
            f"{direct['peak_mb']:.0f} | {iterative['peak_mb']:.0f} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default=str(repo / "build" / "contact_fem"))
    parser.add_argument("--scene", default=str(repo / "prm" / "hertz.prm"))
    parser.add_argument("--levels", type=int, nargs="+", default=[0, 1, 2, 3, 4])
    parser.add_argument("--mpi-levels", type=int, nargs="*", default=[])
    parser.add_argument("--results", default=str(repo / "bench" / "results-solver"))
    args = parser.parse_args()
    results = pathlib.Path(args.results)
    args.scene = str(pathlib.Path(args.scene).resolve())

    print("| level | ranks | DoFs | Newton it. (direct / iterative) | direct solve s / Newton it. "
          "| iterative solve s / Newton it. | of which multigrid set-up | Krylov it. per solve "
          "| direct run s | iterative run s | direct peak MB | iterative peak MB |")
    print("|---:|---:|---:|---|---:|---:|---:|---|---:|---:|---:|---:|")
    crossover = None
    details = []
    runs = [(level, 1) for level in args.levels] + [(level, 2) for level in args.mpi_levels]
    for level, np in runs:
        direct = run(args.binary, args.scene, level, "direct", np, results)
        iterative = run(args.binary, args.scene, level, "iterative", np, results)
        print(row(level, np, direct, iterative), flush=True)
        details += [detail(level, np, direct, "direct"), detail(level, np, iterative, "iterative")]
        if np == 1 and crossover is None and \
                iterative["solve"] / iterative["newton"] < direct["solve"] / direct["newton"]:
            crossover = direct["dofs"]
    print()
    print(f"crossover (serial): {'%d DoFs' % crossover if crossover else 'not reached'}")
    print()
    print("| level | ranks | solver | DoFs | solve s / Newton it. | assembly s / Newton it. "
          "| contact s / Newton it. | contact share of the run | peak kB / DoF |")
    print("|---:|---:|---|---:|---:|---:|---:|---:|---:|")
    for line in details:
        print(line)


if __name__ == "__main__":
    main()
