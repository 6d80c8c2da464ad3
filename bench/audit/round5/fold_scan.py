#!/usr/bin/env python3
"""Reads every Gmsh mesh given with contact_fem --validate through a minimal
scene and prints those refused as folded (the check of round 5 must pass
every valid mesh). usage: fold_scan.py EXE MESH..."""
import re, subprocess, sys, tempfile, os
exe = sys.argv[1]
for mesh in sys.argv[2:]:
    text = open(mesh, errors="replace").read()
    if "$MeshFormat" not in text:
        continue
    dim = 3 if re.search(r"\$Elements", text) and any(
        t in text for t in ["Physical Volume"]) else None
    # element types: 2D cells 2, 3; 3D cells 4, 5, 6
    version = text.split("$MeshFormat")[1].split()[0]
    ids, types = set(), set()
    if version.startswith("2"):
        body = text.split("$Elements")[1].split("$EndElements")[0].split("\n")[2:]
        for line in body:
            t = line.split()
            if len(t) > 4 and t[1].isdigit() and t[3].isdigit():
                types.add(int(t[1])); ids.add((int(t[1]), int(t[3])))
    else:
        continue
    dim = 3 if types & {4, 5, 6, 7} else 2
    cell_types = {4, 5, 6, 7} if dim == 3 else {2, 3}
    mats = sorted({p for t, p in ids if t in cell_types})
    prm = (f"set Dimension = {dim}\nsubsection Geometry\n set Type = mesh file\n"
           f" set Mesh file = {os.path.abspath(mesh)}\nend\nsubsection Materials\n"
           f" set Material ids = {', '.join(map(str, mats))}\n"
           f" set Young's moduli = {', '.join(['1'] * len(mats))}\n"
           f" set Poisson's ratios = {', '.join(['0.3'] * len(mats))}\nend\n"
           "subsection Contact\n set Pairs =\nend\n")
    with tempfile.NamedTemporaryFile("w", suffix=".prm", delete=False) as f:
        f.write(prm)
    out = subprocess.run([exe, f.name, "--validate"], capture_output=True, text=True)
    os.unlink(f.name)
    msg = (out.stdout + out.stderr).strip().splitlines()
    err = [l for l in msg if "error" in l]
    print(f"{mesh}: {'FOLDED' if any('folds' in l for l in err) else 'ok'}"
          f" ({err[0][:120] if err else 'no error'})")
