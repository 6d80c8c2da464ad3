#!/usr/bin/env python3
"""Analyse the runs of bench/hertz_convergence/run.sh.

Reads <results>/<run>/{summary.json, convergence.csv, run.txt} and
<results>/study.txt, computes per cycle

  - the energy error  err_E = sqrt(2 |Pi_h + W - Pi_ref|)  (Pi = 1/2 u.K u - f.u,
    Pi_ref from the overkill run, see reference(); W = the chord-gap work of
    the polygonal Q1 arc that contact_fem reports, 0 for Q2), relative to
    |u_ref|_E = sqrt(2 * strain energy of the reference),
  - the p_max error against the reference p_max (discretisation error) and
    against Hertz (as contact_fem reports it),
  - the effectivity eta / err_E of the SPR estimate contact_fem reports,

then least-squares rates, effectivities on the last cycles and the
comparison adaptive 'spr contact' against the finest uniform mesh. Writes
gnuplot data files (--plot-data) and the generated part of the report
(--doc) between the markers <!-- hertz_convergence:begin --> and
<!-- hertz_convergence:end -->; text outside the markers is kept.

Python 3 standard library only.
"""

import argparse
import base64
import json
import math
import os
import re
import struct
import sys
import zlib

BEGIN = "<!-- hertz_convergence:begin -->"
END = "<!-- hertz_convergence:end -->"

STRATEGIES = ["global", "kelly", "spr", "spr-contact"]
LABEL = {"global": "global", "kelly": "kelly", "spr": "spr", "spr-contact": "spr contact"}
DEGREES = [1, 2]
RATE_WINDOW = 16.0  # long-window rates: cycles with N >= N_final / RATE_WINDOW
RATE_LAST = {"global": 3, "adaptive": 5}  # rates over the last cycles
LIMITED_FACTOR = 3.0  # |Pi_h - Pi_ref| < LIMITED_FACTOR * delta: reference-limited
LAST_CYCLES = 3  # effectivities: mean over this many last cycles


# ---------------------------------------------------------------- reading
def read_keyvalue(path):
    info = {}
    if os.path.exists(path):
        with open(path) as f:
            for line in f:
                key, sep, value = line.rstrip("\n").partition("=")
                if sep:
                    info[key.strip()] = value.strip()
    return info


def read_run(results, name):
    """The cycles of one run (list of dicts) and its run.txt, or None."""
    d = os.path.join(results, name)
    path = os.path.join(d, "summary.json")
    if not os.path.exists(path):
        return None
    try:
        with open(path) as f:
            summary = json.load(f)
    except json.JSONDecodeError:
        print(f"analyse.py: {path} is not valid JSON (run interrupted while "
              f"writing?)", file=sys.stderr)
        return None
    run = read_keyvalue(os.path.join(d, "run.txt"))
    cycles = []
    for c in summary.get("cycles", []):
        if "potential_energy" not in c:
            continue
        contact = c.get("contact", {})
        analytical = c.get("analytical", {})
        steps = c.get("load_steps", [])
        newton = 0
        for s in steps:
            for key in ("newton_iterations", "iterations"):
                if isinstance(s.get(key), (int, float)):
                    newton += int(s[key])
                    break
        cycles.append({
            "cycle": int(c["cycle"]),
            "cells": int(c["n_cells"]),
            "dofs": int(c["n_dofs"]),
            "Pi": float(c["potential_energy"]),
            # Degree 1: work of the contact force on the chord gap of the
            # polygonal arc (contact_fem's analytical block; 0 for degree 2).
            "W": float(analytical.get("chord_gap_work", 0.)),
            "strain": float(c["strain_energy"]),
            "eta": float(c.get("estimated_error", float("nan"))),
            # Plain SPR on the same solution ('Compare with plain SPR').
            "eta_plain": float(c.get("plain_spr_estimated_error", float("nan"))),
            # Contact pressure against the reference run's profile: the
            # mortar multiplier, and the normal traction of the recovered
            # stress with and without the contact terms; the recovered shear
            # traction (zero for frictionless contact) over p_max.
            "p_l2_mortar": float(c.get("pressure_reference_l2_relative_error", float("nan"))),
            "p_l2_rec": float(c.get("recovered_pressure_reference_l2_relative_error",
                                    float("nan"))),
            "p_l2_rec_plain": float(c.get("plain_spr_recovered_pressure_reference_l2_relative_error",
                                          float("nan"))),
            "shear_rec": float(c.get("recovered_shear_traction_max_relative", float("nan"))),
            "shear_rec_plain": float(c.get("plain_spr_recovered_shear_traction_max_relative",
                                           float("nan"))),
            "active": int(contact.get("active_slave_nodes", 0)),
            "slave_h": float(contact.get("slave_element_size", float("nan"))),
            "p_max": float(contact.get("max_contact_pressure", float("nan"))),
            "p_hertz_err": float(analytical.get("p_max_relative_error", float("nan"))),
            "p_hertz": float(analytical.get("p_max", float("nan"))),
            "a_hertz": float(analytical.get("a", float("nan"))),
            "wall": float(c["wall_time"]),
            "cum": float(c["cumulative_wall_time"]),
            "newton": newton,
            "n_steps": len(steps),
        })
    # Newton iterations per cycle from convergence.csv (a column there).
    csv = os.path.join(d, "convergence.csv")
    if os.path.exists(csv):
        with open(csv) as f:
            header = f.readline().strip().split(",")
            rows = [dict(zip(header, line.strip().split(","))) for line in f if line.strip()]
        by_cycle = {int(r["cycle"]): r for r in rows if r.get("cycle", "").isdigit()}
        for c in cycles:
            r = by_cycle.get(c["cycle"])
            if r and r.get("newton_iterations", "").isdigit():
                c["newton"] = int(r["newton_iterations"])
    return {"name": name, "cycles": cycles, "run": run, "status": summary.get("status", "?")}


# ---------------------------------------------------------------- reference
def aitken(p):
    """Limit of the last three values of p by Aitken's delta^2 process, or
    None if the differences do not shrink monotonically."""
    if len(p) < 3:
        return None
    d1, d2 = p[-2] - p[-3], p[-1] - p[-2]
    if d1 == 0 or d2 == 0 or d1 * d2 < 0 or abs(d2) >= abs(d1):
        return None
    return p[-1] - d2 * d2 / (d2 - d1)


def contracting(p, n_diff=3):
    """(ok, diffs, ratios): whether the last n_diff differences of p (fewer if
    p is short, at least 2) have one sign and shrink in magnitude, i.e. look
    like a geometric tail that Aitken may extrapolate."""
    d = [b - a for a, b in zip(p[:-1], p[1:])][-n_diff:]
    ratios = [b / a if a != 0 else float("inf") for a, b in zip(d[:-1], d[1:])]
    ok = len(d) >= 2 and all(0 < q < 1 for q in ratios)
    return ok, d, ratios


def reference(ref):
    """Pi_ref, its uncertainty delta and the reference p_max, strain energy.

    Aitken's extrapolation is used only if the last three differences of the
    reference energies have one sign and contract (a geometric tail); then the
    extrapolation step is the error bar. Otherwise (non-monotone or
    non-contracting differences, e.g. the discretisation error has fallen to
    the level of solver noise) Aitken would extrapolate in an arbitrary
    direction: the last value is taken, with the largest of the last two
    differences as its uncertainty."""
    c = ref["cycles"]
    pis = [x["Pi"] for x in c]
    ok, diffs, ratios = contracting(pis)
    extrapolated = aitken(pis) if ok else None
    diff_text = ", ".join("%.2g" % x for x in diffs)
    ratio_text = ", ".join("%.2f" % q for q in ratios)
    if extrapolated is not None:
        pi_ref = extrapolated
        # The extrapolation correction itself is the error bar.
        delta = abs(extrapolated - pis[-1])
        method = ("Aitken extrapolation of the last three reference cycles: the last "
                  "differences %s have one sign and contract (ratios %s)" % (diff_text, ratio_text))
        delta_text = "the size of the extrapolation step"
        extrapolated_flag = True
    else:
        pi_ref = pis[-1]
        delta = max(abs(x) for x in diffs[-2:]) if diffs else float("nan")
        wrong = None
        if len(pis) >= 3 and diffs[-1] != diffs[-2]:
            d1, d2 = diffs[-2], diffs[-1]
            wrong = pis[-1] - d2 * d2 / (d2 - d1)
        method = ("last reference cycle, no extrapolation: the last differences %s are %s "
                  "(ratios %s), so they are not a geometric tail%s" % (
                      diff_text,
                      "not monotone" if any(q <= 0 for q in ratios) else "not contracting",
                      ratio_text,
                      "; Aitken on the last three would give %.10f, %s" % (
                          wrong, "on the wrong side of the last value (above it, while Pi "
                          "decreases)" if diffs[-1] < 0 and wrong > pis[-1] else
                          "a step of %.2g" % (wrong - pis[-1])) if wrong is not None else ""))
        delta_text = "the largest of the last two differences"
        extrapolated_flag = False
    p_ref = c[-1]["p_max"]
    p_delta = abs(c[-1]["p_max"] - c[-2]["p_max"]) if len(c) > 1 else float("nan")
    strain_ref = c[-1]["strain"]
    return {
        "Pi": pi_ref, "delta": delta, "method": method, "delta_text": delta_text,
        "extrapolated": extrapolated_flag, "p_max": p_ref,
        "p_delta": p_delta, "strain": strain_ref, "norm": math.sqrt(2 * strain_ref),
        "cycles": c,
    }


# ---------------------------------------------------------------- errors
def add_errors(run, ref):
    for c in run["cycles"]:
        dpi = c["Pi"] + c["W"] - ref["Pi"]
        c["dPi"] = dpi
        raw = c["Pi"] - ref["Pi"]
        c["eff_raw"] = c["eta"] / math.sqrt(2 * abs(raw)) if raw != 0 else float("nan")
        c["err"] = math.sqrt(2 * abs(dpi))
        c["err_rel"] = c["err"] / ref["norm"]
        lo = max(abs(dpi) - ref["delta"], 0.)
        c["err_lo"] = math.sqrt(2 * lo) / ref["norm"]
        c["err_hi"] = math.sqrt(2 * (abs(dpi) + ref["delta"])) / ref["norm"]
        c["negative"] = dpi < 0
        c["limited"] = abs(dpi) < LIMITED_FACTOR * ref["delta"]
        c["eta_rel"] = c["eta"] / ref["norm"]
        c["eff"] = c["eta"] / c["err"] if c["err"] > 0 else float("nan")
        c["eff_plain"] = c["eta_plain"] / c["err"] if c["err"] > 0 else float("nan")
        c["p_err"] = abs(c["p_max"] - ref["p_max"]) / ref["p_max"]


def lsq_slope(xs, ys):
    n = len(xs)
    if n < 2:
        return float("nan")
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    mx, my = sum(lx) / n, sum(ly) / n
    sxx = sum((a - mx) ** 2 for a in lx)
    if sxx == 0:
        return float("nan")
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sxx


def rate(run, key, last=None, skip_limited=True):
    """-slope of log(key) against log(DoFs), as s in error ~ N^-s.
    last=k: over the last k distinct meshes; last=None: over the cycles with
    N >= N_final / RATE_WINDOW. Returns (s, number of points)."""
    c = [x for x in run["cycles"] if x[key] > 0 and not (skip_limited and x["limited"])]
    # A repeated mesh (no refinement) would count twice.
    uniq = []
    for x in c:
        if uniq and uniq[-1]["dofs"] == x["dofs"]:
            uniq[-1] = x
        else:
            uniq.append(x)
    if last is not None:
        pts = uniq[-last:]
    elif uniq:
        pts = [x for x in uniq if x["dofs"] >= uniq[-1]["dofs"] / RATE_WINDOW]
    else:
        pts = []
    if len(pts) < 2:
        return float("nan"), len(pts)
    return -lsq_slope([x["dofs"] for x in pts], [x[key] for x in pts]), len(pts)


def reached(cycles, key, target):
    """First cycle from which on `key` stays <= target; None if never."""
    for i, c in enumerate(cycles):
        if all(x[key] <= target for x in cycles[i:]):
            return c
    return None


def first_below(cycles, key, target):
    for c in cycles:
        if c[key] <= target:
            return c
    return None


# ---------------------------------------------------------------- VTU
def _decode_array(text, dtype, header_fmt):
    """A deal.II / VTK 'binary' zlib-compressed data array."""
    text = "".join(text.split())
    hsize = struct.calcsize(header_fmt)
    first = base64.b64decode(text[: 4 * math.ceil(3 * hsize / 3)])
    nblocks = struct.unpack("<" + header_fmt, first[:hsize])[0]
    hlen = 4 * math.ceil((3 + nblocks) * hsize / 3)
    header = struct.unpack("<" + header_fmt * (3 + nblocks),
                           base64.b64decode(text[:hlen])[: (3 + nblocks) * hsize])
    sizes = header[3:]
    raw = base64.b64decode(text[hlen:])
    out, pos = b"", 0
    for s in sizes:
        out += zlib.decompress(raw[pos:pos + s])
        pos += s
    fmt = {"Float32": "f", "Float64": "d", "Int32": "i", "Int64": "q", "UInt8": "B",
           "UInt32": "I", "UInt64": "Q"}[dtype]
    return struct.unpack("<%d%s" % (len(out) // struct.calcsize(fmt), fmt), out)


def read_vtu(path):
    with open(path) as f:
        xml = f.read()
    header_fmt = "Q" if 'header_type="UInt64"' in xml else "I"
    arrays = {}
    for m in re.finditer(r'<DataArray([^>]*)>(.*?)</DataArray>', xml, re.S):
        attrs, body = m.group(1), m.group(2)
        name = re.search(r'Name="([^"]*)"', attrs)
        dtype = re.search(r'type="([^"]*)"', attrs).group(1)
        key = name.group(1) if name else "points"
        if key in ("points", "connectivity", "offsets", "error_indicator"):
            arrays[key] = _decode_array(body, dtype, header_fmt)
    pts = arrays["points"]
    points = [(pts[3 * i], pts[3 * i + 1]) for i in range(len(pts) // 3)]
    conn, offs = arrays["connectivity"], arrays["offsets"]
    cells, start = [], 0
    for o in offs:
        cells.append(conn[start:o])
        start = o
    return points, cells, arrays.get("error_indicator")


def mesh_cells(path, degree):
    """The FE cells of a deal.II VTU written with build_patches(degree): each
    cell is a patch of degree^2 quadrilaterals on a (degree+1)^2 lattice of
    consecutive points (lexicographic). Returns per cell its boundary polygon,
    centroid and area."""
    points, sub, indicator = read_vtu(path)
    n = degree + 1
    per = degree * degree
    out = []
    for k in range(0, len(sub), per):
        ids = sorted(set(i for s in sub[k:k + per] for i in s))
        if len(ids) != n * n:
            continue
        lat = [points[i] for i in ids]  # lexicographic: i + n * j
        ring = ([lat[i] for i in range(n)] + [lat[i * n + n - 1] for i in range(1, n)]
                + [lat[n * (n - 1) + i] for i in range(n - 2, -1, -1)]
                + [lat[i * n] for i in range(n - 2, 0, -1)])
        area = 0.
        for a, b in zip(ring, ring[1:] + ring[:1]):
            area += a[0] * b[1] - b[0] * a[1]
        area = abs(area) / 2
        cx = sum(p[0] for p in ring) / len(ring)
        cy = sum(p[1] for p in ring) / len(ring)
        # error_indicator is cell data written per patch point: constant on
        # the patch; contact_fem writes eta_K (not squared).
        eta = float(indicator[ids[0]]) if indicator is not None else float("nan")
        out.append({"ring": ring, "x": cx, "y": cy, "h": math.sqrt(area), "eta": eta})
    return out


def cycle_vtus(d, cycles):
    """The VTU files of the first and of the last recorded cycle: one VTU per
    load step, numbered from 1 over all cycles (a run stopped at its DoF cap
    may have written one of the next, unrecorded cycle)."""
    def name(k):
        path = os.path.join(d, "solution_%03d.0.vtu" % k)
        return path if os.path.exists(path) else None
    if not cycles:
        return None, None
    return name(cycles[0]["n_steps"]), name(sum(c["n_steps"] for c in cycles))


def band_tests(a):
    return [
        ("contact zone: abs(x) < 0.8a, y < 1.2", lambda c: abs(c["x"]) < 0.8 * a and c["y"] < 1.2),
        ("contact edges: 0.8a <= abs(x) <= 1.2a, y < 1.2",
         lambda c: 0.8 * a <= abs(c["x"]) <= 1.2 * a and c["y"] < 1.2),
        ("near contact: distance to (0, 1) < 2 (rest)",
         lambda c: math.hypot(c["x"], c["y"] - 1) < 2),
        ("loaded top corners: distance to (+-8, 9) < 1",
         lambda c: math.hypot(abs(c["x"]) - 8, c["y"] - 9) < 1),
        ("rest of the cylinder", lambda c: True),
    ]


def eta_shares(cells, a):
    """Share of eta^2 per region (same regions as mesh_bands, plate last) and
    the share of the largest few cells."""
    total = sum(c["eta"] ** 2 for c in cells)
    if not total > 0:
        return None
    shares, taken = [], set()
    cyl = [(i, c) for i, c in enumerate(cells) if c["y"] > 1]
    for name, test in band_tests(a):
        sel = [i for i, c in cyl if i not in taken and test(c)]
        taken.update(sel)
        shares.append(sum(cells[i]["eta"] ** 2 for i in sel) / total)
    shares.append(sum(c["eta"] ** 2 for c in cells if c["y"] <= 1) / total)
    top = sorted(cells, key=lambda c: -c["eta"])
    top2 = sum(c["eta"] ** 2 for c in top[:2]) / total
    top10 = sum(c["eta"] ** 2 for c in top[:10]) / total
    return {"shares": shares, "top2": top2, "top10": top10,
            "top": [(c["x"], c["y"], c["h"], c["eta"] ** 2 / total) for c in top[:4]]}


def mesh_bands(cells, a):
    """Cells of the cylinder (y > 1) by region: the contact zone |x| < a near
    the plate, the contact edges, the rest of the contact neighbourhood, the
    loaded top corners and the bulk; plate cells separately."""
    bands = band_tests(a)
    rows = []
    cyl = [c for c in cells if c["y"] > 1]
    taken = set()
    for name, test in bands:
        sel = [i for i, c in enumerate(cyl) if i not in taken and test(c)]
        taken.update(sel)
        hs = sorted(cyl[i]["h"] for i in sel)
        rows.append((name, len(sel), hs[0] if hs else float("nan"),
                     hs[len(hs) // 2] if hs else float("nan")))
    plate = sorted(c["h"] for c in cells if c["y"] <= 1)
    rows.append(("plate (y < 1)", len(plate), plate[0] if plate else float("nan"),
                 plate[len(plate) // 2] if plate else float("nan")))
    return rows


def write_mesh_data(cells, path):
    with open(path, "w") as f:
        for c in cells:
            for p in c["ring"] + c["ring"][:1]:
                f.write("%.6g %.6g\n" % p)
            f.write("\n")


# ---------------------------------------------------------------- output
def same_mesh_effectivities(run):
    """Mean effectivities of the SPR-contact and the plain SPR estimate on the
    same meshes (last cycles of @p run that are not reference-limited), or
    None if the run has no plain-SPR comparison."""
    if not run:
        return None
    ok = [c for c in run["cycles"] if not c["limited"] and c["err"] > 0
          and not math.isnan(c["eff_plain"])][-LAST_CYCLES:]
    if not ok:
        return None
    contact = sum(c["eff"] for c in ok) / len(ok)
    plain = sum(c["eff_plain"] for c in ok) / len(ok)
    pressure = [c for c in ok if not math.isnan(c["p_l2_rec_plain"])]
    return {"contact": contact, "plain": plain, "cycles": [c["cycle"] for c in ok],
            "verdict": closer_verdict(contact, plain),
            "p_rec": (sum(c["p_l2_rec"] for c in pressure) / len(pressure)
                      if pressure else float("nan")),
            "p_rec_plain": (sum(c["p_l2_rec_plain"] for c in pressure) / len(pressure)
                            if pressure else float("nan"))}


def closer_verdict(contact, plain):
    """Is the effectivity @p contact closer to 1 than @p plain (on a log
    scale), by more than 0.05 %?"""
    gap = abs(math.log(plain)) - abs(math.log(contact))
    return ("yes" if gap > 5e-4 else
            ("no (equal within 0.05 %)" if abs(gap) <= 5e-4 else "no (farther)"))


def fmt(x, digits=3):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "–"
    return "%.*g" % (digits, x)


def pct(x, digits=3):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "–"
    return "%.*g" % (digits, 100 * x)


def write_plot_data(runs, outdir, ref):
    os.makedirs(outdir, exist_ok=True)
    for (deg, strat), run in runs.items():
        with open(os.path.join(outdir, "q%d-%s.dat" % (deg, strat)), "w") as f:
            f.write("# dofs cumulative_wall_time[s] energy_error_rel p_max_error_rel "
                    "eta_rel p_max_hertz_error_abs negative_dPi reference_limited\n")
            for c in run["cycles"]:
                f.write("%d %.6g %.6g %.6g %.6g %.6g %d %d\n" % (
                    c["dofs"], c["cum"], c["err_rel"], max(c["p_err"], 1e-7),
                    c["eta_rel"], abs(c["p_hertz_err"]), c["negative"], c["limited"]))
    # Values the gnuplot scripts load.
    with open(os.path.join(outdir, "reference.gp"), "w") as f:
        f.write("pi_ref = %.12g\ndelta = %.3g\np_ref = %.8g\n" % (ref["Pi"], ref["delta"], ref["p_max"]))
        f.write("p_gap = %.6g\n" % abs(ref["p_max"] / ref["cycles"][-1]["p_hertz"] - 1))
        f.write("p_res = %.6g\n" % max(ref["p_delta"] / ref["p_max"], 1e-7))
        f.write("a_hertz = %.6g\n" % ref["cycles"][-1]["a_hertz"])


def replace_section(path, text):
    old = ""
    if os.path.exists(path):
        with open(path) as f:
            old = f.read()
    block = BEGIN + "\n" + text.rstrip("\n") + "\n" + END
    if BEGIN in old and END in old:
        new = old[:old.index(BEGIN)] + block + old[old.index(END) + len(END):]
    else:
        new = (old.rstrip("\n") + "\n\n" if old else "# Convergence study: Hertz contact\n\n") \
            + block + "\n"
    with open(path, "w") as f:
        f.write(new)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--results", required=True)
    ap.add_argument("--doc", default="-", help="report file, '-' = stdout only")
    ap.add_argument("--plot-data", default=None)
    args = ap.parse_args()
    res = args.results
    if args.plot_data:
        os.makedirs(args.plot_data, exist_ok=True)
    study = read_keyvalue(os.path.join(res, "study.txt"))

    ref_run = read_run(res, "reference")
    if ref_run is None or len(ref_run["cycles"]) < 2:
        sys.exit("analyse.py: no usable reference run in %s" % res)
    ref = reference(ref_run)
    runs = {}
    for deg in DEGREES:
        for s in STRATEGIES:
            r = read_run(res, "q%d-%s" % (deg, s))
            if r and r["cycles"]:
                add_errors(r, ref)
                runs[(deg, s)] = r
    add_errors(ref_run, ref)

    # Cross-checks of Pi_ref from other sequences.
    checks = []
    for key, what in (((2, "global"), "Aitken on the 3 uniform Q2 levels"),
                      ((2, "spr-contact"), "Aitken on the last 3 cycles of Q2 spr contact"),
                      ((1, "spr-contact"), "Aitken on the last 3 cycles of Q1 spr contact")):
        if key in runs:
            c = runs[key]["cycles"]
            ext = aitken([x["Pi"] for x in c])
            checks.append((what, c[-1]["dofs"], c[-1]["Pi"], ext))

    L = []  # report lines
    w = L.append
    a_hertz = 0.
    w("## Hertz contact: uniform against adaptive refinement\n")
    w("Generated by `bench/hertz_convergence/run.sh` (numbers by `analyse.py`); "
      "re-running replaces this section.\n")
    loads = []
    for r in list(runs.values()) + [ref_run]:
        for k in ("loadavg_before", "loadavg_after"):
            try:
                loads.append(float(r["run"].get(k, "").split()[0]))
            except (ValueError, IndexError):
                pass
    w("- Date: %s; machine: %s, `nproc` = %s. 1-minute load average %s–%s at the starts "
      "and ends of the runs (in `results/*/run.txt`; the study itself contributes about "
      "1)%s." % (
          study.get("date", "?"), study.get("cpu", "?"), study.get("nproc", "?"),
          fmt(min(loads)) if loads else "?", fmt(max(loads)) if loads else "?",
          ": the cores were shared with other work, so wall times carry that noise"
          if loads and max(loads) > 1.6 else ""))
    binary = study.get("binary", "build/contact_fem")
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    if binary.startswith(root + os.sep):
        binary = os.path.relpath(binary, root)
    w("- Source: git `%s` (the working tree when the study started), binary `%s` of %s, "
      "sha256 `%s` (copied before the first run; all runs use the copy)%s." % (
          study.get("git", "?"), binary, study.get("binary_mtime", "?"),
          study.get("binary_sha256", "?"),
          "; **the binary at that path changed during the study**"
          if study.get("binary_changed_during_study") else ""))
    w("- Whole study (all runs below, including reference and mesh pictures): %s s." %
      study.get("study_seconds", "?"))
    w("")
    w("### Setup\n")
    w("All runs: `prm/hertz.prm` (R = 8 half-disc, E = 200, nu = 0.3 on a plate with "
      "E = 2e12, p = 0.2 t on the flat top, which slides freely; u_x held only at two "
      "points of the symmetry axis, (0, 1) and (0, 9); end time 1.001; the first cycle "
      "takes the two load steps, later cycles solve at the end time from the transferred "
      "solution), serial, one thread, no VTU output.\n")
    w("| Run | Start mesh | Refinement | Cycles |")
    w("|---|---|---|---|")
    for deg in DEGREES:
        for s in STRATEGIES:
            r = runs.get((deg, s))
            if not r:
                w("| Q%d %s | – | – | **missing** |" % (deg, LABEL[s]))
                continue
            cyc = r["cycles"]
            stop = ("stopped after the first cycle with >= %s DoFs" % r["run"].get("dof_cap")
                    if r["run"].get("stopped_at_dof_cap") == "1" else
                    "all requested cycles" if r["status"] == "converged" else r["status"])
            refine = ("uniform (every cell split)" if s == "global" else
                      "%s indicator, fixed fraction 0.3 (Doerfler), no coarsening" % LABEL[s])
            w("| Q%d %s | Contact refinements = %s (%d cells, %d DoFs) | %s | %d (%s) |" % (
                deg, LABEL[s], study.get("start_contact_refinements", "3"), cyc[0]["cells"],
                cyc[0]["dofs"], refine, len(cyc), stop))
    rc = ref["cycles"]
    w("| reference | default graded mesh (Contact refinements = 6, %d DoFs) | Q2, spr contact, "
      "fixed number 0.3 | %d |" % (rc[0]["dofs"], len(rc)))
    w("")
    w("The 'spr' runs report the plain SPR estimate, all others the SPR-contact estimate "
      "(`global` and `kelly` compute it without using it for marking). The cumulative wall "
      "time is contact_fem's own per-cycle clock summed over the cycles (solve, estimate, "
      "refine, solution transfer); it includes the SPR estimate in every run, also in "
      "`global`.\n")

    w("### Reference (overkill) and error measures\n")
    w("Energy error: `err_E = sqrt(2 |Pi_h + W - Pi_ref|)`, Pi = 1/2 u.K u - f.u from "
      "summary.json, relative to |u_ref|_E = sqrt(2 * strain energy) = %.6g of the "
      "reference." % ref["norm"])
    chords = any(c["W"] != 0. for r in runs.values() for c in r["cycles"])
    if not chords:
        w("W = 0 in this study: the Q1 runs put their elements on a quadratic mapping "
          "(`Finite element/Mapping degree = auto`), so the arc is not replaced by chords. "
          "Q1 on chords (`Mapping degree = 1`) would report the chord-gap work W "
          "(`analytical.chord_gap_work`), the work of the contact force on the sag "
          "h^2 t(1-t)/(2R) of the chords, which lowers Pi_h by about W, as much as "
          "(Pi_h - Pi_ref) itself on adaptive meshes; the formula then uses Pi_h + W.\n")
    else:
        w("W (`analytical.chord_gap_work`, Q1 only) is a geometry error, not a "
          "discretisation error of the displacement: Q1 replaces the arc by chords, which lie "
          "inside the circle by h^2 t(1-t)/(2R), so the discrete cylinder is shorter where it "
          "touches and the contact force does the extra work W = sum over slave faces of "
          "(lambda_a + lambda_b) h^3 / (24 R), which lowers Pi_h by about W. On the adaptive "
          "Q1 meshes W is as large as (Pi_h - Pi_ref) itself: without it the Q1 energy "
          "'error' jumps up and down from cycle to cycle, with the size of the contact "
          "elements, and the effectivities scatter (column 'raw' below). The estimate does not "
          "see W (it measures the stress field on the discrete domain), so it is compared "
          "with the error without W. Q2 arcs deviate from the circle by O(h^4/R^3): W = 0.\n")
    w("Reference: one Q2 run (not a Q1 one: a Q1 overkill accurate enough would need "
      "well over a million DoFs, see below) used for both degrees; both degrees "
      "approximate the same continuous problem.\n")
    w("| Reference cycle | DoFs | Pi | Pi - Pi(previous) | p_max |")
    w("|---:|---:|---:|---:|---:|")
    prev = None
    for c in rc:
        w("| %d | %d | %.10f | %s | %.6f |" % (c["cycle"], c["dofs"], c["Pi"],
                                           "–" if prev is None else "%.3g" % (c["Pi"] - prev),
                                           c["p_max"]))
        prev = c["Pi"]
    w("")
    w("- Pi_ref = %.10f (%s); uncertainty delta = %.2g, taken as %s. Cycles with "
      "|Pi_h - Pi_ref| < %g delta are marked *reference-limited* (their error is not "
      "resolved by the reference) and left out of rates and effectivities." % (
          ref["Pi"], ref["method"], ref["delta"], ref["delta_text"], LIMITED_FACTOR))
    w("- The finest reference mesh has %d DoFs, %.1fx the finest Q2 study mesh and "
      "%.1fx the finest Q1 study mesh." % (
          rc[-1]["dofs"],
          rc[-1]["dofs"] / max(r["cycles"][-1]["dofs"] for (d, s), r in runs.items() if d == 2),
          rc[-1]["dofs"] / max(r["cycles"][-1]["dofs"] for (d, s), r in runs.items() if d == 1)))
    for what, n, pi, ext in checks:
        w("- Cross-check, %s (finest %d DoFs): Pi = %.10f, extrapolated %s; difference "
          "to Pi_ref %s." % (what, n, pi, "%.10f" % ext if ext is not None else "– (not monotone)",
                             "%.2g" % ((ext if ext is not None else pi) - ref["Pi"])))
    w("- p_max reference: %.6f from the finest reference cycle (change in the last cycle "
      "%.2g, i.e. %.2g %%). Hertz's p_max = %.6f: the converged finite model lies %.2f %% "
      "above it (finite cylinder and plate, plate modulus finite), so the p_max error "
      "against Hertz that contact_fem reports levels off near that value; the plots show "
      "the discretisation error |p_max,h - p_max,ref| / p_max,ref." % (
          ref["p_max"], ref["p_delta"], 100 * ref["p_delta"] / ref["p_max"],
          rc[-1]["p_hertz"], 100 * (ref["p_max"] / rc[-1]["p_hertz"] - 1)))
    neg = sorted({"Q%d %s" % (d, LABEL[s]) for (d, s), r in runs.items()
                  for c in r["cycles"] if c["negative"] and c["cycle"] > 0})
    w("- Sign: for a conforming approximation of the variational inequality Pi_h >= Pi. "
      "Here Pi_h < Pi_ref occurs (marked `<0` in the table) in: %s (besides cycle 0, the "
      "common start mesh). There the discrete problem is softer than the exact one (Q1 on "
      "chords: the polygonal arc beyond the leading-order W; mortar contact enforces the gap weakly), the "
      "energy difference is dominated by that consistency error and sqrt(2|dPi|) is not a "
      "bound of the energy-norm error." % (", ".join(neg) if neg else "none"))
    w("")

    # Summary table.
    w("### Summary per run\n")
    w("Rates: least-squares slope of log(error) against log(DoFs), reported as the "
      "exponent s in error ~ N^-s, over the last %d cycles of the adaptive runs and the "
      "last %d levels of the uniform ones ('last'), and over all cycles with N >= N_final / "
      "%g ('long', number of points in brackets); reference-limited cycles are left out. "
      "Effectivity: eta / err_E, mean (min–max) over the last %d cycles that are not "
      "reference-limited. Final err_E in square brackets: the range from Pi_ref +- delta "
      "(given where it exceeds 2 %%).\n" % (RATE_LAST["adaptive"], RATE_LAST["global"],
                                           RATE_WINDOW, LAST_CYCLES))
    w("| Run | Cycles | Final DoFs | Final err_E [%] | Rate err_E last | Rate err_E long | "
      "Rate eta last | Final p_max err [%] | Rate p_max err last | Effectivity (last cycles) "
      "| Cumulative time [s] |")
    w("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    summary = {}
    for deg in DEGREES:
        for s in STRATEGIES:
            r = runs.get((deg, s))
            if not r:
                continue
            c = r["cycles"]
            k = RATE_LAST["global" if s == "global" else "adaptive"]
            re_, npts = rate(r, "err_rel", last=k)
            rwin, nwin = rate(r, "err_rel")
            reta, _ = rate(r, "eta_rel", last=k, skip_limited=False)
            rp, _ = rate(r, "p_err", last=k, skip_limited=False)
            ok = [x for x in c if not x["limited"] and x["err"] > 0][-LAST_CYCLES:]
            effs = [x["eff"] for x in ok]
            eff_mean = sum(effs) / len(effs) if effs else float("nan")
            summary[(deg, s)] = {"rate": re_, "rate_eta": reta, "rate_win": rwin, "eff": eff_mean,
                                 "eff_min": min(effs) if effs else float("nan"),
                                 "eff_max": max(effs) if effs else float("nan"),
                                 "eff_cycles": [x["cycle"] for x in ok],
                                 "eff_raw": [x["eff_raw"] for x in ok]}
            w("| Q%d %s | %d | %d | %s%s | %s | %s (%d) | %s | %s | %s | %s (%s–%s) | %.1f |" % (
                deg, LABEL[s], len(c), c[-1]["dofs"], pct(c[-1]["err_rel"]),
                (" (<0)" if c[-1]["negative"] else "") +
                (" [%s–%s]" % (pct(c[-1]["err_lo"]), pct(c[-1]["err_hi"]))
                 if c[-1]["err_hi"] - c[-1]["err_lo"] > 0.02 * c[-1]["err_rel"] else ""),
                fmt(re_), fmt(rwin), nwin, fmt(reta),
                pct(c[-1]["p_err"]), fmt(rp), fmt(eff_mean), fmt(summary[(deg, s)]["eff_min"]),
                fmt(summary[(deg, s)]["eff_max"]), c[-1]["cum"]))
    w("")

    # Targets.
    w("### Against the targets\n")
    w("| Target | Measured | Met? |")
    w("|---|---|---|")
    s1 = summary.get((1, "global"), {}).get("rate", float("nan"))
    w("| Q1 uniform keeps the optimal rate 1/2 | s = %s | %s |" % (
        fmt(s1), "yes" if s1 >= 0.45 else "no"))
    for s in ("spr-contact", "spr", "kelly"):
        v = summary.get((1, s), {})
        w("| (information) Q1 adaptive (%s): expected 1/2 as well, only the constant "
          "improves | s = %s last, %s long | – |" % (LABEL[s], fmt(v.get("rate", float("nan"))),
                                                    fmt(v.get("rate_win", float("nan")))))
    s2 = summary.get((2, "global"), {}).get("rate", float("nan"))
    w("| Q2 uniform loses the optimal rate 1 | s = %s | %s |" % (
        fmt(s2), "yes (rate below 1)" if s2 < 0.9 else "no"))
    for s in ("spr-contact", "spr", "kelly"):
        v = summary.get((2, s), {})
        w("| Q2 adaptive (%s) restores the rate 1 | s = %s last, %s long | %s |" % (
            LABEL[s], fmt(v.get("rate", float("nan"))), fmt(v.get("rate_win", float("nan"))),
            "yes" if v.get("rate", 0) >= 0.9 else
            ("no (>= 0.9 only over the long window)" if v.get("rate_win", 0) >= 0.9 else "no")))
    for deg in DEGREES:
        for s in ("spr-contact", "spr"):
            e = summary.get((deg, s))
            if e:
                raw = ""
                if deg == 1 and e["eff_raw"] and any(
                        c["W"] != 0. for c in runs[(deg, s)]["cycles"]):
                    raw = "; raw, without W: %s" % " / ".join(fmt(x) for x in e["eff_raw"])
                w("| Q%d %s effectivity in [0.8, 1.25] (last cycles %s) | %s (%s–%s)%s | %s |" % (
                    deg, LABEL[s], ",".join(str(k) for k in e["eff_cycles"]), fmt(e["eff"]),
                    fmt(e["eff_min"]), fmt(e["eff_max"]), raw,
                    "yes" if 0.8 <= e["eff_min"] and e["eff_max"] <= 1.25 else "no"))
        a, b = summary.get((deg, "spr-contact")), summary.get((deg, "spr"))
        if a and b:
            w("| Q%d spr contact closer to 1 than spr, separate runs (different meshes) "
              "| %s vs %s | %s |" % (deg, fmt(a["eff"], 4), fmt(b["eff"], 4),
                                     closer_verdict(a["eff"], b["eff"])))
        same = same_mesh_effectivities(runs.get((deg, "spr-contact")))
        if same:
            w("| Q%d spr contact closer to 1 than spr, same meshes (last cycles %s of the spr "
              "contact run) | %s vs %s | %s |" % (
                  deg, ",".join(str(k) for k in same["cycles"]), fmt(same["contact"], 4),
                  fmt(same["plain"], 4), same["verdict"]))
            if not math.isnan(same["p_rec"]):
                w("| Q%d (not a target) recovered contact pressure closer to the reference "
                  "with the contact terms, same meshes (L2, mean of the same cycles) | %s %% "
                  "vs %s %% | %s |" % (deg, pct(same["p_rec"]), pct(same["p_rec_plain"]),
                                       "yes" if same["p_rec"] < same["p_rec_plain"] else "no"))
    comparisons = {}
    for deg in DEGREES:
        u, a = runs.get((deg, "global")), runs.get((deg, "spr-contact"))
        if not u or not a:
            continue
        fu = u["cycles"][-1]
        for key, what in (("err_rel", "energy error"), ("p_err", "p_max error")):
            hit = reached(a["cycles"], key, fu[key])
            if hit is None:
                w("| Q%d spr contact reaches the finest uniform %s (%s %%, %d DoFs) with "
                  ">= 4x fewer DoFs, <= 1/2 cumulative time | not reached within the run "
                  "(final %s %%) | no |" % (deg, what, pct(fu[key]), fu["dofs"],
                                             pct(a["cycles"][-1][key])))
                continue
            once = first_below(a["cycles"], key, fu[key])
            once_text = ("" if once is None or once is hit else
                         "; first below at cycle %d (%d DoFs, %.1fx fewer, %.2f s, %.2f of "
                         "uniform's cumulative) but above again later" % (
                             once["cycle"], once["dofs"], fu["dofs"] / once["dofs"], once["cum"],
                             once["cum"] / fu["cum"]))
            rn = fu["dofs"] / hit["dofs"]
            rt = hit["cum"] / fu["cum"]
            rt_own = hit["cum"] / fu["wall"]
            comparisons[(deg, key)] = (hit, rn, rt, rt_own)
            w("| Q%d spr contact reaches the finest uniform %s (%s %%, %d DoFs, %.1f s "
              "cumulative, %.1f s for the last level alone) with >= 4x fewer DoFs and "
              "<= 1/2 the cumulative time | cycle %d: %d DoFs (%.1fx fewer), %.2f s "
              "cumulative (%.2f of uniform's cumulative, %.2f of its last level)%s | %s |" % (
                  deg, what, pct(fu[key]), fu["dofs"], fu["cum"], fu["wall"], hit["cycle"],
                  hit["dofs"], rn, hit["cum"], rt, rt_own, once_text,
                  "yes" if rn >= 4 and rt <= 0.5 else
                  ("DoFs yes, time no" if rn >= 4 else
                   ("time yes, DoFs no" if rt <= 0.5 else "no"))))
    w("")
    w("'Reaches' = the first cycle from which on the error stays at or below the "
      "uniform value (the p_max error is not monotone).\n")

    # Plots.
    w("### Plots\n")
    w("![error against DoFs](figures/convergence_dofs.png)\n")
    w("![error against cumulative wall time](figures/convergence_time.png)\n")
    w("Left: relative energy error err_E / |u|_E; right: p_max error against the reference "
      "p_max (grey dotted line: the last change of the reference p_max, below which the "
      "p_max error is not resolved). Solid lines Q1, dashed Q2; open symbols in the energy "
      "panel mark Pi_h < Pi_ref. Thin black lines: slopes N^-1/2 and N^-1.\n")

    # Mesh.
    w("### Where the refinement goes\n")
    mesh_info = []
    for deg in DEGREES:
        d = os.path.join(res, "mesh-q%d" % deg)
        if not os.path.isdir(d):
            continue
        mr = read_run(res, "mesh-q%d" % deg)
        if not mr:
            continue
        first, last = cycle_vtus(d, mr["cycles"])
        if not first or not last:
            continue
        try:
            cells = mesh_cells(last, deg)
            cells0 = mesh_cells(first, deg)
        except Exception as e:  # a broken VTU must not stop the report
            print("analyse.py: cannot read %s: %s" % (last, e), file=sys.stderr)
            continue
        a_hertz = mr["cycles"][-1]["a_hertz"]
        if args.plot_data:
            write_mesh_data(cells, os.path.join(args.plot_data, "mesh-q%d.dat" % deg))
        # The SPR-contact indicators of the last recorded cycle (written with
        # the VTU since commit 9d9625c).
        shares = None
        ind = os.path.join(d, "error_indicators_%02d.0.vtu" % mr["cycles"][-1]["cycle"])
        if os.path.exists(ind):
            try:
                shares = eta_shares(mesh_cells(ind, deg), a_hertz)
            except Exception as e:
                print("analyse.py: cannot read %s: %s" % (ind, e), file=sys.stderr)
        mesh_info.append((deg, mr, mesh_bands(cells0, a_hertz), mesh_bands(cells, a_hertz),
                          len(cells0), len(cells), shares))
    if mesh_info:
        w("From separate Q1 and Q2 'spr contact' runs (same settings as the study, VTU "
          "written, stopped after the first cycle with >= %s DoFs): cells of the start mesh and of the last "
          "mesh by region (h = sqrt(cell area); a = %.4f is Hertz's half-width).\n" % (
              mesh_info[0][1]["run"].get("dof_cap", "?"), a_hertz))
        w("![final adaptive meshes](figures/convergence_mesh.png)\n")
        for deg, mr, b0, b1, n0, n1, sh in mesh_info:
            lc = mr["cycles"][-1]
            w("Q%d, cycle %d (%d DoFs, %d active slave nodes, mean active slave element "
              "%.3g; start: %d active nodes, %.3g):\n" % (
                  deg, lc["cycle"], lc["dofs"], lc["active"], lc["slave_h"],
                  mr["cycles"][0]["active"], mr["cycles"][0]["slave_h"]))
            w("| Region | Cells start | Cells last | min h start | min h last | median h last "
              "| share of eta^2 last |")
            w("|---|---:|---:|---:|---:|---:|---:|")
            for k, ((name, n_a, hmin_a, _), (_, n_b, hmin_b, hmed_b)) in enumerate(zip(b0, b1)):
                w("| %s | %d | %d | %s | %s | %s | %s |" % (
                    name, n_a, n_b, fmt(hmin_a), fmt(hmin_b), fmt(hmed_b),
                    "%s %%" % pct(sh["shares"][k], 2) if sh else "–"))
            if sh:
                w("\nLargest indicators on this cycle: the 2 largest cells carry %s %% of "
                  "eta^2, the 10 largest %s %%; the largest at %s." % (
                      pct(sh["top2"], 2), pct(sh["top10"], 2), "; ".join(
                          "(%.3f, %.3f), h = %.2g, %s %%" % (x, y, h, pct(q, 2))
                          for x, y, h, q in sh["top"])))
            w("")
    w("Active slave nodes on the last cycle of the study runs: " + "; ".join(
        "Q%d %s %d" % (d, LABEL[s], r["cycles"][-1]["active"]) for (d, s), r in
        sorted(runs.items())) + ".\n")

    # The contact terms on identical meshes.
    compared = [(k, r) for k, r in sorted(runs.items())
                if any(not math.isnan(c["eff_plain"]) for c in r["cycles"])]
    if compared:
        w("### What the contact terms change (identical meshes)\n")
        w("The runs that report the SPR-contact estimate also computed plain SPR on the same "
          "solution (`Refinement/Compare with plain SPR = true`, not counted in the wall "
          "time), so the two effectivities below differ only by the contact terms.\n")
        w("The last four columns measure the recovered stress itself on the contact zone: "
          "the L2 error of its normal traction against the reference run's contact pressure "
          "(the mortar pressure's own error for comparison; all relative, D_j-weighted over "
          "the paired slave nodes), and its largest shear traction over p_max, which "
          "frictionless contact makes zero.\n")
        w("| Run | Cycle | DoFs | Active | eta/err_E spr contact | eta/err_E spr | closer to 1 "
          "| p L2 [%] mortar | p L2 [%] recovered, contact | p L2 [%] recovered, plain "
          "| shear/p_max contact | shear/p_max plain |")
        w("|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|")
        for (deg, s), r in compared:
            for c in r["cycles"]:
                if math.isnan(c["eff_plain"]) or c["limited"] or c["err"] <= 0:
                    continue
                gap = abs(math.log(c["eff_plain"])) - abs(math.log(c["eff"]))
                w("| Q%d %s | %d | %d | %d | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                    deg, LABEL[s], c["cycle"], c["dofs"], c["active"], "%.4f" % c["eff"],
                    "%.4f" % c["eff_plain"],
                    "contact" if gap > 5e-4 else ("plain" if gap < -5e-4 else "equal"),
                    pct(c["p_l2_mortar"]), pct(c["p_l2_rec"]), pct(c["p_l2_rec_plain"]),
                    fmt(c["shear_rec"], 2), fmt(c["shear_rec_plain"], 2)))
        w("")

    # Full table.
    w("### All cycles\n")
    w("err_E, eta: relative to |u_ref|_E. `<0`: Pi_h < Pi_ref; `ref`: reference-limited. "
      "p_max err: against the reference; Hertz: against Hertz's p_max (signed).\n")
    w("<details><summary>table (%d rows)</summary>\n" % sum(len(r["cycles"]) for r in runs.values()))
    w("| Run | Cycle | Cells | DoFs | Active | err_E [%] | eta [%] | eta/err_E | "
      "p_max err [%] | Hertz [%] | Newton | Wall [s] | Cumulative [s] |")
    w("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for deg in DEGREES:
        for s in STRATEGIES:
            r = runs.get((deg, s))
            if not r:
                continue
            for c in r["cycles"]:
                flag = (" <0" if c["negative"] else "") + (" ref" if c["limited"] else "")
                w("| Q%d %s | %d | %d | %d | %d | %s%s | %s | %s | %s | %s | %d | %.2f | %.2f |" % (
                    deg, LABEL[s], c["cycle"], c["cells"], c["dofs"], c["active"],
                    pct(c["err_rel"]), flag, pct(c["eta_rel"]), fmt(c["eff"]),
                    pct(c["p_err"], 2), pct(c["p_hertz_err"]), c["newton"], c["wall"], c["cum"]))
    w("\n</details>\n")

    text = "\n".join(L)
    if args.plot_data:
        write_plot_data(runs, args.plot_data, ref)
    if args.doc == "-":
        print(text)
    else:
        os.makedirs(os.path.dirname(os.path.abspath(args.doc)), exist_ok=True)
        replace_section(args.doc, text)
        print("analyse.py: wrote %s" % args.doc, file=sys.stderr)
    # Key numbers on stdout for the console.
    for (deg, s), e in sorted(summary.items()):
        print("Q%d %-12s rate err_E %s  rate eta %s  effectivity %s" % (
            deg, LABEL[s], fmt(e["rate"]), fmt(e["rate_eta"]), fmt(e["eff"])))
    for (deg, key), (hit, rn, rt, rt_own) in sorted(comparisons.items()):
        print("Q%d spr contact reaches uniform %s at %d DoFs: %.1fx fewer DoFs, time ratio %.2f "
              "(%.2f of the last uniform level)" % (deg, key, hit["dofs"], rn, rt, rt_own))


if __name__ == "__main__":
    main()
