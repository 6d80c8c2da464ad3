#!/usr/bin/env python3
"""3D large sliding on the current configuration: a slave node over many
master faces in one load step (issue 29).

Usage: check_current_kinematics_sliding_far_3d.py CONTACT_FEM SCENE.prm MESH.msh

SCENE is tests/scenes/current_kinematics_sliding_far_3d_01.prm: a
neo-Hookean block (E = 100, nu = 0, height 0.5, base 1 x 1 of 3 x 3 slave
faces) on a rigid flat strip (MESH, meshes/sliding_strip_3d.msh: 27 x 4
master faces of 0.1 x 0.45), frictionless; the pressure P = 10 t on its top
(a dead load), the top held in x and y, and slid by (1.2, 0.3) in load
step 2 (t in [1, 2]). With nu = 0 (lambda = 0) uniaxial compression has no
lateral strain, so the answer is homogeneous: the contact pressure P at
every slave node, the stretch s of the block's height from mu (1/s - s) =
P, the contact area 1, the slave base at its reference position plus the
slide. From the run's outputs (forces.csv with two displacement probes,
the contact-surface VTU of each step, 10 digits):

- both steps converge at their first attempt; Newton's displacement
  ratios fall quadratically once r_(k-1) <= 0.1 (r_k <= 10 r_(k-1)^2);
- the master faces a slave node passed over in step 2: the strip's top
  faces (read from MESH) that the segment from the node's position at the
  end of step 1 to that at the end of step 2 crosses (the node's path in
  the step: the block is translated); at least 5 for every slave node
  (the numbers are printed: 13 or 14). A slave face's masters at the end
  of the step are then disjoint from those at its start (the slide, 1.2,
  exceeds a slave face and a master face together), so the pairs changed
  within the step, between its start and its first iterate;
- at the end of each step every slave node active at the pressure P to
  1e-8 relative, at zero weighted gap and displaced by (slide, 0) (to
  1e-10 of the slave element size); a slave face paired with master faces
  that did not cover it would lose part of its D_j and raise p_j (the
  tiling), so the pairs at the end are the faces under the nodes;
- the block's top corner (a displacement probe) displaced by (slide, (s -
  1) 0.5) to 1e-9 h (forces.csv's 10 digits: 1.2e-11 h measured): s from
  the law, not from the run;
- the pair's force (master on slave) is (0, 0, P), with no tangential
  force and no reaction on the block's top, the strip's reaction (0, 0,
  P), the contact area 1, all to 1e-8 of P.

The same slide over a deformable strip (E = 100, nu = 0.3 for both bodies,
the strip's base clamped, the top pressed by 0.1 in step 1 and held): no
closed form, but frictionless hyperelasticity does not depend on the path,
so the slide in one step must end where the slide in 4 steps (0.3 along x,
3 master faces per step) ends: the pair's force, contact area and the
probes' displacements to 1e-8 of the normal force or of the element size;
both converge quadratically and the one-step slide crosses at least 5
master faces again.
"""
import csv
import math
import sys

from scene_run import check_quadratic, perturbation, run_scene
from vtu_files import read_surface

E, HEIGHT = 100.0, 0.5
MU_LAME = E / 2.0                          # nu = 0
LOAD = 10.0                                # the top's pressure per unit of t
SLIDE = (1.2, 0.3)                         # in load step 2 (t in [1, 2])
SLAVE_H = 1.0 / 3.0                        # the slave faces' side
DEFORMABLE = ("Materials/Poisson's ratios=0.3, 0.3", "Boundary conditions/Fixed=2: xyz",
              "Boundary conditions/Pressure=")


def master_faces(mesh):
    """The strip's top faces (physical surface 4) of the MSH 2.2 file mesh,
    each as its (x_min, x_max, y_min, y_max): axis-aligned rectangles in
    the plane z = 0.25."""
    with open(mesh) as f:
        lines = f.read().split("\n")
    start = lines.index("$Nodes")
    nodes = {}
    for line in lines[start + 2:start + 2 + int(lines[start + 1])]:
        k, x, y, _ = line.split()
        nodes[k] = (float(x), float(y))
    start = lines.index("$Elements")
    faces = []
    for line in lines[start + 2:start + 2 + int(lines[start + 1])]:
        fields = line.split()
        tags = int(fields[2])
        if fields[1] == "3" and fields[3] == "4":   # quadrilateral, physical 4
            corners = [nodes[k] for k in fields[3 + tags:]]
            faces.append((min(c[0] for c in corners), max(c[0] for c in corners),
                          min(c[1] for c in corners), max(c[1] for c in corners)))
    return faces


def crosses(a, b, box):
    """Whether the segment a-b (x, y) passes through the interior of box
    (Liang-Barsky clipping: a parameter interval of positive length)."""
    lo, hi = 0.0, 1.0
    for d in range(2):
        delta = b[d] - a[d]
        low, high = box[2 * d], box[2 * d + 1]
        if abs(delta) < 1e-14:
            if not low < a[d] < high:
                return False
            continue
        t0, t1 = sorted(((low - a[d]) / delta, (high - a[d]) / delta))
        lo, hi = max(lo, t0), min(hi, t1)
    return hi - lo > 1e-9


def faces_crossed(faces):
    """Per slave node, the master faces its segment from the end of step 1
    to the end of step 2 crosses (contact_surface_001.vtu, _002.vtu)."""
    before, after = (read_surface(f"contact_surface_{k:03d}.vtu")[0] for k in (1, 2))
    return [sum(crosses(a, b, box) for box in faces) for a, b in zip(before, after)]


def stretch(pressure):
    """s > 0 with mu (1/s - s) = pressure: uniaxial Cauchy stress of the
    neo-Hookean law at nu = 0."""
    c = pressure / MU_LAME
    return (-c + math.sqrt(c * c + 4.0)) / 2.0


def forces():
    with open("results/forces.csv") as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def report(name, good, detail=""):
    print(f"{name}: {'ok' if good else 'FAILED'}{f' ({detail})' if detail else ''}")
    return good


def converged_at_once(name, output, steps):
    return report(f"{name}: {steps} load steps, each converged at its first attempt",
                  output.count("  Load step ") == steps == output.count("| converged"),
                  f"{output.count('  Load step ')} attempts")


contact_fem, scene, mesh = sys.argv[1:4]
faces = master_faces(mesh)

# The rigid strip: closed-form answer.
output = run_scene(contact_fem, scene, "Output/Write VTU=true", *perturbation())
ok = check_quadratic("rigid strip, slid by (1.2, 0.3) in one step", output, 10.0)
ok = converged_at_once("rigid strip", output, 2) and ok
for step, row in enumerate(forces(), start=1):
    t = row["t"]
    pressure, s = LOAD * t, stretch(LOAD * t)
    slide = [SLIDE[0] * max(t - 1, 0.0), SLIDE[1] * max(t - 1, 0.0)]
    _, _, fields, wrong = read_surface(f"contact_surface_{step:03d}.vtu")
    active = [a[0] for a in fields["active"]]
    p_error = max(abs(p[0] - pressure) / pressure for p in fields["contact_pressure"])
    gap = max(abs(g[0]) for g in fields["weighted_gap"]) / SLAVE_H
    base = max(abs(u[d] - (slide + [0.0])[d]) for u in fields["displacement"] for d in range(3))
    ok = report(f"t = {t:g}: all {len(active)} slave nodes active at p = P = {pressure:g} to 1e-8, "
                f"weighted gaps 0 and displaced by ({slide[0]:g}, {slide[1]:g}, 0) to 1e-10 h",
                not wrong and len(active) == 16 and min(active) == 1 and p_error < 1e-8
                and gap < 1e-10 and base / SLAVE_H < 1e-10) and ok
    top = [row[f"probe_1_u{c}"] for c in "xyz"]
    exact = slide + [(s - 1.0) * HEIGHT]
    ok = report(f"t = {t:g}: the top corner displaced by ({exact[0]:g}, {exact[1]:g}, "
                f"{exact[2]:.8f}) (stretch {s:.8f} of the law) to 1e-9 h",
                max(abs(a - b) for a, b in zip(top, exact)) / SLAVE_H < 1e-9) and ok
    expected = {"pair_3_4_normal": (0.0, 0.0, pressure), "pair_3_4_tangential": (0.0, 0.0, 0.0),
                "boundary_1": (0.0, 0.0, 0.0), "boundary_4": (0.0, 0.0, pressure)}
    error = max(abs(row[f"{key}_{c}"] - value[d]) for key, value in expected.items()
                for d, c in enumerate("xyz")) / pressure
    ok = report(f"t = {t:g}: pair force (0, 0, P), tangential force 0, top reaction 0, "
                "strip reaction (0, 0, P), contact area 1, to 1e-8 of P",
                error < 1e-8 and abs(row["pair_3_4_area"] - 1.0) < 1e-8) and ok
crossed = faces_crossed(faces)
ok = report("rigid strip: master faces a slave node passed over in load step 2, at least 5",
            len(crossed) == 16 and min(crossed) >= 5,
            f"{min(crossed)} to {max(crossed)} of the {len(faces)} strip faces, "
            f"{len(crossed)} slave nodes") and ok

# The deformable strip: the slide in one step against the slide in 4.
runs = {}
for slides in (1, 4):
    rate = 1.0 / slides
    output = run_scene(
        contact_fem, scene, *DEFORMABLE, "Output/Write VTU=true",
        "Boundary conditions/Prescribed displacement="
        f"1: x = {SLIDE[0] * rate:g}*max(t - 1, 0); 1: y = {SLIDE[1] * rate:g}*max(t - 1, 0); "
        "1: z = -0.1*min(t, 1)",
        f"Load stepping/End time={1 + slides}", f"Load stepping/Number of load steps={1 + slides}",
        *perturbation())
    name = f"deformable strip, slid in {slides} step{'s' if slides > 1 else ''}"
    ok = check_quadratic(name, output, 10.0) and ok
    ok = converged_at_once(name, output, 1 + slides) and ok
    runs[slides] = forces()[-1]
    if slides == 1:
        crossed = faces_crossed(faces)
        ok = report("deformable strip: master faces a slave node passed over in the slide step, "
                    "at least 5", len(crossed) == 16 and min(crossed) >= 5,
                    f"{min(crossed)} to {max(crossed)}") and ok
one, four = runs[1], runs[4]
scale = one["pair_3_4_normal_z"]
force = max(abs(one[k] - four[k]) for k in one if k.startswith(("pair", "boundary"))) / scale
probes = max(abs(one[k] - four[k]) for k in one if k.startswith("probe")) / SLAVE_H
ok = report("deformable strip: the one-step slide ends where the 4-step slide does "
            "(forces and area to 1e-8 of F_n, probes to 1e-8 h)",
            force < 1e-8 and probes < 1e-8,
            f"F_n {scale:.6g}, largest differences {force:.0e} and {probes:.0e}") and ok
sys.exit(0 if ok else 1)
