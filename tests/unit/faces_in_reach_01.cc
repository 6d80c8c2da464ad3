// faces_within_reach() (faces_in_reach.h) against the rule computed here by
// brute force on the whole list of faces, which every rank generates (the
// same pseudo-random surfaces everywhere) and deals out to the ranks: a
// slab of x per rank, as a partition of the cells would give, and one face
// in eight to a pseudo-random rank. The rule: a rank's slave faces, the
// master faces of the same pair whose boxes meet a slave face's box
// enlarged by its reach, and every face sharing a node with one of those.
// Surfaces (2D lines and 3D quadrilaterals): pair 0, a slave grid under a
// smaller master grid that covers part of it; pair 1, a slave strip that
// shares the nodes of pair 0's master grid along one edge (a chain through
// shared nodes) with its master far away. Printed: the counts that show the
// cases were there (other ranks' faces held as candidates and as the ring),
// and whether every rank found the faces of the rule with their nodes and
// records (the test stops otherwise). By hand it also passed on 1, 3, 4 and 5 ranks.

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>

#include <contact_fem/contact/faces_in_reach.h>

#include <algorithm>
#include <iostream>
#include <set>
#include <string>
#include <vector>

using namespace dealii;
using namespace contact_fem;

namespace
{
  /// A pseudo-random number in [-1, 1) from @p state (a linear
  /// congruential generator).
  double
  random(unsigned long &state)
  {
    state = (1103515245 * state + 12345) % 2147483648ul;
    return static_cast<double>(state >> 8) / 4194304. - 1.;
  }

  /// A grid of faces over [x0, x0 + n h] (and the same in y in 3D) at
  /// height @p z, its nodes moved by a part of h: nodes numbered from
  /// @p first_node (or taken from @p shared_row, the nodes of the row
  /// x = x0), appended to @p faces.
  template <int dim>
  void
  add_grid(std::vector<ReachFace<dim>>     &faces,
           std::vector<Point<dim>>         &points,
           const unsigned int               pair,
           const bool                       slave,
           const double                     x0,
           const double                     y0,
           const double                     z,
           const double                     h,
           const unsigned int               n,
           unsigned long                   &state,
           const std::vector<unsigned int> &shared_row = {})
  {
    const unsigned int                     n_rows = dim == 3 ? n + 1 : 1;
    std::vector<std::vector<unsigned int>> node(n + 1, std::vector<unsigned int>(n_rows));
    for (unsigned int i = 0; i <= n; ++i)
      for (unsigned int j = 0; j < n_rows; ++j)
        {
          if (i == 0 && !shared_row.empty())
            {
              node[i][j] = shared_row[j];
              continue;
            }
          Point<dim> x;
          x[0] = x0 + i * h + 0.1 * h * random(state);
          if (dim == 3)
            {
              x[1] = y0 + j * h + 0.1 * h * random(state);
              x[2] = z + 0.2 * h * random(state);
            }
          else
            x[1] = z + 0.2 * h * random(state);
          node[i][j] = points.size();
          points.push_back(x);
        }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < (dim == 3 ? n : 1); ++j)
        {
          ReachFace<dim> face;
          face.face  = faces.size();
          face.pair  = pair;
          face.slave = slave;
          if (dim == 3)
            face.nodes = {node[i][j], node[i + 1][j], node[i][j + 1], node[i + 1][j + 1]};
          else
            face.nodes = {node[i][0], node[i + 1][0]};
          std::vector<Point<dim>> corners;
          for (const unsigned int k : face.nodes)
            corners.push_back(points[k]);
          face.box = BoundingBox<dim>(corners);
          if (slave)
            face.reach = 0.3 * h;
          else
            face.box.extend(master_box_margin * h);
          faces.push_back(face);
        }
  }

  template <int dim>
  bool
  meet(const BoundingBox<dim> &a, const BoundingBox<dim> &b)
  {
    for (unsigned int d = 0; d < dim; ++d)
      if (a.get_boundary_points().first[d] > b.get_boundary_points().second[d] ||
          b.get_boundary_points().first[d] > a.get_boundary_points().second[d])
        return false;
    return true;
  }

  template <int dim>
  void
  check()
  {
    const MPI_Comm     comm    = MPI_COMM_WORLD;
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int n       = dim == 3 ? 12 : 40;

    std::vector<ReachFace<dim>> faces;
    std::vector<Point<dim>>     points;
    unsigned long               state = 2024;
    add_grid<dim>(faces, points, 0, true, 0., 0., 0., 1. / n, n, state);
    const unsigned int first_master_node = points.size();
    add_grid<dim>(faces, points, 0, false, 0.3, -0.1, 0.4 / n, 1.4 / n, n / 2, state);
    // The master grid's row x = 0.3 + (n / 2) h, shared by pair 1's strip.
    std::vector<unsigned int> row;
    for (unsigned int j = 0; j < (dim == 3 ? n / 2 + 1 : 1); ++j)
      row.push_back(first_master_node + (n / 2) * (dim == 3 ? n / 2 + 1 : 1) + j);
    add_grid<dim>(faces, points, 1, true, points[row[0]][0], -0.1, 0.4 / n, 1.4 / n, 3, state, row);
    add_grid<dim>(faces, points, 1, false, 20., 20., 20., 1. / n, 3, state);

    // The owners: slabs along x, as a partition of the cells would give,
    // with one face in eight dealt to a pseudo-random rank.
    std::vector<unsigned int>   owner(faces.size());
    std::vector<ReachFace<dim>> own;
    for (unsigned int f = 0; f < faces.size(); ++f)
      {
        const auto  &box    = faces[f].box.get_boundary_points();
        const double centre = 0.5 * (box.first[0] + box.second[0]);
        owner[f] =
          std::min(n_ranks - 1, static_cast<unsigned int>(std::max(0., centre * n_ranks / 1.8)));
        if (random(state) > 0.75)
          owner[f] = static_cast<unsigned int>((random(state) + 1.) * 0.5 * n_ranks) % n_ranks;
        if (owner[f] == rank)
          own.push_back(faces[f]);
      }

    // The rule, by brute force over every face.
    std::set<unsigned int> core, rule;
    for (const auto &s : faces)
      if (s.slave && owner[s.face] == rank)
        {
          core.insert(s.face);
          BoundingBox<dim> reach = s.box;
          reach.extend(s.reach);
          for (const auto &m : faces)
            if (!m.slave && m.pair == s.pair && meet(reach, m.box))
              core.insert(m.face);
        }
    std::set<unsigned int> core_nodes;
    for (const unsigned int f : core)
      core_nodes.insert(faces[f].nodes.begin(), faces[f].nodes.end());
    for (const auto &face : faces)
      if (std::any_of(face.nodes.begin(), face.nodes.end(), [&](const unsigned int k) {
            return core_nodes.count(k) > 0;
          }))
        rule.insert(face.face);
    rule.insert(core.begin(), core.end());

    // Each face carries a record (its number and pair, a stand-in for the
    // owner's packed data), which must arrive unchanged.
    for (auto &face : own)
      face.record = {static_cast<double>(face.face), 0.5 + face.pair};
    std::vector<unsigned int> found;
    bool                      records_arrived = true;
    for (const auto &face : faces_within_reach(own, comm))
      {
        found.push_back(face.face);
        records_arrived =
          records_arrived && face.nodes == faces[face.face].nodes &&
          face.record == std::vector<double>{static_cast<double>(face.face), 0.5 + face.pair};
      }
    const bool equal =
      found == std::vector<unsigned int>(rule.begin(), rule.end()) && records_arrived;
    const bool every_rank = Utilities::MPI::min(equal ? 1u : 0u, comm) == 1;
    // Whether some held face is another rank's master face and some is
    // another rank's face of the ring only (the cases the exchange is for).
    unsigned int sent_masters = 0, sent_ring = 0;
    for (const unsigned int f : found)
      if (owner[f] != rank)
        (core.count(f) ? sent_masters : sent_ring) += 1;
    const unsigned int fewest = Utilities::MPI::min(static_cast<unsigned int>(found.size()), comm);
    const unsigned int most   = Utilities::MPI::max(static_cast<unsigned int>(found.size()), comm);
    sent_masters              = Utilities::MPI::sum(sent_masters, comm);
    sent_ring                 = Utilities::MPI::sum(sent_ring, comm);
    if (rank == 0)
      std::cout << dim << "D: " << faces.size() << " faces on 2 pairs; held per rank " << fewest
                << " to " << most << "; other ranks' candidate masters held " << sent_masters
                << ", other ranks' faces of the ring held " << sent_ring
                << "; the faces of the rule with their records on every rank: "
                << (every_rank ? "yes" : "NO") << std::endl;
    AssertThrow(every_rank, ExcMessage("faces_within_reach() differs from the rule."));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>();
  check<3>();
}
