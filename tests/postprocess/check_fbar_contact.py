#!/usr/bin/env python3
"""Newton with contact on a nearly incompressible F-bar body.

Usage: check_fbar_contact.py CONTACT_FEM HERTZ.prm

HERTZ is prm/hertz.prm: the half-disc made neo-Hookean with nu = 0.499 and
F-bar (Finite element/Volumetric strain = B-bar), on the rigid plate, with
the contact on the current configuration and on the reference one (small
kinematics). For each:

- every load step converges without a split, in at most MAX_ITERATIONS
  Newton iterations (the active set settles in a few iterations; with the
  multipliers recovered from the nonlinear residual it cycled, every other
  node switching: 13 iterations and two step splits);
- Newton's displacement ratios fall quadratically once the sets are fixed;
- the answer is Hertz' within 2 % (p_max) and one slave element (a).

CONTACT_FEM_PERTURBATION_SEED, if set, renumbers the DoFs (as
tests/run_perturbed.sh does; seeds 1-3 give the same counts).
"""
import sys

from scene_run import check_quadratic, newton_table, perturbation, run_scene

MAX_ITERATIONS = 10
SETTINGS = ("Materials/Models=neo-hookean, linear", "Materials/Poisson's ratios=0.499, 0.3",
            "Finite element/Volumetric strain=B-bar", "Output/Write VTU=false",
            "Newton/Displacement relative tolerance=1e-10",
            "Newton/Displacement absolute tolerance=1e-12")

contact_fem, scene = sys.argv[1:3]
ok = True
for kinematics in ("current", "small"):
    output = run_scene(contact_fem, scene, *SETTINGS, *perturbation(),
                       f"Contact/Kinematics={kinematics}")
    attempts = newton_table(output)
    iterations = [len(ratios) - 1 for ratios, _ in attempts]
    good = (len(attempts) > 0 and "Newton failed" not in output and "Splitting" not in output
            and max(iterations) <= MAX_ITERATIONS)
    print(f"{kinematics} kinematics: load steps {iterations} Newton iterations, every one "
          f"converged without a split in at most {MAX_ITERATIONS}: {'ok' if good else 'FAILED'}")
    ok = good and ok
    ok = check_quadratic(f"{kinematics} kinematics", output, 100.0) and ok
    good = ("p_max within 2 % of Hertz:    yes" in output
            and "a within one slave element:   yes" in output)
    print(f"{kinematics} kinematics: Hertz' p_max within 2 %, a within one element: "
          f"{'ok' if good else 'FAILED'}")
    ok = good and ok
sys.exit(0 if ok else 1)
