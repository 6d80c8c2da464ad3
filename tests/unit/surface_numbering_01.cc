// number_own_faces() (surface_numbering.h) against the numbering of the
// gathered surface, computed here independently: every rank generates the
// faces of every rank (the same pseudo-random lists everywhere), numbers
// the gathered list as ContactInterface::unpack_faces() does (a face by its
// place, a node by its first appearance, rank after rank), and compares the
// numbers of its own faces and their nodes with those number_own_faces()
// computes from its own faces alone. The node DoFs come from a pool of 60
// nodes spread over every rank's range of owned DoFs, so nodes are named by
// several ranks, by ranks that do not own their DoF, and twice within a
// rank. Four surfaces: quadrilateral faces on every rank, the same with
// rank 0 naming nothing, line faces that also repeat a node within a face,
// and no face at all. Printed per surface: the counts that show the cases
// were there, and whether every rank's numbers were those of the gathered
// surface (the test stops otherwise).

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <contact_fem/contact/surface_numbering.h>

#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

using namespace dealii;
using namespace contact_fem;

namespace
{
  constexpr unsigned int dofs_per_rank = 200;

  /// The first DoF of pool node @p i on @p n_ranks ranks: owned by rank i
  /// mod n_ranks, three DoFs per node.
  types::global_dof_index
  node_dof(const unsigned int i, const unsigned int n_ranks)
  {
    return dofs_per_rank * (i % n_ranks) + 3 * (i / n_ranks);
  }

  /// The node DoFs of rank @p r's faces: @p n_faces faces of
  /// @p nodes_per_face pool nodes drawn by a linear congruential generator
  /// seeded by the rank.
  std::vector<types::global_dof_index>
  faces_of_rank(const unsigned int r,
                const unsigned int n_ranks,
                const unsigned int n_faces,
                const unsigned int nodes_per_face)
  {
    std::vector<types::global_dof_index> dofs;
    unsigned long                        state = 12345 + 977 * r;
    for (unsigned int i = 0; i < n_faces * nodes_per_face; ++i)
      {
        state = (1103515245 * state + 12345) % 2147483648ul;
        dofs.push_back(node_dof((state >> 8) % 60, n_ranks));
      }
    return dofs;
  }

  /// Numbers the faces of every rank (@p all) and checks this rank's with
  /// number_own_faces(); prints the counts on rank 0.
  void
  check(const std::string                                       &name,
        const std::vector<std::vector<types::global_dof_index>> &all,
        const unsigned int                                       nodes_per_face)
  {
    const MPI_Comm     comm    = MPI_COMM_WORLD;
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = all.size();

    // The gathered numbering, and who names which node.
    std::map<types::global_dof_index, unsigned int>           node_of_dof;
    std::map<types::global_dof_index, std::set<unsigned int>> naming;
    std::vector<std::vector<unsigned int>>                    numbers(n_ranks);
    std::vector<unsigned int>                                 first_face(n_ranks);
    unsigned int                                              n_faces = 0, repeated = 0;
    for (unsigned int r = 0; r < n_ranks; ++r)
      {
        first_face[r] = n_faces;
        n_faces += all[r].size() / nodes_per_face;
        std::set<types::global_dof_index> seen;
        for (const auto dof : all[r])
          {
            repeated += !seen.insert(dof).second;
            naming[dof].insert(r);
            const auto inserted = node_of_dof.emplace(dof, node_of_dof.size());
            numbers[r].push_back(inserted.first->second);
          }
      }
    unsigned int shared = 0, by_three = 0, not_owner = 0;
    for (const auto &[dof, ranks] : naming)
      {
        shared += ranks.size() > 1;
        by_three += ranks.size() > 2;
        not_owner += ranks.count(dof / dofs_per_rank) == 0;
      }

    IndexSet owned_here(n_ranks * dofs_per_rank);
    owned_here.add_range(rank * dofs_per_rank, (rank + 1) * dofs_per_rank);
    const OwnSurfaceNumbers own   = number_own_faces(all[rank], nodes_per_face, owned_here, comm);
    const bool              equal = own.first_face == first_face[rank] && own.n_faces == n_faces &&
                       own.n_nodes == node_of_dof.size() && own.nodes == numbers[rank];
    const bool every_rank = Utilities::MPI::min(equal ? 1u : 0u, comm) == 1;
    if (rank == 0)
      std::cout << name << ": " << n_faces << " faces, " << node_of_dof.size()
                << " nodes; named by several ranks " << shared << ", by three or more " << by_three
                << ", not by the owner of its DoF " << not_owner << "; named twice on a rank "
                << repeated << "; numbers of the gathered surface on every rank: "
                << (every_rank ? "yes" : "NO") << std::endl;
    AssertThrow(every_rank, ExcMessage("number_own_faces() differs from the gathered numbering."));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               n_ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);

  std::vector<std::vector<types::global_dof_index>> quads, quads_but_rank_0, lines, none(n_ranks);
  for (unsigned int r = 0; r < n_ranks; ++r)
    {
      quads.push_back(faces_of_rank(r, n_ranks, 12, 4));
      quads_but_rank_0.push_back(r == 0 ? std::vector<types::global_dof_index>() : quads.back());
      lines.push_back(faces_of_rank(r + n_ranks, n_ranks, 25, 2));
    }
  check("quadrilaterals", quads, 4);
  check("quadrilaterals, none on rank 0", quads_but_rank_0, 4);
  check("lines", lines, 2);
  check("no faces", none, 4);
}
