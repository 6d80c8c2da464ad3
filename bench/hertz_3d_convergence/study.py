#!/usr/bin/env python3
"""Convergence study of the 3D Hertz scene (prm/hertz_3d.prm): uniform
('global') against adaptive ('spr contact') refinement, Q1 and Q2, against
an overkill reference of the same scene.

What runs (one job at a time, serial, one thread):
  reference        Q2, 'spr contact', fixed number 0.3, stopped after the
                   first cycle with at least --ref-dof-cap DoFs: Pi_ref is
                   the Aitken extrapolation of its last three potential
                   energies (its uncertainty the change from the Aitken
                   value of the three before), its p_max the reference
                   p_max (the discretisation error of the others). Its
                   last cycle is the largest run of the study: DoFs, wall
                   time, time split and peak memory are reported.
  q1-global, q2-global
                   uniform refinement, --global-cycles-q1 / -q2 cycles;
  q1-spr-contact, q2-spr-contact
                   fixed fraction 0.3, no coarsening, stopped after the
                   first cycle with at least --dof-cap-q1 / -q2 DoFs.
Every run starts from the uniform mesh Sphere refinements = 1 (1,836 DoFs
with Q2; the prm's own graded default is switched off).
Per cycle: the energy error err_E = sqrt(2 |Pi_h - Pi_ref|) / |u_ref|_E,
the p_max error against the reference, DoFs, the cycle's wall time and the
cumulative wall time (what a user pays to get there). Then the targets of
the 2D study: does adaptive reach the finest uniform error with at least 4x
fewer DoFs in at most half the cumulative time? The report goes into
doc/convergence.md between the markers below; gnuplot draws
doc/figures/convergence_3d_{dofs,time}.png.

Usage: bench/hertz_3d_convergence/study.py [--binary B] [--results DIR]
       [--analyse-only] [--cases NAME ...] [--set KEY=VALUE ...]
Python 3 standard library only (gnuplot for the figures, if installed).
"""

import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import time

BEGIN = "<!-- hertz_3d_convergence:begin -->"
END = "<!-- hertz_3d_convergence:end -->"
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def run_case(args, name, settings, dof_cap=0):
    """Runs contact_fem into <results>/<name>; with dof_cap > 0 the run is
    stopped once a cycle with at least dof_cap DoFs is written."""
    out = os.path.join(args.results, name)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    cmd = [args.binary, args.prm, "--output-directory", out,
           "--set", "Output/Write VTU=false", "--set", "Output/Print timing=false"]
    # Uniform rounds only in the start mesh (the prm's default grades it
    # toward the contact); a --set may still change that.
    base = ["Geometry/Hertz sphere/Sphere refinements=1",
            "Geometry/Hertz sphere/Contact refinements=0"]
    for s in base + args.set + settings:
        cmd += ["--set", s]
    print("==", name, " ".join(cmd[1:]), file=sys.stderr, flush=True)
    load = open("/proc/loadavg").read().split()[:3]
    start = time.time()
    env = dict(os.environ, OMP_NUM_THREADS="1", DEAL_II_NUM_THREADS="1")
    with open(os.path.join(out, "stdout.txt"), "w") as log:
        proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, env=env)
        stopped = False
        peak_kb = 0
        while proc.poll() is None:
            peak_kb = max(peak_kb, peak_resident_kb(proc.pid))
            time.sleep(0.5)
            if dof_cap > 0 and max_dofs(out) >= dof_cap:
                time.sleep(1.0)  # summary.json follows the csv row
                proc.kill()
                stopped = True
        proc.wait()
    with open(os.path.join(out, "run.txt"), "w") as f:
        f.write("exit_code=%d\nstopped_at_dof_cap=%d\nelapsed=%.1f\npeak_rss_kb=%d\n"
                "loadavg_before=%s\nloadavg_after=%s\n" % (proc.returncode, stopped,
                                                          time.time() - start, peak_kb,
                                        " ".join(load),
                                        " ".join(open("/proc/loadavg").read().split()[:3])))
    if proc.returncode != 0 and not stopped:
        print("   exit code %d, see %s/stdout.txt" % (proc.returncode, out), file=sys.stderr)


def peak_resident_kb(pid):
    """The process's peak resident set so far (VmHWM), 0 once it is gone;
    sampled every 0.5 s, so a peak in the last half second is missed."""
    try:
        for line in open("/proc/%d/status" % pid):
            if line.startswith("VmHWM:"):
                return int(line.split()[1])
    except OSError:
        pass
    return 0


def run_info(results, name):
    path = os.path.join(results, name, "run.txt")
    if not os.path.exists(path):
        return {}
    return dict(line.split("=", 1) for line in open(path).read().split("\n") if "=" in line)


def aitken(x0, x1, x2):
    """The limit of a geometrically converging sequence from three terms."""
    d1, d2 = x1 - x0, x2 - x1
    return x2 if d2 == d1 else x2 - d2 * d2 / (d2 - d1)


def max_dofs(out):
    path = os.path.join(out, "convergence.csv")
    if not os.path.exists(path):
        return 0
    rows = open(path).read().split("\n")[1:]
    return max([int(r.split(",")[2]) for r in rows if r.strip()] + [0])


def cycles(results, name):
    path = os.path.join(results, name, "summary.json")
    if not os.path.exists(path):
        return []
    return json.load(open(path)).get("cycles", [])


def analyse(results, given=None):
    """given: (Pi_ref, uncertainty, |u_ref|_E, p_max_ref, label) from an
    earlier overkill, instead of a reference run."""
    if given:
        pi_ref, pi_change, norm_ref, p_ref, ref_label = given
    else:
        ref = cycles(results, "reference")
        if not ref:
            sys.exit("study.py: no reference run in " + results)
        energies = [c["potential_energy"] for c in ref]
        if len(energies) >= 4:
            # Aitken on the last three energies; how far it may be off: the
            # change from the Aitken value of the three before.
            pi_ref = aitken(*energies[-3:])
            pi_change = abs(pi_ref - aitken(*energies[-4:-1]))
            how = "Aitken extrapolation of the energies of its last three cycles"
        else:
            pi_ref = energies[-1]
            # How far the reference itself may be off: its last energy change.
            pi_change = abs(energies[-1] - energies[-2]) if len(energies) > 1 else float("nan")
            how = "its last energy"
        norm_ref = math.sqrt(2.0 * ref[-1]["strain_energy"])
        p_ref = ref[-1]["contact"]["max_contact_pressure"]
        ref_label = ("overkill run: Q2 'spr contact', cycles of %s DoFs; Pi_ref = %s" % (
            ", ".join(str(int(c["n_dofs"])) for c in ref), how))
    runs = {}
    for name in ["q1-global", "q1-spr-contact", "q2-global", "q2-spr-contact"]:
        rows = []
        for c in cycles(results, name):
            rows.append({
                "cycle": c["cycle"], "dofs": int(c["n_dofs"]),
                "err_E": math.sqrt(2.0 * abs(c["potential_energy"] - pi_ref)) / norm_ref,
                "p_err": abs(c["contact"]["max_contact_pressure"] - p_ref) / p_ref,
                "eta": c.get("relative_estimated_error"),
                "wall": c["wall_time"], "cumulative": c["cumulative_wall_time"],
                "hanging": c["contact"].get("hanging_slave_vertices", 0)})
        runs[name] = rows
    largest = None
    ref = cycles(results, "reference")
    if ref:
        largest = dict(ref[-1], peak_rss_kb=int(run_info(results, "reference").get("peak_rss_kb", 0)))
    return {"pi_ref": pi_ref, "pi_change": pi_change, "norm_ref": norm_ref, "p_ref": p_ref,
            "ref_label": ref_label, "runs": runs, "largest": largest}


def targets(runs, degree):
    """First adaptive cycle at or below the finest uniform error: its DoFs
    and cumulative time against the finest uniform cycle's."""
    uniform, adaptive = runs["q%d-global" % degree], runs["q%d-spr-contact" % degree]
    if not uniform or not adaptive:
        return None
    finest = uniform[-1]
    for i, row in enumerate(adaptive):
        if row["err_E"] <= finest["err_E"]:
            # Where the adaptive curve crosses the finest uniform error,
            # interpolated log-log from the cycle before.
            crossing_dofs, crossing_time = row["dofs"], row["cumulative"]
            if i > 0 and adaptive[i - 1]["err_E"] > row["err_E"]:
                prev = adaptive[i - 1]
                t = (math.log(prev["err_E"] / finest["err_E"]) /
                     math.log(prev["err_E"] / row["err_E"]))
                crossing_dofs = prev["dofs"] * (row["dofs"] / prev["dofs"]) ** t
                crossing_time = prev["cumulative"] + t * (row["cumulative"] - prev["cumulative"])
            return {"finest": finest, "adaptive": row,
                    "dof_ratio": finest["dofs"] / row["dofs"],
                    "time_ratio": row["cumulative"] / finest["cumulative"],
                    "interpolated_dof_ratio": finest["dofs"] / crossing_dofs,
                    "interpolated_time_ratio": crossing_time / finest["cumulative"]}
    return {"finest": finest, "adaptive": None}


def report(data, study_info):
    lines = []
    w = lines.append
    w("Generated by `bench/hertz_3d_convergence/study.py` (%s)." % study_info)
    w("")
    w("Reference (%s): Pi_ref = %.10g (uncertainty %.2g, "
      "i.e. energy errors below about %.1g are reference-limited), |u_ref|_E = %.6g, "
      "p_max = %.6g." % (data["ref_label"], data["pi_ref"], data["pi_change"],
                         math.sqrt(2 * data["pi_change"]) / data["norm_ref"]
                         if data["pi_change"] == data["pi_change"] else float("nan"),
                         data["norm_ref"], data["p_ref"]))
    w("")
    for name, rows in data["runs"].items():
        if not rows:
            continue
        w("**%s**" % name)
        w("")
        w("| cycle | DoFs | hanging slave vertices | err_E / abs(u)_E | p_max error | eta / abs(u)_E | "
          "wall time [s] | cumulative [s] |")
        w("|---:|---:|---:|---:|---:|---:|---:|---:|")
        for r in rows:
            w("| %d | %d | %d | %.3e | %.2e | %s | %.1f | %.1f |" % (
                r["cycle"], r["dofs"], r["hanging"], r["err_E"], r["p_err"],
                "%.3e" % r["eta"] if r["eta"] is not None else "-", r["wall"], r["cumulative"]))
        w("")
    for degree in [1, 2]:
        t = targets(data["runs"], degree)
        if t is None:
            continue
        f = t["finest"]
        if t["adaptive"] is None:
            w("Q%d: adaptive does not reach the finest uniform error %.3e (%d DoFs) within its "
              "DoF cap." % (degree, f["err_E"], f["dofs"]))
        else:
            a = t["adaptive"]
            w("Q%d: the finest uniform mesh (%d DoFs, %.1f s cumulative) reaches err_E = %.3e; "
              "adaptive reaches %.3e at %d DoFs, %.1f s cumulative: **%.1fx fewer DoFs** "
              "(target >= 4: %s), **%.2f of the time** (target <= 0.5: %s)." % (
                  degree, f["dofs"], f["cumulative"], f["err_E"], a["err_E"], a["dofs"],
                  a["cumulative"], t["dof_ratio"], "met" if t["dof_ratio"] >= 4 else "missed",
                  t["time_ratio"], "met" if t["time_ratio"] <= 0.5 else "missed"))
            w("(Interpolated log-log between the adaptive cycles around the crossing: %.1fx "
              "fewer DoFs, %.2f of the time.)" % (t["interpolated_dof_ratio"],
                                                 t["interpolated_time_ratio"]))
        w("")
    big = data.get("largest")
    if big:
        timing = big.get("timing", {})
        wall = big["wall_time"]
        # The multigrid set-up is part of the linear solve.
        split = ", ".join("%s%s %.1f s (%.0f %%)" % ("of which " if k == "Solve: multigrid setup"
                                                     else "", k, v, 100 * v / wall)
                          for k, v in sorted(timing.items(), key=lambda kv: -kv[1])
                          if v >= 0.005 * wall)
        w("Largest run of the study: the reference's last cycle, %d DoFs (Q2, %d hanging slave "
          "vertices), cycle wall time %.1f s (solver: %s), peak resident memory of the whole "
          "run %.2f GB. Time split of that cycle: %s." % (
              int(big["n_dofs"]), big["contact"].get("hanging_slave_vertices", 0), wall,
              big.get("linear_solver", "?"), big["peak_rss_kb"] / 1024.0 ** 2, split))
        w("")
    return "\n".join(lines)


def write_doc(path, text):
    old = open(path).read() if os.path.exists(path) else ""
    block = BEGIN + "\n" + text.rstrip("\n") + "\n" + END
    if BEGIN in old and END in old:
        new = old[:old.index(BEGIN)] + block + old[old.index(END) + len(END):]
    else:
        new = old.rstrip("\n") + "\n\n" + block + "\n"
    with open(path, "w") as f:
        f.write(new)


def plot(data, results):
    if shutil.which("gnuplot") is None:
        print("study.py: gnuplot not found, no figures", file=sys.stderr)
        return
    os.makedirs(os.path.join(ROOT, "doc", "figures"), exist_ok=True)
    files = []
    for name, rows in data["runs"].items():
        if rows:
            path = os.path.join(results, name + ".dat")
            with open(path, "w") as f:
                for r in rows:
                    f.write("%d %.6e %.6e %.6e\n" % (r["dofs"], r["err_E"], r["cumulative"], r["p_err"]))
            files.append((name, path))
    for x, col, label, out in [(1, 2, "DoFs", "convergence_3d_dofs.png"),
                               (3, 2, "cumulative wall time [s]", "convergence_3d_time.png")]:
        plots = ", ".join("'%s' using %d:%d with linespoints title '%s'" % (p, x, col, n)
                          for n, p in files)
        script = ("set terminal pngcairo size 800,600 noenhanced; set output '%s'; set logscale xy; "
                  "set grid; set xlabel '%s'; set ylabel 'energy error / |u|_E'; "
                  "set title '3D Hertz (prm/hertz_3d.prm): energy error against the overkill "
                  "reference'; plot %s" % (os.path.join(ROOT, "doc", "figures", out), label, plots))
        subprocess.run(["gnuplot", "-e", script], check=False)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", default=os.path.join(ROOT, "build", "contact_fem"))
    ap.add_argument("--prm", default=os.path.join(ROOT, "prm", "hertz_3d.prm"))
    ap.add_argument("--results", default=os.path.join(HERE, "results"))
    ap.add_argument("--doc", default=os.path.join(ROOT, "doc", "convergence.md"))
    ap.add_argument("--analyse-only", action="store_true")
    ap.add_argument("--cases", nargs="+", metavar="NAME",
                    default=["reference", "q1-global", "q1-spr-contact", "q2-global",
                             "q2-spr-contact"],
                    help="run only these (the others are read from --results as they are)")
    ap.add_argument("--ref-dof-cap", type=int, default=250000)
    ap.add_argument("--global-cycles-q1", type=int, default=3)
    ap.add_argument("--global-cycles-q2", type=int, default=4)
    ap.add_argument("--dof-cap-q1", type=int, default=150000)
    ap.add_argument("--dof-cap-q2", type=int, default=150000)
    ap.add_argument("--reference", nargs=5, metavar=("PI", "DELTA", "NORM", "PMAX", "LABEL"),
                    help="take the reference from an earlier overkill instead of running one")
    ap.add_argument("--set", action="append", default=[],
                    help="a further --set for every run (e.g. a coarser start mesh)")
    args = ap.parse_args()
    args.binary = os.path.abspath(args.binary)
    os.makedirs(args.results, exist_ok=True)
    info_path = os.path.join(args.results, "study.txt")
    if not args.analyse_only:
        # Every run uses the same binary, even if it is rebuilt meanwhile.
        copy = os.path.join(args.results, "contact_fem")
        shutil.copy2(args.binary, copy)
        args.binary = copy
        start = time.time()
        if not args.reference and "reference" in args.cases:
            run_case(args, "reference", ["Finite element/Degree=2", "Refinement/Estimator=spr contact",
                                         "Refinement/Strategy=fixed number",
                                         "Refinement/Refine fraction=0.3",
                                         "Refinement/Number of cycles=30"], args.ref_dof_cap)
        adaptive = ["Refinement/Estimator=spr contact", "Refinement/Strategy=fixed fraction",
                    "Refinement/Refine fraction=0.3", "Refinement/Coarsen fraction=0",
                    "Refinement/Number of cycles=30"]
        for degree, n_global, cap in [(1, args.global_cycles_q1, args.dof_cap_q1),
                                      (2, args.global_cycles_q2, args.dof_cap_q2)]:
            fe = ["Finite element/Degree=%d" % degree]
            if "q%d-global" % degree in args.cases:
                run_case(args, "q%d-global" % degree,
                         fe + ["Refinement/Estimator=global",
                               "Refinement/Number of cycles=%d" % n_global])
            if "q%d-spr-contact" % degree in args.cases:
                run_case(args, "q%d-spr-contact" % degree, fe + adaptive, cap)
        git = subprocess.run(["git", "-C", ROOT, "describe", "--always", "--dirty"],
                             capture_output=True, text=True).stdout.strip()
        with open(info_path, "a" if len(args.cases) < 5 else "w") as f:
            f.write("%s, git %s, %s, %d cores, %s %.0f s, extra settings: %s.\n" % (
                time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), git,
                open("/proc/cpuinfo").read().split("model name")[1].split("\n")[0].strip(": \t"),
                os.cpu_count(), "study" if len(args.cases) == 5 else ", ".join(args.cases),
                time.time() - start, "; ".join(args.set) or "none"))
    given = None
    if args.reference:
        r = args.reference
        given = (float(r[0]), float(r[1]), float(r[2]), float(r[3]), r[4])
    data = analyse(args.results, given)
    info = ("; ".join(line.strip().rstrip(".") for line in open(info_path) if line.strip())
            if os.path.exists(info_path) else "no study.txt")
    text = report(data, info)
    print(text)
    if args.doc != "-":
        write_doc(args.doc, text)
        plot(data, args.results)


if __name__ == "__main__":
    main()
