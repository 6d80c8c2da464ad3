"""Reruns are identical: the same scene run RUNS times (under the MPI
launcher, if given) must print the same output and write the same files,
bit for bit, but for the wall times (summary.json's wall_time, its timing
blocks and convergence.csv's wall-time columns) and the directory's lock
file (the process id).

On 2 ranks MUMPS' own parallel factorisation was not deterministic (its
asynchronous scheduling sums contributions in the order messages arrive):
the same system gave solutions that differed in the last bits, and a
Newton residual near round-off differed in its 4th digit between reruns
(doc/stability.md, "Reproducibility"); contact_fem now runs MUMPS on the
first rank only (source/solvers/rank_zero_mumps.cc). On the scene used here
(current_kinematics_penalty_friction_01, whose last Newton residuals sit at
the round-off floor) the former solver gave 6 different outputs in 32 runs,
and this check failed 5 times in 5 (3 runs each, 2026-11-28); with MUMPS
on one rank, 10 runs out of 10 were identical.

Usage: check_reruns_identical.py CONTACT_FEM LAUNCHER RUNS SCENE
(LAUNCHER: the command's words joined by commas, or '' for none)."""
import csv
import io
import json
import os
import shutil
import sys

from scene_run import run_scene

contact_fem, launcher, runs, scene = sys.argv[1:5]
launcher = tuple(word for word in launcher.split(",") if word)


def without_wall_times(name, text):
    """The file's text with the wall times taken out."""
    if name.endswith(".json"):

        def strip(value):
            if isinstance(value, dict):
                return {
                    key: strip(item)
                    for key, item in value.items()
                    if "wall_time" not in key and key != "timing"
                }
            if isinstance(value, list):
                return [strip(item) for item in value]
            return value

        return json.dumps(strip(json.loads(text)), indent=1)
    if name.endswith(".csv"):
        rows = list(csv.reader(io.StringIO(text)))
        if rows:
            timed = [k for k, column in enumerate(rows[0]) if "wall_time" in column]
            for row in rows[1:]:
                for k in timed:
                    if k < len(row):
                        row[k] = "-"
        out = io.StringIO()
        csv.writer(out, lineterminator="\n").writerows(rows)
        return out.getvalue()
    return text


def outputs(k):
    """Every output of run k: stdout and the files of its output directory."""
    directory = f"run_{k}"
    # A fresh directory: a rerun of the test would otherwise report the
    # removal of its earlier files, naming the directory, in log.txt.
    shutil.rmtree(directory, ignore_errors=True)
    result = {"stdout": run_scene(contact_fem, scene, f"Output directory={directory}",
                                  launcher=launcher)}
    for root, _, files in os.walk(directory):
        for name in sorted(files):
            if name.startswith("."):  # the output directory's lock (a process id)
                continue
            path = os.path.join(root, name)
            with open(path, encoding="utf-8") as file:
                result[os.path.relpath(path, directory)] = without_wall_times(name, file.read())
    return result


first = outputs(0)
failed = False
for k in range(1, int(runs)):
    other = outputs(k)
    if sorted(other) != sorted(first):
        print(f"run {k} wrote the files {sorted(other)}, run 0 {sorted(first)}")
        failed = True
        continue
    for name, text in first.items():
        if other[name] != text:
            lines = zip(text.splitlines(), other[name].splitlines())
            line, (a, b) = next(
                ((n, pair) for n, pair in enumerate(lines, 1) if pair[0] != pair[1]),
                (0, ("", "")))
            print(f"run {k} differs from run 0 in {name}, line {line}:\n  {a}\n  {b}")
            failed = True
print(f"{runs} runs of {os.path.basename(scene)} on {launcher[-1] if launcher else 1} "
      f"process(es): {'not identical' if failed else 'identical'} "
      f"({len(first)} outputs compared, wall times left out)")
sys.exit(1 if failed else 0)
