#!/usr/bin/env python3
"""Runs a tied patch scene with its VTU output and checks the tied surfaces.

Usage: check_tied_surface.py CONTACT_FEM SCENE.prm STRESS [SETTING...]

The scene (a tied patch test: a uniform stress across a non-matching tied
interface, exact for the dual-mortar tying) runs in two load steps with
the 'Section/Key=value' SETTINGs, which must make the loads proportional
to the load time t. STRESS ('sxx,syy,sxy' or 'sxx,syy,szz,sxy,sxz,syz') is
the uniform stress at t = 1. tied_surface.pvd and tied_surface_cycle_0.pvd
must list the two steps at 0.5 and 1, and in each tied_surface_NNN.vtu
every node (hanging vertices included) must be tied and carry the traction
t sigma n_s and the normal traction t n.sigma.n (positive in tension,
whatever the sign of n), n the normal of the flat reference surface from
its geometry: to 1e-9 of the stress (the file's 10 digits), each component
uniform to 1e-10. The sign of n_s = +-n is taken from the first node, so a
traction of the wrong sign shows in the normal traction. The traction
integrated over the reference cells (exact for a uniform traction on flat
cells) must equal the pair force of summary.json to 1e-9; with contact
pairs too, contact_surface.pvd must list the same steps. tying_profile.csv
must hold the same traction at each of its rows (the tied slave nodes).
In the volume VTU of each step (solution_NNN.pvtu), the stress must be t
sigma at every point, and tying_traction and tying_normal_traction the
traction above at every tied slave node in the slave body's cells and zero
elsewhere (to the file's single precision).
"""
import json
import os
import sys

from scene_run import run_scene
from vtu_files import collection, read_surface, read_volume, tied_volume

contact_fem, scene, stress = sys.argv[1:4]
stress = [float(x) for x in stress.split(",")]
# CMake splits a setting at its ';': a piece without '=' continues the
# previous one.
settings = []
for piece in sys.argv[4:]:
    if "=" in piece or not settings:
        settings.append(piece)
    else:
        settings[-1] += ";" + piece
dim = 2 if len(stress) == 3 else 3
pairs = [(0, 0), (1, 1), (0, 1)] if dim == 2 else [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)]
sigma = [[0.0] * dim for _ in range(dim)]
for (i, j), value in zip(pairs, stress):
    sigma[i][j] = sigma[j][i] = value
run_scene(contact_fem, scene, "Output directory=results", "Output/Write VTU=true",
          "Output/Write pressure profile=true",
          "Load stepping/Number of load steps=2", *settings)
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)


def cell_area(corners):
    """Length of a line, or area of a flat quadrilateral (half the cross
    product of its diagonals), of the corner points in VTK order."""
    if len(corners) == 2:
        return sum((corners[0][d] - corners[1][d]) ** 2 for d in range(3)) ** 0.5
    a = [corners[2][d] - corners[0][d] for d in range(3)]
    b = [corners[3][d] - corners[1][d] for d in range(3)]
    cross = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    return 0.5 * sum(c * c for c in cross) ** 0.5


contact = os.path.exists(os.path.join("results", "contact_surface.pvd"))
for name in ["tied_surface.pvd", "tied_surface_cycle_0.pvd"] + (["contact_surface.pvd"] if contact else []):
    times = [t for t, _ in collection(name)]
    check(times == [0.5, 1.0], f"{name}: times {times}, expected [0.5, 1.0]")



def unit_normal(points, cells):
    """The unit normal of the surface's first cell (sign arbitrary)."""
    first = [points[n] for n in cells["connectivity"][:cells["offsets"][0]]]
    if dim == 2:
        normal = [first[0][1] - first[1][1], first[1][0] - first[0][0], 0.0]
    else:
        a = [first[2][d] - first[0][d] for d in range(3)]
        b = [first[3][d] - first[1][d] for d in range(3)]
        normal = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    length = sum(c * c for c in normal) ** 0.5
    return [c / length for c in normal[:dim]]


scale = max(abs(x) for x in stress)
volumes = dict(collection("solution.pvd"))
n_points = 0
for time, surface in collection("tied_surface.pvd"):
    points, cells, fields, wrong = read_surface(surface)
    failures += wrong
    n_points = len(points)
    check(set(fields) == {"normal_traction", "tied", "pair", "traction", "displacement"},
          f"{surface}: fields {sorted(fields)}")
    # Small strain: the normal of the reference cells (points less the
    # displacement), where the traction is measured.
    reference = [[x[d] - u[d] for d in range(3)] for x, u in zip(points, fields["displacement"])]
    n = unit_normal(reference, cells)
    expected = [time * sum(sigma[i][j] * n[j] for j in range(dim)) for i in range(dim)]
    # n.sigma.n whatever the sign of n; t = sigma n_s for the slave's
    # outward normal n_s = +-n, taken from the first node.
    expected_normal = sum(expected[d] * n[d] for d in range(dim))
    if sum(expected[d] * fields["traction"][0][d] for d in range(dim)) < 0:
        expected = [-x for x in expected]
    for k in range(n_points):
        t = fields["traction"][k]
        p = fields["normal_traction"][k][0]
        check(abs(fields["tied"][k][0] - 1.0) < 1e-12, f"{surface} node {k}: not tied")
        # The VTU holds 10 significant digits.
        check(all(abs(t[d] - expected[d]) < 1e-9 * scale for d in range(dim)),
              f"{surface} node {k}: traction {t}, expected {expected}")
        check(abs(p - expected_normal) < 1e-9 * scale,
              f"{surface} node {k}: normal traction {p}, expected {expected_normal}")
    for d in range(dim):
        values = [fields["traction"][k][d] for k in range(n_points)]
        check(max(values) - min(values) <= 1e-10 * scale,
              f"{surface}: traction component {d} not uniform: {min(values)} ... {max(values)}")
    # The volume VTU of the step: the same traction at every tied slave
    # node (in the slave body's cells), zero elsewhere, to single precision.
    values, wrong = tied_volume(volumes[time], reference)
    # The uniform stress itself at every point of the volume (both bodies,
    # hanging vertices), to single precision.
    _, volume = read_volume(volumes[time])
    bad = [s for s in volume["stress"] if any(abs(s[3 * i + j] - time * sigma[i][j]) > 1e-6 * scale
                                              for i in range(dim) for j in range(dim))]
    check(not bad, f"{volumes[time]}: {len(bad)} points with a stress other than t sigma, e.g. {bad[:1]}")
    failures += wrong
    for x, at_node in zip(reference, values):
        for t, p in at_node:
            check(all(abs(t[d] - expected[d]) <= 1e-6 * scale for d in range(dim))
                  and abs(p - expected_normal) <= 1e-6 * scale,
                  f"{volumes[time]} at {x}: tying traction {t}, normal {p}, expected "
                  f"{expected}, {expected_normal}")

# The last step: the traction integrated over the reference cells is the
# pair force of summary.json.
force = [0.0] * dim
start = 0
for end, kind in zip(cells["offsets"], cells["types"]):
    nodes = cells["connectivity"][start:end]
    start = end
    corners = nodes[:2] if kind in (3, 21) else nodes[:4]
    check(kind in (3, 9), f"cell type {kind}: only straight Q1 faces are integrated here")
    area = cell_area([reference[n] for n in corners])
    for d in range(dim):
        force[d] += area * sum(fields["traction"][n][d] for n in corners) / len(corners)
with open(os.path.join("results", "summary.json")) as f:
    pair_force = json.load(f)["cycles"][-1]["tying"][0]["force"]
check(all(abs(force[d] - pair_force[d]) <= 1e-9 * max(1.0, scale) for d in range(dim)),
      f"integrated traction {force} differs from the pair force {pair_force} of summary.json")

# tying_profile.csv (the last step): the same traction at every tied slave
# node, in at most the surface's points (hanging vertices have no row).
import csv
with open(os.path.join("results", "tying_profile.csv")) as f:
    rows = list(csv.DictReader(f))
axes = "xyz"[:dim]
check(0 < len(rows) <= n_points, f"tying_profile.csv: {len(rows)} rows for {n_points} surface points")
for k, row in enumerate(rows):
    t = [float(row["traction_" + a]) for a in axes]
    check(row["tied"] == "1", f"tying_profile.csv row {k}: not tied")
    check(all(abs(t[d] - expected[d]) < 1e-9 * scale for d in range(dim)),
          f"tying_profile.csv row {k}: traction {t}, expected {expected}")
    check(abs(float(row["normal_traction"]) - expected_normal) < 1e-9 * scale,
          f"tying_profile.csv row {k}: normal traction {row['normal_traction']}, expected {expected_normal}")

if failures:
    print("\n".join(failures))
    sys.exit(1)
print(f"{n_points} tied slave nodes: traction t sigma n = {expected} (t = 1) at each for t = 0.5 "
      f"and 1, normal traction {expected_normal}; integrated traction = pair force {pair_force}; "
      f"tying_profile.csv: the same at its {len(rows)} rows; the volume VTU: the same at the "
      f"{sum(len(v) for v in values)} points of the slave cells there, zero elsewhere, and the "
      f"stress t sigma at its {len(volume['stress'])} points")
