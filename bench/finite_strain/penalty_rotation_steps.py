#!/usr/bin/env python3
"""The largest rigid-rotation load step that penalty frictional survives on
the current configuration (issue 29 follow-up; doc/finite_strain.md,
"Objectivity under a superposed rigid rotation").

Usage: penalty_rotation_steps.py CONTACT_FEM SCENE.prm [WORKDIR]

SCENE is build/tests/scenes/current_kinematics_friction_3d_01.prm (the
neo-Hookean block on its elastic base). Load program as in
tests/postprocess/check_objectivity_friction_3d.py: pressed by 0.11 (t =
1), pulled at 30 degrees by 0.03 (t = 2), then pulled on by 0.005 per
step while the whole scene is spun about the contact normal (through the
Dirichlet data of the block's top and the base's bottom, the base's
bottom its only support) by a total of 60 degrees in steps of STEP
degrees. Per formulation, Coulomb mu and STEP: whether the run ends,
the splits, and the Newton iterations of the spin steps (counts are
exact; no wall times).
"""
import math
import os
import re
import subprocess
import sys

CENTRE = (0.0, 0.0, 0.25)
TOTAL = 60.0  # degrees of spin
STEPS = (5, 10, 15, 20, 30)  # degrees per load step


def dirichlet(boundary, motion, angle_t):
    c, s = f"cos({angle_t})", f"sin({angle_t})"
    X = ("x", "y", "z")
    rel = [f"({X[d]} + {motion[d]} - {CENTRE[d]!r})" for d in range(3)]
    rows = [f"{CENTRE[0]!r} + ({c})*{rel[0]} - ({s})*{rel[1]} - x",
            f"{CENTRE[1]!r} + ({s})*{rel[0]} + ({c})*{rel[1]} - y",
            f"{CENTRE[2]!r} + {rel[2]} - z"]
    return "; ".join(f"{boundary}: {X[i]} = {rows[i]}" for i in range(3))


def run(contact_fem, scene, formulation, mu, step, extra, workdir):
    steps = int(round(TOTAL / step))
    end = 2 + steps
    angle_t = f"{math.radians(step)!r}*min(max(t - 2, 0), {steps})"
    pull = "(0.03*min(max(t - 1, 0), 1) + 0.005*max(t - 2, 0))"
    top = [f"0.866025403784439*{pull}", f"0.5*{pull}", "-0.11*min(t, 1)"]
    data = "; ".join([dirichlet(1, top, angle_t), dirichlet(2, ("0", "0", "0"), angle_t)])
    settings = [*extra, f"Contact/Formulation={formulation}", f"Contact/Friction=coulomb {mu}",
                f"Load stepping/End time={end}", f"Load stepping/Number of load steps={end}",
                "Boundary conditions/Fixed=", f"Boundary conditions/Prescribed displacement={data}"]
    command = [contact_fem, scene, "--output-directory", workdir]
    for s in settings:
        command += ["--set", s]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    result = subprocess.run(command, env=env, capture_output=True, text=True)
    out = result.stdout + result.stderr
    # Splits of the spin steps (the press, t <= 1, may split at the
    # automatic penalty without any rotation).
    splits = len([x for x in re.findall(r"Splitting the step: retrying from t = ([0-9.e+-]+)", out)
                  if float(x) >= 2])
    # Newton iterations of the converged spin steps (t > 2).
    iterations, t, count = [], None, 0
    for line in out.splitlines():
        m = re.match(r"\s*Load step \d+, t = ([0-9.e+-]+)", line)
        if m:
            t, count = float(m.group(1)), 0
        if re.match(r"\s*\|\s*\d+\s*\|", line):
            count += 1
        if line.rstrip().endswith("| converged") and t is not None and t > 2:
            iterations.append(count - 1)
    inverted = any("inverted" in line for line in out.splitlines()
                   if (m := re.search(r"\(t = ([0-9.]+)\)", line)) and float(m.group(1)) > 2)
    return result.returncode, splits, iterations, inverted


def main():
    contact_fem, scene = sys.argv[1:3]
    workdir = sys.argv[3] if len(sys.argv) > 3 else "results-rotation-steps"
    cases = [("alm frictional", (), "alm"), ("penalty frictional", (), "penalty, auto"),
             ("penalty frictional", ("Contact/Stiffness factor=1e-2",), "penalty, SF 1e-2")]
    print("| formulation | mu | spin per step | exit | splits | Newton its of the spin steps | inverted element in a spin step |")
    print("|---|---|---|---|---|---|---|")
    for mu in (0.3, 2):
        for formulation, extra, name in cases:
            for step in STEPS:
                code, splits, its, inverted = run(contact_fem, scene, formulation, mu, step, extra,
                                                  workdir)
                print(f"| {name} | {mu} | {step} | {code} | {splits} | "
                      f"{' '.join(map(str, its))} | {'yes' if inverted else 'no'} |", flush=True)


if __name__ == "__main__":
    main()
