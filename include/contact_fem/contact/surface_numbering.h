// The global numbers of a rank's own contact faces and of their nodes,
// computed without gathering the other ranks' faces.
#ifndef contact_fem_surface_numbering_h
#define contact_fem_surface_numbering_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>

#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /// The global numbers of one rank's own faces and of their nodes
  /// (number_own_faces()).
  struct OwnSurfaceNumbers
  {
    /// The global number of the rank's first own face; its faces follow in
    /// their order.
    unsigned int first_face = 0;
    /// The global number of every node of the own faces, face after face
    /// (nodes_per_face per face, in the order of @p node_dofs).
    std::vector<unsigned int> nodes;
    /// Over every rank: the number of faces and of distinct nodes.
    unsigned int n_faces = 0;
    unsigned int n_nodes = 0;
  };

  /**
   * The numbering of ContactInterface::unpack_faces(), which gathers every
   * rank's faces and numbers them in rank order (a face by its place in
   * the gathered list, a node by its first appearance: rank after rank,
   * face after face, node after node; a node is named by its first DoF),
   * computed from a rank's own faces only. Collective.
   *
   * @p node_dofs holds the first DoF of every node of the rank's own
   * faces, face after face (nodes_per_face per face), in the order they
   * would be gathered in; @p owned_dofs is the rank's locally owned DoFs
   * (every DoF of @p node_dofs is owned by some rank).
   *
   * A face's number is the exclusive prefix sum of the face counts. A
   * node that a lower rank's face names takes that rank's number; the
   * nodes this rank names first are numbered from the exclusive prefix
   * sum of the counts of first-named nodes, in the order of their first
   * appearance here. Which ranks name a node is decided by the owner of
   * its DoF: each rank sends its nodes' DoFs to their owners, which answer
   * with the ranks naming each (first exchange); the lowest naming rank
   * then sends the node's number to the others (second exchange). Memory:
   * the rank's own nodes and, at a DoF owner, the naming ranks of its DoFs
   * (more than one only at partition boundaries).
   *
   * Throws if the input is inconsistent (a DoF no rank owns, a node left
   * without a number), after its last collective call: a caller that
   * passes the message to every rank (ContactInterface's
   * stop_on_every_rank()) leaves none waiting.
   */
  OwnSurfaceNumbers
  number_own_faces(const std::vector<types::global_dof_index> &node_dofs,
                   const unsigned int                          nodes_per_face,
                   const IndexSet                             &owned_dofs,
                   const MPI_Comm                              comm);
} // namespace contact_fem

#endif
