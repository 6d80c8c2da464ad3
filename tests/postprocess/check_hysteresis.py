#!/usr/bin/env python3
"""Ten load cycles of the Cattaneo scene (prm/cattaneo.prm, Global
refinements 1): P = 10 on t in [0, 1], then the tangential load
Q = Q* sin(pi/2 (t - 1)), Q* = 0.8 mu P = 1.6, with the pressure that
balances its moment, the lower body mirrored: peaks +Q* at t = 2 + 4k,
-Q* at t = 4 + 4k. The tangential displacement is that of the upper flat's
centre relative to the lower flat's centre (two displacement probes in
forces.csv), the force the pair's tangential contact force.

Checks, on every cycle k = 1..10 (t in [2 + 4 (k - 1), 2 + 4 k]):
- the loop closes: the displacement at the end of cycle k equals that at
  the end of cycle k - 1 (the first peak for k = 1: Masing, the reloaded
  state is the virgin one) to 1e-6 of the loop's displacement amplitude,
  and so does the force;
- the dissipated work, the loop's area (trapezoidal rule over the load
  steps), is positive and the same in every cycle to 1e-6 of itself.

Usage: check_hysteresis.py CONTACT_FEM SOURCE_DIR
"""
import csv
import os
import sys

from scene_run import run

contact_fem, source = sys.argv[1:3]
scene = f"""include {source}/prm/cattaneo.prm
set Output directory = results
subsection Geometry
  set Mesh file          = {source}/meshes/two_cylinders.msh
  set Global refinements = 1
end
subsection Boundary conditions
  set Pressure = 1: 0.625*min(t, 1) - 0.375*0.1*x*sin(1.5707963267948966*max(t - 1, 0)); \\
                 2: 0.625*min(t, 1) + 0.375*0.1*x*sin(1.5707963267948966*max(t - 1, 0))
  set Traction = 1: 0.1*sin(1.5707963267948966*max(t - 1, 0)), 0; 2: -0.1*sin(1.5707963267948966*max(t - 1, 0)), 0
end
subsection Load stepping
  set End time             = 42
  set Number of load steps = 168
end
subsection Analytical solution
  set Type = none
end
subsection Output
  set Displacement probes    = 1 @ 0, 8; 2 @ 0, -8
  set Write VTU              = false
  set Write pressure profile = false
  set Print timing           = false
end
"""
with open("hysteresis.prm", "w") as f:
    f.write(scene)
run([contact_fem, "hysteresis.prm"])
with open(os.path.join("results", "forces.csv")) as f:
    rows = list(csv.DictReader(f))
time = [float(r["t"]) for r in rows]
force = [-float(r["pair_3_4_tangential_x"]) for r in rows]
slide = [float(r["probe_1_ux"]) - float(r["probe_2_ux"]) for r in rows]


def at(t):
    """Index of the converged step at time t."""
    return min(range(len(time)), key=lambda i: abs(time[i] - t))


failures = []
peaks = [at(2 + 4 * k) for k in range(11)]
if any(abs(time[i] - (2 + 4 * k)) > 1e-9 for k, i in enumerate(peaks)):
    failures.append("a peak of the load is not a load step")
amplitude = 0.5 * (max(slide) - min(slide))
areas = []
for k in range(1, 11):
    first, last = peaks[k - 1], peaks[k]
    areas.append(sum(0.5 * (force[i] + force[i + 1]) * (slide[i + 1] - slide[i])
                     for i in range(first, last)))
    if abs(slide[last] - slide[first]) > 1e-6 * amplitude:
        failures.append(f"cycle {k}: displacement {slide[last]} at its end, {slide[first]} "
                        "at the end of the cycle before")
    if abs(force[last] - force[first]) > 1e-6 * max(abs(f) for f in force):
        failures.append(f"cycle {k}: force {force[last]} at its end, {force[first]} before")
if min(areas) <= 0.:
    failures.append(f"dissipated work per cycle {areas}: not positive")
if max(areas) - min(areas) > 1e-6 * max(areas):
    failures.append(f"dissipated work per cycle {areas}: not the same in every cycle")
if failures:
    print("\n".join(failures))
    sys.exit(1)
print(f"10 closed loops: displacement amplitude {amplitude:.4e}, peak force "
      f"{max(force):.4f}, dissipated work per cycle {areas[0]:.4e}")
