// The shape of one hexahedron of a mesh file, from its eight corners: valid,
// mirrored (a valid cell whose nodes are listed in the opposite turn), or
// broken (a collapsed edge, a flat corner, a twisted cell).
#ifndef contact_fem_hexahedron_shape_h
#define contact_fem_hexahedron_shape_h

#include <deal.II/base/point.h>

#include <array>

namespace contact_fem
{
  using namespace dealii;

  enum class HexahedronShape
  {
    valid,          ///< every corner Jacobian positive
    mirrored,       ///< every corner Jacobian negative: a valid cell listed
                    ///< in the opposite turn (deal.II's reader reorders it)
    collapsed_edge, ///< two nodes of an edge at one place
    flat,           ///< a corner Jacobian (near) zero: a corner, or the
                    ///< whole cell, without volume
    twisted         ///< corner Jacobians of both signs: a self-intersecting
                    ///< cell, nodes out of Gmsh's order
  };

  struct HexahedronCheck
  {
    HexahedronShape shape = HexahedronShape::valid;
    /// collapsed_edge: the two coincident nodes; flat: the corner whose
    /// Jacobian is (near) zero; twisted: the first corner whose Jacobian is
    /// negative (first = second). Node numbers 0-7 in Gmsh's order.
    unsigned int first = 0, second = 0;
    unsigned int n_negative = 0; ///< corners with a negative Jacobian
    /// The corner Jacobians over the product of their three edge lengths
    /// (the sines of the corner angles, in [-1, 1]): smallest and largest.
    double min_corner = 0., max_corner = 0.;
  };

  /**
   * Classifies the hexahedron with the corners @p x in Gmsh's node order
   * (nodes 0-3 one face, 4-7 the opposite face in the same turn, node 4
   * opposite node 0). A trilinear cell is valid where its Jacobian is
   * positive; the corner Jacobians are the usual test (each the triple
   * product of the three edges leaving a corner, in the order of the
   * reference axes). A corner counts as flat below 1e-8 of the product of
   * its edge lengths, an edge as collapsed below 1e-10 of the longest edge.
   */
  HexahedronCheck
  check_hexahedron(const std::array<Point<3>, 8> &x);
} // namespace contact_fem

#endif
