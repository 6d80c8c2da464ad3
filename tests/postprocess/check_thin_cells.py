#!/usr/bin/env python3
"""Cells far longer than thick: a singular stiffness is blamed on them, not
on a free rigid-body mode (outside-user audit, round 4, doc/metamorphic.md).

Usage: check_thin_cells.py CONTACT_FEM

The 2D patch with its upper block a strip 1 x H (5 x 1 cells) pressed by 2
onto a unit block (3 x 3 cells), held in x at its left side: the exact
pressure is 2 for any H. At H = 1e-9 (aspect ratio 2e8, stiffnesses 4e16
apart) the direct solve finds zero pivots; the warning used to blame "a
rigid-body mode that neither the supports nor the active contact hold".
Checks: H = 1e-9 warns naming the aspect ratio and not a rigid-body mode;
H = 1e-4 (aspect ratio 2e3) does not warn; both give p = 2 to 1e-5.
"""
import json
import subprocess
import sys

from scene_run import ENVIRONMENT

SCENE = """set Dimension = 2
subsection Geometry
  set Type      = mesh file
  set Mesh file = {mesh}
end
subsection Materials
  set Material ids     = 1, 2
  set Young's moduli   = 200, 100
  set Poisson's ratios = 0.2, 0.3
end
subsection Boundary conditions
  set Fixed    = 2: y; 5: x; 6: x
  set Pressure = 1: 2
end
subsection Contact
  set Pairs = 3: 4
end
subsection Output
  set Write VTU = false
  set Write pressure profile = false
  set Print timing = false
end
"""


def write_mesh(name, thickness):
    """Blocks in the ids of tests/metamorphic/blocks_2d.msh: 1 strip top,
    2 block bottom, 3 strip underside (slave), 4 block top, 5 and 6 the
    left sides of block and strip, 7 the right sides."""
    nodes, quads, lines = [], [], []

    def block(nx, ny, y0, height, material, ids):
        base = len(nodes)
        for j in range(ny + 1):
            for i in range(nx + 1):
                nodes.append((i / nx, y0 + height * j / ny))
        index = lambda i, j: base + j * (nx + 1) + i + 1
        for j in range(ny):
            for i in range(nx):
                quads.append((material, [index(i, j), index(i + 1, j), index(i + 1, j + 1),
                                         index(i, j + 1)]))
        bottom, top, left, right = ids
        for i in range(nx):
            lines.extend([(bottom, [index(i, 0), index(i + 1, 0)]),
                          (top, [index(i, ny), index(i + 1, ny)])])
        for j in range(ny):
            lines.extend([(left, [index(0, j), index(0, j + 1)]),
                          (right, [index(nx, j), index(nx, j + 1)])])

    block(3, 3, 0.0, 1.0, 2, (2, 4, 5, 7))
    block(5, 1, 1.0, thickness, 1, (3, 1, 6, 7))
    with open(name, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
        for k, (x, y) in enumerate(nodes):
            f.write(f"{k + 1} {x!r} {y!r} 0\n")
        f.write("$EndNodes\n$Elements\n%d\n" % (len(lines) + len(quads)))
        for k, (tag, v) in enumerate(lines + quads):
            kind = 1 if len(v) == 2 else 3
            f.write(f"{k + 1} {kind} 2 {tag} {tag} " + " ".join(map(str, v)) + "\n")
        f.write("$EndElements\n")


failures = 0
for name, thickness, warned in [("thin", 1e-9, True), ("moderate", 1e-4, False)]:
    write_mesh(name + ".msh", thickness)
    with open(name + ".prm", "w") as f:
        f.write(SCENE.format(mesh=name + ".msh"))
    result = subprocess.run([sys.argv[1], name + ".prm", "--output-directory", "results-" + name],
                            env=ENVIRONMENT, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"{name}: exit {result.returncode}:\n{result.stdout}{result.stderr}")
    with open(f"results-{name}/summary.json") as f:
        cycle = json.load(f)["cycles"][-1]
    warning = cycle.get("singular_stiffness_warning", "")
    pressures = [cycle["contact"]["max_contact_pressure"],
                 cycle["contact"]["min_active_contact_pressure"]]
    ok = (bool(warning) == warned and ("aspect ratio" in warning) == warned
          and "rigid-body mode" not in warning
          and all(abs(p - 2) <= 1e-5 * 2 for p in pressures))
    failures += not ok
    print(f"{name} (H = {thickness:g}): {'warning naming the aspect ratio' if 'aspect ratio' in warning else 'warning: ' + warning if warning else 'no warning'}, "
          f"pressures 2 to 1e-5: {all(abs(p - 2) <= 1e-5 * 2 for p in pressures)} "
          f"({'expected' if ok else 'WRONG'})")
sys.exit(1 if failures else 0)
