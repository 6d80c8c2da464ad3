#!/usr/bin/env python3
"""Metamorphic tests: one scene, transformed, must give the same physics.

A scene template (name.prm.in) describes the scene in its own frame; the
placeholders below put it into the frame of a variant. Each variant is run,
and the invariant results of its summary.json are compared with those of the
untransformed scene, scaled by the known factors (pressure with the moduli,
forces with moduli x length^(dim-1), energies with moduli x length^dim).

Placeholders (p denotes a point of the scene's own frame):
  @MESH(file)@      the mesh file, transformed and written beside the run
  @P(x, y[, z])@    a point p, transformed
  @L(v)@            a length v, scaled
  @E(v)@            a modulus or stress v, scaled
  @STRESS(expr)@    a stress expression, scaled
  @x@ @y@ @z@       the scene-frame coordinates as expressions of x, y, z
  @VEC(a, b[, c])@  a traction vector (expressions), rotated and scaled
  @AXES(xyz)@       support components, mapped by the rotation (quarter turns)
  @DX(a, b[, c])@ @DY(...)@ @DZ(...)@  a component of a displacement, rotated
                    and scaled
  @MAT(id)@         a material id, after the swap of the ids 1 and 2

Further parameters: --set PATH/KEY=VALUE (repeatable; placeholders allowed),
e.g. --set "Contact/Formulation=penalty frictionless"; --penalty-tolerance:
the relative tolerance of the automatic penalty (summary.json
contact.penalty, a function of the geometry only), if not --tolerance.

Variants: name=kind:value, kinds translate (a vector in units of the model
size), rotate (quarter turns about z), rotate_degrees (angle[,ax,ay,az]:
any angle about z or the axis (ax, ay, az); templates without @AXES@, @x@,
@VEC@, e.g. supported by rollers), scale_length,
scale_moduli, scale_load (the loads @STRESS@ and @VEC@ only, at fixed
moduli: a positively homogeneous problem scales its stresses and forces by
the factor and its energy by its square), swap, renumber (the mesh file's
node tags permuted, nodes and elements shuffled, every element turned
inside out). Rules joined by '&' combine, e.g.
far_turned=rotate_degrees:37,0.3,-1,0.4&translate:1e3,-2e3,5e2.
"""
import argparse
import json
import math
import os
import random
import re
import subprocess
import sys


class Variant:
    def __init__(self, spec, dim, size):
        self.name, _, rules = spec.partition("=")
        self.dim = dim
        self.shift = [0.0] * 3
        self.turns = 0
        self.degrees = None
        self.length = 1.0
        self.moduli = 1.0
        self.load = 1.0
        self.swap = False
        self.renumber = False
        # Rules joined by '&' combine (e.g. a turn and a translation): the
        # point is rotated, scaled, then shifted, whatever their order here.
        for rule in rules.split("&"):
            self.add_rule(rule, spec, size)

    def add_rule(self, rule, spec, size):
        kind, _, value = rule.partition(":")
        if kind == "translate":
            parts = [float(v) * size for v in value.split(",")]
            self.shift[: len(parts)] = parts
        elif kind == "rotate":
            self.turns = int(value) % 4
        elif kind == "rotate_degrees":
            angle, *axis = [float(t) for t in value.split(",")]
            self.degrees = angle
            self.axis = axis or [0.0, 0.0, 1.0]
        elif kind == "scale_length":
            self.length = float(value)
        elif kind == "scale_moduli":
            self.moduli = float(value)
        elif kind == "scale_load":
            self.load = float(value)
        elif kind == "swap":
            self.swap = True
        elif kind == "renumber":
            self.renumber = True
        elif kind != "identity":
            sys.exit(f"metamorphic.py: unknown variant kind '{kind}' in '{spec}'")

    def cos_sin(self):
        if self.degrees is not None:
            angle = math.radians(self.degrees)
            return (math.cos(angle), math.sin(angle))
        return [(1, 0), (0, 1), (-1, 0), (0, -1)][self.turns]

    def matrix(self):
        # Rotation by the angle about the axis (z unless given), Rodrigues.
        c, s = self.cos_sin()
        a = getattr(self, "axis", [0.0, 0.0, 1.0])
        n = math.sqrt(sum(t * t for t in a))
        x, y, z = (t / n for t in a)
        return [[c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s],
                [y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s],
                [z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)]]

    def rotate(self, p):
        p = list(p) + [0.0] * (3 - len(p))
        return [sum(r[j] * p[j] for j in range(3)) for r in self.matrix()]

    def point(self, p):
        q = self.rotate(p)
        return [self.length * q[i] + self.shift[i] for i in range(self.dim)]

    def local(self, axis):
        # Scene-frame coordinate as an expression of the variant's x, y, z.
        if self.degrees is not None and list(getattr(self, "axis", [0, 0, 1]))[:2] != [0, 0]:
            sys.exit("metamorphic.py: @x@ @y@ @z@ take turns about z only")
        c, s = self.cos_sin()
        X = f"(x - ({self.shift[0]!r}))"
        Y = f"(y - ({self.shift[1]!r}))"
        Z = f"(z - ({self.shift[2]!r}))"
        expr = {"x": f"({c}*{X} + {s}*{Y})", "y": f"({-s}*{X} + {c}*{Y})", "z": Z}[axis]
        return f"({expr}/{self.length!r})"

    def material(self, m):
        return {1: 2, 2: 1}.get(m, m) if self.swap else m


def fmt(v):
    return repr(float(v))


def split_top_level(text):
    """Splits at the commas that are not inside parentheses."""
    parts, depth, current = [], 0, ""
    for ch in text:
        if ch == "," and depth == 0:
            parts.append(current.strip())
            current = ""
            continue
        depth += {"(": 1, ")": -1}.get(ch, 0)
        current += ch
    return parts + [current.strip()]


def transform_mesh(source, target, v):
    with open(source) as f:
        lines = f.read().splitlines()
    out, section, count = [], None, 0
    for line in lines:
        if line.startswith("$"):
            section = line if not line.startswith("$End") else None
            count = -1
            out.append(line)
            continue
        if section == "$MeshFormat":
            if not line.startswith("2.2 0"):
                sys.exit(f"metamorphic.py: {source}: only ASCII MSH 2.2 is transformed")
        elif section == "$Nodes" and count >= 0:
            fields = line.split()
            x = [float(t) for t in fields[1:4]]
            y = v.point(x[: v.dim]) + x[v.dim:]
            line = " ".join([fields[0]] + [fmt(t) for t in y])
        elif section == "$Elements" and count >= 0:
            fields = line.split()
            # cells: triangles, quadrilaterals; tetrahedra, hexahedra, prisms
            top = {2: {2, 3}, 3: {4, 5, 6}}[v.dim]
            if int(fields[1]) in top:
                fields[3] = str(v.material(int(fields[3])))
            line = " ".join(fields)
        count += 1
        out.append(line)
    if v.renumber:
        out = renumbered(out)
    with open(target, "w") as f:
        f.write("\n".join(out) + "\n")


# Gmsh element type -> its node order turned inside out (lines, triangles,
# quadrilaterals, tetrahedra, hexahedra, prisms; points stay).
REVERSED = {1: [1, 0], 2: [0, 2, 1], 3: [0, 3, 2, 1], 4: [0, 2, 1, 3],
            5: [0, 3, 2, 1, 4, 7, 6, 5], 6: [0, 2, 1, 3, 5, 4], 15: [0]}


def renumbered(lines):
    """The MSH 2.2 lines with the node tags permuted into a sparse range,
    the nodes and the elements listed in a shuffled order (so the second
    body may come first) and every element's nodes in the opposite turn:
    what another mesher, or Gmsh's renumbering, could write for the same
    mesh. Seeded: the same file every run."""
    rng = random.Random(20261128)
    start = lines.index("$Nodes")
    n_nodes = int(lines[start + 1])
    nodes = [l.split() for l in lines[start + 2: start + 2 + n_nodes]]
    tags = rng.sample(range(1, 10 * n_nodes + 1), n_nodes)
    new_tag = {node[0]: str(t) for node, t in zip(nodes, tags)}
    nodes = [[new_tag[node[0]]] + node[1:] for node in nodes]
    rng.shuffle(nodes)
    lines[start + 2: start + 2 + n_nodes] = [" ".join(node) for node in nodes]
    start = lines.index("$Elements")
    n_elements = int(lines[start + 1])
    elements = []
    for line in lines[start + 2: start + 2 + n_elements]:
        fields = line.split()
        kind, n_tags = int(fields[1]), int(fields[2])
        head, vertices = fields[1: 3 + n_tags], [new_tag[t] for t in fields[3 + n_tags:]]
        elements.append(head + [vertices[i] for i in REVERSED[kind]])
    rng.shuffle(elements)
    lines[start + 2: start + 2 + n_elements] = [
        " ".join([str(k + 1)] + e) for k, e in enumerate(elements)]
    return lines


def expand(text, v, template_dir, work_dir):
    c, s = v.cos_sin()

    def numbers(args):
        return [float(a) for a in args.split(",")]

    def mesh(m):
        source = os.path.join(template_dir, m.group(1).strip())
        target = os.path.join(work_dir, v.name + "_" + os.path.basename(source))
        transform_mesh(source, target, v)
        return target

    def vec(m):
        parts = split_top_level(m.group(1))
        k = v.moduli * v.load
        if len(parts) == 3:
            # 3D: the full rotation (any axis).
            R = v.matrix()
            return ", ".join(f"{k!r}*(" + " + ".join(
                f"({R[i][j]!r})*({parts[j]})" for j in range(3)) + ")" for i in range(3))
        a, b = parts[0], parts[1]
        rotated = [f"{k!r}*({c}*({a}) - ({s})*({b}))", f"{k!r}*({s}*({a}) + {c}*({b}))"]
        return ", ".join(rotated)

    def axes(m):
        if v.degrees is not None:
            sys.exit("metamorphic.py: @AXES@ maps supports by quarter turns only")
        mapping = {"x": "x", "y": "y", "z": "z"}
        if v.turns % 2 == 1:
            mapping = {"x": "y", "y": "x", "z": "z"}
        return "".join(sorted(mapping[a] for a in m.group(1).strip()))

    rules = [
        (r"@MESH\(([^)]*)\)@", mesh),
        (r"@P\(([^)]*)\)@", lambda m: ", ".join(fmt(t) for t in v.point(numbers(m.group(1))))),
        (r"@L\(([^)]*)\)@", lambda m: fmt(v.length * float(m.group(1)))),
        (r"@E\(([^)]*)\)@", lambda m: fmt(v.moduli * float(m.group(1)))),
        (r"@STRESS\((.*?)\)@", lambda m: f"{v.moduli * v.load!r}*({m.group(1)})"),
        (r"@VEC\((.*?)\)@", vec),
        (r"@AXES\(([^)]*)\)@", axes),
        (r"@D([XYZ])\(([^)]*)\)@",
         lambda m: fmt(v.length * v.rotate(numbers(m.group(2)))["XYZ".index(m.group(1))])),
        (r"@MAT\(([^)]*)\)@", lambda m: str(v.material(int(m.group(1))))),
        (r"@([xyz])@", lambda m: v.local(m.group(1))),
    ]
    for pattern, replace in rules:
        text = re.sub(pattern, replace, text)
    return text


def run(exe, prm_text, name, work_dir, mpi, override_text=""):
    # The --set values go into a file of their own that includes the
    # scene: contact_fem refuses a key set twice in one file.
    scene = os.path.join(work_dir, name + "_scene.prm")
    prm = os.path.join(work_dir, name + ".prm")
    out_dir = os.path.join(work_dir, "results-" + name)
    with open(scene, "w") as f:
        f.write(prm_text + "\n")
    with open(prm, "w") as f:
        f.write(f"include {scene}\n" + override_text + f"\nset Output directory = {out_dir}\n")
    command = ([mpi, "-np", "2"] if mpi else []) + [exe, prm]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        print(f"  {name}: exit code {result.returncode}: " + " ".join(
            (result.stdout + result.stderr).strip().splitlines()[-1:])[:600])
        return None
    with open(os.path.join(out_dir, "summary.json")) as f:
        return json.load(f)


def invariants(summary, v, dim):
    """(name, value, unit factor) of the results that the transformation
    must leave unchanged once divided by their unit factor."""
    stress = v.moduli * v.load
    force, energy = stress * v.length ** (dim - 1), stress * v.load * v.length ** dim
    cycle = summary["cycles"][-1]
    contact = cycle.get("contact", {})
    result = [("status", summary["status"], None), ("n_dofs", cycle["n_dofs"], None)]
    result += [(f"newton_iterations[{k}]", step["newton_iterations"], None)
               for k, step in enumerate(cycle["load_steps"])]
    for key, unit in [("slave_nodes", None), ("active_slave_nodes", None),
                      ("max_contact_pressure", stress), ("min_active_contact_pressure", stress),
                      ("total_contact_force", force), ("stick_nodes", None), ("slip_nodes", None),
                      ("total_tangential_contact_force", force)]:
        if key in contact:
            result.append(("contact/" + key, contact[key], unit))
    # The automatic penalty (E/h of the pair's statistics) is a modulus per
    # length; 0 where the formulation has none.
    if "penalty" in contact:
        result.append(("contact/penalty", contact["penalty"], v.moduli / v.length))
    for key in ["applied_load", "support_reaction"]:
        if key in cycle.get("reaction", {}):
            result.append(("reaction/" + key, cycle["reaction"][key], force))
    result.append(("strain_energy", cycle["strain_energy"], energy))
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--executable", required=True)
    parser.add_argument("--template", required=True)
    parser.add_argument("--size", type=float, default=1.0, help="model size (for translations)")
    parser.add_argument("--tolerance", type=float, default=1e-7, help="relative tolerance")
    parser.add_argument("--penalty-tolerance", type=float, default=None,
                        help="relative tolerance of contact/penalty (default: --tolerance)")
    parser.add_argument("--any-newton-count", action="store_true",
                        help="leave the Newton iteration counts out (a variant whose residuals "
                             "meet a floor of round-off, not the scaled tolerance)")
    parser.add_argument("--mpirun", default="", help="run the variants on 2 ranks with this mpirun")
    parser.add_argument("--set", action="append", default=[], metavar="PATH/KEY=VALUE",
                        help="a parameter added to the template (placeholders allowed)")
    parser.add_argument("variants", nargs="+")
    args = parser.parse_args()

    with open(args.template) as f:
        template = f.read()
    overrides = "".join(parameter_text(entry) for entry in args.set)
    dim = int(re.search(r"set\s+Dimension\s*=\s*(\d)", template).group(1)) \
        if re.search(r"set\s+Dimension\s*=\s*(\d)", template) else 2
    template_dir = os.path.dirname(os.path.abspath(args.template))
    work_dir = os.getcwd()
    base = Variant("identity=identity:", dim, args.size)
    summary = run(args.executable, expand(template, base, template_dir, work_dir), "identity",
                  work_dir, args.mpirun, expand(overrides, base, template_dir, work_dir))
    if summary is None:
        sys.exit("metamorphic.py: the untransformed scene failed")
    reference = invariants(summary, base, dim)
    print(f"{os.path.basename(args.template)}: reference")
    for name, value, _ in reference:
        print(f"  {name} = {value}")
    failures = 0
    for spec in args.variants:
        v = Variant(spec, dim, args.size)
        summary = run(args.executable, expand(template, v, template_dir, work_dir), v.name,
                      work_dir, args.mpirun, expand(overrides, v, template_dir, work_dir))
        if summary is None:
            failures += 1
            print(f"{v.name}: FAILED")
            continue
        results = invariants(summary, v, dim)
        different, worst = 0, 0.0
        for (name, ref, _), (_, value, unit) in zip(reference, results):
            if args.any_newton_count and name.startswith("newton_iterations"):
                continue
            if unit is None:
                ok = value == ref
            else:
                change = abs(value / unit - ref)
                # Relative to what the verdict compares with: a force at
                # round-off (the net reaction of a displacement-driven
                # scene) is measured against the scene's largest force.
                scale = max(abs(ref), abs_scale(reference, name))
                worst = max(worst, change / max(scale, 1e-300))
                tolerance = args.tolerance
                if name == "contact/penalty" and args.penalty_tolerance is not None:
                    tolerance = args.penalty_tolerance
                ok = change <= tolerance * scale
            if not ok:
                different += 1
                shown = value if unit is None else value / unit
                print(f"  {v.name}: {name} = {shown} (in the scene's units), reference {ref}")
        failures += different
        print(f"{v.name}: {'same' if different == 0 else 'DIFFERENT'} "
              f"(largest relative change {worst:.1e})")
    print(f"{len(args.variants)} variants, {failures} differences")
    sys.exit(1 if failures else 0)


def parameter_text(entry):
    """'Contact/Formulation=penalty frictionless' as the lines of a .prm."""
    path, _, value = entry.partition("=")
    *sections, key = path.split("/")
    return ("".join(f"subsection {name}\n" for name in sections) + f"set {key} = {value}\n"
            + "end\n" * len(sections))


def abs_scale(reference, name):
    # Forces near zero are compared with the largest force of the scene.
    forces = [abs(v) for n, v, _ in reference if n.startswith("reaction/") or n.endswith("_force")]
    pressures = [abs(v) for n, v, _ in reference if n.endswith("pressure")]
    if name.endswith("pressure"):
        return max(pressures, default=0.0)
    if name.startswith("reaction/") or name.endswith("_force"):
        return max(forces, default=0.0)
    return 0.0


if __name__ == "__main__":
    main()
