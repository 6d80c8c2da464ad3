#!/usr/bin/env python3
"""Report of the stability suite (bench/stability/run.sh).

Reads <results>/<group>/<case>/{run.txt, summary.json, stdout.txt,
pressure_profile.csv}, judges every case against what run.sh says to expect
of it, and writes a Markdown report (default doc/stability.md): one table per
group, the automatic findings with a command to reproduce each, then the
hand-written reading of the run kept in bench/stability/notes.md.

Standard library only. Usage:
    analyse.py [--results DIR] [--doc FILE | --doc -]
"""

import argparse
import csv
import datetime
import glob
import json
import math
import os
import re
import shlex
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

GROUPS = [
    ("stiffness", "Stiffness ratio between the bodies (Hertz scene)"),
    ("incompressible", "Near-incompressible bodies, Q1 against Q2 (Hertz scene, rigid plate)"),
    ("load", "Load magnitude, 1e-8 to 1e2 times the Hertz default"),
    ("gap", "Initial gap and initial penetration (contact blocks)"),
    ("pull", "Loads that pull the bodies apart"),
    ("mesh", "Distorted meshes and contact sides meshed 10x finer / coarser"),
    ("mechanism", "Rotation of the Hertz half-disc about its centre (held by Boundary conditions/Fixed "
                  "points in prm/hertz.prm; the *-nofix cases remove it)"),
    ("penalty", "Automatic penalty and scale factor times 1e-6 ... 1e6 (Contact/Stiffness factor)"),
    ("regularised", "Penalty formulation (Contact/Formulation = penalty frictionless), fixed "
                    "and adaptive penalty (Contact/Adaptive penalty)"),
    ("newton", "Newton damping (Newton/Damping)"),
    ("reach", "Search reach and kinematics (gaps closed in one step, fine meshes in one step, "
              "fast approach, load-step independence, beyond small sliding)"),
    ("friction", "Friction: Coulomb mu = 0 ... 1e3 and Tresca, reversed tangential load, "
                 "stiff/soft pairs, penalty frictional across penalty scales, updated "
                 "kinematics, Hertz and Cattaneo"),
    ("iterative", "Iterative linear solver (Linear solver/Type = iterative: CG or GMRES with "
                  "ML multigrid) on the stiff, nearly incompressible, Q2, adaptive and "
                  "frictional cases; its limits are those of Type = auto"),
    ("finite-strain", "Finite strain (issue 29, item 6): neo-Hookean Hertz with contact on the "
                      "current configuration up to a flattened disc, element inversion, near "
                      "incompressibility (F-bar Q1, Q2), large sliding over hanging nodes, "
                      "self-contact and reach beyond the paired surfaces"),
    ("3d-stiffness", "3D: stiffness ratio between the bodies (Hertz sphere, 3D patch test)"),
    ("3d-incompressible", "3D: near-incompressible sphere, Q1 against Q2, standard and B-bar "
                          "(plate 1e4 x stiffer)"),
    ("3d-load", "3D: load magnitude, 1e-12 to 1e2 times the shipped Hertz sphere pressure"),
    ("3d-gap", "3D: initial gap and initial penetration (Geometry/Hertz sphere/Initial gap, "
               "patch blocks apart or overlapping), in one and several load steps"),
    ("3d-grazing", "3D: grazing contact (contact from one node, master edge just off the "
                   "slave's)"),
    ("3d-mesh", "3D: distorted meshes (Geometry/Distortion) on the patch blocks and the sphere"),
    ("3d-regularised", "3D: penalty formulation, automatic, too small and too large penalty, "
                       "adaptive; alm scale factor"),
    ("3d-friction", "3D friction: Coulomb mu = 0 ... 1e3 and Tresca on the 3D frictional "
                    "patch, reversed and cyclic pulls, stiff/soft pairs, penalty frictional "
                    "across penalty scales, updated kinematics, pure slip, Hertz sphere and "
                    "3D Cattaneo"),
    ("3d-iterative", "3D: iterative linear solver on the stiff and nearly incompressible "
                     "cases; Type = auto at its limits"),
    ("3d-finite-strain", "3D finite strain (issue 29, item 6): neo-Hookean blocks and "
                         "hemisphere with contact on the current configuration: large loads "
                         "up to element inversion and step splits, near incompressibility "
                         "(F-bar Q1, Q2), large sliding over hanging nodes, initial gap and "
                         "penetration, grazing, distorted meshes, tiny loads"),
]

# same=GROUP/CASE: the contact answer (p_max and the transmitted force) must
# equal that case's to this relative tolerance (load-step independence).
SAME_TOL = 1e-8

FLAGS = ("hertz", "hertz-approx", "empty", "centred", "cone", "stick-all", "slip-all")

# ratio=MU: |tangential / normal contact force| must equal MU to this
# relative tolerance (absolute for MU = 0). Slip nodes sit on their bound to
# 1e-8 of the largest bound (the program's own check), hence the same here.
RATIO_TOL = 1e-8
# differs=GROUP/CASE: the tangential traction profiles must differ by more
# than this fraction of the other case's largest contact pressure.
DIFFERS_TOL = 1e-3

# Tolerances of the verdicts.
HERTZ_P_TOL = 0.05        # |p_max / p_Hertz - 1| (a case's ptol= overrides it)
HERTZ_A_TOL = 1.5         # |a - a_Hertz| in slave elements
HERTZ_A_REL_TOL = 0.03  # ... unless within 3 % of a (the finite-body limit is ~2 %)
CENTRE_TOL = 0.5          # |centre of the pressure| in slave elements
IMBALANCE_TOL = 1e-6
PRESSURE_TOL = 1e-6       # patch-type cases: max |p_i / p - 1|


def read_kv(path):
    info = {}
    if os.path.exists(path):
        with open(path, errors="replace") as f:
            for line in f:
                key, sep, value = line.rstrip("\n").partition("=")
                if sep:
                    info[key] = value
    return info


def read_profile(path):
    rows = []
    if not os.path.exists(path):
        return rows
    with open(path) as f:
        for r in csv.DictReader(f):
            try:
                rows.append({k: float(v) for k, v in r.items()})
            except (TypeError, ValueError):
                continue
    return rows


def parse_stdout(path):
    out = {"splits": 0, "newton_failures": 0, "failure": "", "step_attempts": 0,
           "last_t": None, "errors": [], "grows": 0, "warnings": [],
           # friction: the two cone lines of alm frictional, and the stick /
           # slip columns of the Newton tables (every iteration of every
           # attempt): rows with a slip node, stick/slip set changes
           "cone": {}, "newton_rows": 0, "rows_with_slip": 0, "max_slip_in_row": 0,
           "ss_changes": 0}
    if not os.path.exists(path):
        return out
    continuing = False
    header = []   # columns of the current Newton table
    with open(path, errors="replace") as f:
        for line in f:
            s = line.strip()
            # the failure message may be wrapped over indented lines
            if continuing:
                if line.startswith((" ", "\t")) and s and not s.startswith(("|", "The results")):
                    out["failure"] += " " + s
                    continue
                continuing = False
            m = re.match(r"(slip nodes off the slip bound|stick nodes outside the cone):\s*(.*)", s)
            if m:
                out["cone"][m.group(1)] = m.group(2)
                continue
            if s.startswith("friction cone:"):
                out["cone"]["friction cone"] = s.partition(":")[2].strip()
                continue
            if s.startswith("| it |"):
                header = [c.strip() for c in s.strip("|").split("|")]
                continue
            if s.startswith("|") and "slip" in header:
                cells = [c.strip() for c in s.strip("|").split("|")]
                try:
                    slip = int(cells[header.index("slip")])
                except (ValueError, IndexError):
                    slip = None
                if slip is not None:
                    out["newton_rows"] += 1
                    out["max_slip_in_row"] = max(out["max_slip_in_row"], slip)
                    out["rows_with_slip"] += slip > 0
                    try:
                        out["ss_changes"] += int(cells[header.index("s/s ch.")].split()[0])
                    except (ValueError, IndexError):
                        pass
                continue
            if s.startswith("Warning:"):
                out["warnings"].append(s[len("Warning:"):].strip())
            elif s.startswith("Growing the step"):
                out["grows"] += 1
            elif s.startswith("Splitting the step"):
                out["splits"] += 1
            elif s.startswith("Newton failed at"):
                out["newton_failures"] += 1
            elif s.startswith("Error: giving up at"):
                out["failure"] = s[len("Error: giving up at"):].strip()
                continuing = True
            elif s.startswith("Load step"):
                out["step_attempts"] += 1
                m = re.search(r"t = (\S+)", s)
                if m:
                    out["last_t"] = m.group(1)
            elif ("Error" in s or "Exception" in s or "error:" in s) and len(out["errors"]) < 3:
                out["errors"].append(s)
    return out


def fmt(x, spec=".2e"):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "-"
    return format(x, spec)


def pct(x):
    return "-" if x is None else "%+.1f %%" % (100. * x)


def parse_expect(text):
    """Flags and key=value tokens of the EXPECT string of run.sh; a value may
    hold spaces ("diag=no contact"): words without '=' that are not flags
    continue the previous value."""
    flags, kv, last = [], [], None
    for word in text.split():
        if word in FLAGS:
            flags.append(word)
            last = None
        elif "=" in word:
            key, _, value = word.partition("=")
            kv.append([key, value])
            last = kv[-1]
        elif last is not None:
            last[1] += " " + word
        else:
            flags.append(word)
    return flags, [(k, v) for k, v in kv]


def warning_label(text):
    """Short label of one warning of the program, for the tables."""
    m = re.search(r"largest displacement, (\S+),", text)
    if m:
        return "large displacement (|u| = %s)" % m.group(1)
    if "lock volumetrically" in text:
        m = re.search(r"body (\d+)", text)
        return "locking" + (" (body %s)" % m.group(1) if m else "")
    m = re.search(r"singular in (\d+) Newton solve", text)
    if m:
        return "singular stiffness (%s solves)" % m.group(1)
    m = re.search(r"body (\d+) is held only weakly against rotation: a couple turns it (\S+) times", text)
    if m:
        return "weakly held rotation (body %s, theta G V = %s)" % m.groups()
    m = re.search(r"leaves the small-strain range \(largest principal strain (\S+), "
                  r"largest rotation (\S+) rad", text)
    if m:
        return "beyond small strain (strain %s, rotation %s)" % m.groups()
    m = re.search(r"slave side is (\S+) times stiffer", text)
    if m:
        ratio = ("%.3g" % float(m.group(1))).replace("e+0", "e").replace("e+", "e")
        return "stiff slave (%s x the master)" % ratio
    return text if len(text) <= 60 else text[:57] + "..."


def iterations_text(its):
    if not its:
        return "none converged"
    if len(its) <= 10:
        return " ".join(str(i) for i in its)
    return "%s … %s (%d steps, %d its)" % (" ".join(str(i) for i in its[:5]),
                                           " ".join(str(i) for i in its[-2:]),
                                           len(its), sum(its))


def reproduce(run):
    sets = [s for s in run.get("sets", "").split("\t") if s]
    parts = ["build/contact_fem", run.get("scene", "?")]
    for s in sets:
        # double quotes read better ("Young's moduli=...") and are safe
        # unless the value holds characters the shell expands in them
        quoted = '"%s"' % s if not re.search(r'["$`\\!]', s) else shlex.quote(s)
        parts += ["--set", quoted]
    return " ".join(parts)


def analyse_case(d):
    run = read_kv(os.path.join(d, "run.txt"))
    case = {"dir": d, "run": run, "group": run.get("group", "?"),
            "name": run.get("name", os.path.basename(d)),
            "rc": int(run.get("exit_code", "-1") or -1),
            "elapsed": float(run.get("elapsed", "nan") or "nan"),
            "order": int(run.get("order", "0") or 0)}
    case["flags"], case["expect_kv"] = parse_expect(run.get("expect", ""))
    case["expect"] = case["flags"] + ["%s=%s" % kv for kv in case["expect_kv"]]
    case["out"] = parse_stdout(os.path.join(d, "stdout.txt"))
    trim = read_kv(os.path.join(d, "trim.txt"))
    case["stdout_lines"] = int(trim["stdout_lines"]) if "stdout_lines" in trim else None
    # counts of a trimmed console log were taken by run.sh before trimming
    for key in ("step_attempts", "splits", "newton_failures"):
        if trim.get(key, "").isdigit():
            case["out"][key] = int(trim[key])
    summary = None
    path = os.path.join(d, "summary.json")
    if os.path.exists(path):
        try:
            with open(path) as f:
                summary = json.load(f)
        except ValueError:
            summary = None
    case["summary"] = summary
    c0 = summary["cycles"][0] if summary and summary.get("cycles") else {}
    case["its"] = [s.get("newton_iterations") for s in c0.get("load_steps", [])]
    case["last_time"] = c0.get("load_steps", [{}])[-1].get("time") if c0.get("load_steps") else None
    contact = c0.get("contact", {})
    reaction = c0.get("reaction", {})
    analytical = c0.get("analytical", {})
    case["contact"], case["reaction"], case["analytical"] = contact, reaction, analytical
    case["wall"] = summary.get("wall_time") if summary else None
    case["status"] = summary.get("status") if summary else None
    # warnings: console lines "Warning: ..." and cycles[*].warning of summary.json
    texts = list(case["out"]["warnings"])
    for cyc in (summary or {}).get("cycles", []):
        w = cyc.get("warning")
        if w and not any(w in t for t in texts):
            texts.append(w)
    case["warnings"] = texts
    labels, locked = [], []
    for t in texts:
        label = warning_label(t)
        m = re.match(r"locking \(body (\d+)\)", label)
        if m:
            locked.append(m.group(1))
            label = "locking"
        if label not in labels:
            labels.append(label)
    if len(locked) > 1:
        labels = [("locking (bodies %s)" % ", ".join(locked)) if l == "locking" else l
                  for l in labels]
    elif locked:
        labels = [("locking (body %s)" % locked[0]) if l == "locking" else l for l in labels]
    case["warning_labels"] = labels

    full = read_profile(os.path.join(d, "pressure_profile.csv"))
    case["profile"] = full
    prof = [r for r in full if r.get("active", 0) > 0.5]
    case["n_active_profile"] = len(prof)
    # 3D scenes (a z column) are quarter models: the pressure centre is not
    # on the axis, and no centre is measured.
    case["dim"] = 3 if full and "z" in full[0] else 2
    if prof:
        ps = [r["pressure"] for r in prof]
        case["p_min"], case["p_max"] = min(ps), max(ps)
        total = sum(ps)
        case["centre"] = (sum(r["pressure"] * r["x"] for r in prof) / total
                          if total > 0 and case["dim"] == 2 else None)
    else:
        case["p_min"] = case["p_max"] = case["centre"] = None
    h = contact.get("slave_element_size") or None
    case["centre_h"] = (case["centre"] / h) if (case["centre"] is not None and h) else None
    judge(case)
    return case


def judge(case):
    """Sets case['verdict'] (short), case['kind'] (ok / expected / indicative /
    hang / failure / unclear / wrong) and case['notes'] (list of str)."""
    rc, out, exp = case["rc"], case["out"], case["flags"]
    notes = []
    kv = case["expect_kv"]
    diag = next((v for k, v in kv if k == "diag"), None)
    wanted = [v for k, v in kv if k == "warn"]
    tol = next((float(v) for k, v in kv if k == "tol"), None)
    ptol = next((float(v) for k, v in kv if k == "ptol"), HERTZ_P_TOL)
    imbalance_tol = tol if tol is not None else IMBALANCE_TOL
    pressure_tol = tol if tol is not None else PRESSURE_TOL
    warned = bool(case["warnings"])
    missing = [w for w in wanted
               if not any(w.lower() in t.lower() for t in case["warnings"])]
    for w in missing:
        notes.append("the expected warning '%s' is not printed" % w)

    if rc in (124, 137):
        lines = case["stdout_lines"]
        case["kind"] = "hang"
        case["verdict"] = ("HANG: killed after %s s; %d step attempts, %d splits, t stuck at %s%s"
                           % (case["run"].get("timeout", "?"), out["step_attempts"], out["splits"],
                              out["last_t"], "" if lines is None else ", %d console lines" % lines))
        case["notes"] = notes
        return
    if rc == 1:
        text = out["errors"][0] if out["errors"] else "?"
        # diag= on a refused input (e.g. a self-contact pair): the refusal is the answer
        case["kind"] = "expected" if diag and diag.lower() in text.lower() else "failure"
        case["verdict"] = ("refused as expected (exit 1): " if case["kind"] == "expected" else
                           "bad input (exit 1): ") + text
        case["notes"] = notes
        return
    if rc == 3:
        # Converged, but beyond small-strain linear elasticity (README: exit codes).
        expected = bool(diag) and "range" in diag.lower()
        case["kind"] = "expected" if expected else "unclear"
        case["verdict"] = "converged outside the model's range (exit 3)"
        case["notes"] = notes
        return
    if rc not in (0, 2):
        case["kind"] = "failure"
        case["verdict"] = "CRASH (exit %d): %s" % (rc, out["errors"][0] if out["errors"] else "")
        case["notes"] = notes
        return
    if rc == 2:
        text = out["failure"] or (out["errors"][0] if out["errors"] else "no message")
        has = [label for label, pattern in (("step", r"load step \d+"),
                                            ("iteration", r"iteration"),
                                            ("residuals", r"\|r_u\|"),
                                            ("hint", r"hint|set contact/"))
               if re.search(pattern, text, re.I)]
        text += " [message gives: %s]" % (", ".join(has) if has else "nothing")
        if diag:
            if diag.lower() in text.lower() and not missing:
                case["kind"] = "expected"
                case["verdict"] = "stops as expected: " + text
            elif diag.lower() in text.lower():
                case["kind"] = "unclear"
                case["verdict"] = "stops with the expected '%s', but without the expected warning: %s" % (diag, text)
            else:
                case["kind"] = "unclear"
                case["verdict"] = ("stops, but not with the expected '%s' diagnosis: %s" % (diag, text))
        else:
            case["kind"] = "failure"
            case["verdict"] = "FAILS: " + text
        case["notes"] = notes
        return

    # rc == 0: converged
    kind = "ok"
    if diag:
        kind = "wrong"
        notes.append("converged although a '%s' stop was expected" % diag)
    imb = case["reaction"].get("relative_imbalance")
    applied = case["reaction"].get("applied_load")
    if imb is not None and imb > imbalance_tol:
        kind = "wrong"
        if applied is not None and applied < 1e-14:
            # since 539de7a: |sum of reactions| / (half the sum of |reactions|)
            notes.append("reaction imbalance %.2g (no applied load: the support reactions "
                         "do not cancel)" % imb)
        else:
            notes.append("reaction imbalance %.2g" % imb)
    n_active = case["contact"].get("active_slave_nodes")
    # "p=..." is a key=value token of the EXPECT string (parse_expect puts
    # it in kv, not among the flags).
    for e in exp + ["p=" + v for k, v in kv if k == "p"]:
        if e.startswith("p="):
            p = float(e[2:])
            if not n_active:
                kind = "wrong"
                notes.append("no active node, expected p = %g" % p)
            elif case["p_min"] is not None:
                dev = max(abs(case["p_min"] / p - 1.), abs(case["p_max"] / p - 1.))
                case["p_dev"] = dev
                if dev > pressure_tol:
                    kind = "wrong"
                    notes.append("pressure %.6g … %.6g, expected %g" % (case["p_min"], case["p_max"], p))
        if e == "centred" and case["centre_h"] is not None and abs(case["centre_h"]) > CENTRE_TOL:
            kind = "wrong"
            notes.append("pressure centre off by %.2g elements" % case["centre_h"])
        if e == "empty" and n_active:
            kind = "wrong"
            notes.append("%d active nodes, expected none" % n_active)
    kind = judge_friction(case, kind, notes)
    a = case["analytical"]
    if a and ("hertz" in exp or "hertz-approx" in exp):
        perr = a.get("p_max_relative_error")
        aerr = a.get("a_error_in_slave_elements")
        bad = []
        if perr is not None and abs(perr) > ptol:
            bad.append("p_max %s" % pct(perr))
        # On fine meshes the half-width settles ~2 % below Hertz (the half-disc
        # is a finite body, not a half-space): many elements, but no mesh error.
        arel = (a.get("a_error") / a["a"]) if a.get("a_error") is not None and a.get("a") else None
        if aerr is not None and abs(aerr) > HERTZ_A_TOL and not (
                arel is not None and abs(arel) <= HERTZ_A_REL_TOL):
            bad.append("a off by %.2g elements" % aerr)
        if case["centre_h"] is not None and abs(case["centre_h"]) > CENTRE_TOL:
            bad.append("pressure centre off by %.2g elements" % case["centre_h"])
        if bad:
            if "hertz" in exp:
                kind = "wrong" if kind == "ok" else kind
                notes.append("converged but far from Hertz: " + ", ".join(bad))
            else:
                kind = "indicative" if kind == "ok" else kind
                notes.append("differs from Hertz (formula only indicative here): " + ", ".join(bad))
    if kind == "wrong" and warned and not missing:
        kind = "warned"
    elif missing and kind in ("ok", "indicative"):
        kind = "unclear"
    case["kind"] = kind
    verdict = {"ok": "converged, correct", "indicative": "converged (see note)",
               "wrong": "CONVERGED, CHECK FAILS",
               "warned": "converged, check fails, the program warns",
               "unclear": "converged, expected warning missing"}[kind]
    if out["splits"]:
        verdict += ", after %d step split(s)" % out["splits"]
        if out["grows"]:
            verdict += " (the step grew back %d time(s))" % out["grows"]
    case["verdict"] = verdict
    case["notes"] = notes


def judge_friction(case, kind, notes):
    """Friction tokens of a converged case: cone, ratio=MU, stick-all,
    slip-all (same=, near= and differs= compare with other cases: see
    judge_same)."""
    exp, out, contact = case["flags"], case["out"], case["contact"]
    kv = case["expect_kv"]
    if "cone" in exp:
        lines = out["cone"]
        bad = [k for k in ("slip nodes off the slip bound", "stick nodes outside the cone")
               if not lines.get(k, "").startswith("ok")]
        if bad:
            kind = "wrong"
            notes.append("friction cone: " + "; ".join(
                "%s %s" % (k, lines.get(k, "not printed")) for k in bad))
    for key, value in kv:
        if key != "ratio":
            continue
        mu, _, tol = value.partition(",")
        mu, tol = float(mu), (float(tol) if tol else RATIO_TOL)
        r = contact.get("tangential_over_normal_force")
        if r is None:
            kind = "wrong"
            notes.append("no tangential / normal force in summary.json")
            continue
        case["ratio"] = r
        dev = abs(abs(r) - mu) / mu if mu > 0 else abs(r)
        if not dev <= tol:
            kind = "wrong"
            notes.append("|Q/N| = %.10g, expected %g (off by %.2g%s)"
                         % (abs(r), mu, dev, " relative" if mu > 0 else ""))
    for key, value in kv:
        if key != "force":
            continue
        want = [float(v) for v in value.split(",")]
        got = contact.get("contact_force_components")
        norm = math.sqrt(sum(w * w for w in want)) or 1.
        if not got or len(got) != len(want):
            kind = "wrong"
            notes.append("no contact force components in summary.json")
        else:
            dev = max(abs(g - w) for g, w in zip(got, want)) / norm
            if not dev <= RATIO_TOL:
                kind = "wrong"
                notes.append("contact force (%s), expected (%s)" % (
                    ", ".join("%.10g" % g for g in got), value))
            else:
                notes.append("contact force (%s) to %.1g" % (value, dev))
    cat = case["analytical"].get("cattaneo") if case["analytical"] else None
    if cat:
        notes.append("Cattaneo: c/a %.3f (exact %.3f, error %.2f slave elements), stick zone "
                     "centre %.3g, tangential L2 error %.3f" % (
                         cat.get("c_h_over_a", float("nan")), cat.get("c_over_a", float("nan")),
                         cat.get("c_error_in_slave_elements", float("nan")),
                         cat.get("stick_zone_center", float("nan")),
                         cat.get("tangential_l2_relative_error", float("nan"))))
    n_stick, n_slip = contact.get("stick_nodes"), contact.get("slip_nodes")
    if "stick-all" in exp:
        if n_slip is None or n_slip > 0 or not n_stick:
            kind = "wrong"
            notes.append("stick / slip nodes at the end %s / %s, expected all stick" % (n_stick, n_slip))
        if out["rows_with_slip"]:
            kind = "wrong"
            notes.append("slip chatter: %d of %d Newton iterations have slip nodes (up to %d)"
                         % (out["rows_with_slip"], out["newton_rows"], out["max_slip_in_row"]))
        elif out["newton_rows"]:
            notes.append("no slip node in any of %d Newton iterations" % out["newton_rows"])
    if "slip-all" in exp:
        if n_stick is None or n_stick > 0 or not n_slip:
            kind = "wrong"
            notes.append("stick / slip nodes at the end %s / %s, expected all slip" % (n_stick, n_slip))
    return kind


def judge_same(cases):
    """Applies the same=GROUP/CASE tokens: a converged case whose p_max or
    contact force differs from the named case's by more than SAME_TOL is
    wrong (unless it warns)."""
    by_id = {c["group"] + "/" + c["name"]: c for c in cases}
    for c in cases:
        for key, value in c["expect_kv"]:
            if key in ("near", "force-near") and c["rc"] == 0:
                judge_near(c, by_id, value, force_only=(key == "force-near"))
            elif key == "differs" and c["rc"] == 0:
                judge_differs(c, by_id, value)
        for key, other_id in c["expect_kv"]:
            if key != "same" or c["rc"] != 0:
                continue
            other = by_id.get(other_id)
            if other is None or other["rc"] != 0:
                c["notes"].append("no converged run of %s to compare with" % other_id)
                continue
            diffs = []
            for name in ("max_contact_pressure", "total_contact_force"):
                a, b = c["contact"].get(name), other["contact"].get(name)
                if a is None or b is None or b == 0:
                    continue
                diffs.append(abs(a / b - 1.))
            diff = max(diffs) if diffs else float("nan")
            if not diff <= SAME_TOL:
                c["kind"] = "warned" if c["warnings"] else "wrong"
                c["verdict"] = ("CONVERGED, CHECK FAILS" if c["kind"] == "wrong" else
                                "converged, check fails, the program warns")
                c["notes"].append("p_max / contact force differ from %s by %.2g" % (other_id, diff))
            else:
                c["notes"].append("same p_max and contact force as %s (%.1g relative)"
                                  % (other_id, diff))


def fail_comparison(c, note):
    if c["kind"] in ("ok", "indicative", "warned", "wrong"):
        c["kind"] = "warned" if c["warnings"] else "wrong"
        c["verdict"] = ("CONVERGED, CHECK FAILS" if c["kind"] == "wrong" else
                        "converged, check fails, the program warns")
    c["notes"].append(note)


def judge_near(c, by_id, value, force_only=False):
    """near=GROUP/CASE,TOL: p_max and the contact force within TOL relative
    of that case's (a penalty answer against the alm one); force-near=: the
    contact force only (another mesh: p_max is a nodal peak)."""
    other_id, _, tol = value.partition(",")
    tol = float(tol) if tol else 1e-2
    other = by_id.get(other_id)
    if other is None or other["rc"] != 0:
        c["notes"].append("no converged run of %s to compare with" % other_id)
        return
    diffs = []
    names = ("total_contact_force",) if force_only else ("max_contact_pressure", "total_contact_force")
    for name in names:
        a, b = c["contact"].get(name), other["contact"].get(name)
        if a is not None and b:
            diffs.append(abs(a / b - 1.))
    diff = max(diffs) if diffs else float("nan")
    what = "contact force" if force_only else "p_max / contact force"
    if not diff <= tol:
        fail_comparison(c, "%s differ from %s by %.2g (> %g)" % (what, other_id, diff, tol))
    else:
        c["notes"].append("%s within %.1g of %s" % (what, diff, other_id))


def judge_differs(c, by_id, other_id):
    """differs=GROUP/CASE: the tangential traction profile must differ from
    that case's by more than DIFFERS_TOL of its largest pressure (hysteresis:
    the same boundary data reached along another path)."""
    other = by_id.get(other_id)
    if other is None or other["rc"] != 0:
        c["notes"].append("no converged run of %s to compare with" % other_id)
        return
    mine, theirs = c.get("profile") or [], other.get("profile") or []
    # 2D: one signed column; 3D: the vector's components.
    keys = [k for k in ("tangential_traction", "tangential_traction_x", "tangential_traction_y",
                        "tangential_traction_z") if mine and k in mine[0]]
    if not mine or len(mine) != len(theirs) or not keys:
        fail_comparison(c, "no tangential traction profile to compare with %s" % other_id)
        return
    scale = max(abs(r["pressure"]) for r in theirs) or 1.
    diff = max(math.sqrt(sum((a[k] - b[k]) ** 2 for k in keys))
               for a, b in zip(mine, theirs)) / scale
    qa = c["contact"].get("total_tangential_contact_force")
    qb = other["contact"].get("total_tangential_contact_force")
    forces = "" if qa is None or qb is None else ", tangential force %.4g against %.4g" % (qa, qb)
    if not diff > DIFFERS_TOL:
        fail_comparison(c, "no hysteresis: tangential tractions within %.2g of %s's%s"
                        % (diff, other_id, forces))
    else:
        c["notes"].append("hysteresis: tangential tractions differ from %s's by %.2g of p_max%s"
                          % (other_id, diff, forces))


def table(cases, hertz, pressure, warnings, friction=False):
    head = ["case", "what", "Newton its per step", "splits", "result", "imbalance"]
    if hertz:
        head += ["p_max err", "a err [el]", "centre [el]"]
    if pressure:
        head += ["pressure (active nodes)"]
    if friction:
        head += ["stick / slip", "Q/N", "p_max", "slip its / s/s changes"]
    if warnings:
        head += ["warnings"]
    head += ["wall [s]"]
    rows = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for c in cases:
        out = c["out"]
        split_txt = str(out["splits"])
        if out["newton_failures"]:
            split_txt += " (%d failed Newton)" % out["newton_failures"]
        if out["grows"]:
            split_txt += ", grew back %dx" % out["grows"]
        result = c["verdict"]
        if c["notes"]:
            result += "; " + "; ".join(c["notes"])
        imb = c["reaction"].get("relative_imbalance")
        imb_txt = fmt(imb, ".1e")
        if imb is not None and (c["reaction"].get("applied_load") or 0.) < 1e-14:
            imb_txt += " (no applied load)"
        if c["rc"] == 2 and c["summary"] and c["last_time"] is not None:
            imb_txt += " (at t = %.4g)" % c["last_time"]
        row = ["`%s`" % c["name"], c["run"].get("description", ""),
               iterations_text(c["its"]), split_txt, result.replace("|", "\\|"), imb_txt]
        if hertz:
            a = c["analytical"] if c["rc"] == 0 else {}
            row += [pct(a.get("p_max_relative_error")) if a else "-",
                    fmt(a.get("a_error_in_slave_elements"), ".2f") if a else "-",
                    fmt(c["centre_h"], "+.2f") if c["rc"] == 0 else "-"]
        if pressure:
            if c["p_min"] is not None and c["rc"] == 0:
                row.append("%.6g … %.6g (%d nodes)" % (c["p_min"], c["p_max"], c["n_active_profile"]))
            elif c["rc"] == 0:
                row.append("no active node")
            else:
                row.append("-")
        if friction:
            ct = c["contact"] if c["rc"] == 0 else {}
            row.append("%d / %d" % (ct["stick_nodes"], ct["slip_nodes"])
                       if ct.get("stick_nodes") is not None else "-")
            row.append(fmt(ct.get("tangential_over_normal_force"), ".6g")
                       if ct.get("tangential_over_normal_force") is not None else "-")
            row.append(fmt(ct.get("max_contact_pressure"), ".6g")
                       if ct.get("max_contact_pressure") is not None else "-")
            o = c["out"]
            row.append("%d of %d / %d" % (o["rows_with_slip"], o["newton_rows"], o["ss_changes"])
                       if o["newton_rows"] else "-")
        if warnings:
            row.append("; ".join(c["warning_labels"]).replace("|", "\\|") or "-")
        wall = c["wall"] if c["wall"] is not None and c["rc"] in (0, 2) else None
        row.append(fmt(wall, ".2f") if wall is not None else "%.0f (killed)" % c["elapsed"]
                   if c["rc"] in (124, 137) else fmt(c["elapsed"], ".2f"))
        rows.append("| " + " | ".join(row) + " |")
    return "\n".join(rows)


def set_value(case, key):
    for s in case["run"].get("sets", "").split("\t"):
        k, sep, v = s.partition("=")
        if sep and k == key:
            return v.strip()
    return None


def locking_table(cases):
    """p_max error of the incompressible group on the default mesh: one row
    per nu, one column per element (Q1/Q2, standard/B-bar)."""
    cells, nus, cols = {}, [], []
    for c in cases:
        keys = {s.partition("=")[0] for s in c["run"].get("sets", "").split("\t") if s}
        # (3D: the sphere's mesh keys name the base mesh of each degree)
        keys = {k for k in keys if not k.startswith("Geometry/Hertz sphere/")}
        if keys - {"Finite element/Degree", "Materials/Poisson's ratios",
                   "Finite element/Volumetric strain"}:
            continue  # refined-mesh cases
        nu = (set_value(c, "Materials/Poisson's ratios") or "?").split(",")[0].strip()
        deg = set_value(c, "Finite element/Degree") or "1"
        strain = set_value(c, "Finite element/Volumetric strain") or "standard"
        col = "Q%s %s" % (deg, strain)
        if nu not in nus:
            nus.append(nu)
        if col not in cols:
            cols.append(col)
        a = c["analytical"] if c["rc"] == 0 else {}
        if c["rc"] != 0:
            txt = c["kind"]
        else:
            txt = pct(a.get("p_max_relative_error")) if a else "-"
            if any(l.startswith("locking") for l in c["warning_labels"]):
                txt += " (warns)"
        cells[(nu, col)] = txt
    if len(cols) < 2:
        return ""
    nus.sort(key=float)
    cols.sort(key=lambda x: (x.split()[0], x.split()[1] != "standard"))
    rows = ["| nu | " + " | ".join(cols) + " |", "|" + "---|" * (len(cols) + 1)]
    for nu in nus:
        rows.append("| %s | " % nu + " | ".join(cells.get((nu, col), "") for col in cols) + " |")
    return "\n".join(rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--results", default=os.path.join(HERE, "results"))
    ap.add_argument("--doc", default=os.path.join(REPO, "doc", "stability.md"))
    ap.add_argument("--notes", default=os.path.join(HERE, "notes.md"))
    args = ap.parse_args()

    cases = [analyse_case(os.path.dirname(p))
             for p in glob.glob(os.path.join(args.results, "*", "*", "run.txt"))]
    if not cases:
        print("analyse.py: no runs under %s" % args.results, file=sys.stderr)
        return 1
    cases.sort(key=lambda c: c["order"])
    judge_same(cases)

    shas = sorted({c["run"].get("binary_sha256", "?") for c in cases})
    gits = sorted({c["run"].get("git", "?") for c in cases})
    total = sum(c["elapsed"] for c in cases if not math.isnan(c["elapsed"]))
    kinds = {}
    for c in cases:
        kinds[c["kind"]] = kinds.get(c["kind"], 0) + 1

    md = []
    md.append("# Stability suite")
    md.append("")
    md.append("Generated by `bench/stability/analyse.py` from the runs of "
              "`bench/stability/run.sh` (%s). Re-run: `bench/stability/run.sh` "
              "(about %.0f s of run time, one case at a time)." %
              (datetime.date.today().isoformat(), total))
    md.append("")
    binaries = sorted({c["run"].get("binary", "build/contact_fem") for c in cases})
    md.append("- binary: %s, sha256 %s%s; checkout at run time `%s` (the binary may be "
              "built from another commit: see the reading below)" %
              (", ".join("`%s`" % b.replace(REPO + "/", "") for b in binaries),
               ", ".join("`%s`" % s for s in shas),
               " (**the binary changed during the suite**)" if len(shas) > 1 else "",
               ", ".join(gits)))
    if len(shas) > 1:
        for sha in shas:
            names = [c["group"] + "/" + c["name"] for c in cases
                     if c["run"].get("binary_sha256") == sha]
            md.append("  - `%s`: %d cases, %s … %s" % (sha, len(names), names[0], names[-1]))
    md.append("- %d cases, %.0f s in total: %s" % (
        len(cases), total, ", ".join("%d %s" % (n, k) for k, n in sorted(kinds.items()))))
    per_group = []
    for g in [g for g, _ in GROUPS] + sorted({c["group"] for c in cases} - {g for g, _ in GROUPS}):
        gk = {}
        for c in cases:
            if c["group"] == g:
                gk[c["kind"]] = gk.get(c["kind"], 0) + 1
        if gk:
            per_group.append("%s %d (%s)" % (g, sum(gk.values()), ", ".join(
                "%d %s" % (n, k) for k, n in sorted(gk.items()))))
    md.append("- per group: " + "; ".join(per_group))
    if any(c["group"] == "friction" for c in cases):
        md.append("- friction (group 11): Coulomb mu = 0 ... 1e3 and Tresca on a pressed and pulled "
                  "block (|Q/N| = mu to 1e-8 when it slides, slip nodes on their bound and stick "
                  "nodes inside the cone to 1e-8, mu = 1e3 without a slip node in any Newton "
                  "iteration), a reversed tangential load (hysteresis: the unloading branch and "
                  "the final state differ from the loading branch and the pressed state), "
                  "1e6 stiff/soft pairs, penalty frictional across penalty scales against alm, "
                  "updated kinematics, Hertz and Cattaneo; the reading of that run is the first "
                  "section of \"Reading of the run\" below.")
    md.append("- verdict kinds: *ok* = converged and matches the expected physics; "
              "*expected* = stops with the diagnosis the case is meant to provoke; "
              "*indicative* = converged, reference only indicative; *warned* = converged, a "
              "check fails, and the program printed a warning (the one the case expects, if "
              "it names one); *failure* = reported "
              "solver failure; *unclear* = stops with a misleading diagnosis, or an expected "
              "warning is missing; *wrong* = "
              "converged but a check fails and nothing is said (a silent wrong answer unless "
              "the notes explain it); *hang* = killed by the time limit.")
    md.append("- columns: *Newton its per step* lists the converged load steps only (failed "
              "attempts are counted under *splits*); *imbalance* = `reaction.relative_imbalance` "
              "(of the last converged step for failed runs); *p_max err* = "
              "`analytical.p_max_relative_error`; *a err [el]* = "
              "`analytical.a_error_in_slave_elements`; *centre [el]* = pressure-weighted mean x "
              "of the active slave nodes (deformed position, from pressure_profile.csv) in slave "
              "elements, 0 for a centred contact; *wall* = `wall_time` of summary.json "
              "(elapsed time for killed runs); *warnings* = the program's \"Warning:\" lines "
              "and `cycles[*].warning` of summary.json, shortened. *splits* also counts how often "
              "the step grew back (\"Growing the step\"). Hertz errors are only given for "
              "converged runs. Friction table: *stick / slip* = final stick and slip "
              "nodes; *Q/N* = `contact.tangential_over_normal_force` (signed); *slip its / s/s "
              "changes* = Newton iterations (of every step and attempt) with a slip node, out "
              "of all, and the sum of the stick/slip set changes. "
              "Reproduce commands name `build/contact_fem`; use the binary above.")
    md.append("- tolerances of the verdicts: |p_max err| ≤ %g, |a err| ≤ %g elements "
              "(or ≤ %g a on meshes so fine that the half-disc's finite-body effect, ~2 %% "
              "of a, spans more elements), "
              "|centre| ≤ %g elements, imbalance ≤ %g, patch pressures within %g relative "
              "(a case's `tol=` overrides the last two); friction: |Q/N| within 1e-8 "
              "of mu unless the case names another tolerance (`ratio=MU,TOL`), hysteresis "
              "(`differs=`) when the tangential tractions differ by more than 1e-3 of p_max." %
              (HERTZ_P_TOL, HERTZ_A_TOL, HERTZ_A_REL_TOL, CENTRE_TOL, IMBALANCE_TOL,
               PRESSURE_TOL))
    md.append("")

    known = [g for g, _ in GROUPS]
    extra = sorted({c["group"] for c in cases} - set(known))
    for g, title in GROUPS + [(e, e) for e in extra]:
        gc = [c for c in cases if c["group"] == g]
        if not gc:
            continue
        hertz = any(c["analytical"] for c in gc) or any(
            "hertz" in e for c in gc for e in c["expect"])
        pressure = any(e.startswith("p=") or e in ("empty", "centred")
                       for c in gc for e in c["expect"])
        warnings = any(c["warning_labels"] for c in gc)
        md.append("## %s" % title)
        md.append("")
        md.append(table(gc, hertz, pressure, warnings, friction=(g in ("friction", "3d-friction"))))
        md.append("")
        if g in ("incompressible", "3d-incompressible"):
            pivot = locking_table(gc)
            if pivot:
                md.append("p_max error against Hertz side by side (default mesh; \"(warns)\" = "
                          "the locking warning is printed):")
                md.append("")
                md.append(pivot)
                md.append("")

    md.append("## Automatic findings")
    md.append("")
    md.append("Cases whose verdict is *hang*, *failure*, *unclear*, *warned* or *wrong*, or with a note; "
              "each with the command that reproduces it (from the repository root).")
    md.append("")
    for c in cases:
        if c["kind"] in ("hang", "failure", "unclear", "warned", "wrong") or c["notes"]:
            md.append("- **%s/%s** (%s): %s%s%s" % (
                c["group"], c["name"], c["kind"], c["verdict"],
                ("; " + "; ".join(c["notes"])) if c["notes"] else "",
                (" [warns: %s]" % "; ".join(c["warning_labels"])) if c["warning_labels"] else ""))
            md.append("  `%s`" % reproduce(c["run"]))
    md.append("")

    if os.path.exists(args.notes):
        with open(args.notes) as f:
            md.append(f.read().rstrip() + "\n")

    text = "\n".join(md) + "\n"
    if args.doc == "-":
        sys.stdout.write(text)
    else:
        os.makedirs(os.path.dirname(os.path.abspath(args.doc)), exist_ok=True)
        with open(args.doc, "w") as f:
            f.write(text)
        print("wrote %s" % args.doc, file=sys.stderr)
    for c in cases:
        print("%-40s %-10s %s" % (c["group"] + "/" + c["name"], c["kind"], c["verdict"][:110]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
