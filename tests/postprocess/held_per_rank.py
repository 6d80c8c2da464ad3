"""What each rank holds of the contact interface on 2 ranks (issue 32 item 1):
the checks on summary.json's "held_per_rank" of a run's last cycle (the
per-rank size of the contact data), run by check_held_state.py on each of its
2-rank runs (formerly a test of their own, held_per_rank_01, which ran the
3D frictional Hertz scene a second time). Checks:

- the slave rows (the nodes whose multiplier, active flag and friction state
  a rank decides) are split: each rank owns a part, the parts add up to the
  slave nodes of the summary, and each rank owns fewer than all of them;
- a rank's ghosts (row states imported point to point) are slave nodes it
  does not own: owned + ghosts <= the slave nodes it holds;
- the interface DoFs a rank owns add up to the interface DoFs, and the
  interface DoFs it holds are at least those;
- the node states a share received in the contact zone's all-gather are
  states of nodes the rank neither owns nor ghosts: at most the slave nodes
  held less the owned and the ghosts.

- the faces within reach of a rank's own (what it would hold once the
  surfaces are held per rank: its slave faces, the master faces within
  their search boxes, the slave faces coupled to its master faces, and one
  ring) are at least its own slave faces and at most the faces it holds,
  and on some rank fewer (the projection is not every face).

Today every rank holds the whole interface (its faces, slave nodes and
interface DoFs); the counts are printed so that a run shows what a rank
holds, and the checks hold once a rank holds only its share.
"""


def per_rank_checks(contact):
    """The checks above on the last cycle's "contact" block of summary.json:
    a list of (name, passed)."""
    held = contact["held_per_rank"]
    n_slave = contact["slave_nodes"]
    owned, ghosts, nodes = held["rows_owned"], held["row_ghosts"], held["slave_nodes"]
    return [
        ("2 ranks", len(owned) == 2),
        ("the rows owned add up to the slave nodes", sum(owned) == n_slave),
        ("each rank owns a part, fewer than all", all(0 < n < n_slave for n in owned)),
        ("owned + ghosts <= slave nodes held",
         all(o + g <= n for o, g, n in zip(owned, ghosts, nodes))),
        ("the interface DoFs owned add up to the interface",
         sum(held["interface_dofs_owned"]) == max(held["interface_dofs"])),
        ("own slave faces <= faces within reach <= faces held",
         all(s <= w <= f for s, w, f in zip(contact["slave_faces_per_rank"],
                                            held["faces_within_reach"], held["faces"]))),
        ("some rank has fewer faces within reach than it holds",
         any(w < f for w, f in zip(held["faces_within_reach"], held["faces"]))),
        ("zone states received <= held - owned - ghosts",
         all(z <= n - o - g for z, n, o, g in zip(held["zone_nodes_received"], nodes, owned,
                                                  ghosts))),
    ]

