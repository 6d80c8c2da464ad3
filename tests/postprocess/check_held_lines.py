#!/usr/bin/env python3
"""The constraint lines of the held slave nodes on 2 ranks (issue 32 item 1).

Usage: check_held_lines.py CONTACT_FEM MPIEXEC,-np,2 SCENE.prm...

Runs each SCENE on 2 ranks (the launcher given comma-separated) with
CONTACT_FEM_CHECK_HELD_STATE set. In that mode the candidate constraints
of every search and the trial (and test) constraints of every Newton
iteration are built twice: at the DoFs of the slave nodes a rank needs
(ContactInterface::line_dofs(): the DoFs it reads, i.e. its locally relevant
DoFs and the linearised and objective-slip patches of its rows, closed under
the masters of the contact and tied lines) and at every interface DoF, as
before; the program stops if a line at a DoF the rank reads differs in one
entry, coefficient or inhomogeneity bit (ContactInterface::check_held_lines()).
Reads summary.json's held_per_rank of the last cycle and checks:

- the run finished (no line differs at a DoF a rank reads);
- each rank compared the lines at some DoFs;
- the held lines are fewer, in one scene at least: some rank holds the
  lines of fewer slave nodes than all, and its constraints left out lines
  that the full ones store (the comparison is not vacuous);
- in one scene at least, some rank holds the lines of slave nodes with no
  locally relevant DoF (beyond its rows and row ghosts): the seeds beyond
  the relevant DoFs or the closure reached another slave node.
"""
import json
import sys

import scene_run
from scene_run import run_scene


def main():
    contact_fem, launcher, scenes = sys.argv[1], sys.argv[2], sys.argv[3:]
    scene_run.ENVIRONMENT["CONTACT_FEM_CHECK_HELD_STATE"] = "1"
    ok, fewer, left_out, beyond = True, False, False, False
    for scene in scenes:
        run_scene(contact_fem, scene, "Output directory=results", "Output/Write VTU=false",
                  launcher=launcher.split(","))
        with open("results/summary.json") as f:
            contact = json.load(f)["cycles"][-1]["contact"]
        held = contact["held_per_rank"]
        name = scene.split("/")[-1]
        for key in ("slave_nodes", "rows_owned", "row_ghosts", "line_nodes", "interface_dofs",
                    "line_dofs", "check_lines_compared", "check_lines_left_out"):
            print(f"{name} {key}: {' / '.join(str(v) for v in held[key])}")
        checks = [
            ("2 ranks", len(held["line_nodes"]) == 2),
            ("each rank compared the lines", all(n > 0 for n in held["check_lines_compared"])),
            ("line nodes <= slave nodes",
             all(h <= n for h, n in zip(held["line_nodes"], held["slave_nodes"]))),
        ]
        for text, good in checks:
            print(f"{name} {text}: {'ok' if good else 'FAILED'}")
            ok = ok and good
        fewer = fewer or any(h < n for h, n in zip(held["line_nodes"], held["slave_nodes"]))
        left_out = left_out or any(n > 0 for n in held["check_lines_left_out"])
        beyond = beyond or any(h > r + g for h, r, g in
                               zip(held["line_nodes"], held["rows_owned"], held["row_ghosts"]))
    print(f"a rank held the lines of fewer slave nodes than all: {'ok' if fewer else 'FAILED'}")
    print(f"the held constraints left lines out: {'ok' if left_out else 'FAILED'}")
    print("a rank held the lines of slave nodes beyond its rows and row ghosts: "
          f"{'ok' if beyond else 'FAILED'}")
    sys.exit(0 if ok and fewer and left_out and beyond else 1)


if __name__ == "__main__":
    main()
