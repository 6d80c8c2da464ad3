// The 3D mortar operators of a slave quadrilateral face with each of its
// masters as functions of the node coordinates, with their first derivatives: D, M,
// the weighted gap, its normal part and the averaged unit nodal normals,
// and the dual basis they are built from. Forward automatic
// differentiation (Sacado) of the kernel of mortar_3d_number.h; the values
// are exactly those of the double path (integrate_pair()). The 3D
// counterpart of mortar_linearisation.h, for bilinear (4-node) and
// biquadratic (9-node) faces, Q1 on a quadratic mapping included (a vertex
// where a master edge crosses a curved slave edge, found by bisection, is
// differentiated by the implicit-function theorem). Where the clipping
// changes topology (a vertex entering or leaving a polygon, a quadrature
// point clamped to the master's rim) the derivative is the one-sided one
// of the topology found.
#ifndef contact_fem_mortar_3d_linearisation_h
#define contact_fem_mortar_3d_linearisation_h

#include <deal.II/base/point.h>

#include <contact_fem/contact/mortar_3d.h>
#include <contact_fem/contact/mortar_linearisation.h>

#include <array>
#include <vector>

namespace contact_fem
{
  namespace Mortar
  {
    /**
     * A slave face with its masters and the slave faces next to it, by
     * their nodes: indices into @p points, whose coordinates (x, y and z
     * of each point, in this order) are the independent variables.
     */
    struct QuadFacePatch
    {
      /// Node indices in QuadFace order; orientation and element degree as
      /// in PairPatch::Face.
      using Face = PairPatch::Face;
      std::vector<Point<3>> points;
      /// [0]: the slave face; others: slave faces sharing one of its
      /// nodes, which enter its averaged nodal normals.
      std::vector<Face> slave_faces;
      /// Every master of the slave face: their overlaps, in this order,
      /// are the support of its dual basis (as ContactInterface builds it).
      std::vector<Face> masters;
      /// Per point (empty: none): the axes normal to a symmetry plane
      /// through it, removed from its nodal normal
      /// (ContactInterface::Node::symmetry_plane).
      std::vector<std::array<bool, 3>> symmetry_planes;

      /// A face as a QuadFace of the current coordinates.
      QuadFace
      quad_face(const Face &face) const;
    };

    /// The operators of the slave face of a QuadFacePatch with one of its
    /// masters; j: slave DoF node, l: master DoF node.
    struct LinearisedQuadPair
    {
      /// Unit nodal normals: the area-weighted mean of the normals of the
      /// slave faces at node j (as ContactInterface averages them).
      std::vector<std::array<Linearised, 3>> normals;
      /// The number of vertices of each overlap polygon of the slave face
      /// (all masters, in order: the topology).
      std::vector<unsigned int> polygon_sizes;
      /// Dual basis coefficients A_jk on the overlaps of all masters.
      std::vector<std::vector<Linearised>>   dual_coefficients;
      std::vector<Linearised>                D;
      std::vector<std::vector<Linearised>>   M;
      std::vector<std::array<Linearised, 3>> weighted_gap;
      /// g_j = n_j . weighted_gap_j.
      std::vector<Linearised> normal_gap;
      /// Only if linearise_slave_face() is asked for them (a check of the
      /// segmentation; the operators do not need them): the vertices of
      /// this master's overlap polygons, slave parameters (xi, eta) in
      /// overlap()'s order.
      std::vector<std::vector<std::array<Linearised, 2>>> vertices;
    };

    /**
     * The operators of the slave face of @p patch with each of its masters
     * (dual basis on the overlaps of all masters, Gauss points as
     * n_quadrature_points()), with their derivatives if @p derivatives:
     * @p pairs[i] for masters[i], with empty D if that master does not
     * overlap the slave face. Returns false if none does.
     *
     * The nodal normals and the dual basis are linearised once for all
     * masters. Each AD evaluation has only the variables its result
     * depends on directly: the normals those of the slave faces' nodes;
     * each master's overlap, its dual basis integrals and its operators
     * the slave face's and the master's coordinates and the normal
     * components (36 for bilinear faces, 66 for 9-node faces with a
     * bilinear shape, 81 for biquadratic ones: a FixedADNumber, whose
     * derivatives are on the stack; then chained to the coordinates), at
     * fixed dual basis coefficients: the operators are linear in them, so
     * their part is added with the integrals of the standard basis.
     * With @p with_vertices, each pair also gets the vertices of its
     * overlap polygons (LinearisedQuadPair::vertices).
     */
    bool
    linearise_slave_face(const QuadFacePatch             &patch,
                         const bool                       derivatives,
                         std::vector<LinearisedQuadPair> &pairs,
                         const bool                       with_vertices = false);

    /// The unit nodal normals at the nodes of the slave face
    /// (slave_faces[0]) of @p patch, from its slave faces
    /// (LinearisedQuadPair::normals without masters), with their
    /// derivatives.
    std::vector<std::array<Linearised, 3>>
    linearise_nodal_normals(const QuadFacePatch &patch);
  } // namespace Mortar
} // namespace contact_fem

#endif
