#!/usr/bin/env python3
"""Smoke test of bench/scaling (structure only, no times): one serial run
of a small scene must give a table with a column 'np 1', the whole-run
rows, a row for every timer section of the run's summary.json, the Newton
iterations of the run, a positive peak memory and the status.

Usage: check_scaling.py CONTACT_FEM SCALING_SCRIPT SCENE.prm
"""
import json
import pathlib
import subprocess
import sys

contact_fem, script, scene = sys.argv[1:4]
done = subprocess.run([sys.executable, script, scene, "--binary", contact_fem, "--np", "1",
                       "--results", "results", "--output", "table.md",
                       "--set", "Output/Write VTU=false"], capture_output=True, text=True)
failures = []
if done.returncode != 0:
    failures.append(f"bench/scaling exited with {done.returncode}:\n{done.stderr}")
else:
    rows = {}
    for line in pathlib.Path("table.md").read_text().splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if line.startswith("|") and len(cells) == 2:
            rows[cells[0]] = cells[1]
    summary = json.loads(pathlib.Path("results/np1-run0/summary.json").read_text())
    cycle = summary["cycles"][0]
    expected = ["", "Process wall [s]", "Program wall_time [s]", "Newton iterations",
                "Peak memory per rank [MB] (max / min)", "Status"]
    expected += [f"{name} [s]" for name in cycle["timing"]]
    failures += [f"no row '{name}'" for name in expected if name not in rows]
    if rows.get("") != "np 1":
        failures.append(f"header column '{rows.get('')}', expected 'np 1'")
    newton = sum(step["newton_iterations"] for step in cycle["load_steps"])
    if rows.get("Newton iterations") != str(newton):
        failures.append(f"Newton iterations '{rows.get('Newton iterations')}', expected {newton}")
    if float(rows.get("Peak memory per rank [MB] (max / min)", "0 / 0").split("/")[0]) <= 0.:
        failures.append("no positive peak memory")
    if rows.get("Status") != "converged":
        failures.append(f"status '{rows.get('Status')}'")
if failures:
    print("\n".join(failures))
    sys.exit(1)
print("bench/scaling: table with np 1, the whole-run rows, every timer section, Newton, "
      "memory, status")
