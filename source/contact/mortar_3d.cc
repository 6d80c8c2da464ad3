#include <deal.II/base/quadrature_lib.h>

#include <contact_fem/contact/mortar.h>
#include <contact_fem/contact/mortar_3d.h>

// Boost 1.74 rescales overlay input to an integer grid by default, which put
// the intersection vertices ~1e-8 of the box off (sum M missed the overlap
// area by that much); later versions drop the rescaling. Turned off here
// only: the polygon types below appear in no other translation unit, and the
// R-trees elsewhere (boxes and points) do not use the overlay code.
#define BOOST_GEOMETRY_NO_ROBUSTNESS
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>

#include <algorithm>
#include <cmath>

namespace contact_fem
{
  namespace Mortar
  {
    namespace
    {
      /// 1D node indices (in LineFace order: -1, 1, 0) of the tensor-product
      /// node @p i of a quadrilateral face of degree @p p.
      std::array<unsigned int, 2>
      line_indices(const unsigned int p, const unsigned int i)
      {
        Assert(p == 1 || p == 2, ExcNotImplemented());
        if (p == 1)
          return {{i % 2, i / 2}};
        // Vertices, the lines x = -1, x = 1, y = -1, y = 1, the centre.
        static const unsigned int q2[9][2] = {
          {0, 0}, {1, 0}, {0, 1}, {1, 1}, {0, 2}, {1, 2}, {2, 0}, {2, 1}, {2, 2}};
        return {{q2[i][0], q2[i][1]}};
      }

      /// Boundary nodes of a face of geometry degree @p p, counterclockwise
      /// in the parameter plane.
      std::vector<unsigned int>
      boundary_ring(const unsigned int p)
      {
        if (p == 1)
          return {0, 1, 3, 2};
        return {0, 6, 1, 5, 3, 7, 2, 4};
      }

      double
      cross_2d(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
      {
        return a[0] * b[1] - a[1] * b[0];
      }

      /// Collapsed (Duffy) Gauss rule with n x n points on the triangle
      /// (0,0), (1,0), (0,1): x = u, y = v (1 - u). Exact for polynomials of
      /// total degree 2 n - 2 (the factor 1 - u of the Jacobian costs one),
      /// and of any order, which QGaussSimplex<2> of deal.II 9.4 is not.
      void
      triangle_rule(const unsigned int     n,
                    std::vector<Point<2>> &points,
                    std::vector<double>   &weights)
      {
        const QGauss<1> q(n);
        points.clear();
        weights.clear();
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              const double u = q.point(i)[0], v = q.point(j)[0];
              points.emplace_back(u, v * (1. - u));
              weights.push_back(q.weight(i) * q.weight(j) * (1. - u));
            }
      }

      /// Calls f(xi, w) for the quadrature points of the given parameter
      /// polygons: each is cut into triangles fanning out from its vertex
      /// centroid, with the rule above on each. The weights carry the signed
      /// triangle areas, so a polygon that is not convex but star-shaped
      /// from its centroid is integrated exactly too.
      template <typename Function>
      void
      for_each_point(const std::vector<ParameterPolygon> &polygons,
                     const unsigned int                   n,
                     const Function                      &f)
      {
        std::vector<Point<2>> ref_points;
        std::vector<double>   ref_weights;
        triangle_rule(n, ref_points, ref_weights);
        for (const ParameterPolygon &polygon : polygons)
          {
            Point<2> c;
            for (const Point<2> &v : polygon)
              c += v / static_cast<double>(polygon.size());
            for (unsigned int k = 0; k < polygon.size(); ++k)
              {
                const Tensor<1, 2> a   = polygon[k] - c;
                const Tensor<1, 2> b   = polygon[(k + 1) % polygon.size()] - c;
                const double       det = cross_2d(a, b);
                if (det == 0.)
                  continue;
                for (unsigned int q = 0; q < ref_points.size(); ++q)
                  f(c + ref_points[q][0] * a + ref_points[q][1] * b, ref_weights[q] * det);
              }
          }
      }

      double
      clamp(const double x)
      {
        return std::max(-1., std::min(1., x));
      }

      /// Interpolated (not normalised) nodal normal field at @p xi.
      Tensor<1, 3>
      interpolated_normal(const QuadFace                  &face,
                          const std::vector<Tensor<1, 3>> &normals,
                          const Point<2>                  &xi)
      {
        AssertDimension(normals.size(), face.n_shape_nodes());
        Tensor<1, 3> n;
        for (unsigned int k = 0; k < normals.size(); ++k)
          n += quad_shape_value(face.shape_degree(), k, xi) * normals[k];
        return n;
      }
    } // namespace

    double
    quad_shape_value(const unsigned int p, const unsigned int i, const Point<2> &xi)
    {
      const auto [a, b] = line_indices(p, i);
      return shape_value(p, a, xi[0]) * shape_value(p, b, xi[1]);
    }

    Tensor<1, 2>
    quad_shape_gradient(const unsigned int p, const unsigned int i, const Point<2> &xi)
    {
      const auto [a, b] = line_indices(p, i);
      Tensor<1, 2> g;
      g[0] = shape_derivative(p, a, xi[0]) * shape_value(p, b, xi[1]);
      g[1] = shape_value(p, a, xi[0]) * shape_derivative(p, b, xi[1]);
      return g;
    }

    Point<2>
    quad_node_parameter(const unsigned int p, const unsigned int i)
    {
      const auto [a, b] = line_indices(p, i);
      return Point<2>(node_parameter(p, a), node_parameter(p, b));
    }

    Point<3>
    QuadFace::point(const Point<2> &xi) const
    {
      Assert(nodes.size() == 4 || nodes.size() == 9, ExcNotImplemented());
      Point<3> x;
      for (unsigned int i = 0; i < nodes.size(); ++i)
        x += quad_shape_value(degree(), i, xi) * nodes[i];
      return x;
    }

    std::array<Tensor<1, 3>, 2>
    QuadFace::tangents(const Point<2> &xi) const
    {
      Assert(nodes.size() == 4 || nodes.size() == 9, ExcNotImplemented());
      std::array<Tensor<1, 3>, 2> t;
      for (unsigned int i = 0; i < nodes.size(); ++i)
        {
          const Tensor<1, 2> g = quad_shape_gradient(degree(), i, xi);
          t[0] += g[0] * nodes[i];
          t[1] += g[1] * nodes[i];
        }
      return t;
    }

    Tensor<1, 3>
    face_normal(const QuadFace &face, const Point<2> &xi, const double orientation)
    {
      const auto         t = face.tangents(xi);
      const Tensor<1, 3> n = cross_product_3d(t[0], t[1]);
      return orientation * n / n.norm();
    }

    FullMatrix<double>
    dual_basis_coefficients(const QuadFace &slave, const std::vector<ParameterPolygon> &polygons)
    {
      Assert(!polygons.empty(), ExcMessage("The dual basis needs a non-empty overlap."));
      const unsigned int p = slave.shape_degree(), n = slave.n_shape_nodes();
      FullMatrix<double> Me(n, n), De(n, n);
      // Exact for flat parallelogram faces; the Jacobian of other faces is
      // not polynomial, hence the generous rule (as in 2D).
      for_each_point(polygons, 2 * p + 6, [&](const Point<2> &xi, const double w) {
        const auto   t   = slave.tangents(xi);
        const double jxw = cross_product_3d(t[0], t[1]).norm() * w;
        for (unsigned int j = 0; j < n; ++j)
          {
            const double Nj = quad_shape_value(p, j, xi);
            De(j, j) += Nj * jxw;
            for (unsigned int k = 0; k < n; ++k)
              Me(j, k) += Nj * quad_shape_value(p, k, xi) * jxw;
          }
      });
      FullMatrix<double> Me_inverse(n, n), A(n, n);
      Me_inverse.invert(Me);
      De.mmult(A, Me_inverse);
      return A;
    }

    bool
    project_along(const QuadFace     &face,
                  const Point<3>     &x,
                  const Tensor<1, 3> &direction,
                  Point<2>           &eta)
    {
      // Residual r(eta, t) = face(eta) - x - t d; linear in eta and t for
      // flat parallelograms, bilinear (or biquadratic) otherwise.
      eta      = Point<2>();
      double t = 0.;
      for (unsigned int it = 0; it < 30; ++it)
        {
          const auto         tangents = face.tangents(eta);
          const Tensor<1, 3> r        = face.point(eta) - x - t * direction;
          Tensor<2, 3>       J;
          for (unsigned int i = 0; i < 3; ++i)
            {
              J[i][0] = tangents[0][i];
              J[i][1] = tangents[1][i];
              J[i][2] = -direction[i];
            }
          const double scale = tangents[0].norm() * tangents[1].norm() * direction.norm();
          if (!(std::abs(determinant(J)) > 1e-12 * scale))
            return false;
          const Tensor<1, 3> step = invert(J) * r;
          eta[0] -= step[0];
          eta[1] -= step[1];
          t -= step[2];
          if (!(std::abs(eta[0]) < 1e3 && std::abs(eta[1]) < 1e3))
            return false;
          if (std::abs(step[0]) + std::abs(step[1]) < 1e-13)
            return true;
        }
      return false;
    }

    bool
    overlap(const QuadFace                  &slave,
            const std::vector<Tensor<1, 3>> &slave_normals,
            const QuadFace                  &master,
            std::vector<ParameterPolygon>   &polygons)
    {
      namespace bg       = boost::geometry;
      using BoostPoint   = bg::model::d2::point_xy<double>;
      using BoostPolygon = bg::model::polygon<BoostPoint, /*clockwise=*/false>;
      polygons.clear();

      // The auxiliary plane: through the slave centre, normal n0, spanned by
      // e1 (the slave xi tangent made orthogonal to n0) and e2 = n0 x e1.
      const Point<2> centre;
      Tensor<1, 3>   n0 = interpolated_normal(slave, slave_normals, centre);
      AssertThrow(n0.norm() > 0., ExcMessage("The slave normals cancel at the face centre."));
      n0 /= n0.norm();
      const Point<3> x0       = slave.point(centre);
      const auto     tangents = slave.tangents(centre);
      Tensor<1, 3>   e1       = tangents[0] - (tangents[0] * n0) * n0;
      e1 /= e1.norm();
      const Tensor<1, 3> e2 = cross_product_3d(n0, e1);

      // Projection along n0 into the plane, in (e1, e2) coordinates.
      const auto project = [&](const QuadFace &face) {
        BoostPolygon polygon;
        for (const unsigned int i : boundary_ring(face.degree()))
          {
            const Tensor<1, 3> r = face.nodes[i] - x0;
            bg::append(polygon.outer(), BoostPoint(r * e1, r * e2));
          }
        // Closes the ring and orients it counterclockwise: the master, whose
        // normal opposes n0, comes clockwise.
        bg::correct(polygon);
        return polygon;
      };
      const BoostPolygon slave_polygon = project(slave), master_polygon = project(master);
      const double       slave_area = bg::area(slave_polygon);
      // A master seen edge-on (or warped into a bow tie) from the plane
      // projects to no valid polygon: no overlap to integrate.
      if (!(bg::area(master_polygon) > 1e-10 * slave_area))
        return false;

      std::vector<BoostPolygon> intersection;
      try
        {
          bg::intersection(slave_polygon, master_polygon, intersection);
        }
      catch (const bg::exception &)
        {
          // Invalid input (a self-intersecting projected polygon): as above.
          return false;
        }

      for (const BoostPolygon &piece : intersection)
        {
          // Touching edges or corners give no piece or a zero-area one;
          // slivers of this relative size are round-off of shared edges.
          if (!(bg::area(piece) > 1e-10 * slave_area))
            continue;
          const auto &ring = piece.outer();
          // Boost closes the ring by repeating the first vertex.
          const std::size_t n_vertices =
            (ring.size() > 1 && bg::equals(ring.front(), ring.back())) ? ring.size() - 1 :
                                                                          ring.size();
          ParameterPolygon polygon;
          for (std::size_t v = 0; v < n_vertices; ++v)
            {
              const Point<3> x = x0 + ring[v].x() * e1 + ring[v].y() * e2;
              Point<2>       xi;
              if (!project_along(slave, x, n0, xi))
                {
                  polygons.clear();
                  return false;
                }
              // Vertices on the slave boundary come back up to round-off.
              polygon.emplace_back(clamp(xi[0]), clamp(xi[1]));
            }
          double area = 0.;
          for (std::size_t v = 0; v < polygon.size(); ++v)
            area += cross_2d(polygon[v], polygon[(v + 1) % polygon.size()]);
          // The slave's parameter orientation relative to n0 depends on its
          // vertex order (deal.II face orientation): make it counterclockwise.
          if (area < 0.)
            std::reverse(polygon.begin(), polygon.end());
          polygons.push_back(polygon);
        }
      return !polygons.empty();
    }

    bool
    integrate_pair(const QuadFace                  &slave,
                   const std::vector<Tensor<1, 3>> &slave_normals,
                   const FullMatrix<double>        &dual_coefficients,
                   const QuadFace                  &master,
                   const unsigned int               n_quadrature_points,
                   QuadSegmentOperators            &result)
    {
      if (!overlap(slave, slave_normals, master, result.polygons))
        return false;
      const unsigned int ps = slave.shape_degree(), pm = master.shape_degree();
      const unsigned int ns = slave.n_shape_nodes(), nm = master.n_shape_nodes();
      AssertDimension(dual_coefficients.m(), ns);

      result.D.assign(ns, 0.);
      result.weighted_gap.assign(ns, Tensor<1, 3>());
      result.M.reinit(ns, nm);
      result.overlap_area = 0.;

      std::vector<double> phi(ns);
      for_each_point(result.polygons, n_quadrature_points, [&](const Point<2> &xi, const double w) {
        const auto     t       = slave.tangents(xi);
        const double   jxw     = cross_product_3d(t[0], t[1]).norm() * w;
        const Point<3> x_slave = slave.point(xi);
        Point<2>       eta;
        if (!project_along(master, x_slave, interpolated_normal(slave, slave_normals, xi), eta))
          return;
        // The segmentation projected along n0, the normal field may differ
        // slightly: stay on the master face (partition of unity kept).
        eta                           = Point<2>(clamp(eta[0]), clamp(eta[1]));
        const Tensor<1, 3> separation = master.point(eta) - x_slave;

        result.overlap_area += jxw;
        for (unsigned int j = 0; j < ns; ++j)
          {
            phi[j] = 0.;
            for (unsigned int k = 0; k < ns; ++k)
              phi[j] += dual_coefficients(j, k) * quad_shape_value(ps, k, xi);
            result.D[j] += phi[j] * jxw;
            result.weighted_gap[j] += phi[j] * jxw * separation;
          }
        for (unsigned int l = 0; l < nm; ++l)
          {
            const double Nl = quad_shape_value(pm, l, eta);
            for (unsigned int j = 0; j < ns; ++j)
              result.M(j, l) += phi[j] * Nl * jxw;
          }
      });
      return result.overlap_area > 0.;
    }
  } // namespace Mortar
} // namespace contact_fem
