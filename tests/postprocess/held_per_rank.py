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
        ("zone states received <= held - owned - ghosts",
         all(z <= n - o - g for z, n, o, g in zip(held["zone_nodes_received"], nodes, owned,
                                                  ghosts))),
    ]

