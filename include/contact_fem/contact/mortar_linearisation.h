// The 2D mortar operators of one slave/master face pair as functions of the
// node coordinates, with their first derivatives: D, M, the weighted gap,
// its normal part and the averaged unit nodal normals, and the segmentation
// (overlap ends on both faces) and dual basis they are built from. The
// derivatives come from forward automatic differentiation (Sacado) of the
// kernel in mortar_number.h; the values are exactly those of the double
// path (integrate_pair()). For the consistent tangent of finite-strain
// contact (doc/finite_strain.md, "Contact linearisation").
#ifndef contact_fem_mortar_linearisation_h
#define contact_fem_mortar_linearisation_h

#include <deal.II/base/point.h>

#include <contact_fem/contact/mortar.h>

#include <array>
#include <vector>

namespace contact_fem
{
  namespace Mortar
  {
    /**
     * A slave/master face pair and the slave faces next to it, by their
     * nodes: indices into @p points, whose coordinates (x and y of each
     * point, in this order) are the independent variables.
     */
    struct PairPatch
    {
      struct Face
      {
        /// Node indices in LineFace order (ends, then the interior node).
        std::vector<unsigned int> nodes;
        /// +1 or -1: see face_normal().
        double orientation = 1.;
        /// As in LineFace (0: isoparametric).
        unsigned int element_degree = 0;
      };
      std::vector<Point<2>> points;
      /// [0]: the slave face of the pair; others: slave faces sharing one of
      /// its nodes, which enter its averaged nodal normals.
      std::vector<Face> slave_faces;
      Face              master;
      /// Further master faces of the slave face: their overlaps join the
      /// pair's in the support of the dual basis, as ContactInterface builds
      /// it on all masters of a slave face.
      std::vector<Face> other_masters;
      /// Per point (empty: none): the axes normal to a symmetry plane
      /// through it, removed from its nodal normal
      /// (ContactInterface::Node::symmetry_plane).
      std::vector<std::array<bool, 2>> symmetry_planes;

      /// A face as a LineFace of the current coordinates.
      LineFace
      line_face(const Face &face) const;
    };

    /// A value and its derivatives with respect to the 2 * points.size()
    /// coordinates of a PairPatch (empty: values only).
    struct Linearised
    {
      double              value = 0.;
      std::vector<double> derivatives;
    };

    /// The operators of a PairPatch; j: slave DoF node, l: master DoF node.
    struct LinearisedPair
    {
      /// Unit nodal normals n_j: the measure-weighted mean of the normals of
      /// the slave faces at node j (as ContactInterface averages them).
      std::vector<std::array<Linearised, 2>> normals;
      /// Slave parameters of the overlap ends, and which master end node
      /// bounds each (-1: a slave end; overlap()).
      Linearised         xi_begin, xi_end;
      std::array<int, 2> bounding_master_ends = {{-1, -1}};
      /// Master parameters of the overlap ends (the slave end points moved
      /// along their normals, or +-1 at a bounding master end).
      Linearised eta_begin, eta_end;
      /// Dual basis coefficients A_jk on the overlaps of all masters.
      std::vector<std::vector<Linearised>>   dual_coefficients;
      std::vector<Linearised>                D;
      std::vector<std::vector<Linearised>>   M;
      std::vector<std::array<Linearised, 2>> weighted_gap;
      /// g_j = n_j . weighted_gap_j.
      std::vector<Linearised> normal_gap;
    };

    /**
     * The operators of @p patch (dual basis on the overlaps of the master
     * and the other masters, Gauss points as n_quadrature_points()), with
     * their derivatives if
     * @p derivatives. Returns false if the faces do not overlap.
     */
    bool
    linearise_pair(const PairPatch &patch, const bool derivatives, LinearisedPair &result);

    /// The unit nodal normals at the nodes of the slave face
    /// (slave_faces[0]) of @p patch, from the slave faces of @p patch
    /// (LinearisedPair::normals without a master), with their derivatives.
    std::vector<std::array<Linearised, 2>>
    linearise_nodal_normals(const PairPatch &patch);
  } // namespace Mortar
} // namespace contact_fem

#endif
