#!/usr/bin/env python3
"""A Gmsh tetrahedral hemisphere on a tetrahedral block, its whole curved
surface the slave (outside-user audit, round 4, doc/metamorphic.md).

Usage: check_sphere_on_block.py CONTACT_FEM MESH

meshes/sphere_on_block_tet.msh (R = 1, 171 tetrahedra split into
hexahedra), the flat top pushed down by 0.01 in one step, frictionless.
The mortar integration used to stop the run before the first step ("a
quadrature point of the slave face ... does not project onto the master
face"): a flank face 0.4 above the block, whose interpolated normal at a
quadrature point missed the master face that the segmentation's face normal
reached. Checks: the run converges; the block's support reaction equals
the pair force and the top's reaction is its opposite (1e-8 of the force);
the force is vertical to 2 % (the geometry is symmetric, the tetrahedra
are not) and the contact radius, sqrt(area / pi), is within 40 % of the
Hertz radius sqrt(R d) for the approach d that the pair's force gives with
E* of the two bodies (a coarse mesh: a is 0.7 tetrahedron sizes). Then
the hemisphere touching without a press: a warning names the preload that
the pole node's negative mortar gap gives (it used to call the pressures
round-off).
"""
import csv
import json
import math
import subprocess
import sys

from scene_run import ENVIRONMENT

SCENE = f"""set Dimension = 3
subsection Geometry
  set Type      = mesh file
  set Mesh file = {sys.argv[2]}
  set Manifolds = 3: sphere 0, 0, 1.6, 1
end
subsection Materials
  set Material ids     = 1, 2
  set Young's moduli   = 100, 200
  set Poisson's ratios = 0.3, 0.25
end
subsection Boundary conditions
  set Fixed    = 2: xyz
  set Prescribed displacement = 1: x = 0; 1: y = 0; 1: z = -0.01*t
end
subsection Contact
  set Pairs       = 3: 4
  set Formulation = alm frictionless
end
subsection Output
  set Write VTU = false
  set Write pressure profile = false
  set Print timing = false
end
"""
with open("sphere.prm", "w") as f:
    f.write(SCENE)
result = subprocess.run([sys.argv[1], "sphere.prm", "--output-directory", "results"],
                        env=ENVIRONMENT, capture_output=True, text=True)
if result.returncode != 0:
    sys.exit(f"exit {result.returncode}:\n{result.stdout}{result.stderr}")
with open("results/forces.csv") as f:
    row = list(csv.DictReader(f))[-1]
vec = lambda name: [float(row[f"{name}_{c}"]) for c in "xyz"]
pair = [a + b for a, b in zip(vec("pair_3_4_normal"), vec("pair_3_4_tangential"))]
base, top = vec("boundary_2"), vec("boundary_1")
force = math.sqrt(sum(c * c for c in pair))
balance = max(max(abs(a - b) for a, b in zip(base, pair)),
              max(abs(a + b) for a, b in zip(top, pair))) / force
sideways = math.hypot(pair[0], pair[1]) / pair[2]
e_star = 1 / ((1 - 0.3 ** 2) / 100 + (1 - 0.25 ** 2) / 200)
approach = (3 * pair[2] / (4 * e_star)) ** (2 / 3)  # F = 4/3 E* sqrt(R) d^1.5, R = 1
radius = math.sqrt(float(row["pair_3_4_area"]) / math.pi)
hertz = math.sqrt(approach)
checks = [(f"support and top reactions against the pair force: {balance:.1e} (1e-8)", balance < 1e-8),
          (f"sideways / vertical force: {sideways:.2e} (0.02)", sideways < 0.02),
          (f"contact radius {radius:.3f}, Hertz {hertz:.3f} (40 %)", abs(radius / hertz - 1) < 0.4)]
with open("results/summary.json") as f:
    status = json.load(f)["status"]
checks.insert(0, (f"status {status}", status == "converged"))

# The same hemisphere touching the block without a press: the pole node's
# dual-mortar gap starts negative (about h^2 / R on this coarse mesh), so
# the bodies press each other. The warning used to call those pressures
# round-off ("read the state as without contact"); they are a preload.
UNLOADED = "Boundary conditions/Prescribed displacement=1: x = 0; 1: y = 0; 1: z = 0"
result = subprocess.run([sys.argv[1], "sphere.prm", "--output-directory", "results-unloaded",
                         "--set", UNLOADED], env=ENVIRONMENT, capture_output=True, text=True)
with open("results-unloaded/summary.json") as f:
    cycle = json.load(f)["cycles"][-1]
preload = cycle.get("preload_warning", "")
checks.append((f"unloaded: exit {result.returncode}, a preload warning "
               f"{'given' if preload else 'missing'}, no round-off warning: "
               f"{'unloaded_warning' not in cycle}",
               result.returncode == 0 and bool(preload) and "unloaded_warning" not in cycle))
for text, ok in checks:
    print(text + ("" if ok else ": WRONG"))
sys.exit(0 if all(ok for _, ok in checks) else 1)
