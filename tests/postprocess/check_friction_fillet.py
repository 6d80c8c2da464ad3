#!/usr/bin/env python3
"""The frictional slide over a rounded master corner (issue 29).

Usage: check_friction_fillet.py CONTACT_FEM SCENE.prm

SCENE is tests/postprocess/friction_block_fillet.prm: the sliding block of
finite_strain_spr_friction_adaptive_01 (Coulomb mu = 0.3, alm frictional,
current kinematics, the slave's top pulled 0.8 along x from t = 1 to 3)
on a master whose leading corner is a fillet of radius R = 0.5 about
(3.5, 0.5). With the square corner the run stops at t = 2.66: the slave's
leading end cannot pass the corner (doc/finite_strain.md, "The slip
front: a rounded master corner"). Over the fillet:

- every one of the 12 load steps converges without a split, to t = 3;
- at every step the pair's force balances the reaction on the pulled top
  (the slave's equilibrium) and the master's two supports (the master's),
  to 1e-8 of the pair's force (Newton stops at 1e-12 of the step's
  correction);
- at least three steps have every active node slipping (the plateau), and
  there the pair's |T| / |N| = mu to 1e-8: in 2D every slipping node's
  tangential traction is mu p times its normal turned by 90 degrees, so
  the sums keep the ratio whatever the normals' directions on the arc;
- at t = 3 the slave's leading end lies on the fillet: an active node more
  than R / 100 below the master's flat top, and every active node slips
  with |t_j| = mu p_j (to 1e-8 of the largest p).
"""
import csv
import math
import sys

from scene_run import converged_sets, csv_numbers, perturbation, run_scene

MU = 0.3
R = 0.5  # the fillet's radius
END_TIME, STEPS = 3.0, 12
TOLERANCE = 1e-8


def vector(row, name):
    return (row[name + "_x"], row[name + "_y"])


def norm(v):
    return math.hypot(*v)


contact_fem, scene = sys.argv[1:3]
output = run_scene(contact_fem, scene, *perturbation())
forces = csv_numbers("results/forces.csv")
sets = converged_sets(output)
ok = True

splits = output.count("Splitting the step")
good = (len(forces) == len(sets) == STEPS and splits == 0
        and abs(forces[-1]["t"] - END_TIME) < 1e-12)
print(f"load steps converged: {len(sets)} of {STEPS}, splits {splits}, last t = "
      f"{forces[-1]['t'] if forces else '-'}: {'ok' if good else 'FAILED'}")
ok = good and ok

worst_slave, worst_master = 0.0, 0.0
for row in forces:
    pair = [n + t for n, t in zip(vector(row, "pair_3_4_normal"), vector(row, "pair_3_4_tangential"))]
    top, base, master_top = vector(row, "boundary_1"), vector(row, "boundary_2"), vector(row, "boundary_4")
    scale = norm(pair)
    worst_slave = max(worst_slave, norm([p + b for p, b in zip(pair, top)]) / scale)
    worst_master = max(worst_master,
                       norm([b + m - p for p, b, m in zip(pair, base, master_top)]) / scale)
good = worst_slave < TOLERANCE and worst_master < TOLERANCE
print(f"force balance of the slave {worst_slave:.1e}, of the master {worst_master:.1e} "
      f"(< {TOLERANCE:g} of the pair's force): {'ok' if good else 'FAILED'}")
ok = good and ok

plateau = []
for (active, stick, slip), row in zip(sets, forces):
    if active > 0 and slip == active:
        ratio = norm(vector(row, "pair_3_4_tangential")) / norm(vector(row, "pair_3_4_normal"))
        plateau.append((row["t"], abs(ratio - MU) / MU))
good = len(plateau) >= 3 and max(e for _, e in plateau) < TOLERANCE
print(f"steps with every active node slipping: t = {', '.join(f'{t:g}' for t, _ in plateau)}; "
      f"pair |T| / |N| = {MU} to {TOLERANCE:g}: {'ok' if good else 'FAILED'} (largest relative "
      f"error {max((e for _, e in plateau), default=1):.1e})")
ok = good and ok

with open("results/pressure_profile.csv") as f:
    nodes = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
active = [n for n in nodes if n["active"] == 1]
p_max = max(n["pressure"] for n in active)
on_fillet = [n for n in active if n["y"] < 1 - R / 100]
slip_error = max(abs(abs(n["tangential_traction"]) - MU * n["pressure"]) / p_max for n in active)
good = (len(on_fillet) >= 1 and all(n["stick"] == 0 for n in active)
        and slip_error < TOLERANCE)
print(f"t = 3: {len(active)} active nodes, all slipping, |t_j| = mu p_j to {slip_error:.1e} of "
      f"p_max; {len(on_fillet)} on the fillet (lowest y = "
      f"{min((n['y'] for n in on_fillet), default=1):.4f}): {'ok' if good else 'FAILED'}")
ok = good and ok
sys.exit(0 if ok else 1)
