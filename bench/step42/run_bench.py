#!/usr/bin/env python3
"""contact_fem side by side with deal.II's step-42: cost per DoF and Newton
iteration.

What it does, in this order (one heavy job at a time):

 1. checks that deal.II's step-42 is installed
    (/usr/share/doc/libdeal.ii-doc/examples/step-42, Debian package
    libdeal.ii-doc); it installs nothing itself;
 2. copies step-42 into <build-dir>/src, applies step-42-bench.patch (see
    README.md beside this script: yield stress and VTU output as parameters,
    the plastic zone printed, the first residuals timed), builds it with
    cmake -DCMAKE_BUILD_TYPE=Release (reused while the source and the patch
    are unchanged);
 3. runs step-42 on p1_adaptive.prm as shipped (Q1, 3 initial global
    refinements, sphere obstacle, Kelly "percentage" refinement) but with the
    yield stress raised to 1e10 (linear elastic) and without VTU output, for
    --step42-cycles cycles, serial, then the same run under
    "mpirun -np NP"; optionally (--step42-plastic-cycles) the shipped
    elastoplastic material (yield stress 400) too;
 4. runs contact_fem on prm/hertz.prm (2D) at every --hertz-levels value
    of Geometry/Global refinements, serial, then the largest level under
    "mpirun -np NP"; always with Output/Write VTU = false and Output/Print
    timing = true, plus the user's --set overrides and --prm-snippet;
 5. runs contact_fem's 3D Hertz, prm/hertz_3d.prm (a quarter hemisphere
    on a plate), with Q1 (step-42's element, 81 matrix entries per
    interior row) at every --contact-fem-3d-levels value of Geometry/Hertz
    sphere/Sphere refinements, then with Q2 at every
    --contact-fem-3d-q2-levels value (none by default), serial, with
    Linear solver/Type = iterative (CG + ML AMG; step-42 solves with AMG
    too), then the largest Q1 level under "mpirun -np NP"; Output/Write
    VTU = false, Output/Print timing = true, plus --set-3d;
 6. prints a Markdown report (also written to <results>/report.md, raw
    numbers to <results>/data.json).

Cost per DoF-iteration = seconds / (DoFs x Newton iterations), in
microseconds, for the whole cycle (total), the linear solves and the
assembly. One Newton iteration = one linear solve in both programs.

Cost per matrix entry and iteration = the same seconds / (DoFs x entries
per row x Newton iterations): neither program prints its number of
nonzeros, so the entries per row are the interior-row average of a regular
mesh of the element, an approximation (see entries_per_row()): 2D Q1 18,
2D Q2 32, 3D Q1 81, 3D Q2 192 (a vertex row of 3D Q2 has 375, an edge row
225, a face row 135, a cell row 81; a regular mesh has 1 : 3 : 3 : 1 of
them). Boundary rows have fewer entries, rows coupled by the contact
(mortar) or by hanging nodes more.

  step-42 (per cycle, from its TimerOutput table, which it prints and
  resets every cycle):
    total    = "Total wallclock time elapsed since start" (setup incl. the
               Kelly estimate and refinement, Newton loop, line search,
               untimed remainder)
    solve    = "Solve" (AMG set-up + BiCGStab, every Newton iteration)
    assembly = "Assembling" (Newton matrix and right-hand side, integrated
               anew every iteration) + "Residual and lambda" (the nonlinear
               residual of the accepted and of the line-search iterates)
    contact  = "update active set";  setup = "Setup"
  contact_fem (summary.json, one cycle, all load steps):
    total    = wall_time
    solve    = the "Solve..." sections (today "Solve: linear")
    assembly = the "Assembly..." sections (bulk = cell matrices once per
               mesh and loads, system = distribution per iteration, residual)
    contact  = the "Contact..." sections;  setup = the "Setup..." sections

Usage:
  python3 bench/step42/run_bench.py [options]
  python3 bench/step42/run_bench.py --skip-step42 --skip-contact-fem-2d \
      --contact-fem-3d-levels 3 4 5     # only the 3D contact_fem rows

Options (defaults in brackets):
  --binary PATH             contact_fem executable [<repo>/build/contact_fem]
  --results DIR             output [bench/step42/results/run-<UTC time>]
  --build-dir DIR           step-42 build [bench/step42/results/step42-build]
  --step42-cycles N         adaptive cycles of step-42 [6: up to 0.49M DoFs;
                            7 reaches 1.49M DoFs, +6 min serial]
  --step42-initial-refinements N   [3, as p1_adaptive.prm]
  --step42-yield-stress X   [1e10: linear elastic]
  --step42-plastic-cycles N also run the shipped yield stress 400 for N
                            cycles, serial [5; 0: no]
  --hertz-prm FILE          contact_fem 2D scene [prm/hertz.prm]
  --hertz-levels "0 1 2"    Global refinements [0 1 2 3 4]
  --np N                    ranks of the MPI runs at the largest size;
                            0 = no MPI run [2]
  --set "Sub/Key=value"     contact_fem override of the 2D scene,
                            repeatable, e.g.
                            --set "Linear solver/Type=iterative"
  --prm-snippet FILE        .prm lines appended after "include <hertz.prm>"
                            (a wrapper file in the results directory)
  --contact-fem-3d-prm FILE contact_fem 3D scene [prm/hertz_3d.prm]
  --contact-fem-3d-levels 3 4 5
                            Sphere refinements of the Q1 3D rows [3 4 5:
                            7,545 / 54,105 / 412,185 DoFs]; none: no Q1
                            rows. 6 has 3.3 million DoFs: too large here
  --contact-fem-3d-q2-levels 2 3 4
                            Sphere refinements of the Q2 3D rows [none]
                            (8,124 / 54,684 / 412,764 DoFs; 5 has 3.3
                            million: too large here)
  --set-3d "Sub/Key=value"  override of the 3D runs, after the bench's own
                            (Type = iterative, the level, the degree)
  --skip-step42, --skip-contact-fem (2D and 3D), --skip-contact-fem-2d
  --step42-from DATA_JSON   with --skip-step42: the step-42 rows (and runs)
                            of an earlier run's data.json go into this
                            report [the newest
                            bench/step42/results/run-*/data.json that has
                            step-42 rows]; "none": no step-42 rows
  --timeout S               per run [3600]
  --jobs N                  make -j for step-42 [2]

Threads are pinned to one per process (OMP_NUM_THREADS=1,
DEAL_II_NUM_THREADS=1). Standard library only.
"""

import argparse
import datetime
import hashlib
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
STEP42_SRC = Path("/usr/share/doc/libdeal.ii-doc/examples/step-42")
PATCH = HERE / "step-42-bench.patch"

MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"}
THREAD_ENV = {"OMP_NUM_THREADS": "1", "DEAL_II_NUM_THREADS": "1"}


def log(msg):
    print(f"[{datetime.datetime.utcnow():%H:%M:%S}] {msg}", file=sys.stderr, flush=True)


# --------------------------------------------------------------------------
# running a command: elapsed time and peak RSS of the process (wait4)
# --------------------------------------------------------------------------
def run_measured(cmd, cwd, stdout_path, timeout, extra_env=None):
    env = dict(os.environ)
    env.update(THREAD_ENV)
    env.update(MPI_ENV)
    if extra_env:
        env.update(extra_env)
    load = open("/proc/loadavg").read().split()[:3]
    t0 = time.monotonic()
    with open(stdout_path, "w") as out:
        out.write("# " + " ".join(str(c) for c in cmd) + "\n")
        out.flush()
        proc = subprocess.Popen([str(c) for c in cmd], cwd=str(cwd), stdout=out,
                                stderr=subprocess.STDOUT, env=env,
                                start_new_session=True)
        timed_out = []

        def kill():
            timed_out.append(True)
            try:
                os.killpg(proc.pid, signal.SIGTERM)
            except ProcessLookupError:
                pass

        timer = threading.Timer(timeout, kill)
        timer.start()
        _, status, usage = os.wait4(proc.pid, 0)
        timer.cancel()
        proc.returncode = os.waitstatus_to_exitcode(status)
    elapsed = time.monotonic() - t0
    load_after = open("/proc/loadavg").read().split()[:3]
    return {"rc": proc.returncode, "elapsed": elapsed,
            "peak_rss_mb": usage.ru_maxrss / 1024.0,
            "timed_out": bool(timed_out), "load_before": " ".join(load),
            "load_after": " ".join(load_after),
            "command": " ".join(str(c) for c in cmd)}


# --------------------------------------------------------------------------
# step-42: build
# --------------------------------------------------------------------------
def check_step42():
    if not (STEP42_SRC / "step-42.cc").is_file():
        sys.exit(f"run_bench.py: {STEP42_SRC} not found: deal.II's examples are "
                 "in the Debian package libdeal.ii-doc:\n"
                 "    apt-get install libdeal.ii-doc")


def build_step42(build_dir, jobs):
    """Copy, patch, build (Release). Returns the executable."""
    build_dir = build_dir.resolve()
    key = hashlib.sha256((STEP42_SRC / "step-42.cc").read_bytes() +
                         PATCH.read_bytes()).hexdigest()
    exe = build_dir / "build" / "step-42"
    stamp = build_dir / "source.sha256"
    if exe.is_file() and stamp.is_file() and stamp.read_text().strip() == key:
        log(f"step-42: reusing {exe}")
        return exe
    if build_dir.exists():
        shutil.rmtree(build_dir)
    src = build_dir / "src"
    shutil.copytree(STEP42_SRC, src)
    subprocess.run(["patch", "-p1", "--no-backup-if-mismatch", "-i", str(PATCH)],
                   cwd=src, check=True, stdout=subprocess.DEVNULL)
    (build_dir / "build").mkdir()
    blog = open(build_dir / "build.log", "w")
    log(f"step-42: configuring and building in {build_dir} (Release)")
    for cmd in (["cmake", "-DCMAKE_BUILD_TYPE=Release", str(src)],
                ["make", f"-j{jobs}"]):
        r = subprocess.run(cmd, cwd=build_dir / "build", stdout=blog,
                           stderr=subprocess.STDOUT)
        if r.returncode != 0:
            sys.exit(f"run_bench.py: '{' '.join(cmd)}' failed, see "
                     f"{build_dir / 'build.log'}")
    if not exe.is_file():
        sys.exit(f"run_bench.py: no {exe} after the build")
    stamp.write_text(key + "\n")
    return exe


# --------------------------------------------------------------------------
# step-42: run and parse
# --------------------------------------------------------------------------
def step42_prm(path, outdir, cycles, initial, yield_stress):
    path.write_text(
        "# p1_adaptive.prm of deal.II's step-42, for the bench\n"
        "set polynomial degree             = 1\n"
        f"set number of initial refinements = {initial}\n"
        f"set number of cycles              = {cycles}\n"
        "set refinement strategy           = percentage\n"
        "set obstacle                      = sphere\n"
        f"set output directory              = {outdir}/\n"
        "# bench patch: linear elastic unless the yield stress is the shipped 400\n"
        f"set yield stress                  = {yield_stress}\n"
        "set graphical output              = false\n")


TIMER_ROW = re.compile(r"^\|\s*(.+?)\s*\|\s*(\d+)\s*\|\s*([0-9.eE+-]+)s\s*\|")
TIMER_TOTAL = re.compile(r"Total wallclock time elapsed since start\s*\|\s*([0-9.eE+-]+)s")


def parse_step42(text):
    cycles = []
    cur = None
    for line in text.splitlines():
        m = re.match(r"^Cycle (\d+):", line)
        if m:
            cur = {"cycle": int(m.group(1)), "newton": 0, "bicgstab": [],
                   "timing": {}, "calls": {}}
            cycles.append(cur)
            continue
        if cur is None:
            continue
        if m := re.search(r"Number of active cells:\s*(\d+)", line):
            cur["cells"] = int(m.group(1))
        elif m := re.search(r"Number of degrees of freedom:\s*(\d+)", line):
            cur["dofs"] = int(m.group(1))
        elif re.match(r"^\s*Newton iteration \d+", line):
            cur["newton"] += 1
        elif m := re.search(r"in (\d+) Bicgstab iterations", line):
            cur["bicgstab"].append(int(m.group(1)))
        elif m := re.search(r"Size of active set:\s*(\d+)", line):
            cur["active_set"] = int(m.group(1))
        elif m := re.search(r"Plastic quadrature points:\s*(\d+) of (\d+)", line):
            cur["plastic_q"] = int(m.group(1))
            cur["q_points"] = int(m.group(2))
        elif m := TIMER_TOTAL.search(line):
            cur["total"] = float(m.group(1))
        elif m := TIMER_ROW.match(line):
            cur["timing"][m.group(1)] = float(m.group(3))
            cur["calls"][m.group(1)] = int(m.group(2))
        elif m := re.search(r"resident in kB:\s*(\d+)\s+(\d+)", line):
            cur["vm_rss_mb"] = int(m.group(2)) / 1024.0
        elif m := re.search(r"Contact force =\s*(\S+)", line):
            cur["contact_force"] = float(m.group(1))
    rows = []
    for c in cycles:
        if "total" not in c or "dofs" not in c:
            continue  # unfinished cycle
        t = c["timing"]
        rows.append({
            "cycle": c["cycle"], "cells": c.get("cells"), "dofs": c["dofs"],
            "its": c["newton"], "wall": c["total"],
            "solve": t.get("Solve", 0.0),
            "assembly": t.get("Assembling", 0.0) + t.get("Residual and lambda", 0.0),
            "assembly_matrix": t.get("Assembling", 0.0),
            "residual": t.get("Residual and lambda", 0.0),
            "amg_setup": t.get("Solve: setup preconditioner", 0.0),
            "krylov": t.get("Solve: iterate", 0.0),
            "contact": t.get("update active set", 0.0),
            "setup": t.get("Setup", 0.0),
            "output": t.get("Graphical output", 0.0),
            "lin_its": (sum(c["bicgstab"]) / len(c["bicgstab"])) if c["bicgstab"] else None,
            "lin_its_list": c["bicgstab"],
            "active": c.get("active_set"),
            "plastic_q": c.get("plastic_q"), "q_points": c.get("q_points"),
            "contact_force": c.get("contact_force"),
            "vm_rss_mb": c.get("vm_rss_mb"),
            "timing": t,
        })
    return rows


def run_step42(exe, results, label, cycles, initial, yield_stress, np_, timeout):
    d = results / label
    d.mkdir(parents=True, exist_ok=True)
    prm = d / "input.prm"
    step42_prm(prm, d / "output", cycles, initial, yield_stress)
    cmd = ([*mpirun(np_), str(exe), str(prm)] if np_ > 0 else [str(exe), str(prm)])
    log(f"step-42 {label}: {cycles} cycles, yield stress {yield_stress}, "
        f"{'np ' + str(np_) if np_ else 'serial'}")
    rec = run_measured(cmd, d, d / "stdout.txt", timeout)
    rows = parse_step42((d / "stdout.txt").read_text(errors="replace"))
    for r in rows:
        r.update(program="step-42", ranks=max(np_, 1), label=label,
                 yield_stress=yield_stress, case=f"cycle {r['cycle']}",
                 dim=3, degree=1, entries_per_row=entries_per_row(3, 1))
    log(f"step-42 {label}: rc {rec['rc']}, {rec['elapsed']:.1f} s, "
        f"{len(rows)} cycles parsed")
    return {"run": rec, "rows": rows}


def mpirun(np_):
    return ["mpirun", "-np", str(np_), "--bind-to", "none"]


# --------------------------------------------------------------------------
# contact_fem
# --------------------------------------------------------------------------
def entries_per_row(dim, degree):
    """Matrix entries per row, approximately: the average over the rows of
    a regular mesh's interior (no boundary, no constraints). A node couples
    with the nodes of the cells around it, dim components each. 2D Q2:
    vertex 25 nodes, edge 15, cell 9, in the ratio 1 : 2 : 1 -> 2 x 16 = 32.
    3D Q2: vertex 125, edge 75, face 45, cell 27, ratio 1 : 3 : 3 : 1 ->
    3 x 64 = 192."""
    nodes = {(2, 1): 9, (2, 2): 16, (3, 1): 27, (3, 2): 64}.get((dim, degree))
    return dim * nodes if nodes else None


def contact_fem_rows(summary, label, ranks, level, case=None):
    rows = []
    dim = int(summary.get("dim", 2))
    degree = int(summary.get("degree", 1))
    for c in summary.get("cycles", []):
        t = c.get("timing", {})

        # Sections that are parts of another one ("Solve: multigrid setup"
        # is inside "Solve: linear"): counted once.
        parts = {"Solve: multigrid setup"}

        def group(prefix):
            if prefix in t:  # a parent section: do not add its children too
                return t[prefix]
            return sum(v for k, v in t.items()
                       if k.startswith(prefix + ":") and k not in parts)

        its = sum(ls.get("newton_iterations", 0) for ls in c.get("load_steps", []))
        krylov = [n for ls in c.get("load_steps", []) for n in ls.get("linear_iterations", [])]
        rows.append({
            "program": "contact_fem", "label": label, "ranks": ranks,
            "case": case or f"GR {level}", "level": level,
            "dim": dim, "degree": degree, "entries_per_row": entries_per_row(dim, degree),
            "cells": c.get("n_cells"), "dofs": c.get("n_dofs"), "its": its,
            "its_per_step": [ls.get("newton_iterations") for ls in c.get("load_steps", [])],
            "wall": c.get("wall_time", summary.get("wall_time")),
            "solve": group("Solve"), "assembly": group("Assembly"),
            "contact": group("Contact"), "setup": group("Setup"),
            "output": group("Output"), "check": group("Check"),
            "lin_its": sum(krylov) / len(krylov) if krylov else None,
            "active": c.get("contact", {}).get("active_slave_nodes"),
            "status": summary.get("status"), "timing": t,
        })
    if len(summary.get("cycles", [])) == 1 and "wall_time" in summary:
        rows[0]["wall"] = summary["wall_time"]
    return rows


def run_contact_fem(binary, scene, level, sets, results, np_, timeout,
                    level_key="Geometry/Global refinements", case=None, tag=None):
    """One contact_fem run; case names the rows ("GR 2", "3D Q1 SR 4"), tag
    the run directory."""
    case = case or f"GR {level}"
    tag = tag or f"GR{level}"
    label = f"contact_fem-{tag}-" + (f"np{np_}" if np_ else "serial")
    d = results / label
    d.mkdir(parents=True, exist_ok=True)
    # a summary.json left by an earlier run into the same folder is not
    # this run's
    stale = d / "output" / "summary.json"
    if stale.exists():
        stale.unlink()
    cmd = [str(binary), str(scene)]
    for s in ([f"{level_key}={level}",
               "Output/Write VTU=false", "Output/Print timing=true"] + sets):
        cmd += ["--set", s]
    cmd += ["--output-directory", str(d / "output")]
    if np_:
        cmd = mpirun(np_) + cmd
    log(f"contact_fem {case}, {'np ' + str(np_) if np_ else 'serial'}")
    rec = run_measured(cmd, REPO, d / "stdout.txt", timeout)
    rows = []
    try:
        summary = json.loads((d / "output" / "summary.json").read_text())
        rows = contact_fem_rows(summary, label, max(np_, 1), level, case)
        if rec["rc"] == 0:
            shutil.copy(d / "output" / "summary.json", d / "summary.json")
    except (OSError, ValueError) as e:
        log(f"contact_fem {case}: no summary.json ({e})")
    log(f"contact_fem {case}: rc {rec['rc']}{' (timeout)' if rec['timed_out'] else ''}, "
        f"{rec['elapsed']:.1f} s, peak RSS {rec['peak_rss_mb']:.0f} MB")
    return {"run": rec, "rows": rows}


# --------------------------------------------------------------------------
# report
# --------------------------------------------------------------------------
def per(x, r):
    """microseconds per DoF and Newton iteration"""
    if x is None or not r.get("dofs") or not r.get("its"):
        return None
    return 1e6 * x / (r["dofs"] * r["its"])


def per_entry(x, r):
    """microseconds per matrix entry (approximate entries per row) and
    Newton iteration"""
    p = per(x, r)
    if p is None or not r.get("entries_per_row"):
        return None
    return p / r["entries_per_row"]


def f(x, digits=2):
    if x is None:
        return "-"
    if isinstance(x, int):
        return f"{x:,}"
    return f"{x:.{digits}f}"


def main_table(rows):
    out = ["| Program | Case | Ranks | DoFs | Newton its | Wall [s] | Solve [s] | "
           "Assembly [s] | Contact [s] | Setup [s] | Total µs/(DoF·it) | "
           "Solve µs/(DoF·it) | Assembly µs/(DoF·it) | Krylov its/solve | "
           "Entries/row (approx.) | Total µs/(entry·it) | Solve µs/(entry·it) |",
           "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        its = str(r["its"])
        if r.get("its_per_step"):
            its += " (" + "+".join(str(i) for i in r["its_per_step"]) + ")"
        prog = r["program"]
        if prog == "step-42" and r.get("yield_stress", 1e10) < 1e9:
            prog += " (plastic)"
        out.append(
            f"| {prog} | {r['case']} | {r['ranks']} | {f(r['dofs'])} | {its} | "
            f"{f(r['wall'])} | {f(r['solve'])} | {f(r['assembly'])} | "
            f"{f(r['contact'], 3)} | {f(r['setup'])} | {f(per(r['wall'], r))} | "
            f"{f(per(r['solve'], r))} | {f(per(r['assembly'], r))} | "
            f"{f(r['lin_its'], 1)} | {f(r.get('entries_per_row'))} | "
            f"{f(per_entry(r['wall'], r), 3)} | {f(per_entry(r['solve'], r), 3)} |")
    return out


def comparable_table(c_rows, s_rows):
    """Each contact_fem size next to the step-42 cycle nearest in DoFs."""
    out = ["| contact_fem | DoFs | step-42 | DoFs | Total µs/(DoF·it) c_fem / step-42 | "
           "ratio | Solve c_fem / step-42 | ratio | Assembly c_fem / step-42 | ratio | "
           "Total µs/(entry·it) c_fem / step-42 | ratio | Solve µs/(entry·it) "
           "c_fem / step-42 | ratio |",
           "|---|---:|---|---:|---|---:|---|---:|---|---:|---|---:|---|---:|"]
    for c in c_rows:
        cands = [s for s in s_rows if s["ranks"] == c["ranks"]]
        if not cands:
            continue
        s = min(cands, key=lambda s: abs(math.log(s["dofs"] / c["dofs"])))
        cells = []
        for key in ("wall", "solve", "assembly"):
            a, b = per(c[key], c), per(s[key], s)
            cells.append(f"{f(a)} / {f(b)}")
            cells.append(f(a / b) if a is not None and b else "-")
        for key in ("wall", "solve"):
            a, b = per_entry(c[key], c), per_entry(s[key], s)
            cells.append(f"{f(a, 3)} / {f(b, 3)}")
            cells.append(f(a / b) if a is not None and b else "-")
        rk = f" ({c['ranks']} ranks)" if c["ranks"] > 1 else ""
        out.append(f"| {c['case']}{rk} | {f(c['dofs'])} | {s['case']}{rk} | "
                   f"{f(s['dofs'])} | " + " | ".join(cells) + " |")
    return out


def machine():
    env = {k: v for k, v in os.environ.items() if k != "OMP_NUM_THREADS"}
    model = "unknown"
    try:
        for line in subprocess.run(["lscpu"], capture_output=True, text=True,
                                   env=env).stdout.splitlines():
            if line.startswith("Model name:"):
                model = line.split(":", 1)[1].strip()
    except OSError:
        pass
    return f"{model}, {os.cpu_count()} cores"


def git_rev():
    try:
        return subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=REPO,
                              capture_output=True, text=True).stdout.strip()
    except OSError:
        return "?"


def ranks_note(r):
    return f" ({r['ranks']} ranks)" if r["ranks"] > 1 else ""


def report(data, args):
    rows = data["rows"]
    s_rows = [r for r in rows if r["program"] == "step-42" and r.get("yield_stress", 0) >= 1e9]
    p_rows = [r for r in rows if r["program"] == "step-42" and r.get("yield_stress", 0) < 1e9]
    c_rows = [r for r in rows if r["program"] == "contact_fem"]
    c2 = [r for r in c_rows if r.get("dim", 2) == 2]
    c3 = [r for r in c_rows if r.get("dim", 2) == 3]
    # the settings of step-42's rows: this run's, or those of the run they
    # were taken from (--skip-step42, --step42-from)
    s42 = data.get("step42_from")
    s_args = s42["args"] if s42 else vars(args)
    lines = ["# contact_fem and deal.II's step-42: cost per DoF and Newton iteration", "",
             f"- Date: {data['date']}; machine: {data['machine']}; load average "
             f"before the first run: {data['load_first']}",
             f"- contact_fem: git {data['git']}, `{data['binary']}`"]
    if c2:
        lines.append(
            f"- contact_fem 2D: `{data['scene']}` at Global refinements {args.hertz_levels}, "
            "`Output/Write VTU=false`, `Output/Print timing=true`"
            + ("".join(f", `--set \"{s}\"`" for s in args.set))
            + (f", snippet `{args.prm_snippet}`" if args.prm_snippet else ""))
    if c3:
        lines.append(
            f"- contact_fem 3D (rows \"3D Qk SR n\"): `{data.get('scene_3d')}` at "
            f"`Geometry/Hertz sphere/Sphere refinements` "
            + "; ".join(f"{' '.join(map(str, lv))} with Q{deg}"
                        for deg, lv in ((1, data.get("levels_3d", [])),
                                        (2, data.get("levels_3d_q2", []))) if lv)
            + ", `Linear solver/Type=iterative` (CG + ML AMG), `Output/Write VTU=false`, "
            "`Output/Print timing=true`"
            + ("".join(f", `--set-3d \"{s}\"`" for s in args.set_3d)))
    if s_rows or p_rows:
        lines.append(
            f"- step-42: deal.II's example (libdeal.ii-doc) plus step-42-bench.patch, "
            f"Release; p1_adaptive.prm (Q1, {s_args.get('step42_initial_refinements', 3)} "
            f"initial refinements, sphere obstacle, Kelly 30 %/3 %), "
            f"{s_args.get('step42_cycles', '?')} cycles, yield stress "
            f"{s_args.get('step42_yield_stress', 1e10):g}, no VTU output"
            + (f". **Rows taken from an earlier run**: `{s42['path']}` ({s42['date']}, "
               f"machine {s42['machine']}, load before its first run {s42['load_first']})"
               if s42 else ""))
    lines += ["- One run each; OMP_NUM_THREADS=1, DEAL_II_NUM_THREADS=1; " +
              (f"MPI runs with `mpirun -np {args.np}` at the largest size only "
               "(step-42 repeats every cycle to get there; its MPI rows are the "
               "last two cycles of that run; contact_fem 3D: the largest Q1 level)."
               if args.np > 0 else "no MPI runs."),
              "- µs/(DoF·it) = 1e6 x seconds / (DoFs x Newton iterations). Newton its "
              "of contact_fem: all load steps (per step in brackets). Krylov its: "
              "BiCGStab iterations per Newton solve of step-42 (AMG-preconditioned), "
              "CG iterations per solve of contact_fem's iterative solver (ML AMG).",
              "- µs/(entry·it) = µs/(DoF·it) / (matrix entries per row). Neither program "
              "prints its number of nonzeros: entries per row are **approximate**, the "
              "interior-row average of a regular mesh of the element (2D Q1 18, 2D Q2 32, "
              "3D Q1 81, 3D Q2 192, whose vertex rows have 375); boundary rows have "
              "fewer, rows coupled by the mortar contact or by hanging nodes more.",
              ""]
    lines += main_table(c_rows + s_rows + p_rows)
    checks = [r for r in c_rows if r.get("check") and r.get("wall")]
    if checks:
        lines += ["", "contact_fem's held-rotation check (the `Check: ...` sections: CG "
                  "solves with the iterative solver, back substitutions with the direct "
                  "one; step-42 has no such check) is in Wall and Total, in no other "
                  "column: " + "; ".join(
                      f"{r['case']}{ranks_note(r)} {r['check']:.2f} s "
                      f"({100 * r['check'] / r['wall']:.0f} %)" for r in checks) + "."]
    lines += ["", "Comparable sizes (nearest step-42 cycle in DoFs, same ranks):", ""]
    lines += comparable_table(c_rows, s_rows)
    lines += ["", "Wall time of every run (process, as measured by the script):", "",
              "| Run | Exit | Elapsed [s] | Peak RSS [MB] | Load before | Load after |",
              "|---|---:|---:|---:|---|---|"]
    for name, rec in data["runs"].items():
        lines.append(f"| {name} | {rec['rc']}{' (timeout)' if rec['timed_out'] else ''} | "
                     f"{rec['elapsed']:.1f} | {rec['peak_rss_mb']:.0f} | {rec['load_before']} | "
                     f"{rec.get('load_after', '-')} |")
    lines += ["", f"Whole bench: {data['bench_seconds']:.0f} s."]
    pl = [r for r in s_rows + p_rows if r.get("plastic_q") is not None]
    if pl:
        lines += ["", "step-42 plastic zone (quadrature points above the yield stress, "
                  "final iterate): " + "; ".join(
                      f"{'plastic' if r['yield_stress'] < 1e9 else 'elastic'} "
                      f"{r['case']}, {r['ranks']} rank(s): {r['plastic_q']:,} of "
                      f"{r['q_points']:,}" for r in pl)]
    return "\n".join(lines) + "\n"


def reuse_step42(path, results):
    """The step-42 rows and runs of an earlier data.json: path, or the
    newest bench/step42/results/run-*/data.json with step-42 rows; None
    when there is none or path is "none"."""
    if path and path.lower() == "none":
        return None
    if path:
        candidates = [Path(path)]
    else:
        candidates = sorted((HERE / "results").glob("run-*/data.json"), reverse=True)
    for c in candidates:
        if c.resolve().parent == results:
            continue
        try:
            d = json.loads(c.read_text())
        except (OSError, ValueError) as e:
            if path:
                sys.exit(f"run_bench.py: --step42-from {path}: {e}")
            continue
        rows = [r for r in d.get("rows", []) if r.get("program") == "step-42"]
        if not rows:
            if path:
                sys.exit(f"run_bench.py: --step42-from {path}: no step-42 rows")
            continue
        for r in rows:  # data.json files written before these fields existed
            r.setdefault("dim", 3)
            r.setdefault("degree", 1)
            r.setdefault("entries_per_row", entries_per_row(3, 1))
        runs = {k.replace(" (earlier run)", ""): v for k, v in d.get("runs", {}).items()
                if k.startswith("step-42")}
        # rows that this data.json itself took from an earlier run: name that one
        origin = d.get("step42_from") or {
            "path": str(c.resolve()), "date": d.get("date"), "machine": d.get("machine"),
            "load_first": d.get("load_first"), "args": d.get("args", {})}
        log(f"step-42: rows of {origin['path']} ({origin['date']}), not run again")
        out = dict(origin, rows=rows, runs=runs)
        if "step42_mpi_all_cycles" in d:
            out["step42_mpi_all_cycles"] = d["step42_mpi_all_cycles"]
        return out
    log("step-42: --skip-step42 and no earlier data.json with step-42 rows: none in the report")
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default=str(REPO / "build" / "contact_fem"))
    ap.add_argument("--results")
    ap.add_argument("--build-dir", default=str(HERE / "results" / "step42-build"))
    ap.add_argument("--step42-cycles", type=int, default=6)
    ap.add_argument("--step42-initial-refinements", type=int, default=3)
    ap.add_argument("--step42-yield-stress", type=float, default=1e10)
    ap.add_argument("--step42-plastic-cycles", type=int, default=5)
    ap.add_argument("--hertz-prm", default=str(REPO / "prm" / "hertz.prm"))
    ap.add_argument("--hertz-levels", default="0 1 2 3 4")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--set", action="append", default=[])
    ap.add_argument("--prm-snippet")
    ap.add_argument("--contact-fem-3d-prm", default=str(REPO / "prm" / "hertz_3d.prm"))
    ap.add_argument("--contact-fem-3d-levels", nargs="*", default=["3", "4", "5"])
    ap.add_argument("--contact-fem-3d-q2-levels", nargs="*", default=[])
    ap.add_argument("--set-3d", action="append", default=[])
    ap.add_argument("--skip-step42", action="store_true")
    ap.add_argument("--step42-from")
    ap.add_argument("--skip-contact-fem", action="store_true")
    ap.add_argument("--skip-contact-fem-2d", action="store_true")
    ap.add_argument("--timeout", type=float, default=3600)
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()

    t_start = time.monotonic()
    stamp = datetime.datetime.utcnow()
    results = Path(args.results or HERE / "results" / f"run-{stamp:%Y%m%d-%H%M%S}").resolve()
    results.mkdir(parents=True, exist_ok=True)
    binary = Path(args.binary).resolve()
    levels = [int(x) for x in args.hertz_levels.replace(",", " ").split()]

    def int_list(items):
        return [int(x) for item in items for x in item.replace(",", " ").split()]
    levels_3d = int_list(args.contact_fem_3d_levels)
    levels_3d_q2 = int_list(args.contact_fem_3d_q2_levels)
    for s in args.set + args.set_3d:
        if "=" not in s or "/" not in s.split("=", 1)[0]:
            sys.exit(f"run_bench.py: --set '{s}': expected \"Subsection/Key=value\"")

    scene = Path(args.hertz_prm).resolve()
    if args.prm_snippet:
        wrapper = results / "contact_fem_scene.prm"
        wrapper.write_text(f"include {scene}\n# --prm-snippet {args.prm_snippet}:\n" +
                           Path(args.prm_snippet).read_text() + "\n")
        scene = wrapper

    scene_3d = Path(args.contact_fem_3d_prm).resolve()
    data = {"date": f"{stamp:%Y-%m-%d %H:%M} UTC", "machine": machine(),
            "git": git_rev(), "binary": str(binary), "scene": str(scene),
            "scene_3d": str(scene_3d), "levels_3d": levels_3d, "levels_3d_q2": levels_3d_q2,
            "load_first": " ".join(open("/proc/loadavg").read().split()[:3]),
            "args": vars(args), "runs": {}, "rows": []}

    if not args.skip_step42:
        check_step42()
        exe = build_step42(Path(args.build_dir), args.jobs)
    if not args.skip_contact_fem and not binary.is_file():
        sys.exit(f"run_bench.py: no contact_fem binary at {binary} (--binary)")

    def save():
        (results / "data.json").write_text(json.dumps(data, indent=1))

    if args.skip_step42:
        s42 = reuse_step42(args.step42_from, results)
        if s42:
            data["step42_from"] = {k: s42[k] for k in ("path", "date", "machine",
                                                        "load_first", "args")}
            data["rows"] += s42["rows"]
            for name, rec in s42["runs"].items():
                data["runs"][f"{name} (earlier run)"] = rec
            if "step42_mpi_all_cycles" in s42:
                data["step42_mpi_all_cycles"] = s42["step42_mpi_all_cycles"]

    if not args.skip_contact_fem and not args.skip_contact_fem_2d and levels:
        for i, level in enumerate(levels):
            res = run_contact_fem(binary, scene, level, args.set, results, 0, args.timeout)
            data["runs"][f"contact_fem GR {level} serial"] = res["run"]
            data["rows"] += res["rows"]
            save()
        if args.np > 0:
            res = run_contact_fem(binary, scene, max(levels), args.set, results,
                                  args.np, args.timeout)
            data["runs"][f"contact_fem GR {max(levels)} np {args.np}"] = res["run"]
            data["rows"] += res["rows"]
            save()

    # contact_fem in 3D: the iterative solver (AMG, as step-42), the level
    # knob of the Hertz sphere, Q1 (step-42's element) and optionally Q2
    if not args.skip_contact_fem and (levels_3d or levels_3d_q2):
        # Uniform levels: the prm's default grades the sphere toward the
        # contact; --set-3d comes later and may change that.
        sets_3d = ["Linear solver/Type=iterative",
                   "Geometry/Hertz sphere/Contact refinements=0"]
        key_3d = "Geometry/Hertz sphere/Sphere refinements"
        runs_3d = ([(1, level, 0) for level in levels_3d] +
                   [(2, level, 0) for level in levels_3d_q2])
        if args.np > 0:
            runs_3d.append((1, max(levels_3d), args.np) if levels_3d
                           else (2, max(levels_3d_q2), args.np))
        for deg, level, np_ in runs_3d:
            case = f"3D Q{deg} SR {level}"
            res = run_contact_fem(binary, scene_3d, level,
                                  sets_3d + [f"Finite element/Degree={deg}"] + args.set_3d,
                                  results, np_, args.timeout, level_key=key_3d,
                                  case=case, tag=f"3d-Q{deg}-SR{level}")
            data["runs"][f"contact_fem {case} " +
                         (f"np {np_}" if np_ else "serial")] = res["run"]
            data["rows"] += res["rows"]
            save()

    if not args.skip_step42:
        res = run_step42(exe, results, "step42-serial", args.step42_cycles,
                         args.step42_initial_refinements, args.step42_yield_stress,
                         0, args.timeout)
        data["runs"]["step-42 serial"] = res["run"]
        data["rows"] += res["rows"]
        save()
        if args.np > 0:
            res = run_step42(exe, results, f"step42-np{args.np}", args.step42_cycles,
                             args.step42_initial_refinements, args.step42_yield_stress,
                             args.np, args.timeout)
            data["runs"][f"step-42 np {args.np}"] = res["run"]
            # the MPI rows: the largest two cycles (the small ones say little)
            data["rows"] += res["rows"][-2:]
            data["step42_mpi_all_cycles"] = res["rows"]
            save()
        if args.step42_plastic_cycles > 0:
            res = run_step42(exe, results, "step42-plastic-serial",
                             args.step42_plastic_cycles,
                             args.step42_initial_refinements, 400.0, 0, args.timeout)
            data["runs"]["step-42 plastic serial"] = res["run"]
            data["rows"] += res["rows"]
            save()

    data["bench_seconds"] = time.monotonic() - t_start
    save()
    text = report(data, args)
    (results / "report.md").write_text(text)
    print(text)
    log(f"report: {results / 'report.md'}")
    failed = [k for k, v in data["runs"].items() if v["rc"] != 0]
    if failed:
        log("failed runs: " + ", ".join(failed))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
