#!/usr/bin/env python3
"""Contact on the current configuration on curved 3D faces against 2D.

Usage: check_current_kinematics_cylinders_3d.py CONTACT_FEM SCENE_3D.prm SCENE_2D.prm

SCENE_3D is tests/scenes/current_kinematics_cylinders_3d_01.prm: the two
half-cylinders of meshes/two_cylinders_extruded.msh (one cell layer, u_z = 0
on both ends: plane strain), Q1 on the quadratic mapping (9-node curved
contact faces), neo-Hookean, pressed by 1.0 with Contact/Kinematics =
current. SCENE_2D is prm/two_cylinders.prm, run here on the 2D mesh the
3D one extrudes (meshes/two_cylinders.msh, unrefined) with the same
materials, load and kinematics: an independent computation (the 2D
linearisation of the mortar operators, Mortar::linearise_pair(), against
the 3D one per slave face on curved faces).

- 3D against 2D, both current: p_max and the contact area (depth 1)
  against the contact length within 2e-5 relative, u_y at the upper
  half-disc's lowest point and top (on both node layers in z) within 1e-5
  relative (measured 4.5e-6, 1.6e-8, 3.0e-6). With small kinematics the
  two differ by 1.4e-5 and 9.0e-6 (the segmentation rule:
  two_cylinders_3d_q1_01; printed, not bounded);
- the bounds discriminate: small and current kinematics differ by at
  least 100 times them (p_max by 2.1 %, u_y by 0.5 %), in 3D and in 2D;
- the pair's normal force balances the load 16 and the support's reaction
  to 1e-9;
- 3D current: Newton quadratic once the active set has settled
  (r_k <= 10 r_(k-1)^2).

CONTACT_FEM_PERTURBATION_SEED, if set, renumbers the DoFs.
"""
import csv
import sys

from scene_run import check_quadratic, perturbation, run_scene

LOAD = 16.0  # the pressure 1.0 on the upper flat face, 16 x 1
P_TOLERANCE = 2e-5
U_TOLERANCE = 1e-5


def results(dim):
    """(p_max, contact area or length, u_y at the lowest point, u_y at the
    top) of results/, checking the force balance; in 3D the u_y of both
    node layers."""
    with open("results/pressure_profile.csv") as f:
        p_max = max(float(r["pressure"]) for r in csv.DictReader(f))
    with open("results/forces.csv") as f:
        row = list(csv.DictReader(f))[-1]
    size = float(row["pair_3_4_area" if dim == 3 else "pair_3_4_length"])
    forces = [float(row["pair_3_4_normal_y"]), float(row["boundary_2_y"])]
    balance = max(abs(force - LOAD) for force in forces) / LOAD
    probes = [float(row[f"probe_{i}_uy"]) for i in range(1, 5 if dim == 3 else 3)]
    if dim == 2:
        probes = [probes[0], probes[0], probes[1], probes[1]]
    return p_max, size, probes, balance


def run(contact_fem, scene, dim, kinematics):
    settings = [f"Contact/Kinematics={kinematics}", "Output/Write pressure profile=true",
                "Output/Print Newton iterations=true", *perturbation()]
    if dim == 2:
        settings += ["Output directory=results", "Geometry/Global refinements=0",
                     "Materials/Models=neo-hookean, neo-hookean",
                     "Boundary conditions/Pressure=1: 1.0*t",
                     "Newton/Displacement relative tolerance=1e-10",
                     "Output/Write VTU=false", "Output/Print timing=false",
                     "Output/Displacement probes=1 @ 0, 0; 1 @ 0, 8"]
    output = run_scene(contact_fem, scene, *settings)
    return output, results(dim)


def differences(a, b):
    """Relative differences of p_max, the contact size and the largest of u_y."""
    return (abs(a[0] - b[0]) / b[0], abs(a[1] - b[1]) / b[1],
            max(abs(x - y) / abs(y) for x, y in zip(a[2], b[2])))


def main():
    contact_fem, scene_3d, scene_2d = sys.argv[1:4]
    ok = True
    answers = {}
    for kinematics in ("current", "small"):
        output, answers[3, kinematics] = run(contact_fem, scene_3d, 3, kinematics)
        if kinematics == "current":
            ok = check_quadratic("3D current", output, 10.0) and ok
        _, answers[2, kinematics] = run(contact_fem, scene_2d, 2, kinematics)
    for key, (p_max, size, probes, balance) in sorted(answers.items()):
        good = balance < 1e-9
        print(f"{key[0]}D {key[1]}: p_max {p_max:.10g}, contact size {size:.10g}, u_y "
              f"{', '.join(f'{u:.10g}' for u in probes)}; pair force and reaction against the "
              f"load to 1e-9: {'ok' if good else 'FAILED'} ({balance:.1e})")
        ok = good and ok
    dp, ds, du = differences(answers[3, "current"], answers[2, "current"])
    good = dp < P_TOLERANCE and ds < P_TOLERANCE and du < U_TOLERANCE
    print(f"current: 3D against 2D: p_max {dp:.1e}, contact size {ds:.1e} "
          f"(bound {P_TOLERANCE:g}), u_y {du:.1e} (bound {U_TOLERANCE:g}): "
          f"{'ok' if good else 'FAILED'}")
    ok = good and ok
    dp, ds, du = differences(answers[3, "small"], answers[2, "small"])
    print(f"small (for scale, not bounded): 3D against 2D: p_max {dp:.1e}, "
          f"contact size {ds:.1e}, u_y {du:.1e}")
    for dim in (3, 2):
        dp, ds, du = differences(answers[dim, "current"], answers[dim, "small"])
        good = dp > 100 * P_TOLERANCE and ds > 100 * P_TOLERANCE and du > 100 * U_TOLERANCE
        print(f"{dim}D: current against small kinematics: p_max {dp:.2e}, contact size "
              f"{ds:.2e}, u_y {du:.2e}, at least 100 times the bounds: "
              f"{'ok' if good else 'FAILED'}")
        ok = good and ok
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
