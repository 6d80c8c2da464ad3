// Mortar operators of 3D surface interfaces (the kernel that
// ContactInterface<3> uses): quadrilateral faces, segmentation of a slave face
// against a master face by polygon clipping in an auxiliary plane, the dual
// multiplier basis over the overlapped part of a slave face, and the D / M
// blocks. The 3D counterpart of mortar.h, with the same conventions.
#ifndef contact_fem_mortar_3d_h
#define contact_fem_mortar_3d_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <contact_fem/contact/mortar.h>

#include <array>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  namespace Mortar
  {
    /// An overlap polygon of a slave face: its vertices as slave parameters
    /// (xi, eta), counterclockwise, not closed. Its edges are straight in the
    /// auxiliary plane of the slave face (see overlap()), where it was cut
    /// out, so it is integrated there and covers the overlap of flat faces
    /// of any shape exactly; edges on the slave boundary (both ends on the
    /// same line xi = +-1 or eta = +-1) follow the face instead, so a fully
    /// covered curved face is integrated whole.
    using ParameterPolygon = std::vector<Point<2>>;

    /**
     * A quadrilateral surface face in 3D whose geometry is bilinear (4 nodes)
     * or biquadratic (9 nodes), parameters (xi, eta) in [-1, 1]^2.
     *
     * Node order is deal.II's face DoF order (that of FE_Q<2>(p) and of the
     * MappingQ support points of a face), as for LineFace: first the four
     * vertices in deal.II's lexicographic vertex order
     *   0: (-1, -1), 1: (1, -1), 2: (-1, 1), 3: (1, 1),
     * then, for 9 nodes, the midpoints of the face lines 0..3
     *   4: (-1, 0), 5: (1, 0), 6: (0, -1), 7: (0, 1),
     * and the centre 8: (0, 0). quad_node_parameter() returns these.
     *
     * The displacement and the multipliers use the tensor-product Lagrange
     * shapes of shape_degree(), the element degree: it equals the geometry
     * degree unless a degree-1 element lies on a biquadratic geometry (Q1 on
     * a quadratic mapping, as in 2D); then only the four vertices carry DoFs
     * and all node-indexed data of the DoFs (normals, D, rows and columns of
     * M) have four entries.
     */
    struct QuadFace
    {
      std::vector<Point<3>> nodes;
      /// Degree of the shape functions of the DoFs; 0: the geometry degree.
      unsigned int element_degree = 0;

      unsigned int
      degree() const
      {
        return nodes.size() == 4 ? 1 : 2;
      }
      unsigned int
      shape_degree() const
      {
        return element_degree > 0 ? element_degree : degree();
      }
      /// Number of DoF nodes, (shape_degree() + 1)^2.
      unsigned int
      n_shape_nodes() const
      {
        return (shape_degree() + 1) * (shape_degree() + 1);
      }
      /// Position at parameter @p xi.
      Point<3>
      point(const Point<2> &xi) const;
      /// The tangents dx/dxi and dx/deta at @p xi.
      std::array<Tensor<1, 3>, 2>
      tangents(const Point<2> &xi) const;
    };

    /// The 1D node indices (LineFace order: -1 -> 0, 1 -> 1, 0 -> 2) of
    /// node @p i of a quadrilateral face of degree @p p (1 or 2). Inline,
    /// as the shapes below: the kernel evaluates them at every quadrature
    /// point.
    inline std::array<unsigned int, 2>
    quad_line_indices(const unsigned int p, const unsigned int i)
    {
      if (p == 1)
        return {{i % 2, i / 2}};
      // Vertices, the lines x = -1, x = 1, y = -1, y = 1, the centre.
      static constexpr unsigned int q2[9][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0, 2},
                                                {1, 2}, {2, 0}, {2, 1}, {2, 2}};
      return {{q2[i][0], q2[i][1]}};
    }

    /// Tensor-product Lagrange shape function @p i of degree @p p (node
    /// order of QuadFace) at @p xi.
    inline double
    quad_shape_value(const unsigned int p, const unsigned int i, const Point<2> &xi)
    {
      const auto [a, b] = quad_line_indices(p, i);
      return lagrange_value(p, a, xi[0]) * lagrange_value(p, b, xi[1]);
    }
    /// Gradient with respect to (xi, eta) of quad_shape_value().
    Tensor<1, 2>
    quad_shape_gradient(const unsigned int p, const unsigned int i, const Point<2> &xi);
    /// Parameter (xi, eta) of node @p i of a face of degree @p p.
    Point<2>
    quad_node_parameter(const unsigned int p, const unsigned int i);

    /// Unit normal t_xi x t_eta / |t_xi x t_eta| times @p orientation (+1 or
    /// -1, chosen so that it points out of the body: deal.II's face vertex
    /// order gives the outward normal on some faces of a hexahedron and the
    /// inward one on others).
    Tensor<1, 3>
    face_normal(const QuadFace &face, const Point<2> &xi, const double orientation);

    /**
     * Coefficients A of the dual basis Phi_j = sum_k A_jk N_k of a slave
     * face: A = D_e M_e^{-1} with D_e = diag(int N_j) and M_e = (int N_j N_k),
     * integrated over the whole face, so that int Phi_j N_k = delta_jk int N_k
     * there (biorthogonality, Wohlmuth 2000).
     */
    FullMatrix<double>
    dual_basis_coefficients(const QuadFace &slave);

    /**
     * The same, with D_e and M_e integrated over the overlapped part of the
     * slave face only: the union of the @p polygons of all its masters (as
     * integrate_pair() or overlap() return them, with the same
     * @p slave_normals, which define the auxiliary plane). Biorthogonal there,
     * which keeps the gap and the pressure consistent at the rim of the
     * master surface (as in 2D and Kratos). The polygons must not overlap
     * each other. Near-singular when they cover almost none of a node's
     * support (the caller leaves such nodes out of contact, as in 2D).
     */
    FullMatrix<double>
    dual_basis_coefficients(const QuadFace                      &slave,
                            const std::vector<Tensor<1, 3>>     &slave_normals,
                            const std::vector<ParameterPolygon> &polygons);

    /**
     * The area of the overlap @p polygons (slave parameters) projected along
     * n0 into the auxiliary plane of @p slave, the region
     * integrate_pair() integrates: edges straight in that plane, but edges
     * on the slave boundary following the face. Exact up to round-off for
     * Q1 and Q2 faces. {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}} gives the whole
     * face's. (The same polygons' area in the slave parameters is not the
     * region's on a curved face: an edge straight in the plane is curved
     * in the parameters, and the zero-width joins of the clipping, which
     * have no area in the plane, have some there.)
     */
    double
    projected_area(const QuadFace                      &slave,
                   const std::vector<Tensor<1, 3>>     &slave_normals,
                   const std::vector<ParameterPolygon> &polygons);

    /**
     * Projects a point @p x along @p direction onto the surface of @p face:
     * returns the parameter eta with face(eta) = x + t direction for some t,
     * found by Newton's method on (eta, t) from eta = 0 (exact after one
     * step for flat parallelogram faces). eta may lie outside [-1, 1]^2.
     * Returns false if Newton does not converge or the direction is
     * tangential to the face.
     */
    bool
    project_along(const QuadFace     &face,
                  const Point<3>     &x,
                  const Tensor<1, 3> &direction,
                  Point<2>           &eta);

    /**
     * The overlap of a slave face with a master face, as polygons of slave
     * parameters (see ParameterPolygon). Segmentation as in Popp et
     * al. (2010) and Kratos' exact mortar segmentation: the auxiliary plane
     * passes through the slave centre with the normal n0 interpolated from
     * @p slave_normals there; the boundary nodes of both faces (4, or 8 with
     * the edge midpoints of a 9-node face, so curved edges are replaced by
     * two chords each) are projected along n0 into it; the two polygons are
     * intersected (Sutherland-Hodgman: the master clipped by the slave, or
     * by the convex pieces of its fan from the centre if a curved edge bends
     * inward; robust for edges that coincide up to round-off); the vertices
     * of the intersection are mapped back along n0 onto the slave face
     * (those within 1e-10 of its boundary put on it), except where a master
     * edge crosses a chord of the slave boundary: that vertex goes where the
     * master edge crosses the curved slave edge itself, so the overlap keeps
     * the slave edge up to there (mapped back, it would land inside the face
     * by the chord's sag and cut off the lens between chord and edge: 1e-4
     * of a curved face that a master edge crosses). Usually one convex
     * polygon; a curved face can give a non-convex one or several. Returns
     * false, with no polygons, if the intersection has no area (faces apart,
     * or touching along an edge or at a corner: pieces below 1e-10 of the
     * slave's projected area are dropped).
     */
    bool
    overlap(const QuadFace                  &slave,
            const std::vector<Tensor<1, 3>> &slave_normals,
            const QuadFace                  &master,
            std::vector<ParameterPolygon>   &polygons);

    /// The mortar blocks of one slave face against one master face.
    struct QuadSegmentOperators
    {
      /// int_overlap Phi_j dA for every slave DoF node j (the lumped D row).
      std::vector<double> D;
      /// int_overlap Phi_j N^m_l dA, slave DoF node j by master DoF node l.
      FullMatrix<double> M;
      /// int_overlap Phi_j (x_master - x_slave) dA for every slave DoF node
      /// j: the weighted gap vector on the face geometry, which the nodal
      /// form sum_l M_jl x_l - D_j x_j only equals for isoparametric faces.
      std::vector<Tensor<1, 3>> weighted_gap;
      /// Area of the overlapped part of the slave face.
      double overlap_area = 0.;
      /// The overlap in slave parameters (input of dual_basis_coefficients()).
      std::vector<ParameterPolygon> polygons;
    };

    /**
     * Segmentation and integration of one slave/master face pair.
     *
     * @p slave_normals: nodal normals of the slave DoF nodes (averaged, unit,
     * pointing out of the slave body). The overlap is that of overlap(). Its
     * polygons are cut into triangles in the auxiliary plane (fan from the
     * vertex centroid) and integrated by a collapsed Gauss rule with
     * @p n_quadrature_points per direction (exact for polynomials of total
     * degree 2 n - 2), each point mapped back along n0 to the slave face.
     * For flat parallelogram faces the integrands are polynomials: n = 3 is
     * exact for bilinear faces, n = 5 for biquadratic ones; the areas (sum D,
     * sum M) are exact for every flat face. At each quadrature point the
     * master parameter is the projection along the interpolated slave normal
     * field (as in 2D and in Kratos' conditions), clamped to the master face.
     *
     * Returns false if the faces do not overlap.
     */
    bool
    integrate_pair(const QuadFace                  &slave,
                   const std::vector<Tensor<1, 3>> &slave_normals,
                   const FullMatrix<double>        &dual_coefficients,
                   const QuadFace                  &master,
                   const unsigned int               n_quadrature_points,
                   QuadSegmentOperators            &result);

    /// The point of @p face closest to @p x, as parameters in [-1, 1]^2:
    /// Gauss-Newton from the centre; a coordinate that leaves the face is
    /// held on its bound and the other one minimised along that edge (exact
    /// after one step for flat parallelograms).
    Point<2>
    closest_parameter(const QuadFace &face, const Point<3> &x);

    /// A box that holds all of @p face, not only its nodes, as the 2D one.
    BoundingBox<3>
    whole_face_box(const QuadFace &face);

    /// Gauss points per direction of the mortar integration of a pair:
    /// 2 p + 1 is exact for flat parallelograms (polynomial integrands); on
    /// other faces the master parameter and the rim dual basis are not
    /// polynomial. Measured on the patch test against an unstructured
    /// master mesh (contact_patch_3d_04), the spread of the pressure with
    /// Q1: 1.2e-6 with 3 points, 2.2e-8 with 4, 5e-10 with 5, below the 10
    /// printed digits with 6.
    unsigned int
    n_quadrature_points(const QuadFace &slave, const QuadFace &master);

    /// The vertex nodes (positions in QuadFace::nodes) of the edge of a
    /// face on which the parameter @p xi (on the boundary) lies, or of the
    /// vertex.
    std::vector<unsigned int>
    boundary_vertices(const Point<2> &xi);
  } // namespace Mortar
} // namespace contact_fem

#endif
