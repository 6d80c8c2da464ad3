#!/usr/bin/env python3
"""The contact forces from the held slave nodes on 2 ranks (issue 32 item 1).

Usage: check_held_state.py CONTACT_FEM MPIEXEC,-np,2 SCENE.prm...

Runs each SCENE on 2 ranks (the launcher given comma-separated) with
CONTACT_FEM_CHECK_HELD_STATE set. In that mode every contact force
(FrictionlessFormulation::contact_forces(), with AlmFrictional's and
PenaltyFrictional's terms) is computed twice: from the rows each rank owns,
summed by the owners of the DoFs (ContactInterface::sum_forces()), and from
every slave node on each rank, and the program stops if the two differ in
one bit at any interface DoF. Reads summary.json's held_per_rank of the
last cycle and checks:

- the run finished (no difference at any interface DoF);
- each rank compared the forces at some DoFs;
- no difference was counted outside the relevant DoFs either (the owners'
  sums reach every rank: a rank needs no slave node coupled to its master
  DoFs);
- each rank holds the state of fewer slave nodes than all: rows owned +
  closed ghosts < slave nodes, on some rank; and the closed ghosts include
  the row ghosts (closed ghosts >= row ghosts);
- the split of the slave rows, ghosts, interface DoFs and zone states of
  held_per_rank.py (the test held_per_rank_01 once, on a run of its own of
  the first scene here).
"""
import json
import sys

import scene_run
from held_per_rank import per_rank_checks
from scene_run import run_scene


def main():
    contact_fem, launcher, scenes = sys.argv[1], sys.argv[2], sys.argv[3:]
    scene_run.ENVIRONMENT["CONTACT_FEM_CHECK_HELD_STATE"] = "1"
    ok, left_out = True, False  # left_out: a difference outside the relevant DoFs
    for scene in scenes:
        run_scene(contact_fem, scene, "Output directory=results", "Output/Write VTU=false",
                  launcher=launcher.split(","))
        with open("results/summary.json") as f:
            contact = json.load(f)["cycles"][-1]["contact"]
        held = contact["held_per_rank"]
        name = scene.split("/")[-1]
        for key in ("slave_nodes", "rows_owned", "row_ghosts", "closed_ghosts",
                    "check_dofs_compared", "check_dofs_left_out", "interface_dofs",
                    "interface_dofs_owned", "zone_nodes_received"):
            print(f"{name} {key}: {' / '.join(str(v) for v in held[key])}")
        owned, closed, ghosts = held["rows_owned"], held["closed_ghosts"], held["row_ghosts"]
        checks = [
            ("each rank compared the forces", all(n > 0 for n in held["check_dofs_compared"])),
            ("a rank holds fewer states than all",
             any(o + c < n for o, c, n in zip(owned, closed, held["slave_nodes"]))),
            ("closed ghosts >= row ghosts", all(c >= g for c, g in zip(closed, ghosts))),
        ] + per_rank_checks(contact)
        for text, good in checks:
            print(f"{name} {text}: {'ok' if good else 'FAILED'}")
            ok = ok and good
        left_out = left_out or any(n > 0 for n in held["check_dofs_left_out"])
    print(f"no difference outside the relevant DoFs: {'FAILED' if left_out else 'ok'}")
    sys.exit(0 if ok and not left_out else 1)


if __name__ == "__main__":
    main()
