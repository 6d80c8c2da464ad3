#!/usr/bin/env python3
"""Finite-strain bodies (Materials/Models) against the closed-form answers of
their laws.

Usage: check_finite_strain.py CONTACT_FEM SCENE_2D.prm MESH_3D.msh

SCENE_2D is tests/scenes/finite_strain_stretch_01.prm: two blocks of unit
width, each stretched by 25 % along y under displacement control, body 1
neo-Hookean (E = 100, nu = 0.3), body 2 Saint Venant-Kirchhoff (E = 200,
nu = 0.2). The deformation is homogeneous, so the finite-element answer is
exact up to Newton's tolerance and the reactions of the stretched tops
(boundary 1, body 1; boundary 4, body 2) must equal the first
Piola-Kirchhoff stress P_yy of the law times the reference width to 1e-8:
- plane-strain uniaxial stress (right sides free), Q1, Q1 with F-bar
  (Volumetric strain = B-bar: F-bar = F in a homogeneous deformation) and
  Q2: the lateral
  stretch a solves S_xx(a, 1.25) = 0;
- plane-strain uniaxial strain (right sides on rollers, a = 1), Q2;
- 3D (MESH_3D, the blocks of meshes/contact_blocks_3d.geo, 1 x 1 x 0.5),
  Q1, Q1 with F-bar and Q2: uniaxial stress along z, both lateral stretches a from
  S_xx = 0;
- the small-strain limit: a stretch of 1e-7 gives the reactions of the
  linear law (the same scene with Models = linear, linear) to 1e-5
  relative (the difference is of the order of the strain).
"""
import json
import math
import sys

from scene_run import run_scene


def lame(E, nu):
    return E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))


def second_piola(model, lam, mu, stretches):
    """Principal S of the law at F = diag(stretches) (3 of them; plane strain: z = 1)."""
    J = math.prod(stretches)
    if model == "neo-hookean":
        return [mu * (1 - 1 / s**2) + lam * math.log(J) / s**2 for s in stretches]
    E = [(s * s - 1) / 2 for s in stretches]
    return [lam * sum(E) + 2 * mu * e for e in E]


def axial_stress(model, E, nu, stretch, lateral_free, dim):
    """P along the stretch of F = diag(a, (a,) stretch), a from S_aa = 0 if lateral_free."""
    lam, mu = lame(E, nu)

    def stretches(a):
        return [a, stretch, 1.0] if dim == 2 else [a, a, stretch]

    a = 1.0
    if lateral_free:
        # Bisection on S_xx(a) = 0 (increasing in a), then to round-off.
        lo, hi = 0.5, 1.5
        for _ in range(200):
            a = 0.5 * (lo + hi)
            if second_piola(model, lam, mu, stretches(a))[0] > 0:
                hi = a
            else:
                lo = a
    axis = 1 if dim == 2 else 2
    return stretch * second_piola(model, lam, mu, stretches(a))[axis]


def reactions(directory):
    with open(f"{directory}/summary.json") as f:
        summary = json.load(f)
    step = summary["cycles"][-1]["load_steps"][-1]
    return {r["support"]: r["force"] for r in step["forces"]["reactions"]}


contact_fem, scene_2d, mesh_3d = sys.argv[1:4]
failures = []


def check(name, computed, expected, tolerance=1e-8, reference="closed form"):
    error = abs(computed - expected) / abs(expected)
    print(f"{name}: reaction {computed:.10g}, {reference} {expected:.10g}, "
          f"relative difference {'below' if error < tolerance else 'ABOVE'} {tolerance:g}")
    if not error < tolerance:
        failures.append(name)


bodies_2d = [("boundary 1", "neo-hookean", 100.0, 0.3), ("boundary 4", "saint-venant-kirchhoff", 200.0, 0.2)]
for degree, lateral, volumetric in [(1, "free", "standard"), (1, "free", "B-bar"),
                                    (2, "free", "standard"), (2, "rollers", "standard")]:
    directory = f"results_2d_q{degree}_{lateral}_{volumetric}"
    settings = [f"Output directory={directory}", f"Finite element/Degree={degree}",
                f"Finite element/Volumetric strain={volumetric}",
                "Output/Print Newton iterations=false"]
    if lateral == "rollers":
        settings.append("Boundary conditions/Fixed=3: y; 5: x; 2: y; 6: x; 0: x")
    run_scene(contact_fem, scene_2d, *settings)
    force = reactions(directory)
    for support, model, E, nu in bodies_2d:
        element = f"Q{degree}" + (" F-bar" if volumetric == "B-bar" else "")
        check(f"2D {element}, lateral {lateral}, {model}", force[support][1],
              axial_stress(model, E, nu, 1.25, lateral == "free", 2))

# 3D: lower block (body 1 of the mesh, z in [0, 0.5]) and upper block
# (body 2, z in [0.5, 1]), each stretched by 25 % of its height 0.5.
for degree, volumetric in [(1, "standard"), (1, "B-bar"), (2, "standard")]:
    directory = f"results_3d_q{degree}_{volumetric}"
    run_scene(contact_fem, scene_2d, f"Output directory={directory}", "Dimension=3",
              f"Finite element/Degree={degree}", f"Finite element/Volumetric strain={volumetric}",
              "Geometry/Type=mesh file",
              f"Geometry/Mesh file={mesh_3d}", "Boundary conditions/Fixed=2: z; 4: z; 5: x; 6: y",
              "Boundary conditions/Prescribed displacement=3: z = 0.125*t; 1: z = 0.125*t",
              "Output/Print Newton iterations=false")
    force = reactions(directory)
    for support, model, E, nu in [("boundary 3", "neo-hookean", 100.0, 0.3),
                                  ("boundary 1", "saint-venant-kirchhoff", 200.0, 0.2)]:
        element = f"Q{degree}" + (" F-bar" if volumetric == "B-bar" else "")
        check(f"3D {element}, lateral free, {model}", force[support][2],
              axial_stress(model, E, nu, 1.25, True, 3))

# Small-strain limit: hyperelastic and linear runs of a 1e-7 stretch.
small = []
for models in ["neo-hookean, saint-venant-kirchhoff", "linear, linear"]:
    directory = "results_small_" + models.split(",")[0]
    run_scene(contact_fem, scene_2d, f"Output directory={directory}", f"Materials/Models={models}",
              "Boundary conditions/Prescribed displacement=1: y = 1e-7*t; 4: y = 1e-7*t",
              "Output/Print Newton iterations=false")
    small.append(reactions(directory))
for support, model, E, nu in bodies_2d:
    check(f"strain 1e-7, {model}", small[0][support][1], small[1][support][1], 1e-5, "linear law")

if failures:
    sys.exit("failed: " + "; ".join(failures))
print("all reactions match")
