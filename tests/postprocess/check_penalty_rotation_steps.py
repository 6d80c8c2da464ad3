#!/usr/bin/env python3
"""Penalty frictional at the automatic penalty under large rigid-rotation
load steps on the current configuration (Contact/Kinematics = current).

Usage: check_penalty_rotation_steps.py CONTACT_FEM SCENE.prm

SCENE is tests/scenes/current_kinematics_friction_3d_01.prm (a neo-Hookean
block on an elastic base, mu = 0.3), held at the base's bottom only, with
penalty frictional at Stiffness factor 1 (eps_t = eps_n = 1e4 E / h):
pressed by 0.11 (t = 1), pulled at 30 degrees by 0.03 (t = 2, 14 stick
and 2 slip nodes), then pulled on by 0.005 per step while the whole scene
turns about the contact normal by 20 degrees (step 3),
through the Dirichlet data of the block's top and the base's bottom (u = c
+ R (X + u_0 - c) - X). Checked: the spin step converges without a
split, and its stick/slip counts are those of the step before (a rigid
rotation changes no frictional state; the pull adds 0.005 per step, which
leaves 14 / 2 as in the unrotated run). Before the step's first update
kept the stick nodes sticking, the linearised rotation of the predictor
made them slip at iteration 1 and every such step split (13 splits over
three 20 degree steps, elements inverted; bench/finite_strain/
penalty_rotation_steps.py, doc/finite_strain.md).
"""
import math
import re
import sys

from scene_run import converged_sets, perturbation, run_scene

CENTRE = (0.0, 0.0, 0.25)
SPIN = math.radians(20.0)  # per step
SPIN_STEPS = 1
END = 2 + SPIN_STEPS


def dirichlet(boundary, motion):
    angle = f"{SPIN!r}*min(max(t - 2, 0), {SPIN_STEPS})"
    c, s = f"cos({angle})", f"sin({angle})"
    rel = [f"({X} + {m} - {o!r})" for X, m, o in zip("xyz", motion, CENTRE)]
    rows = [f"{CENTRE[0]!r} + ({c})*{rel[0]} - ({s})*{rel[1]} - x",
            f"{CENTRE[1]!r} + ({s})*{rel[0]} + ({c})*{rel[1]} - y",
            f"{CENTRE[2]!r} + {rel[2]} - z"]
    return "; ".join(f"{boundary}: {X} = {row}" for X, row in zip("xyz", rows))


def main():
    contact_fem, scene = sys.argv[1:3]
    pull = "(0.03*min(max(t - 1, 0), 1) + 0.005*max(t - 2, 0))"
    top = (f"0.866025403784439*{pull}", f"0.5*{pull}", "-0.11*min(t, 1)")
    data = "; ".join([dirichlet(1, top), dirichlet(2, ("0", "0", "0"))])
    output = run_scene(contact_fem, scene, *perturbation(),
                       "Contact/Formulation=penalty frictional",
                       f"Load stepping/End time={END}", f"Load stepping/Number of load steps={END}",
                       "Boundary conditions/Fixed=",
                       f"Boundary conditions/Prescribed displacement={data}")
    # The press (t = 1) may split at this penalty with or without rotation.
    splits = [float(t) for t in
              re.findall(r"Splitting the step: retrying from t = ([0-9.e+-]+)", output)]
    spin_splits = [t for t in splits if t >= 2]
    sets = converged_sets(output)
    ok = not spin_splits and len(sets) >= 2 and sets[-1] == sets[-2]
    print(f"penalty frictional, automatic penalty: the 20 degree spin step converges without "
          f"a split, with the stick/slip counts of the step before: {'ok' if ok else 'FAILED'} "
          f"(splits from t = {spin_splits}, converged (active, stick, slip) of the last two "
          f"steps {sets[-2:]})")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
