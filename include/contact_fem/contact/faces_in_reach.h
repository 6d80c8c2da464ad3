// The contact faces a rank needs at a search, found by exchanging bounding
// boxes instead of gathering the whole surfaces.
#ifndef contact_fem_faces_in_reach_h
#define contact_fem_faces_in_reach_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>

#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /// One of a rank's own contact faces, as faces_within_reach() sees it.
  template <int dim>
  struct ReachFace
  {
    unsigned int face  = 0; ///< its global number
    unsigned int pair  = 0;
    bool         slave = false;
    /// The box of its nodes at the search configuration; a master face's
    /// with the broad phase's margin (master_box_margin).
    BoundingBox<dim> box;
    /// A slave face's search reach (its box is enlarged by it); 0 for a
    /// master face.
    double reach = 0.;
    /// The global numbers of its nodes.
    std::vector<unsigned int> nodes;
    /// The owner's record of the face (as ContactInterface::initialize()
    /// packs it), carried to the ranks that hold the face, not read.
    std::vector<double> record;
  };

  /// The margin of a master face's box in the broad phase, relative to the
  /// face's side, so that the touching boxes of flat faces meet.
  constexpr double master_box_margin = 1e-2;

  /**
   * The faces a rank holds at a search, sorted by number, with their
   * records, from its own faces @p own alone (issue 32 item 1): its slave faces, the
   * master faces of the same pair whose boxes meet a slave face's box
   * enlarged by its reach (the broad phase's candidates), and every face
   * sharing a node with one of those (the nodal normals and sizes sum over
   * them). The master-side forces of a rank's segments go to the owners of
   * the master DoFs as values, so a rank does not need the slave faces
   * coupled to its own master faces. Collective.
   *
   * Two rounds, each an all-gather of a few boxes per rank (a level of the
   * R-tree of the boxes the rank asks about) and a point-to-point exchange
   * of the faces that meet them (Utilities::MPI::some_to_some()); the
   * receiver then selects exactly: the candidates by the same box test as
   * the broad phase, the ring by shared node numbers. A face goes to a
   * rank at most once. A rank holds its own faces and the faces sent to it,
   * never the whole surface.
   */
  template <int dim>
  std::vector<ReachFace<dim>>
  faces_within_reach(const std::vector<ReachFace<dim>> &own, const MPI_Comm comm);
} // namespace contact_fem

#endif
