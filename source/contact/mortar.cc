#include <deal.II/base/quadrature_lib.h>

#include <contact_fem/contact/mortar.h>
#include <contact_fem/contact/mortar_kernel.h>
#include <contact_fem/contact/mortar_number.h>
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
      Assert(p == 1 || p == 2, ExcNotImplemented());
      return lagrange_value(p, i, xi);
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
      Assert(p == 1 || p == 2, ExcNotImplemented());
      return lagrange_derivative(p, i, xi);
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

    FullMatrix<double>
    dual_basis_coefficients(const LineFace                               &slave,
                            const std::vector<std::pair<double, double>> &intervals)
    {
      const unsigned int n = slave.shape_degree() + 1;
      FullMatrix<double> Me(n, n), De(n, n);
      dual_basis_integrals(slave, intervals, De, Me);
      FullMatrix<double> Me_inverse(n, n), A(n, n);
      Me_inverse.invert(Me);
      De.mmult(A, Me_inverse);
      return A;
    }

    namespace
    {
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
      /// Slave parameter @p xi in [-1, 1] whose point, moved along the
      /// interpolated nodal normal n(xi), passes through @p x, for a point
      /// @p x that lies between the normal lines of the slave's end nodes
      /// (a master end inside the slave's shadow). At round-off distance of
      /// an end line the nearer end is the answer. False if @p x lies
      /// clearly outside both lines: the end normals then cross before
      /// they reach the master's line (a distant master face, e.g. a
      /// steep flank of a die above an indented slave face), the map xi ->
      /// eta is not monotone and the faces do not overlap.
      bool
      slave_image(const LineFace                  &slave,
                  const std::vector<Tensor<1, 2>> &normals,
                  const Point<2>                  &x,
                  double                          &xi)
      {
        const auto f = [&](const double xi) {
          return normal_line_offset(slave, normals, x, xi);
        };
        const double g_begin = f(-1.).first, g_end = f(1.).first;
        if ((g_begin < 0.) == (g_end < 0.) && g_begin != 0. && g_end != 0.)
          {
            constexpr double round_off = 1e-8;
            xi = std::abs(g_begin) < std::abs(g_end) ? -1. : 1.;
            return std::min(std::abs(g_begin), std::abs(g_end)) <=
                   round_off * (slave.nodes[1] - slave.nodes[0]).norm();
          }
        xi = bracketed_root(f, -1., 1.);
        return true;
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
              double xi = 0.;
              if (!slave_image(slave, slave_normals, master.point(eta), xi))
                return false;
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
      double lower = -1., upper = 1.;
      if (!overlap(slave, slave_normals, master, lower, upper))
        return false;

      integrate_overlap(slave, slave_normals, dual_coefficients, master, slave, master,
                        n_quadrature_points, lower, upper, result);
      return result.overlap_length > 0.;
    }

    double
    master_parameter(const LineFace     &slave,
                     const LineFace     &master,
                     const Point<2>     &x,
                     const Tensor<1, 2> &n)
    {
      double eta = 0.;
      // Inside the overlap the normal line crosses the master face, up to
      // round-off at the overlap's ends.
      constexpr double round_off_beyond_end = 1e-8;
      AssertThrow(project_along(master, x, n, eta) && std::abs(eta) <= 1. + round_off_beyond_end,
                  ExcMessage("Mortar integration: the slave face from " +
                             coordinates_text(slave.nodes[0]) + " to " +
                             coordinates_text(slave.nodes[1]) +
                             " has a quadrature point of its overlap that does not "
                             "project onto the master face from " +
                             coordinates_text(master.nodes[0]) + " to " +
                             coordinates_text(master.nodes[1]) + "."));
      return std::max(-1., std::min(1., eta));
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
