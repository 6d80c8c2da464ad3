#!/usr/bin/env python3
"""Newton's rate in the slide steps of 'penalty frictional' on the current
configuration in 3D (issue 29).

Usage: check_current_penalty_friction_rate.py CONTACT_FEM PATCH.prm

PATCH is tests/scenes/frictional_patch_3d_penalty_01.prm (the 3D patch,
linear bulk, pressed, then pulled at 30 degrees until every node slips,
mu = 0.3), run with Contact/Kinematics = current. The bulk is linear, so
Newton's rate is that of the contact force alone. The tangent was checked
against central differences of the assembled contact force at slip and
stick iterates (relative error 1e-9, round-off; doc/finite_strain.md), and
the force's remainder along each Newton step falls as the step squared:
no term is missing. What remains is the size of the quadratic constant: the
penalty force eps_n (-G_j) f_j on the deformed surfaces has a second
derivative of order eps_n D_j / h (the gap's change under a turn of the
faces, amplified by the penalty), so the sequences are quadratic with a
constant that grows with the penalty. Over the iterations without a set
change (scene_run.newton_ratios(), r the displacement ratio):

- Contact/Stiffness factor = 0.01 (eps = 100 E / h): r_k <= 10 r_(k-1)^2
  once r_(k-1) <= 0.1 (measured: at most 0.36);
- the automatic penalty (1e4 E / h): every r_k / r_(k-1)^2 below 1e4
  (measured 135, 2.4e3, 2.7: the first iterates after the stick/slip switch
  are in the pre-asymptotic range of the stiff penalty), and the last pair
  of the full-slip step t = 2.5 quadratic with C = 10 (measured 2.7;
  a tangent error e would leave r_k / r_(k-1) = e, there r_k / r_(k-1) =
  4e-5);
- both: every step converges to Newton's tolerance (not "to linear-solver
  accuracy", where a stalled iteration is accepted) without a split, and
  the slide steps end with every node slipping.

Checked to fail without the slip direction's derivative (T / |t*|) (I -
d d^T) d t* in the tangent: the slide steps stall and are accepted at
linear-solver accuracy.
"""
import sys

from scene_run import check_quadratic, converged_sets, newton_ratios, perturbation, run_scene


def report(name, good, detail):
    print(f"{name}: {'ok' if good else 'FAILED'} ({detail})")
    return good


def run(contact_fem, scene, factor):
    return run_scene(contact_fem, scene, "Contact/Kinematics=current",
                     f"Contact/Stiffness factor={factor}", *perturbation())


def constants(ratios):
    return [b / a**2 for a, b in zip(ratios, ratios[1:])
            if a is not None and b is not None and a <= 0.1]


def check_common(name, output):
    # Newton's own tolerance, not "converged to linear-solver accuracy"
    # (where a stalled iteration is accepted).
    converged = sum(line.rstrip().endswith("| converged") for line in output.splitlines())
    sets = converged_sets(output)
    return report(f"{name}: 5 steps converged to the Newton tolerance without a split, every "
                  "node slips at t = 2, 2.5",
                  converged == 5 and "Splitting" not in output and
                  len(sets) == 5 and all(s[1] == 0 and s[2] == s[0] > 0 for s in sets[3:]),
                  f"sets (active, stick, slip) {sets}")


def main():
    contact_fem, scene = sys.argv[1:3]

    soft = run(contact_fem, scene, 0.01)
    ok = check_common("eps = 100 E / h", soft)
    ok = check_quadratic("eps = 100 E / h", soft, 10.0) and ok

    stiff = run(contact_fem, scene, 1)
    ok = check_common("automatic penalty", stiff) and ok
    steps = newton_ratios(stiff)
    every = [c for ratios in steps for c in constants(ratios)]
    last = constants(steps[-1])
    ok = report("automatic penalty: every r_k / r_(k-1)^2 below 1e4, the last of t = 2.5 below 10",
                len(steps) == 5 and every and max(every) < 1e4 and last and last[-1] < 10,
                f"constants {', '.join(f'{c:.3g}' for c in every)}") and ok
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
