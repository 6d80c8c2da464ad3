#!/usr/bin/env python3
"""Direct (MUMPS) against iterative (CG + ML multigrid) linear solver on the
Hertz scene at increasing uniform refinement, serial, one run after the
other; optionally `mpirun -np 2` at the largest levels.

Per run it reads summary.json (timing sections, Newton and Krylov
iterations, DoFs, dimension, degree) and the peak resident memory
(/usr/bin/time), and prints one markdown table: solve time per Newton
iteration, multigrid set-up per Newton iteration, Krylov iterations,
whole-run time, peak memory. The crossover is the smallest size at which
the iterative solve per Newton iteration is the faster; next to it the
size from which `Linear solver/Type = auto` of the binary takes the
iterative solver, and whether that choice matches the measurement.

2D (default): prm/hertz.prm at `Geometry/Global refinements` 0-4.
3D: the 3D Hertz scene (quarter hemisphere on a plate), whose level knob is
`Geometry/Hertz sphere/Sphere refinements` (picked from the scene's
`Geometry/Type`; any other scene: `Geometry/Global refinements`, or name it
with --level-key), with the element degree chosen by --degree:

  bench/solver_crossover.py --scene prm/hertz_3d.prm --degree 2 \\
                            --levels 1 2 3 4 --mpi-levels 3

Sphere refinements 1 / 2 / 3 / 4 = 1,836 / 8,124 / 54,684 / 412,764 DoFs
with Q2; 345 / 1,257 / 7,545 / 54,105 (5: 412,185) with Q1.

Below 2,000 DoFs "iterative" is a direct solve too: ML's coarsest level
(KLU, up to 2,000 rows) is then the whole matrix, and CG takes 1 iteration.

Guards, so that one run of a long bench cannot take the machine down:
  - the iterative run of a level goes first; the direct one is skipped (and
    reported as such) when that level's DoFs exceed --direct-max-dofs
    (3D default 100,000; 2D none) or the level exceeds --direct-max-level.
    A 3D factorisation grows much faster than a 2D one: MUMPS on the
    hemisphere took 4.6 s per Newton iteration and 1.7 GB at 54,684 DoFs
    (Q2), 5.6 s and 1.4 GB at 54,105 (Q1), measured at load 2.5-3.5; on Q1
    blocks 1.7 s at 47k and 74 s, 10 GB at 346k (doc/performance.md). At
    412k DoFs that extrapolates to 4-5 minutes per Newton iteration and
    13-18 GB: above the default, skipped;
  - a run longer than --timeout seconds is stopped and reported as "> T s";
  - a run whose processes together hold more than --memory-limit MB of
    resident memory is stopped and reported as "> M MB".
A run that fails otherwise is reported as failed (the bench goes on; exit
status 1 at the end).

Usage: bench/solver_crossover.py [--binary B] [--levels 0 1 2 3 4]
                                 [--mpi-levels 3 4] [--results DIR]
                                 [--scene prm/hertz.prm] [--degree 1|2]
                                 [--level-key Sub/Key] [--set Sub/Key=value]
                                 [--direct-max-dofs N] [--direct-max-level L]
                                 [--timeout S] [--memory-limit MB]
Results go to bench/results-solver/ for prm/hertz.prm at its own degree,
else to bench/results-solver-<scene>-q<degree>/ (ignored by git: results-*/),
with the report also in <results>/report.md. Timings are wall-clock: run it
on a quiet machine.
"""
import argparse
import json
import os
import pathlib
import re
import signal
import subprocess
import sys
import threading
import time

repo = pathlib.Path(__file__).resolve().parent.parent


# --------------------------------------------------------------------------
# the scene
# --------------------------------------------------------------------------
def read_prm(path, values=None, stack=None):
    """The `set` entries of a parameter file (following `include`), as
    "Subsection/Key" -> value."""
    values = {} if values is None else values
    stack = [] if stack is None else stack
    for raw in pathlib.Path(path).read_text().splitlines():
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        word, _, rest = line.partition(" ")
        rest = rest.strip()
        if word == "subsection":
            stack.append(rest)
        elif word == "end" and stack:
            stack.pop()
        elif word == "set" and "=" in rest:
            key, _, value = rest.partition("=")
            values["/".join(stack + [key.strip()])] = value.strip()
        elif word == "include":
            read_prm(pathlib.Path(path).parent / rest, values, stack)
    return values


def level_key_of(prm):
    """The refinement knob of the scene's geometry."""
    if prm.get("Geometry/Type", "").lower() == "hertz sphere":
        return "Geometry/Hertz sphere/Sphere refinements"
    return "Geometry/Global refinements"


def auto_crossover_from_source(dim):
    """Type = auto's crossover as written in the source (if the binary did
    not say it)."""
    try:
        text = (repo / "source" / "solvers" / "linear_solver.cc").read_text()
    except OSError:
        return None
    m = re.search(rf"crossover_{dim}d\s*=\s*(\d+)", text)
    return int(m.group(1)) if m else None


# --------------------------------------------------------------------------
# running: process tree, timeout, memory limit
# --------------------------------------------------------------------------
def process_tree(root):
    """pid -> resident kB of root and its descendants (mpirun's ranks too)."""
    parent, rss = {}, {}
    page_kb = os.sysconf("SC_PAGE_SIZE") // 1024
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
        except (OSError, IndexError):
            continue
        parent[int(entry)] = int(fields[1])
        rss[int(entry)] = int(fields[21]) * page_kb
    tree, todo = {}, [root]
    while todo:
        pid = todo.pop()
        if pid in rss and pid not in tree:
            tree[pid] = rss[pid]
            todo += [p for p, pp in parent.items() if pp == pid]
    return tree


def run_guarded(command, cwd, env, timeout, memory_limit_mb):
    """Runs command in its own session; stops it (the whole process tree)
    after timeout seconds or above memory_limit_mb of summed resident
    memory. Returns (CompletedProcess-like, status, largest summed RSS MB),
    status "ok", "timeout" or "memory"."""
    proc = subprocess.Popen(command, cwd=cwd, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, start_new_session=True)
    out, err = [], []
    readers = [threading.Thread(target=lambda s, b: b.append(s.read()), args=(s, b))
               for s, b in ((proc.stdout, out), (proc.stderr, err))]
    for t in readers:
        t.start()
    status, peak_sum_kb, start = "ok", 0, time.monotonic()
    while proc.poll() is None:
        tree = process_tree(proc.pid)
        peak_sum_kb = max(peak_sum_kb, sum(tree.values()))
        stop = None
        if timeout and time.monotonic() - start > timeout:
            stop = "timeout"
        elif memory_limit_mb and peak_sum_kb > 1024 * memory_limit_mb:
            stop = "memory"
        if stop:
            status = stop
            for sig in (signal.SIGTERM, signal.SIGKILL):
                for pid in list(process_tree(proc.pid)) + [proc.pid]:
                    try:
                        os.kill(pid, sig)
                    except ProcessLookupError:
                        pass
                try:
                    os.killpg(proc.pid, sig)
                except ProcessLookupError:
                    pass
                try:
                    proc.wait(timeout=10)
                    break
                except subprocess.TimeoutExpired:
                    continue
            break
        time.sleep(0.25)
    proc.wait()
    for t in readers:
        t.join()
    done = subprocess.CompletedProcess(command, proc.returncode, "".join(out), "".join(err))
    return done, status, peak_sum_kb / 1024.0


def run(binary, scene, level, solver, np, results, level_key, sets, timeout,
        memory_limit_mb):
    name = f"level{level}-{solver}-np{np}"
    out = results / name
    out.mkdir(parents=True, exist_ok=True)
    # The scene is run as it is (relative mesh paths resolve from its own
    # directory), with the bench's settings as command-line overrides.
    sets = [f"{level_key}={level}", f"Linear solver/Type={solver}",
            "Output/Write VTU=false", "Output/Write pressure profile=false"] + sets
    command = ["/usr/bin/time", "-f", "peak_kb %M"]
    if np > 1:
        command += ["mpirun", "-np", str(np)]
    command += [str(binary), str(scene), "--output-directory", str(out)]
    for s in sets:
        command += ["--set", s]
    env = dict(os.environ, OMP_NUM_THREADS="1", DEAL_II_NUM_THREADS="1",
               OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    summary_file = out / "summary.json"
    if summary_file.exists():
        summary_file.unlink()
    print(f"[{time.strftime('%H:%M:%S')}] {name}: {level_key} = {level}",
          file=sys.stderr, flush=True)
    done, status, _ = run_guarded(command, out, env, timeout, memory_limit_mb)
    (out / "console.txt").write_text(done.stdout + done.stderr)
    stopped = None
    if status == "timeout":
        stopped = {"status": "timeout", "note": f"> {timeout:g} s"}
    elif status == "memory":
        stopped = {"status": "memory", "note": f"> {memory_limit_mb:.0f} MB"}
    elif done.returncode != 0:
        print(f"{name} failed (exit {done.returncode}); see {out}/console.txt",
              file=sys.stderr, flush=True)
        stopped = {"status": "failed", "note": f"failed (exit {done.returncode})"}
    if stopped:
        # the size, if the run got as far as printing it
        m = re.search(r"Cycle 0: \d+ cells, (\d+) DoFs", done.stdout)
        if m:
            stopped["dofs"] = int(m.group(1))
        print(f"{name}: {stopped['note']}", file=sys.stderr, flush=True)
        return stopped
    # With MPI, /usr/bin/time reports the largest resident set of mpirun and
    # the ranks it waited for: the peak of one rank, not of the job.
    peak_kb = int(done.stderr.strip().splitlines()[-1].split()[-1])
    summary = json.loads(summary_file.read_text())
    cycle = summary["cycles"][0]
    steps = cycle["load_steps"]
    newton = sum(step["newton_iterations"] for step in steps)
    krylov = [n for step in steps for n in step.get("linear_iterations", [])]
    timing = cycle["timing"]
    return {
        "status": "ok",
        "dim": int(summary.get("dim", 2)),
        "degree": int(summary.get("degree", 1)),
        "linear_solver": cycle.get("linear_solver", ""),
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


def ok(r):
    return r is not None and r["status"] == "ok"


# --------------------------------------------------------------------------
# tables
# --------------------------------------------------------------------------
def detail(level, np, r, solver):
    """Seconds per Newton iteration of each part, the contact share and the
    memory per DoF."""
    if not ok(r):
        dofs = f"{r['dofs']:,}" if r.get("dofs") else "-"
        return f"| {level} | {np} | {solver} | {dofs} | {r['note']} | - | - | - | - |"
    n = r["newton"]
    return (f"| {level} | {np} | {solver} | {r['dofs']:,} | {r['solve'] / n:.3f} | "
            f"{r['assembly'] / n:.3f} | {r['contact'] / n:.4f} | "
            f"{100 * r['contact'] / r['wall']:.1f} % | {1024 * r['peak_mb'] / r['dofs']:.2f} |")


def row(level, np, direct, iterative):
    def per(r, key):
        return f"{r[key] / r['newton']:.3f}" if ok(r) else r["note"]

    def value(r, key, digits, otherwise):
        return f"{r[key]:.{digits}f}" if ok(r) else otherwise
    dofs = direct.get("dofs") or iterative.get("dofs")
    krylov = (f"{iterative['krylov_mean']:.0f} (max {iterative['krylov_max']})"
              if ok(iterative) and iterative["krylov_mean"] is not None else "-")
    newton = (f"{direct['newton'] if ok(direct) else '-'} / "
              f"{iterative['newton'] if ok(iterative) else '-'}")
    return (f"| {level} | {np} | {f'{dofs:,}' if dofs else '-'} | {newton} | "
            f"{per(direct, 'solve')} | {per(iterative, 'solve')} | "
            f"{per(iterative, 'setup') if ok(iterative) else '-'} | {krylov} | "
            f"{value(direct, 'wall', 1, direct.get('note'))} | "
            f"{value(iterative, 'wall', 1, iterative.get('note'))} | "
            f"{value(direct, 'peak_mb', 0, '-')} | {value(iterative, 'peak_mb', 0, '-')} |")


def iterative_faster(direct, iterative):
    """True / False, or None when the pair does not decide it (the direct run
    skipped or failed)."""
    if not ok(iterative):
        return False if ok(direct) else None
    if ok(direct):
        return iterative["solve"] / iterative["newton"] < direct["solve"] / direct["newton"]
    if direct["status"] in ("timeout", "memory"):
        return True  # the iterative run finished, the direct one did not
    return None


def auto_threshold(binary, scene, level, level_key, sets, results, dim, timeout,
                   memory_limit_mb):
    """The crossover of Type = auto as the binary says it (one short run at
    the smallest level), else as the source says it."""
    r = run(binary, scene, level, "auto", 1, results, level_key, sets, timeout,
            memory_limit_mb)
    text = r.get("linear_solver", "")
    m = re.search(r"(\d)D crossover (\d+)", text)
    if m:
        return int(m.group(2)), f"this binary, at level {level}: \"{text}\""
    value = auto_crossover_from_source(dim)
    why = f"the binary said \"{text}\"" if text else f"the auto run: {r.get('note', '?')}"
    return value, f"source/solvers/linear_solver.cc ({why})"


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.splitlines()[0],
        epilog="See the top of the script for the guards and the 3D levels.")
    parser.add_argument("--binary", default=str(repo / "build" / "contact_fem"))
    parser.add_argument("--scene", default=str(repo / "prm" / "hertz.prm"))
    parser.add_argument("--levels", type=int, nargs="+",
                        help="values of the level key [2D: 0 1 2 3 4; 3D: 1 2 3 4]")
    parser.add_argument("--mpi-levels", type=int, nargs="*", default=[])
    parser.add_argument("--results",
                        help="[bench/results-solver for prm/hertz.prm at its own degree, "
                             "else bench/results-solver-<scene>-q<degree>]")
    parser.add_argument("--degree", type=int, choices=(1, 2),
                        help="Finite element/Degree [the scene's]")
    parser.add_argument("--level-key",
                        help="the refinement parameter the levels set [from the scene: "
                             "Geometry/Hertz sphere/Sphere refinements for Type = hertz "
                             "sphere, else Geometry/Global refinements]")
    parser.add_argument("--set", action="append", default=[], metavar="SUB/KEY=VALUE",
                        help="further overrides of every run, after the bench's own")
    parser.add_argument("--direct-max-dofs", type=int,
                        help="skip the direct run of a level whose iterative run has "
                             "more DoFs [3D: 100000; 2D: no limit]; 0: no limit")
    parser.add_argument("--direct-max-level", type=int,
                        help="skip the direct runs above this level [no limit]")
    parser.add_argument("--timeout", type=float, default=1800.,
                        help="seconds per run; a longer run is stopped and reported as "
                             "'> T s' [1800]; 0: none")
    parser.add_argument("--memory-limit", type=float,
                        help="MB of resident memory of a run (all its processes); a run "
                             "above it is stopped and reported as '> M MB' [85 %% of "
                             "MemAvailable at start]; 0: none")
    parser.add_argument("--no-auto-check", action="store_true",
                        help="do not run Type = auto at the smallest level to read its "
                             "crossover from the binary (the source's value is printed)")
    args = parser.parse_args()
    scene = pathlib.Path(args.scene).resolve()
    prm = read_prm(scene)
    dim = int(prm.get("Dimension", "2"))
    scene_degree = int(prm.get("Finite element/Degree", "1"))
    degree = args.degree or scene_degree
    level_key = args.level_key or level_key_of(prm)
    levels = args.levels if args.levels else ([0, 1, 2, 3, 4] if dim == 2 else [1, 2, 3, 4])
    sets = ([f"Finite element/Degree={args.degree}"] if args.degree else []) + args.set
    if level_key.startswith("Geometry/Hertz sphere/"):
        # Uniform levels: the prm's default grades the sphere toward the
        # contact (a --set may still ask for that).
        sets = ["Geometry/Hertz sphere/Contact refinements=0"] + sets
    if args.results:
        results = pathlib.Path(args.results).resolve()
    elif scene == (repo / "prm" / "hertz.prm").resolve() and degree == scene_degree \
            and not args.set:
        results = repo / "bench" / "results-solver"
    else:
        results = repo / "bench" / f"results-solver-{scene.stem}-q{degree}"
    results.mkdir(parents=True, exist_ok=True)
    direct_max_dofs = args.direct_max_dofs
    if direct_max_dofs is None:
        direct_max_dofs = 100000 if dim == 3 else 0
    memory_limit = args.memory_limit
    if memory_limit is None:
        with open("/proc/meminfo") as f:
            avail = [int(line.split()[1]) for line in f if line.startswith("MemAvailable:")]
        memory_limit = 0.85 * avail[0] / 1024 if avail else 0
    guards = (args.timeout, memory_limit)

    lines = []

    def emit(line=""):
        print(line, flush=True)
        lines.append(line)

    emit("| level | ranks | DoFs | Newton it. (direct / iterative) | direct solve s / Newton it. "
         "| iterative solve s / Newton it. | of which multigrid set-up | Krylov it. per solve "
         "| direct run s | iterative run s | direct peak MB | iterative peak MB |")
    emit("|---:|---:|---:|---|---:|---:|---:|---|---:|---:|---:|---:|")
    serial = []  # (level, DoFs, iterative faster?) of the decided serial levels
    undecided = []  # (level, DoFs or None, why)
    details = []
    failed = False
    runs = [(level, 1) for level in levels] + [(level, 2) for level in args.mpi_levels]
    for level, np in runs:
        iterative = run(args.binary, scene, level, "iterative", np, results, level_key,
                        sets, *guards)
        skip = None
        if args.direct_max_level is not None and level > args.direct_max_level:
            skip = f"skipped (level > {args.direct_max_level})"
        elif direct_max_dofs and iterative.get("dofs", 0) > direct_max_dofs:
            skip = f"skipped (> {direct_max_dofs:,} DoFs)"
        if skip:
            direct = {"status": "skipped", "note": skip}
            print(f"level{level}-direct-np{np}: {skip}", file=sys.stderr, flush=True)
        else:
            direct = run(args.binary, scene, level, "direct", np, results, level_key,
                         sets, *guards)
        failed |= any(r["status"] in ("failed", "timeout", "memory")
                      for r in (direct, iterative))
        emit(row(level, np, direct, iterative))
        details += [detail(level, np, direct, "direct"),
                    detail(level, np, iterative, "iterative")]
        faster = iterative_faster(direct, iterative)
        dofs = iterative.get("dofs") or direct.get("dofs")
        if np == 1:
            if faster is None:
                why = (f"direct {direct['note']}" if not ok(direct)
                       else f"iterative {iterative['note']}")
                undecided.append((level, dofs, why))
            else:
                serial.append((level, dofs, faster))
    emit()
    where = f"{dim}D Q{degree}, {scene.name}, {level_key}"
    crossover = next((dofs for _, dofs, faster in serial if faster), None)
    if crossover:
        text = "%d DoFs" % crossover
        below = [dofs for _, dofs, faster in serial if not faster and dofs < crossover]
        above = [dofs for _, dofs, faster in serial if not faster and dofs > crossover]
        if below:
            text += f" (the direct solve the faster at {max(below)})"
        if above:
            text += f"; the direct solve the faster again at {', '.join(map(str, above))}"
    else:
        text = "not reached"
    if undecided:
        text += "; not decided at " + ", ".join(f"level {level} ({why})"
                                                for level, _, why in undecided)
    emit(f"crossover (serial, {where}): {text}")

    if (serial or undecided) and not args.no_auto_check:
        threshold, source = auto_threshold(args.binary, scene, min(levels), level_key, sets,
                                           results, dim, *guards)
    else:
        threshold, source = auto_crossover_from_source(dim), "source/solvers/linear_solver.cc"
    if threshold is not None:
        picks = []
        mismatch = []
        cases = sorted([(level, dofs, faster, None) for level, dofs, faster in serial] +
                       [(level, dofs, None, why) for level, dofs, why in undecided])
        for level, dofs, faster, why in cases:
            if dofs is None:
                picks.append(f"level {level}: not measured ({why})")
                continue
            auto_iterative = dofs >= threshold
            picks.append(f"level {level} ({dofs:,} DoFs): auto "
                         f"{'iterative' if auto_iterative else 'direct'}, measured faster "
                         + (f"{'iterative' if faster else 'direct'}" if why is None
                            else f"not decided ({why})"))
            if why is None and auto_iterative != faster:
                mismatch.append(f"level {level}")
        verdict = ("no level decided." if not serial else
                   "auto's choice matches the measurement at every decided level."
                   if not mismatch else "auto's choice differs at " + ", ".join(mismatch) + ".")
        emit(f"Linear solver/Type = auto: iterative from {threshold} DoFs in {dim}D "
             f"({source}); " + "; ".join(picks) + ". " + verdict)
    else:
        emit(f"Linear solver/Type = auto: its {dim}D crossover not found ({source}).")
    emit()
    emit("| level | ranks | solver | DoFs | solve s / Newton it. | assembly s / Newton it. "
         "| contact s / Newton it. | contact share of the run | peak kB / DoF |")
    emit("|---:|---:|---|---:|---:|---:|---:|---:|---:|")
    for line in details:
        emit(line)
    (results / "report.md").write_text("\n".join(lines) + "\n")
    print(f"report: {results / 'report.md'}", file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
