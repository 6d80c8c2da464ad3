#!/usr/bin/env python3
"""A slave node that re-enters contact under `penalty frictional` with
current kinematics (issue 29, doc/finite_strain.md, "The full-slip step's
cycle" and "Re-entry into contact").

Usage: check_penalty_reentry.py CONTACT_FEM SCENE_3D.prm

SCENE_3D is tests/scenes/current_kinematics_penalty_friction_3d_01.prm (a
neo-Hookean block pressed onto a wider base, then pulled at 30 degrees in
the plane, mu = 0.3) with the block's cells at its base on x < 0 refined
once (`Geometry/Local refinements`), on a shorter program of three steps
(PROGRAM): pressed by 0.11 in one step instead of two (t = 1), pulled by
0.03 (t = 2: stick and slip nodes), then by 0.125 (t = 3: full slip). In
the full-slip step the slave surface's corner opens, and the linear step
from its open state drives it 3.5e-3 (2 % of h) into the master, 300 times
the penetrations of its neighbours: without the limit (Contact/Entry depth
factor = 0) its penalty pressure swamps the next update, the sets cycle
and the step is split once (on this program as on the scene's four steps;
with the first version's floor, the node entering by 1e-3 h, five times on
the four steps). The update is now shortened so that such a node enters
as deep as the deepest node in contact. Checks:

- every load step converges without a split;
- at t = 3 every active node slips, and the pair's normal force and
  tangential / normal force ratio equal those of `alm frictional` on the
  same scene and steps (exact gap constraint; it converges this step
  without a split) within 1e-3 and 1e-4 relative (measured 8e-5 and
  1.4e-5, as on the four steps: the penalty's penetrations). The ratio is
  0.2814, not mu = 0.3: the pair's sums mix the tilted normals of the
  bulged block's rim.

The scene's separate pressing steps cost a quarter of the CPU of the two
runs and change nothing checked here (doc/performance.md, "Session 37").
"""
import re
import sys

from scene_run import perturbation, run_scene

# The scene's pull at 30 degrees from x, its press in one step.
PULL = "(0.03*min(max(t - 1, 0), 1) + 0.125*max(t - 2, 0))"
PROGRAM = ("Geometry/Local refinements=1: -0.6, -0.6, 0.3, 0, 0.6, 0.45",
           "Boundary conditions/Prescribed displacement="
           f"1: x = 0.866025403784439*{PULL}; 1: y = 0.5*{PULL}; 1: z = -0.11*min(t, 1)",
           "Load stepping/End time=3", "Load stepping/Number of load steps=3")


def report(name, good, detail):
    print(f"{name}: {'ok' if good else 'FAILED'} ({detail})")
    return good


def final_forces(output):
    """Stick and slip counts, normal force and F_t / F_n at t = 3."""
    results = output[output.rfind("Results at t = 3"):] if "Results at t = 3" in output else ""
    sets = re.search(r"stick / slip nodes:\s+(\d+) / (\d+)", results)
    ratio = re.search(r"tangential / normal force:\s+([-0-9.e+]+)", results)
    normal = re.findall(r"pair 3: 4: normal \(([^)]*)\)", output)
    if not (sets and ratio and normal):
        return {"stick": -1, "slip": 0, "normal": float("nan"), "ratio": float("nan")}
    return {"stick": int(sets.group(1)), "slip": int(sets.group(2)),
            "normal": float(normal[-1].split(",")[2]), "ratio": float(ratio.group(1))}


def main():
    contact_fem, scene = sys.argv[1:3]
    output = run_scene(contact_fem, scene, *PROGRAM, *perturbation())
    splits = output.count("Splitting the step")
    steps = re.findall(r"Load step \d+, t = ([0-9.e+-]+)", output)
    ok = report("three load steps to t = 3, no split", splits == 0 and steps == ["1", "2", "3"],
                f"{splits} splits, steps at t = {', '.join(steps)}")
    alm = run_scene(contact_fem, scene, *PROGRAM, "Contact/Formulation=alm frictional",
                    *perturbation())
    penalty, reference = final_forces(output), final_forces(alm)
    ok = report("at t = 3 every active node slips", penalty["stick"] == 0 and penalty["slip"] > 0,
                f"stick / slip {penalty['stick']} / {penalty['slip']}") and ok
    normal = abs(penalty["normal"] / reference["normal"] - 1.)
    ratio = abs(penalty["ratio"] / reference["ratio"] - 1.)
    ok = report("normal force and F_t / F_n as alm frictional's within 1e-3, 1e-4",
                normal < 1e-3 and ratio < 1e-4,
                f"ratio {penalty['ratio']:.4f}, relative differences {normal:.0e}, {ratio:.0e}") and ok
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
