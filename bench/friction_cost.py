#!/usr/bin/env python3
"""Cost of friction (doc/performance.md, "Friction cost").

Three groups of serial runs, every variant repeated REPS times; the
repetitions are interleaved (rep 1 of every variant, then rep 2, ...) so that
a change of machine load hits all variants alike. Reported per variant:
Newton iterations per load step (summary.json), program wall time
(summary.json "wall_time", median and min), process elapsed and peak
resident memory (/usr/bin/time -f "%e %M"), time per Newton iteration
(median wall time / total iterations, and the median Newton work, i.e.
assembly + linear solve + contact seconds, / total iterations), and the
shares of the wall time of the program's TimerOutput sections: assembly
(bulk + system + residual), linear solve, contact (search, active set,
check), setup (DoFs, sparsity), output (VTU) and the rest (held-rotation
check, results, untimed).

  hertz     prm/hertz.prm, Contact refinements 6 (the default) and 8:
            alm frictionless (as shipped) / alm frictional, coulomb 0.2 /
            alm frictional, coulomb 0 / penalty frictional, coulomb 0.2.
  cattaneo  prm/cattaneo.prm, Global refinements 2 and 3: the scene as
            shipped (alm frictional mu = 0.2, normal phase t in [0, 1] then
            the tangential one, 4 steps) / its normal phase only (End
            time = 1, 2 steps, same step size) / the normal phase with alm
            frictionless (no friction law, Analytical solution/Type = none,
            and the two fixed points of prm/two_cylinders.prm, because
            frictionless contact holds neither the shift nor the rotation of
            the upper body; with the tangential load it would slide away).
  hertz3d   prm/hertz_3d.prm as tests/scenes/frictional_hertz_3d_01 runs it
            (Q1, Sphere refinements 3, Contact refinements 0; and Sphere
            refinements 4): the same four variants as hertz.
  cattaneo3d prm/cattaneo_3d.prm (Mindlin's sphere, alm frictional mu =
            0.5): the scene as shipped (the normal step, then four
            tangential ones) / its normal step only (End time = 0.2, 1 step)
            / the normal step with alm frictionless (no friction law,
            Analytical solution/Type = none, u_x held at the pole and the
            centre of the flat face, on the axis, where it vanishes anyway).
  overhead  "a frictionless scene pays nothing": prm/hertz.prm (as shipped
            and at Global refinements 2) and prm/two_cylinders.prm with the
            binary before friction (--old-binary, a Release build of 2c19b61;
            --old-label names it, e.g. "before 3D (755e6be)" for what a 2D
            scene pays for 3D)
            and the current one: iterations and results must be identical,
            times within noise, peak memory alike; with the 3D Hertz
            (frictional_hertz_3d_01's mesh, frictionless) for what a 3D
            frictionless scene pays for 3D friction (--old-binary: a build
            from before 3D friction).

Usage:
  python3 bench/friction_cost.py [--binary B] [--old-binary OLD] [--old-label L]
          [--reps N] [--groups hertz,cattaneo,hertz3d,cattaneo3d,overhead]
          [--results DIR]

Prints Markdown tables (also written to DIR/report.md) and every run to
DIR/runs.csv. Threads are pinned to one (OMP_NUM_THREADS=1,
DEAL_II_NUM_THREADS=1); VTU output is on as in the .prm files.
"""
import argparse
import csv
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent

FRICTIONAL = ["Contact/Formulation=alm frictional", "Contact/Friction=coulomb 0.2"]
CATTANEO_NORMAL = ["Load stepping/End time=1", "Load stepping/Number of load steps=2"]
CATTANEO_FRICTIONLESS = CATTANEO_NORMAL + [
    "Contact/Formulation=alm frictionless", "Contact/Friction=",
    "Analytical solution/Type=none",
    "Boundary conditions/Fixed points=1 @ 0, 0: x; 1 @ 0, 8: x"]


HERTZ_3D_Q1 = ["Finite element/Degree=1", "Geometry/Hertz sphere/Contact refinements=0",
               "Output/Write VTU=false"]
CATTANEO_3D_NORMAL = ["Load stepping/End time=0.2", "Load stepping/Number of load steps=1"]
CATTANEO_3D_FRICTIONLESS = CATTANEO_3D_NORMAL + [
    "Contact/Formulation=alm frictionless", "Contact/Friction=",
    "Analytical solution/Type=none", "Analytical solution/Symmetry fraction=1",
    "Boundary conditions/Fixed points=1 @ 0, 0, 2: x; 1 @ 0, 0, 8.1237: x"]


def friction_variants(group, scene, new, prm, base):
    """The frictionless run and the three frictional ones of one scene."""
    return [
        (group, scene, "alm frictionless", new, prm, base),
        (group, scene, "alm frictional mu=0.2", new, prm, base + FRICTIONAL),
        (group, scene, "alm frictional mu=0", new, prm,
         base + ["Contact/Formulation=alm frictional", "Contact/Friction=coulomb 0"]),
        (group, scene, "penalty frictional mu=0.2", new, prm,
         base + ["Contact/Formulation=penalty frictional", "Contact/Friction=coulomb 0.2"]),
    ]


def variants(groups, new, old, old_label="before friction (2c19b61)"):
    """(group, scene label, variant label, binary, prm, --set list)."""
    out = []
    if "hertz" in groups:
        for cr in (6, 8):
            base = [f"Geometry/Hertz cylinder/Contact refinements={cr}"]
            out += friction_variants("hertz", f"hertz, CR {cr}", new, "prm/hertz.prm", base)
    if "hertz3d" in groups:
        for sr in (3, 4):
            base = HERTZ_3D_Q1 + [f"Geometry/Hertz sphere/Sphere refinements={sr}"]
            out += friction_variants("hertz3d", f"hertz_3d Q1, SR {sr}", new,
                                     "prm/hertz_3d.prm", base)
    if "cattaneo3d" in groups:
        scene, prm, base = "cattaneo_3d", "prm/cattaneo_3d.prm", ["Output/Write VTU=false"]
        out += [
            ("cattaneo3d", scene, "alm frictional mu=0.5, 5 steps (shipped)", new, prm, base),
            ("cattaneo3d", scene, "alm frictional mu=0.5, normal step", new, prm,
             base + CATTANEO_3D_NORMAL),
            ("cattaneo3d", scene, "alm frictionless, normal step", new, prm,
             base + CATTANEO_3D_FRICTIONLESS),
        ]
    if "cattaneo" in groups:
        for gr in (2, 3):
            base = [f"Geometry/Global refinements={gr}"]
            scene = f"cattaneo, GR {gr}"
            out += [
                ("cattaneo", scene, "alm frictional mu=0.2, t in [0,2] (4 steps)", new,
                 "prm/cattaneo.prm", base),
                ("cattaneo", scene, "alm frictional mu=0.2, t in [0,1] (2 steps)", new,
                 "prm/cattaneo.prm", base + CATTANEO_NORMAL),
                ("cattaneo", scene, "alm frictionless, t in [0,1] (2 steps)", new,
                 "prm/cattaneo.prm", base + CATTANEO_FRICTIONLESS),
            ]
    if "overhead" in groups:
        for scene, prm, sets in (
                ("hertz.prm", "prm/hertz.prm", []),
                ("hertz.prm, GR 2", "prm/hertz.prm", ["Geometry/Global refinements=2"]),
                ("two_cylinders.prm", "prm/two_cylinders.prm", []),
                ("hertz_3d.prm, Q1 SR 3", "prm/hertz_3d.prm",
                 HERTZ_3D_Q1 + ["Geometry/Hertz sphere/Sphere refinements=3"])):
            out += [("overhead", scene, old_label, old, prm, sets),
                    ("overhead", scene, "current", new, prm, sets)]
    return out


def run_one(binary, prm, sets, directory):
    directory.mkdir(parents=True, exist_ok=True)
    cmd = [str(binary), str(REPO / prm)]
    for s in sets + ["Output/Print timing=true"]:
        cmd += ["--set", s]
    cmd += ["--output-directory", str(directory)]
    timefile = directory / "time.txt"
    load = open("/proc/loadavg").read().split()[0]
    with open(directory / "stdout.txt", "w") as out:
        rc = subprocess.call(["/usr/bin/time", "-f", "%e %M", "-o", str(timefile)] + cmd,
                             stdout=out, stderr=subprocess.STDOUT)
    elapsed, rss = open(timefile).read().split()[-2:]
    rec = {"rc": rc, "elapsed": float(elapsed), "rss_mb": int(rss) / 1024.,
           "load": float(load), "command": " ".join(
               [Path(binary).name, prm] + [f'--set "{s}"' for s in sets])}
    try:
        summary = json.load(open(directory / "summary.json"))
    except (OSError, ValueError):
        rec["status"] = "no summary"
        return rec
    cycle = summary["cycles"][-1]
    rec.update(status=summary.get("status"), wall=summary["wall_time"],
               dofs=cycle["n_dofs"],
               its=[s["newton_iterations"] for s in cycle["load_steps"]],
               timing=cycle.get("timing", {}),
               results={"active": cycle.get("contact", {}).get("active_slave_nodes"),
                        "p_max": cycle.get("contact", {}).get("max_contact_pressure"),
                        "energy": cycle.get("potential_energy")})
    c = cycle.get("contact", {})
    rec["stick_slip"] = (c.get("stick_nodes"), c.get("slip_nodes"))
    profile = directory / "pressure_profile.csv"
    rec["profile"] = profile.read_bytes() if profile.exists() else None
    return rec


def shares(rec):
    t, w = rec["timing"], rec["wall"]
    asm = sum(v for k, v in t.items() if k.startswith("Assembly"))
    sol = sum(v for k, v in t.items() if k.startswith("Solve"))
    con = sum(v for k, v in t.items() if k.startswith("Contact"))
    setup = sum(v for k, v in t.items() if k.startswith("Setup"))
    output = sum(v for k, v in t.items() if k.startswith("Output"))
    return (asm / w, sol / w, con / w, setup / w, output / w,
            (w - asm - sol - con - setup - output) / w)


def newton_work(rec):
    """Assembly + linear solve + contact seconds: the work of the Newton loop."""
    return sum(v for k, v in rec["timing"].items()
               if k.startswith(("Assembly", "Solve", "Contact")))


def fmt_its(its):
    return ", ".join(str(i) for i in its)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", default=str(REPO / "build/contact_fem"))
    ap.add_argument("--old-binary", default="")
    ap.add_argument("--old-label", default="before friction (2c19b61)")
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--groups", default="hertz,cattaneo,hertz3d,cattaneo3d,overhead")
    ap.add_argument("--results", default="")
    a = ap.parse_args()
    groups = a.groups.split(",")
    if "overhead" in groups and not a.old_binary:
        sys.exit("friction_cost.py: the overhead group needs --old-binary")
    results = Path(a.results or REPO / "bench" / time.strftime("results-friction-cost-%Y%m%d-%H%M%S"))
    results.mkdir(parents=True, exist_ok=True)
    os.environ.update(OMP_NUM_THREADS="1", DEAL_II_NUM_THREADS="1")
    a.binary = os.path.abspath(a.binary)
    if a.old_binary:
        a.old_binary = os.path.abspath(a.old_binary)
    os.chdir(REPO)

    vs = variants(groups, a.binary, a.old_binary, a.old_label)
    runs = {i: [] for i in range(len(vs))}
    loads = [open("/proc/loadavg").read().strip()]
    for rep in range(a.reps):
        for i, (g, scene, label, binary, prm, sets) in enumerate(vs):
            d = results / g / f"{i:02d}" / f"rep{rep}"
            rec = run_one(binary, prm, sets, d)
            runs[i].append(rec)
            print(f"[{rep}] {scene:18s} {label:45s} rc={rec['rc']} {rec.get('status')} "
                  f"its={rec.get('its')} wall={rec.get('wall', 0):.3f} "
                  f"elapsed={rec['elapsed']:.2f} rss={rec['rss_mb']:.0f}MB load={rec['load']}",
                  file=sys.stderr, flush=True)
    loads.append(open("/proc/loadavg").read().strip())

    with open(results / "runs.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["group", "scene", "variant", "rep", "rc", "status", "dofs", "its", "wall",
                    "elapsed", "rss_mb", "load1", "stick", "slip", "command"])
        for i, v in enumerate(vs):
            for r, rec in enumerate(runs[i]):
                w.writerow([v[0], v[1], v[2], r, rec["rc"], rec.get("status"), rec.get("dofs"),
                            fmt_its(rec.get("its", [])), rec.get("wall"), rec["elapsed"],
                            f"{rec['rss_mb']:.1f}", rec["load"], *rec.get("stick_slip", ("", "")),
                            rec["command"]])

    lines = [f"Load average (1, 5, 15 min) before: {loads[0]}; after: {loads[1]}. "
             f"{a.reps} runs per variant, interleaved.", ""]
    header = ("| Scene | Variant | DoFs | Newton its/step | Total its | Wall median [s] | "
              "Wall min [s] | Wall per it. [ms] | Newton work per it. [ms] | Assembly | Linear solve | "
              "Contact | Setup | Output | Other | Process elapsed median [s] | Peak RSS [MB] |")
    lines += [header, "|---|---|---:|---|---:|---:|---:|---:|---:" + "|---:" * 9 + "|"]
    notes = []
    for i, v in enumerate(vs):
        rs = [r for r in runs[i] if r.get("status") == "converged" and r["rc"] == 0]
        if len(rs) < len(runs[i]):
            notes.append(f"{v[1]} / {v[2]}: {len(runs[i]) - len(rs)} run(s) failed "
                         f"({[r.get('status') for r in runs[i]]})")
        if not rs:
            continue
        its = {tuple(r["its"]) for r in rs}
        if len(its) > 1:
            notes.append(f"{v[1]} / {v[2]}: iteration counts differ between repetitions: {its}")
        walls = [r["wall"] for r in rs]
        med = statistics.median(walls)
        total = sum(rs[0]["its"])
        sh = [statistics.median(x) for x in zip(*(shares(r) for r in rs))]
        lines.append(
            f"| {v[1]} | {v[2]} | {rs[0]['dofs']} | {fmt_its(rs[0]['its'])} | {total} | "
            f"{med:.3f} | {min(walls):.3f} | {1000 * med / total:.1f} | "
            f"{1000 * statistics.median(newton_work(r) for r in rs) / total:.1f} | "
            + " | ".join(f"{100 * s:.0f} %" for s in sh)
            + f" | {statistics.median(r['elapsed'] for r in rs):.2f} | "
            f"{statistics.median(r['rss_mb'] for r in rs):.0f} |")

    # The overhead group: same iterations and results, old against new.
    if "overhead" in groups:
        lines.append("")
        lines.append(f"{a.old_label} against the current binary, frictionless scenes:")
        lines.append("")
        lines.append("| Scene | Iterations equal | Results equal (active nodes, p_max, energy; pressure_profile.csv bytes) | "
                     "Wall median before / after [s] | Wall min before / after [s] | "
                     "Contact: search median before / after [ms] | Peak RSS before / after [MB] |")
        lines.append("|---|---|---|---|---|---|---|")
        idx = [i for i, v in enumerate(vs) if v[0] == "overhead"]
        for i_old, i_new in zip(idx[0::2], idx[1::2]):
            o, n = runs[i_old], runs[i_new]
            if not all(r.get("status") == "converged" for r in o + n):
                lines.append(f"| {vs[i_old][1]} | failed runs | | | | | |")
                continue
            same_its = all(r["its"] == o[0]["its"] for r in o + n)
            same_res = all(r["results"] == o[0]["results"] and r["profile"] == o[0]["profile"]
                           for r in o + n)
            wo, wn = [r["wall"] for r in o], [r["wall"] for r in n]
            lines.append(
                f"| {vs[i_old][1]} | {'yes' if same_its else 'NO'} ({fmt_its(o[0]['its'])}) | "
                f"{'yes' if same_res else 'NO'} | "
                f"{statistics.median(wo):.3f} / {statistics.median(wn):.3f} | "
                f"{min(wo):.3f} / {min(wn):.3f} | "
                f"{1000 * statistics.median(r['timing'].get('Contact: search', 0) for r in o):.1f} / "
                f"{1000 * statistics.median(r['timing'].get('Contact: search', 0) for r in n):.1f} | "
                f"{statistics.median(r['rss_mb'] for r in o):.0f} / "
                f"{statistics.median(r['rss_mb'] for r in n):.0f} |")
    if notes:
        lines += [""] + [f"- {x}" for x in notes]
    report = "\n".join(lines) + "\n"
    (results / "report.md").write_text(report)
    print(report)
    print(f"runs in {results}", file=sys.stderr)


if __name__ == "__main__":
    main()
