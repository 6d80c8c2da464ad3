// Mortar operators of 2D line interfaces: exact segmentation of a slave face
// against a master face, the dual multiplier basis, and the D / M blocks.
#ifndef contact_fem_mortar_h
#define contact_fem_mortar_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <array>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  namespace Mortar
  {
    /**
     * The nodes of a line face whose geometry has polynomial degree p: p+1
     * nodes, of type Vector (a point, or a vector of AD numbers in the
     * linearisation). Node order follows deal.II's face DoF order: the two
     * end vertices first (parameter xi = -1 and xi = +1), then the interior
     * node (xi = 0, p = 2).
     *
     * The displacement and the multipliers on the face use the Lagrange
     * shapes of shape_degree(), the element degree. It equals the geometry
     * degree (isoparametric) unless a degree-1 element lies on a curved,
     * degree-2 geometry (a quadratic mapping of Q1 elements): then the
     * interior node is a geometry node only and carries no DoFs.
     */
    template <typename Vector>
    struct LineFaceNodes
    {
      std::vector<Vector> nodes;
      /// Degree of the shape functions of the DoFs; 0: the geometry degree.
      unsigned int element_degree = 0;

      unsigned int
      degree() const
      {
        return nodes.size() - 1;
      }
      unsigned int
      shape_degree() const
      {
        return element_degree > 0 ? element_degree : degree();
      }
    };

    /// A surface face in double coordinates.
    struct LineFace : LineFaceNodes<Point<2>>
    {
      /// Position at parameter xi in [-1, 1].
      Point<2>
      point(const double xi) const;
      /// dx/dxi at xi.
      Tensor<1, 2>
      tangent(const double xi) const;
    };

    /// Lagrange shape function @p i of degree @p p (node order of LineFace)
    /// at xi, for any number type (double, or an automatic-differentiation
    /// number in the linearisation, mortar_linearisation.h).
    template <typename Number>
    Number
    lagrange_value(const unsigned int p, const unsigned int i, const Number &xi)
    {
      // Branches, not ?:, so that expression-template numbers compile.
      if (p == 1)
        {
          if (i == 0)
            return 0.5 * (1. - xi);
          return 0.5 * (1. + xi);
        }
      switch (i)
        {
          case 0:
            return 0.5 * xi * (xi - 1.);
          case 1:
            return 0.5 * xi * (xi + 1.);
          default:
            return 1. - xi * xi;
        }
    }

    /// d/dxi of lagrange_value().
    template <typename Number>
    Number
    lagrange_derivative(const unsigned int p, const unsigned int i, const Number &xi)
    {
      if (p == 1)
        return Number(i == 0 ? -0.5 : 0.5);
      switch (i)
        {
          case 0:
            return xi - 0.5;
          case 1:
            return xi + 0.5;
          default:
            return -2. * xi;
        }
    }

    /// Lagrange shape function @p i of degree @p p (node order of LineFace) at xi.
    double
    shape_value(const unsigned int p, const unsigned int i, const double xi);
    /// A box that holds the whole face interpolated from @p nodes, not
    /// only the nodes: x(xi) - c = sum_k N_k(xi) (x_k - c) for the nodes'
    /// box centre c (the N_k sum to 1), so each coordinate stays within
    /// @p lebesgue (max over xi of sum_k |N_k(xi)|) times the nodes'
    /// half-extent of c; padded by round-off of the coordinates.
    template <int spacedim>
    BoundingBox<spacedim>
    interpolant_box(const std::vector<Point<spacedim>> &nodes, const double lebesgue);

    /// max_xi sum_i |shape_value(p, i, xi)|: 1 for p = 1, 1.25 for p = 2.
    double
    lebesgue_constant(const unsigned int p);

    /// d/dxi of shape_value().
    double
    shape_derivative(const unsigned int p, const unsigned int i, const double xi);
    /// Parameter of node @p i of a face of degree @p p.
    double
    node_parameter(const unsigned int p, const unsigned int i);

    /// Unit normal obtained by rotating the tangent clockwise by 90 degrees
    /// and multiplying by @p orientation (+1 or -1, chosen so that it points
    /// out of the body).
    Tensor<1, 2>
    face_normal(const LineFace &face, const double xi, const double orientation);

    /**
     * Coefficients A of the dual basis Phi_j = sum_k A_jk N_k of a slave face:
     * A = D_e M_e^{-1} with D_e = diag(int N_j) and M_e = (int N_j N_k), both
     * integrated over the given parameter @p intervals of the face (default:
     * the whole face), so that int Phi_j N_k = delta_jk int N_k there
     * (biorthogonality, Wohlmuth 2000). Integrating over the part of the face
     * that overlaps the master keeps biorthogonality, and so a consistent
     * gap and pressure, at the rim of the master surface (as Kratos does).
     */
    FullMatrix<double>
    dual_basis_coefficients(const LineFace                               &slave,
                            const std::vector<std::pair<double, double>> &intervals = {{-1., 1.}});

    /**
     * The slave parameter interval [lower, upper] whose points, moved along
     * the interpolated nodal normals, land on @p master. Returns false if
     * there is none. If @p bounding_master_ends is given, it receives for
     * lower and upper the master node (0 or 1) whose slave image bounds
     * them, or -1 where a slave end does.
     */
    bool
    overlap(const LineFace                  &slave,
            const std::vector<Tensor<1, 2>> &slave_normals,
            const LineFace                  &master,
            double                          &lower,
            double                          &upper,
            std::array<int, 2>              *bounding_master_ends = nullptr);

    /// The mortar blocks of one slave face against one master face.
    struct SegmentOperators
    {
      /// int_overlap Phi_j ds for every slave node j (the lumped D row).
      std::vector<double> D;
      /// int_overlap Phi_j N^m_l ds, slave node j by master node l.
      FullMatrix<double> M;
      /// int_overlap Phi_j (x_master - x_slave) ds for every slave node j:
      /// the weighted gap vector on the face geometry (curved where the
      /// geometry is), which the nodal form sum_l M_jl x_l - D_j x_j only
      /// equals for isoparametric faces.
      std::vector<Tensor<1, 2>> weighted_gap;
      /// Length of the overlapped part of the slave face.
      double overlap_length = 0.;
      /// Slave parameter interval of the overlap.
      double xi_begin = 0., xi_end = 0.;
    };

    /**
     * Projects a point @p x along the direction @p direction onto the curve
     * of @p face: the parameter eta with (face(eta) - x) x direction = 0 (2D
     * cross product). Where the line crosses the face, eta in [-1, 1] is the
     * bracketed root, to the precision of double arithmetic; where it passes
     * beside the face, eta is the root on the continuation of the face's
     * chord, outside [-1, 1] on the side where the line passes. Returns
     * false only if the line is parallel to that chord and misses the face.
     */
    bool
    project_along(const LineFace     &face,
                  const Point<2>     &x,
                  const Tensor<1, 2> &direction,
                  double             &eta);

    /**
     * Segmentation and integration of one slave/master face pair.
     *
     * The slave face carries the nodal normals @p slave_normals (averaged,
     * unit, pointing out of the slave body). The normal field along the slave
     * face is the interpolation of the nodal normals (continuous across
     * faces, so neighbouring slave faces tile the master without gaps or
     * overlaps). The overlap is the set of slave parameters whose point
     * projects along that normal field into the master face; its ends are the
     * slave face ends or the slave-side images of the master end nodes. The
     * blocks are integrated by Gauss quadrature with @p n_quadrature_points
     * on the overlap, which is exact for flat faces.
     *
     * Returns false if the faces do not overlap.
     */
    bool
    integrate_pair(const LineFace                  &slave,
                   const std::vector<Tensor<1, 2>> &slave_normals,
                   const FullMatrix<double>        &dual_coefficients,
                   const LineFace                  &master,
                   const unsigned int               n_quadrature_points,
                   SegmentOperators                &result);

    /// The point of @p face closest to @p x: its parameter in [-1, 1]
    /// (Gauss-Newton from the chord projection, exact for straight faces).
    double
    closest_parameter(const LineFace &face, const Point<2> &x);

    /// A box that holds all of @p face, not only its nodes (a quadratic
    /// face bulges beyond them): the penetration check needs the exact
    /// nearest face. The search works on the nodes' boxes, whose reach (a
    /// fraction of the face size) covers that bulge.
    BoundingBox<2>
    whole_face_box(const LineFace &face);

    /// Gauss points of the mortar integration of a pair: exact for flat
    /// faces (polynomial integrands) with two to spare.
    unsigned int
    n_quadrature_points(const LineFace &slave, const LineFace &master);
  } // namespace Mortar
} // namespace contact_fem

#endif
