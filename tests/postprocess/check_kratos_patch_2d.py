#!/usr/bin/env python3
"""Kratos' 2D frictionless patch test (tests/scenes/kratos_patch_01) against
Kratos' stored displacements to 1e-6 relative, by the 10 digits of
summary.json's displacement probes (the scene's expected output holds 8
digits, compared by numdiff to 1e-6 absolute: 8e-4 of u_x).

Usage: check_kratos_patch_2d.py CONTACT_FEM SCENE.prm RESULTS.json MESH.msh

RESULTS.json is Kratos' hyper_simple_patch_test_results.json, a verbatim
copy in meshes/kratos/ALM_frictionless_2D_hyper_simple_patch_test/ of
the file in Kratos' repository (applications/
ContactStructuralMechanicsApplication/tests/ALM_frictionless_contact_test_2D/,
commit 1c01e3a7; the origin in meshes/kratos/README.md).
MESH.msh is the scene's mesh, converted from Kratos' .mdpa with Kratos'
node ids: each probe is matched to the Kratos node at its point. Every
component of u at the four interface nodes must equal Kratos' to 1e-6
relative (both codes solve the same discrete problem: flat interface,
matching nodes, exact mortar operators; measured 3e-10, the digits
summary.json holds).
"""
import json
import sys

from scene_run import perturbation, run_scene

TOLERANCE = 1e-6


def mesh_nodes(name):
    """{Kratos node id: (x, y)} of the Gmsh 2.2 file."""
    with open(name) as f:
        lines = f.read().split("$Nodes")[1].split("$EndNodes")[0].split("\n")
    nodes = {}
    for line in lines[2:]:
        if line.strip():
            i, x, y, _ = line.split()
            nodes[int(i)] = (float(x), float(y))
    return nodes


def main():
    contact_fem, scene, results, mesh = sys.argv[1:5]
    with open(results) as f:
        kratos = json.load(f)
    nodes = mesh_nodes(mesh)
    run_scene(contact_fem, scene, *perturbation())
    with open("results/summary.json") as f:
        probes = json.load(f)["cycles"][-1]["displacement_probes"]
    ok, checked = True, set()
    for probe in probes:
        point = tuple(float(c) for c in probe["point"].split("@")[1].split(","))
        matches = [i for i, p in nodes.items()
                   if max(abs(a - b) for a, b in zip(p, point)) < 1e-9 and f"NODE_{i}" in kratos]
        if len(matches) != 1:
            print(f"probe {probe['point']}: {len(matches)} Kratos nodes with results there: FAILED")
            ok = False
            continue
        node = matches[0]
        checked.add(node)
        for component, computed in zip("XY", probe["displacement"]):
            expected = kratos[f"NODE_{node}"][f"DISPLACEMENT_{component}"][-1]
            error = abs(computed - expected) / abs(expected)
            good = error <= TOLERANCE
            ok = ok and good
            print(f"node {node} {point} u_{component.lower()}: {computed:.10e} against Kratos' "
                  f"{expected:.10e}: relative {error:.1e} (tolerance {TOLERANCE:g}) "
                  f"{'ok' if good else 'FAILED'}")
    expected_nodes = {int(k[5:]) for k in kratos if k.startswith("NODE_")}
    if checked != expected_nodes:
        print(f"nodes checked {sorted(checked)}, Kratos' {sorted(expected_nodes)}: FAILED")
        ok = False
    print("all checks passed" if ok else "FAILED")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
