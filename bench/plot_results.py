#!/usr/bin/python3
"""Plots of a contact_fem run, for any scene.

Usage: bench/plot_results.py OUTPUT_DIRECTORY [--force-x COLUMN]

Reads OUTPUT_DIRECTORY/convergence.csv and forces.csv (written by every run)
and writes beside them:
  error_vs_dofs.png  every error measure the run knows (the estimate, and
                     with an analytical or reference solution the errors)
                     against the DoFs of each adaptive cycle, log-log;
  error_vs_time.png  the same against the cumulative wall time;
  force_vs_displacement.png  each contact pair's normal force and each
                     support's reaction (magnitudes) of every load step of
                     the latest cycle that solved the whole load path,
                     against the first displacement probe
                     (Output/Displacement probes), or the load time t
                     without probes; --force-x names another forces.csv
                     column for the x axis.
Needs Debian's python3-matplotlib (installed by .ci/setup); runs headless.
"""
import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# convergence.csv columns that measure an error (plotted when present).
ERROR_COLUMNS = {
    "relative_estimated_error": "estimate eta / |u|_E",
    "energy_error": "energy-norm error",
    "pressure_l2_relative_error": "pressure L2 error (analytical)",
    "pressure_reference_l2_relative_error": "pressure L2 error (reference)",
    "p_max_relative_error": "|p_max error| (analytical)",
}


def read_csv(path):
    if not os.path.isfile(path):
        sys.exit(f"{path}: no such file (is this a contact_fem output directory?)")
    with open(path) as f:
        return list(csv.DictReader(f))


def number(text):
    try:
        value = float(text)
    except (TypeError, ValueError):
        return math.nan
    return value


def plot_errors(rows, x_column, x_label, path):
    x = [number(r[x_column]) for r in rows]
    figure, axes = plt.subplots(figsize=(6, 4.5))
    plotted = 0
    for column, label in ERROR_COLUMNS.items():
        if column not in rows[0]:
            continue
        points = [(xi, abs(number(r[column]))) for xi, r in zip(x, rows)]
        points = [(xi, yi) for xi, yi in points if yi > 0 and math.isfinite(yi) and xi > 0]
        if points:
            axes.loglog(*zip(*points), "o-", label=label)
            plotted += 1
    axes.set_xlabel(x_label)
    axes.set_ylabel("error")
    axes.grid(True, which="both", alpha=0.3)
    if plotted:
        axes.legend()
    else:
        axes.text(0.5, 0.5, "no error measure in convergence.csv", ha="center",
                  transform=axes.transAxes)
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)


def magnitude(row, prefix, axes_names):
    return math.sqrt(sum(number(row.get(prefix + a, "")) ** 2 for a in axes_names
                         if prefix + a in row))


def plot_forces(rows, force_x, path):
    # The latest cycle that solved the whole load path (later cycles of a
    # frictionless scene start from the transferred solution at the end).
    steps = {}
    for r in rows:
        steps.setdefault(int(r["cycle"]), []).append(r)
    cycle = max(steps, key=lambda c: (len(steps[c]), c))
    rows = steps[cycle]
    columns = list(rows[0].keys())
    if force_x is None:
        probes = [c for c in columns if c.startswith("probe_")]
        force_x = probes[0] if probes else "t"
    if force_x not in columns:
        sys.exit(f"forces.csv has no column '{force_x}' (columns: {', '.join(columns)})")
    x = [number(r[force_x]) for r in rows]
    # The force vectors: '<name>_x', '<name>_y'[, '<name>_z'].
    vectors = []
    for c in columns:
        if c.endswith("_x") and not c.startswith("probe_"):
            name = c[:-2]
            if not name.endswith("_tangential"):
                vectors.append(name)
    figure, axes = plt.subplots(figsize=(6, 4.5))
    for name in vectors:
        axes.plot(x, [magnitude(r, name + "_", "xyz") for r in rows], "o-",
                  label=name.replace("_", " "))
    axes.set_xlabel(force_x + (" (load time)" if force_x == "t" else "") + f", cycle {cycle}")
    axes.set_ylabel("force magnitude")
    axes.grid(True, alpha=0.3)
    axes.legend()
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("directory")
    parser.add_argument("--force-x", default=None,
                        help="forces.csv column for the x axis of force_vs_displacement.png")
    args = parser.parse_args()
    convergence = read_csv(os.path.join(args.directory, "convergence.csv"))
    forces = read_csv(os.path.join(args.directory, "forces.csv"))
    if not convergence or not forces:
        sys.exit(f"{args.directory}: convergence.csv or forces.csv has no rows (did the run solve?)")
    written = []
    for x_column, label, name in (("dofs", "DoFs", "error_vs_dofs.png"),
                                  ("cumulative_wall_time", "cumulative wall time [s]",
                                   "error_vs_time.png")):
        path = os.path.join(args.directory, name)
        plot_errors(convergence, x_column, label, path)
        written.append(path)
    path = os.path.join(args.directory, "force_vs_displacement.png")
    plot_forces(forces, args.force_x, path)
    written.append(path)
    print("written: " + ", ".join(written))


if __name__ == "__main__":
    main()
