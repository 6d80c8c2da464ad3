#!/usr/bin/env python3
"""The 3D friction results (issue 28 item 4) on the 3D frictional patch test.

Usage: check_friction_outputs_3d.py CONTACT_FEM SCENE.prm

SCENE is tests/scenes/frictional_patch_3d_01.prm: two blocks 1 x 1 x 0.5
(E = 100, nu = 0, so G = 50), the upper one pressed by p = 1 and its top
then moved along d = (cos 30, sin 30, 0) by 0.006 (t in [1, 2]) and 0.01
(t - 1.75) beyond t = 1.75, mu = 0.3; side shear tractions keep the stress
uniform. From t = 2 on every node slips: the shear stress is mu p = 0.3,
the two blocks shear elastically by mu p / G (0.5 + 0.5) = 0.006, so at
t = 2.5 the slave (lower block) has slid relative to the master by
0.0135 - 0.006 = 0.0075 along -d, 0.005 of it in the last step.

Checks, at t = 2.5:
- pressure_profile.csv, every active node: tangential_traction_x, _y, _z =
  mu p d, slip_increment = -0.005 d, accumulated_tangential_displacement
  = -0.0075 d, accumulated_slip = 0.0075 (one way: the path length is the
  displacement's length), stick = 0 (to 1e-9 of the values: the files
  print 10 digits);
- the contact-surface VTU of the last step carries the same fields with
  the same values (its accumulated_slip and the vector components);
- summary.json: stick_nodes + slip_nodes = active slave nodes (0 + 16),
  tangential_contact_force_components = mu N d, max_accumulated_slip =
  0.0075, and the balance in x, y and z (relative_imbalance_components)
  below 1e-10;
- SPR contact (Refinement/Estimator = spr contact) imposes the whole
  traction, its tangential part too: the stress is uniform (sigma_zz = -1,
  sigma_xz, sigma_yz = mu d), so the recovered stress is exact and the
  estimate is at round-off (the loop stops after the first cycle); were
  the shear of the contact face taken as zero, it would be of the order of
  mu p / p = 0.3.
"""
import csv
import json
import math
import re
import sys

from scene_run import run_scene

MU, P = 0.3, 1.
D = (math.cos(math.radians(30.)), math.sin(math.radians(30.)), 0.)
TOTAL, LAST = 0.0075, 0.005

contact_fem, scene = sys.argv[1:3]
failures = []


def close(value, exact, scale, what):
    if abs(value - exact) > 1e-9 * scale:  # the files print 10 digits
        failures.append(f"{what}: {value!r}, expected {exact!r}")


run_scene(contact_fem, scene, "Output directory=results", "Output/Write pressure profile=true",
          "Output/Write VTU=true")
with open("results/pressure_profile.csv") as f:
    rows = [r for r in csv.DictReader(f) if r["active"] == "1"]
if len(rows) != 16:
    failures.append(f"{len(rows)} active nodes, expected 16")
for r in rows:
    where = f"node ({r['x']}, {r['y']})"
    for k, c in enumerate("xyz"):
        close(float(r[f"tangential_traction_{c}"]), MU * P * D[k], MU * P, f"{where} t_{c}")
        close(float(r[f"slip_increment_{c}"]), -LAST * D[k], TOTAL, f"{where} slip_{c}")
        close(float(r[f"accumulated_tangential_displacement_{c}"]), -TOTAL * D[k], TOTAL,
              f"{where} accumulated_{c}")
    close(float(r["accumulated_slip"]), TOTAL, TOTAL, f"{where} accumulated_slip")
    if r["stick"] != "0":
        failures.append(f"{where} sticks")

with open("results/contact_surface_005.vtu") as f:
    vtu = f.read()


def vtu_array(name):
    match = re.search(rf'Name="{name}"[^>]*>([^<]*)<', vtu)
    return [float(v) for v in match.group(1).split()] if match else None


active = vtu_array("active")
fields = {"accumulated_slip": TOTAL}
for k, c in enumerate("xyz"):
    fields[f"tangential_traction_{c}"] = MU * P * D[k]
    fields[f"slip_increment_{c}"] = -LAST * D[k]
    fields[f"accumulated_tangential_displacement_{c}"] = -TOTAL * D[k]
for name, exact in fields.items():
    values = vtu_array(name)
    if values is None or active is None:
        failures.append(f"contact_surface_005.vtu has no {name}")
        continue
    scale = MU * P if name.startswith("tangential") else TOTAL
    for value in (v for v, on in zip(values, active) if on > 0.5):
        close(value, exact, scale, f"VTU {name}")

with open("results/summary.json") as f:
    cycle = json.load(f)["cycles"][-1]
contact, reaction = cycle["contact"], cycle["reaction"]
pair = cycle["load_steps"][-1]["forces"]["pairs"][0]
if pair["stick_nodes"] + pair["slip_nodes"] != contact["active_slave_nodes"] or pair["stick_nodes"]:
    failures.append(f"stick {pair['stick_nodes']} + slip {pair['slip_nodes']}, "
                    f"active {contact['active_slave_nodes']}: expected 0 + 16")
normal = contact["total_normal_contact_force"]
for k in range(3):
    close(contact["tangential_contact_force_components"][k], MU * normal * D[k], normal,
          f"tangential_contact_force_components[{k}]")
close(contact["max_accumulated_slip"], TOTAL, TOTAL, "max_accumulated_slip")
if len(reaction["relative_imbalance_components"]) != 3 or \
        max(abs(v) for v in reaction["relative_imbalance_components"]) > 1e-10:
    failures.append(f"relative_imbalance_components {reaction['relative_imbalance_components']}")

output = run_scene(contact_fem, scene, "Output directory=spr", "Refinement/Estimator=spr contact",
                   "Refinement/Number of cycles=2")
if "Estimate at round-off level" not in output:
    lines = [line for line in output.splitlines() if "estimated error" in line]
    failures.append(f"SPR contact estimate not at round-off: {lines}")

if failures:
    print("\n".join(failures))
    sys.exit(1)
print(f"{len(rows)} slip nodes: traction mu p along the pull, slip and accumulated slip along "
      "-pull (profile and VTU), summary counts, force and balance in x, y, z; SPR contact exact")
