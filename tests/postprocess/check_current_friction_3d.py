#!/usr/bin/env python3
"""Coulomb friction at large deformation in 3D (Contact/Kinematics = current).

Usage: check_current_friction_3d.py CONTACT_FEM SCENE.prm

SCENE is tests/scenes/current_kinematics_friction_3d_01.prm: a neo-Hookean
block pressed by 22 % onto a rigid flat base (non-matching) and pulled in
the plane at 30 degrees from x, mu = 0.3. From forces.csv, the pressure
profile (nodal pressure, tangential traction, slip of the last step, stick
flag) and the Newton tables:

- run to t = 7 (four steps of full slip): every step converges, Newton's
  displacement ratios fall quadratically once r_(k-1) <= 0.1 (r_k <= 10
  r_(k-1)^2 over the iterations without set changes); in the full-slip
  steps the pair's |F_t| / F_n tends to mu (its relative error falls from
  step to step, below 1e-6 at t = 7) and F_t to the pull direction (within
  1e-3 rad at t = 7); at t = 7 every active node slips, its tangential
  traction is mu p_j to 1e-8 (of the largest mu p) and opposes its slip,
  which follows the pull direction (within 1e-2 rad);
- at t = 3 (pulled by 0.03), step 3 of the same run (its contact-surface
  VTU, the same 10 digits as the pressure profile of a run that ends there):
  nodes stick, each inside the cone (|t_j| < mu p_j), the slip nodes on it
  to 1e-8, and 0 < |F_t| / F_n < mu;
- mu = 0 is alm frictionless on the current configuration: run to t = 4
  with coulomb 0 and with alm frictionless, the same forces at every step
  to 1e-10 of the largest and the same Newton iterations.
"""
import csv
import math
import re
import sys

from scene_run import check_quadratic, newton_ratios, run_scene
from vtu_files import active_nodes, collection, read_surface

MU = 0.3
PULL = math.radians(30.0)


def forces():
    with open("results/forces.csv") as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def pair(row):
    """(F_n, |F_t|, angle of F_t) of the pair (master on slave)."""
    tx, ty = row["pair_3_4_tangential_x"], row["pair_3_4_tangential_y"]
    return row["pair_3_4_normal_z"], math.hypot(tx, ty), math.atan2(ty, tx)


def profile():
    with open("results/pressure_profile.csv") as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def angle_to(angle, target):
    return abs(math.remainder(angle - target, 2 * math.pi))


def report(name, good, detail):
    print(f"{name}: {'ok' if good else 'FAILED'} ({detail})")
    return good


contact_fem, scene = sys.argv[1:3]
write_profile = "Output/Write pressure profile=true"
output = run_scene(contact_fem, scene, write_profile, "Output/Write VTU=true",
                   "Load stepping/End time=7", "Load stepping/Number of load steps=7")
ok = check_quadratic("block pulled at 30 degrees", output, 10.0)
rows = forces()
ok = report("steps converged", len(rows) == 7 == output.count("| converged"),
            f"{len(rows)} steps") and ok
errors, angles = [], []
for row in rows[3:]:
    normal, tangential, angle = pair(row)
    errors.append(abs(tangential / normal - MU) / MU)
    # The base pulls the block back: F_t (master on slave) against the pull.
    angles.append(angle_to(angle, PULL + math.pi))
falling = all(b < a for a, b in zip(errors, errors[1:]))
ok = report("full slip: |F_t| / F_n -> mu, relative error falling, < 1e-6 at t = 7",
            falling and errors[-1] < 1e-6, ", ".join(f"{e:.1e}" for e in errors)) and ok
ok = report("full slip: F_t against the pull, < 1e-3 rad at t = 7", angles[-1] < 1e-3,
            ", ".join(f"{a:.1e}" for a in angles)) and ok
nodes = [n for n in profile() if n["active"] == 1]
bound = max(MU * n["pressure"] for n in nodes)
off = max(abs(math.hypot(n["tangential_traction_x"], n["tangential_traction_y"]) -
              MU * n["pressure"]) for n in nodes) / bound
turn = max(angle_to(math.atan2(n["slip_increment_y"], n["slip_increment_x"]), PULL)
           for n in nodes)
opposed = all(n["tangential_traction_x"] * n["slip_increment_x"] +
              n["tangential_traction_y"] * n["slip_increment_y"] < 0 for n in nodes)
every = all(n["stick"] == 0 for n in nodes)
ok = report("t = 7, every active node slips, |t_j| = mu p_j to 1e-8, against its slip, "
            "slip along the pull within 1e-2 rad", every and off < 1e-8 and opposed and
            turn < 1e-2, f"{len(nodes)} nodes, |t| off mu p {off:.1e}, slip turned {turn:.1e}") and ok

# t = 3: step 3 of the run to t = 7 (the same steps as a run to t = 3).
normal, tangential, _ = pair(rows[2])
_, _, surface, _ = read_surface(dict(collection("contact_surface.pvd"))[3.0])
nodes = active_nodes(surface)
stick = [n for n in nodes if n["stick"] == 1]
inside = all(math.hypot(n["tangential_traction_x"], n["tangential_traction_y"]) <
             MU * n["pressure"] for n in stick)
off = max((abs(math.hypot(n["tangential_traction_x"], n["tangential_traction_y"]) -
               MU * n["pressure"]) for n in nodes if n["stick"] == 0), default=0.0) / bound
ok = report("t = 3, below the limit: stick nodes inside the cone, slip nodes on it to 1e-8, "
            "0 < |F_t| / F_n < mu", len(stick) > 0 and inside and off < 1e-8 and
            0 < tangential / normal < MU,
            f"{len(stick)} of {len(nodes)} stick, |F_t| / F_n = {tangential / normal:.4f}") and ok

short = ("Load stepping/End time=4", "Load stepping/Number of load steps=4")
coulomb_0 = run_scene(contact_fem, scene, "Contact/Friction=coulomb 0", *short)
with_zero = forces()
frictionless = run_scene(contact_fem, scene, "Contact/Formulation=alm frictionless",
                         "Contact/Friction=", *short)
without = forces()
scale = max(abs(v) for r in without for k, v in r.items() if k not in ("cycle", "step", "t"))
worst = max(abs(a[k] - b[k]) for a, b in zip(with_zero, without) for k in a) / scale
same = [len(r) for r in newton_ratios(coulomb_0)] == [len(r) for r in newton_ratios(frictionless)]
ok = report("mu = 0 equals alm frictionless: forces to 1e-10, same Newton iterations",
            len(with_zero) == len(without) == 4 and worst < 1e-10 and same,
            f"largest difference {worst:.1e} of the largest force") and ok
sys.exit(0 if ok else 1)
