#!/usr/bin/env python3
"""Objectivity of friction on the current configuration in 2D
(Contact/Kinematics = current, issue 29): a large rigid rotation
superposed during the load steps leaves the frictional state unchanged.

Usage: check_objectivity_friction_2d.py CONTACT_FEM SCENE.prm FORMULATION [SETTING...]

Each SETTING ('Section/Key=value', e.g. 'Contact/Friction=tresca 5') is
given to both runs.

SCENE is tests/scenes/current_kinematics_friction_01.prm (neo-Hookean
blocks 4 x 1, the upper one pressed onto the lower, mu = 0.3), held at the
lower block's bottom only, with the load program (steps of 0.5)

    t = 0 .. 1  pressed down by 0.25 (two steps),
    t = 1 .. 5  pulled along x by 0.1 per step (every node sticks at t =
                1.5 and 2, the ends slip at 2.5, every node from t = 3),

run twice: as it is, and with the rigid rotation R(t) by 15 degrees per
step for t = 1 .. 4 (90 degrees in all: through the stick, stick-slip
and full-slip steps) about the point (2, 1) on the
interface superposed through the Dirichlet data (u = c + R (X + u_0 - c) -
X on the upper block's top and the lower block's bottom). In 2D every
rotation turns the normal; the slip and, for the penalty, the history
traction carried by the turn of the normal must follow it: both runs take
the same steps (the penalty, at Stiffness factor 1e-2, splits the full-slip
steps at t = 3.5 and 4 once, in both runs alike), per load step the same
active, stick and slip counts, and the pair's forces R^T F equal to the unrotated ones to 1e-7 of |F_n|; at t = 5
per node the same flags, p_j and R^T t_j to 1e-7 of the largest p.
"""
import math
import sys

from scene_run import converged_sets, csv_numbers, perturbation, run_scene

CENTRE = (2.0, 1.0)
END, STEPS = 5, 10
TURN = math.radians(15.0)  # per step of 0.5
TOLERANCE = 1e-7
ANGLE_T = f"{2 * TURN!r}*min(max(t - 1, 0), 3)"
TOP = ["0.2*max(t - 1, 0)", "-0.25*min(t, 1)"]


def report(name, good, detail):
    print(f"{name}: {'ok' if good else 'FAILED'} ({detail})")
    return good


def angle(t):
    return 2 * TURN * min(max(t - 1, 0), 3)


def dirichlet(boundary, motion):
    c, s = f"cos({ANGLE_T})", f"sin({ANGLE_T})"
    rx, ry = (f"(x + {motion[0]} - {CENTRE[0]!r})", f"(y + {motion[1]} - {CENTRE[1]!r})")
    return (f"{boundary}: x = {CENTRE[0]!r} + ({c})*{rx} - ({s})*{ry} - x; "
            f"{boundary}: y = {CENTRE[1]!r} + ({s})*{rx} + ({c})*{ry} - y")


def settings(formulation, rotated):
    common = ["Output/Write pressure profile=true", f"Contact/Formulation={formulation}",
              f"Load stepping/End time={END}", f"Load stepping/Number of load steps={STEPS}"]
    if not rotated:
        return common + ["Boundary conditions/Fixed=2: xy",
                         f"Boundary conditions/Prescribed displacement=1: x = {TOP[0]}; "
                         f"1: y = {TOP[1]}"]
    data = "; ".join([dirichlet(1, TOP), dirichlet(2, ("0", "0"))])
    return common + ["Boundary conditions/Fixed=",
                     f"Boundary conditions/Prescribed displacement={data}"]


def back(t, v):
    a = angle(t)
    return [math.cos(a) * v[0] + math.sin(a) * v[1], -math.sin(a) * v[0] + math.cos(a) * v[1]]


def vector(row, prefix):
    return [row[f"{prefix}_{c}"] for c in "xy"]


# At the automatic penalty the unrotated scene splits steps (eps_t = 1e4 E /
# h against pull steps of 0.1; the stored 2D penalty scene pulls in 16
# steps with the master's top held): a softer one, as the 3D test.
EXTRA = {"penalty frictional": ("Contact/Stiffness factor=1e-2",)}


def run(contact_fem, scene, formulation, rotated, extra):
    output = run_scene(contact_fem, scene, *perturbation(), *EXTRA.get(formulation, ()),
                       *extra, *settings(formulation, rotated))
    return output, csv_numbers("results/forces.csv"), csv_numbers("results/pressure_profile.csv")


def main():
    contact_fem, scene, formulation = sys.argv[1:4]
    extra = sys.argv[4:]
    reference = run(contact_fem, scene, formulation, False, extra)
    turned = run(contact_fem, scene, formulation, True, extra)
    formulation = ", ".join([formulation, *extra])  # the name in the report
    times = [[row["t"] for row in forces] for _, forces, _ in (reference, turned)]
    ok = report(f"{formulation}: both runs take the same load steps (friction depends on the "
                "load path)", times[0] == times[1] and times[0][-1] == END,
                f"{len(times[0])} steps")
    sets = [converged_sets(o) for o, _, _ in (reference, turned)]
    kinds = {(stick > 0, slip > 0) for _, stick, slip in sets[0][2:]}
    ok = report(f"{formulation}: the active, stick and slip counts of every step (stick, "
                "stick and slip, slip steps while turning)",
                len(sets[0]) == len(times[0]) and sets[0] == sets[1] and
                kinds >= {(True, False), (True, True), (False, True)},
                f"reference {sets[0]}, rotated {sets[1]}") and ok
    per_step = []
    for a, b in zip(reference[1], turned[1]):
        scale = math.hypot(*vector(a, "pair_3_4_normal"))
        per_step.append(max(math.dist(vector(a, f"pair_3_4_{kind}"),
                                      back(b["t"], vector(b, f"pair_3_4_{kind}")))
                            for kind in ("normal", "tangential")) / scale)
    ok = report(f"{formulation}: the pair's R^T F_n, R^T F_t of every step equal the "
                f"reference's to {TOLERANCE:g} of |F_n|",
                len(per_step) == len(times[0]) and max(per_step) < TOLERANCE,
                "relative differences per step " + ", ".join(f"{e:.1e}" for e in per_step)) and ok

    def key(n):
        return (round(n["reference_x"], 9), round(n["reference_y"], 9))

    nodes = {key(n): n for n in reference[2]}
    scale = max(n["pressure"] for n in reference[2])
    flags, pressure, traction = len(turned[2]) == len(nodes), 0.0, 0.0
    for n in turned[2]:
        m = nodes.get(key(n))
        if m is None:
            flags = False
            continue
        flags = flags and (n["active"], n["stick"]) == (m["active"], m["stick"])
        pressure = max(pressure, abs(n["pressure"] - m["pressure"]) / scale)
        # 2D: the tangential traction is a scalar along tau = n turned,
        # which turns with the scene.
        traction = max(traction, abs(n["tangential_traction"] - m["tangential_traction"]) / scale)
    ok = report(f"{formulation}, t = {END}: per node the same flags, p_j and t_j to "
                f"{TOLERANCE:g} of the largest p", flags and pressure < TOLERANCE and
                traction < TOLERANCE, f"p off {pressure:.1e}, t off {traction:.1e}") and ok
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
