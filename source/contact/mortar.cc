#include <deal.II/base/quadrature_lib.h>

#include <contact_fem/contact/mortar.h>

#include <algorithm>
#include <cmath>

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
      gauss_rule(const unsigned int   n,
                 std::vector<double> &points,
                 std::vector<double> &weights)
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
    dual_basis_coefficients(const LineFace                                &slave,
                            const std::vector<std::pair<double, double>> &intervals)
    {
      const unsigned int  p = slave.shape_degree(), n = p + 1;
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

    bool
    project_along(const LineFace     &face,
                  const Point<2>     &x,
                  const Tensor<1, 2> &direction,
                  double             &eta)
    {
      // f(eta) = (face(eta) - x) x d; linear in eta for straight faces.
      eta = 0.;
      const double scale = face.tangent(0.).norm() * direction.norm();
      for (unsigned int it = 0; it < 20; ++it)
        {
          const double f  = cross(face.point(eta) - x, direction);
          const double df = cross(face.tangent(eta), direction);
          if (std::abs(df) < 1e-12 * scale)
            return false;
          const double step = f / df;
          eta -= step;
          if (std::abs(step) < 1e-13)
            return std::isfinite(eta);
        }
      return false;
    }

    namespace
    {
      /// Slave parameter xi whose point, moved along the interpolated nodal
      /// normal n(xi), passes through @p x: (x - s(xi)) x n(xi) = 0. Newton
      /// from the given xi (a quadratic equation for straight slave faces:
      /// the start must be near the wanted root).
      bool
      slave_image(const LineFace                   &slave,
                  const std::vector<Tensor<1, 2>> &normals,
                  const Point<2>                  &x,
                  double                          &xi)
      {
        const unsigned int p = slave.shape_degree();
        for (unsigned int it = 0; it < 30; ++it)
          {
            Tensor<1, 2> n, dn;
            for (unsigned int i = 0; i <= p; ++i)
              {
                n += shape_value(p, i, xi) * normals[i];
                dn += shape_derivative(p, i, xi) * normals[i];
              }
            const Tensor<1, 2> r  = x - slave.point(xi);
            const double       f  = cross(r, n);
            const double       df = cross(-slave.tangent(xi), n) + cross(r, dn);
            if (std::abs(df) < 1e-14 * slave.tangent(xi).norm())
              return false;
            const double step = f / df;
            xi -= step;
            if (std::abs(step) < 1e-13)
              return std::isfinite(xi);
          }
        return false;
      }
    } // namespace

    bool
    overlap(const LineFace                   &slave,
            const std::vector<Tensor<1, 2>> &slave_normals,
            const LineFace                   &master,
            double                           &lower,
            double                           &upper)
    {
      // Where do the slave ends land on the master? The map xi -> eta is
      // monotone on the face, so the overlap follows from eta(-1), eta(1)
      // and, for master ends in between, the slave images of those ends
      // (found by Newton from the linear guess, which picks the root inside
      // the face; the other root of the quadratic lies far outside).
      double eta_a = 0., eta_b = 0.;
      if (!project_along(master, slave.nodes[0], slave_normals[0], eta_a) ||
          !project_along(master, slave.nodes[1], slave_normals[1], eta_b))
        return false;
      if (std::max(eta_a, eta_b) <= -1. || std::min(eta_a, eta_b) >= 1. ||
          eta_a == eta_b)
        return false;
      lower = -1.;
      upper = 1.;
      for (const double end : {-1., 1.})
        if (end > std::min(eta_a, eta_b) && end < std::max(eta_a, eta_b))
          {
            double xi = -1. + 2. * (end - eta_a) / (eta_b - eta_a);
            if (!slave_image(slave, slave_normals, master.point(end), xi))
              return false;
            xi = std::max(-1., std::min(1., xi));
            // The part of the slave face beyond this master end is outside.
            const bool beyond_is_upper = (eta_b - eta_a) * end > 0.;
            if (beyond_is_upper)
              upper = std::min(upper, xi);
            else
              lower = std::max(lower, xi);
          }
      // Overlaps shorter than this are round-off of a shared end point.
      return upper - lower >= 1e-10;

    }

    bool
    integrate_pair(const LineFace                   &slave,
                   const std::vector<Tensor<1, 2>> &slave_normals,
                   const FullMatrix<double>        &dual_coefficients,
                   const LineFace                   &master,
                   const unsigned int                n_quadrature_points,
                   SegmentOperators                 &result)
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

      std::vector<double> xq, wq;
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
          if (!project_along(master, x_slave, n, eta))
            continue;
          // Guard against round-off just outside the master face.
          eta = std::max(-1., std::min(1., eta));
          const Tensor<1, 2> separation = master.point(eta) - x_slave;

          result.overlap_length += jxw;
          for (unsigned int j = 0; j <= ps; ++j)
            {
              double phi_j = 0.;
              for (unsigned int k = 0; k <= ps; ++k)
                phi_j += dual_coefficients(j, k) * shape_value(ps, k, xi);
              result.D[j] += phi_j * jxw;
              result.weighted_gap[j] += phi_j * jxw * separation;
              for (unsigned int l = 0; l <= pm; ++l)
                result.M(j, l) += phi_j * shape_value(pm, l, eta) * jxw;
            }
        }
      return result.overlap_length > 0.;
    }
  } // namespace Mortar
} // namespace contact_fem
