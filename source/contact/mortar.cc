#include <deal.II/base/quadrature_lib.h>

#include <contact_fem/contact/mortar.h>
#include <contact_fem/contact/mortar_kernel.h>
#include <contact_fem/core/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace contact_fem
{
  namespace Mortar
  {
    double
    node_parameter(const unsigned int p, const unsigned int i)
    {
      Assert(p == 1 || p == 2, ExcNotImplemented());
      (void)p;
      return (i == 0 ? -1. : (i == 1 ? 1. : 0.));
    }

    double
    shape_value(const unsigned int p, const unsigned int i, const double xi)
    {
      if (p == 1)
        return (i == 0 ? 0.5 * (1. - xi) : 0.5 * (1. + xi));
      Assert(p == 2, ExcNotImplemented());
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

    double
    lebesgue_constant(const unsigned int p)
    {
      Assert(p == 1 || p == 2, ExcNotImplemented());
      // Degree 2: |N_0| + |N_1| + |N_2| = 1 + |xi| - xi^2, largest at |xi| = 1/2.
      return p == 1 ? 1. : 1.25;
    }

    template <int spacedim>
    BoundingBox<spacedim>
    interpolant_box(const std::vector<Point<spacedim>> &nodes, const double lebesgue)
    {
      const auto [low, high] = BoundingBox<spacedim>(nodes).get_boundary_points();
      Point<spacedim> lower, upper;
      for (unsigned int d = 0; d < spacedim; ++d)
        {
          const double centre = 0.5 * (low[d] + high[d]);
          const double radius = 0.5 * (high[d] - low[d]) * lebesgue +
                                1e-12 * (std::abs(centre) + 0.5 * (high[d] - low[d]));
          lower[d] = centre - radius;
          upper[d] = centre + radius;
        }
      return BoundingBox<spacedim>(std::make_pair(lower, upper));
    }

    template BoundingBox<2>
    interpolant_box(const std::vector<Point<2>> &, const double);
    template BoundingBox<3>
    interpolant_box(const std::vector<Point<3>> &, const double);

    double
    shape_derivative(const unsigned int p, const unsigned int i, const double xi)
    {
      if (p == 1)
        return (i == 0 ? -0.5 : 0.5);
      Assert(p == 2, ExcNotImplemented());
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

    Point<2>
    LineFace::point(const double xi) const
    {
      Point<2> x;
      for (unsigned int i = 0; i < nodes.size(); ++i)
        x += shape_value(degree(), i, xi) * nodes[i];
      return x;
    }

    Tensor<1, 2>
    LineFace::tangent(const double xi) const
    {
      Tensor<1, 2> t;
      for (unsigned int i = 0; i < nodes.size(); ++i)
        t += shape_derivative(degree(), i, xi) * nodes[i];
      return t;
    }

    Tensor<1, 2>
    face_normal(const LineFace &face, const double xi, const double orientation)
    {
      const Tensor<1, 2> t = face.tangent(xi);
      Tensor<1, 2>       n;
      n[0] = t[1];
      n[1] = -t[0];
      return orientation * n / n.norm();
    }

    namespace
    {
      double
      cross(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
      {
        return a[0] * b[1] - a[1] * b[0];
      }

      /// Gauss rule on [-1, 1] (weights sum to 2).
      void
      gauss_rule(const unsigned int n, std::vector<double> &points, std::vector<double> &weights)
      {
        const QGauss<1> q(n);
        points.resize(n);
        weights.resize(n);
        for (unsigned int i = 0; i < n; ++i)
          {
            points[i]  = 2. * q.point(i)[0] - 1.;
            weights[i] = 2. * q.weight(i);
          }
      }
    } // namespace

    FullMatrix<double>
    dual_basis_coefficients(const LineFace                               &slave,
                            const std::vector<std::pair<double, double>> &intervals)
    {
      const unsigned int p = slave.shape_degree(), n = p + 1;
      // Exact for straight faces; curved faces have a non-polynomial
      // Jacobian, hence the generous rule.
      std::vector<double> xg, wg;
      gauss_rule(2 * p + 8, xg, wg);
      std::vector<double> xq, wq;
      for (const auto &[a, b] : intervals)
        for (unsigned int q = 0; q < xg.size(); ++q)
          {
            xq.push_back(a + 0.5 * (xg[q] + 1.) * (b - a));
            wq.push_back(0.5 * (b - a) * wg[q]);
          }

      FullMatrix<double> Me(n, n), De(n, n);
      for (unsigned int q = 0; q < xq.size(); ++q)
        {
          const double jxw = slave.tangent(xq[q]).norm() * wq[q];
          for (unsigned int j = 0; j < n; ++j)
            {
              const double Nj = shape_value(p, j, xq[q]);
              De(j, j) += Nj * jxw;
              for (unsigned int k = 0; k < n; ++k)
                Me(j, k) += Nj * shape_value(p, k, xq[q]) * jxw;
            }
        }
      FullMatrix<double> Me_inverse(n, n), A(n, n);
      Me_inverse.invert(Me);
      De.mmult(A, Me_inverse);
      return A;
    }

    namespace
    {
      /// (face(eta) - x) x d for each face node's parameter: the offsets of
      /// the face from the line through @p x along @p d. The differences
      /// x_i - x are formed first, so that the round-off is that of the
      /// face's size, not of the coordinates' distance from the origin.
      double
      line_offset(const LineFace &face, const Point<2> &x, const Tensor<1, 2> &d, const double eta)
      {
        Tensor<1, 2> r;
        for (unsigned int i = 0; i < face.nodes.size(); ++i)
          r += shape_value(face.degree(), i, eta) * (face.nodes[i] - x);
        return cross(r, d);
      }

      /**
       * A root of @p f (returning the value and the derivative) between
       * @p a and @p b, where f(a) and f(b) differ in sign: Newton steps
       * that stay in the bracket, bisection otherwise. The bracket shrinks
       * at every step, so it ends at the precision that double arithmetic
       * reaches, whatever the round-off of f.
       */
      template <typename Function>
      double
      bracketed_root(const Function &f, double a, double b)
      {
        double fa = f(a).first;
        if (fa == 0.)
          return a;
        constexpr double epsilon = std::numeric_limits<double>::epsilon();
        double           x = 0.5 * (a + b), step = std::abs(b - a), step_before = step;
        for (unsigned int it = 0; it < 200; ++it)
          {
            const auto [fx, dfx] = f(x);
            if (fx == 0.)
              return x;
            if ((fx < 0.) == (fa < 0.))
              {
                a  = x;
                fa = fx;
              }
            else
              b = x;
            const double newton = x - fx / dfx;
            step_before         = step;
            // Bisect where Newton leaves the bracket or does not halve the
            // step of two iterations ago.
            if (!(std::isfinite(newton) && (newton - a) * (newton - b) < 0.) ||
                std::abs(newton - x) > 0.5 * step_before)
              {
                step = 0.5 * std::abs(b - a);
                x    = 0.5 * (a + b);
              }
            else
              {
                step = std::abs(newton - x);
                x    = newton;
              }
            if (step <= 4. * epsilon * std::max(1., std::abs(x)))
              return x;
          }
        return x;
      }
    } // namespace

    bool
    project_along(const LineFace     &face,
                  const Point<2>     &x,
                  const Tensor<1, 2> &direction,
                  double             &eta)
    {
      // f(eta) = (face(eta) - x) x d: linear in eta on straight faces,
      // quadratic on curved ones. Where f changes sign between the face's
      // ends the line crosses the face: the root is bracketed. Otherwise the
      // line passes beside the face, and the continuation of the chord says
      // on which side.
      const double f_begin = line_offset(face, x, direction, -1.);
      const double f_end   = line_offset(face, x, direction, 1.);
      if ((f_begin <= 0.) != (f_end <= 0.) || f_begin == 0. || f_end == 0.)
        {
          eta = bracketed_root(
            [&](const double e) {
              return std::make_pair(line_offset(face, x, direction, e),
                                    cross(face.tangent(e), direction));
            },
            -1., 1.);
          return true;
        }
      // No crossing (a curved face may also be crossed twice, which the
      // interpolated normals of neighbouring faces never ask for).
      if (f_end == f_begin)
        return false;
      eta = -1. - 2. * f_begin / (f_end - f_begin);
      return std::isfinite(eta);
    }

    namespace
    {
      /// (x - s(xi)) x n(xi), s the slave face, n its interpolated nodal
      /// normal, and its derivative; differences formed as in line_offset().
      std::pair<double, double>
      normal_line_offset(const LineFace                  &slave,
                         const std::vector<Tensor<1, 2>> &normals,
                         const Point<2>                  &x,
                         const double                     xi)
      {
        const unsigned int p = slave.shape_degree();
        Tensor<1, 2>       n, dn, r;
        for (unsigned int i = 0; i <= p; ++i)
          {
            n += shape_value(p, i, xi) * normals[i];
            dn += shape_derivative(p, i, xi) * normals[i];
          }
        for (unsigned int i = 0; i < slave.nodes.size(); ++i)
          r += shape_value(slave.degree(), i, xi) * (x - slave.nodes[i]);
        return {cross(r, n), cross(-slave.tangent(xi), n) + cross(r, dn)};
      }

      /// Slave parameter xi in [-1, 1] whose point, moved along the
      /// interpolated nodal normal n(xi), passes through @p x, for a point
      /// @p x that lies between the normal lines of the slave's end nodes
      /// (a master end inside the slave's shadow). At round-off distance of
      /// an end line the nearer end is the answer.
      double
      slave_image(const LineFace                  &slave,
                  const std::vector<Tensor<1, 2>> &normals,
                  const Point<2>                  &x)
      {
        const auto f = [&](const double xi) {
          return normal_line_offset(slave, normals, x, xi);
        };
        const double g_begin = f(-1.).first, g_end = f(1.).first;
        if ((g_begin < 0.) == (g_end < 0.) && g_begin != 0. && g_end != 0.)
          return std::abs(g_begin) < std::abs(g_end) ? -1. : 1.;
        return bracketed_root(f, -1., 1.);
      }
    } // namespace

    bool
    overlap(const LineFace                  &slave,
            const std::vector<Tensor<1, 2>> &slave_normals,
            const LineFace                  &master,
            double                          &lower,
            double                          &upper,
            std::array<int, 2>              *bounding_master_ends)
    {
      // Where do the slave ends land on the master? The map xi -> eta is
      // monotone on the face, so the overlap follows from eta(-1), eta(1)
      // and, for master ends in between, the slave images of those ends.
      // Every decision is geometric: a slave end either lands on the master
      // face or beside it on a known side; projections do not fail.
      double eta_a = 0., eta_b = 0.;
      if (!project_along(master, slave.nodes[0], slave_normals[0], eta_a) ||
          !project_along(master, slave.nodes[1], slave_normals[1], eta_b))
        return false;
      if (std::max(eta_a, eta_b) <= -1. || std::min(eta_a, eta_b) >= 1. || eta_a == eta_b)
        return false;
      lower                   = -1.;
      upper                   = 1.;
      std::array<int, 2> ends = {{-1, -1}};
      for (const int end : {0, 1})
        {
          const double eta = end == 0 ? -1. : 1.;
          if (eta > std::min(eta_a, eta_b) && eta < std::max(eta_a, eta_b))
            {
              const double xi = slave_image(slave, slave_normals, master.point(eta));
              // The part of the slave face beyond this master end is outside.
              const bool beyond_is_upper = (eta_b - eta_a) * eta > 0.;
              if (beyond_is_upper && xi < upper)
                {
                  upper   = xi;
                  ends[1] = end;
                }
              else if (!beyond_is_upper && xi > lower)
                {
                  lower   = xi;
                  ends[0] = end;
                }
            }
        }
      if (bounding_master_ends)
        *bounding_master_ends = ends;
      // Overlaps shorter than this are round-off of a shared end point.
      return upper - lower >= 1e-10;
    }

    bool
    integrate_pair(const LineFace                  &slave,
                   const std::vector<Tensor<1, 2>> &slave_normals,
                   const FullMatrix<double>        &dual_coefficients,
                   const LineFace                  &master,
                   const unsigned int               n_quadrature_points,
                   SegmentOperators                &result)
    {
      const unsigned int ps = slave.shape_degree(), pm = master.shape_degree();
      double             lower = -1., upper = 1.;
      if (!overlap(slave, slave_normals, master, lower, upper))
        return false;

      result.D.assign(ps + 1, 0.);
      result.weighted_gap.assign(ps + 1, Tensor<1, 2>());
      result.M.reinit(ps + 1, pm + 1);
      result.overlap_length = 0.;
      result.xi_begin       = lower;
      result.xi_end         = upper;

      std::vector<double> xq, wq, phi(ps + 1);
      gauss_rule(n_quadrature_points, xq, wq);
      for (unsigned int q = 0; q < xq.size(); ++q)
        {
          // Map the Gauss point into the overlap interval of the slave face.
          const double xi  = lower + 0.5 * (xq[q] + 1.) * (upper - lower);
          const double jxw = slave.tangent(xi).norm() * wq[q] * 0.5 * (upper - lower);

          Tensor<1, 2> n;
          for (unsigned int i = 0; i <= ps; ++i)
            n += shape_value(ps, i, xi) * slave_normals[i];
          const Point<2> x_slave = slave.point(xi);
          double         eta     = 0.;
          // Inside the overlap the normal line crosses the master face, up
          // to round-off at the overlap's ends.
          constexpr double round_off_beyond_end = 1e-8;
          AssertThrow(project_along(master, x_slave, n, eta) &&
                        std::abs(eta) <= 1. + round_off_beyond_end,
                      ExcMessage("Mortar integration: the slave face from " +
                                 coordinates_text(slave.nodes[0]) + " to " +
                                 coordinates_text(slave.nodes[1]) +
                                 " has a quadrature point of its overlap that does not "
                                 "project onto the master face from " +
                                 coordinates_text(master.nodes[0]) + " to " +
                                 coordinates_text(master.nodes[1]) + "."));
          eta                           = std::max(-1., std::min(1., eta));
          const Tensor<1, 2> separation = master.point(eta) - x_slave;

          result.overlap_length += jxw;
          add_quadrature_point<2>(dual_coefficients, ps, pm, xi, eta, jxw, separation, phi, result);
        }
      return result.overlap_length > 0.;
    }

    double
    closest_parameter(const LineFace &face, const Point<2> &x)
    {
      const Tensor<1, 2> chord = face.nodes[1] - face.nodes[0];
      double             xi =
        std::clamp(2. * ((x - face.nodes[0]) * chord) / chord.norm_square() - 1., -1., 1.);
      if (face.degree() == 1)
        return xi;
      for (unsigned int it = 0; it < 20; ++it)
        {
          const Tensor<1, 2> t                   = face.tangent(xi);
          const double       step                = ((x - face.point(xi)) * t) / t.norm_square();
          const double       next                = std::clamp(xi + step, -1., 1.);
          constexpr double   parameter_tolerance = 1e-12;
          const bool         done                = std::abs(next - xi) < parameter_tolerance;
          xi                                     = next;
          if (done)
            break;
        }
      return xi;
    }

    BoundingBox<2>
    whole_face_box(const LineFace &face)
    {
      return interpolant_box(face.nodes, lebesgue_constant(face.degree()));
    }

    unsigned int
    n_quadrature_points(const LineFace &slave, const LineFace &)
    {
      return slave.shape_degree() + 3;
    }
  } // namespace Mortar
} // namespace contact_fem
