#!/usr/bin/env python3
"""Coulomb friction on curved 3D faces on the current configuration, against 2D.

Usage: check_current_friction_cylinders_3d.py CONTACT_FEM SCENE_3D.prm SCENE_2D.prm

SCENE_3D is tests/scenes/current_kinematics_cylinders_3d_01.prm (the
extruded half-cylinders, plane strain, Q1 on the quadratic mapping: 9-node
curved contact faces, neo-Hookean, Contact/Kinematics = current), SCENE_2D
prm/two_cylinders.prm on the 2D mesh it extrudes, both run here with `alm
frictional`, `coulomb 0.3` and the upper half-disc's flat top driven
instead of the pressure (so it cannot roll): pressed by 0.25 (t = 1; the
contact force about 14.9), then pulled along x by 0.2 (t = 2: every active
node slips). The 2D run is an independent computation (2D's linearisation
of the operators and of the slip, against 3D's per slave face).

- every step of both converges; 3D's Newton quadratic once the sets are
  fixed (r_k <= 10 r_(k-1)^2);
- the stick and slip counts of every step's converged iterate: 3D's are
  twice 2D's (two node layers), and at t = 2 every active node slips;
- the pair's normal and tangential forces, x and y, of every step: 3D
  against 2D within 1e-5 of the normal force (the segmentation rule leaves
  3.6e-6 at the press: current_kinematics_cylinders_3d_01), the z
  components zero to 1e-9 of it, and the pulled step's tangential force
  at least 0.25 of the normal one (so the comparison sees the friction).

CONTACT_FEM_PERTURBATION_SEED, if set, renumbers the DoFs.
"""
import csv
import sys

from scene_run import check_quadratic, converged_sets, newton_table, perturbation, run_scene

PRESS = "0.25*min(t,1)"
PULL = "0.2*max(t-1,0)"


def run(contact_fem, scene, dim):
    driven = f"1: x = {PULL}; 1: y = -{PRESS}" + ("; 1: z = 0" if dim == 3 else "")
    settings = ["Contact/Formulation=alm frictional", "Contact/Friction=coulomb 0.3",
                "Boundary conditions/Pressure=", "Boundary conditions/Fixed points=",
                f"Boundary conditions/Prescribed displacement={driven}",
                "Load stepping/End time=2", "Load stepping/Number of load steps=2",
                "Output/Displacement probes=", "Output/Print Newton iterations=true", *perturbation()]
    if dim == 2:
        settings += ["Output directory=results", "Geometry/Global refinements=0",
                     "Materials/Models=neo-hookean, neo-hookean", "Contact/Kinematics=current",
                     "Newton/Displacement relative tolerance=1e-10",
                     "Output/Write VTU=false", "Output/Print timing=false"]
    output = run_scene(contact_fem, scene, *settings)
    with open("results/forces.csv") as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    return output, rows


def main():
    contact_fem, scene_3d, scene_2d = sys.argv[1:4]
    output_3d, rows_3d = run(contact_fem, scene_3d, 3)
    output_2d, rows_2d = run(contact_fem, scene_2d, 2)
    ok = check_quadratic("3D Coulomb", output_3d, 10.0)
    converged = all(len(newton_table(o)) == 2 and all(c for _, c in newton_table(o))
                    for o in (output_3d, output_2d))
    print(f"every step converged at the first attempt, 3D and 2D: {'ok' if converged else 'FAILED'}")
    ok = converged and ok

    sets_3d, sets_2d = converged_sets(output_3d), converged_sets(output_2d)
    good = (len(sets_3d) == len(sets_2d) == 2 and
            all(a == tuple(2 * v for v in b) for a, b in zip(sets_3d, sets_2d)) and
            sets_3d[-1][1] == 0 and sets_3d[-1][2] == sets_3d[-1][0] > 0)
    print(f"(active, stick, slip) 3D {sets_3d} twice 2D's {sets_2d}, all slipping at t = 2: "
          f"{'ok' if good else 'FAILED'}")
    ok = good and ok

    for r3, r2 in zip(rows_3d, rows_2d):
        normal = abs(r2["pair_3_4_normal_y"])
        keys = [f"pair_3_4_{kind}_{c}" for kind in ("normal", "tangential") for c in "xy"]
        worst = max(abs(r3[k] - r2[k]) for k in keys) / normal
        out_of_plane = max(abs(r3[f"pair_3_4_{kind}_z"]) for kind in ("normal", "tangential"))
        good = worst < 1e-5 and out_of_plane < 1e-9 * normal
        print(f"t = {r3['t']:g}: 3D normal ({r3['pair_3_4_normal_x']:.9g}, "
              f"{r3['pair_3_4_normal_y']:.9g}), tangential ({r3['pair_3_4_tangential_x']:.9g}, "
              f"{r3['pair_3_4_tangential_y']:.9g}); against 2D {worst:.1e} of the normal force "
              f"(bound 1e-5), z parts {out_of_plane:.1e}: {'ok' if good else 'FAILED'}")
        ok = good and ok
    last = rows_3d[-1]
    ratio = abs(last["pair_3_4_tangential_x"]) / abs(last["pair_3_4_normal_y"])
    good = len(rows_3d) == len(rows_2d) == 2 and ratio > 0.25
    print(f"t = 2: |F_t| / F_n = {ratio:.5f} (> 0.25): {'ok' if good else 'FAILED'}")
    ok = good and ok
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
