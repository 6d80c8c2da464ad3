// The 2D mortar kernel written once over the number type: double in the
// operators (mortar.cc) and a forward automatic-differentiation number in
// their linearisation (mortar_linearisation.cc). Decisions (which end bounds
// an overlap) and iterative roots are always taken in double; an AD number
// only adds the derivatives to those values (implicit_root()).
#ifndef contact_fem_mortar_number_h
#define contact_fem_mortar_number_h

#include <deal.II/base/table.h>

#include <contact_fem/contact/mortar.h>
#include <contact_fem/contact/mortar_kernel.h>

#include <cmath>
#include <type_traits>
#include <utility>
#include <vector>

namespace contact_fem
{
  namespace Mortar
  {
    /// The value of a double or of an AD number.
    template <typename Number>
    double
    value_of(const Number &x)
    {
      if constexpr (std::is_same_v<Number, double>)
        return x;
      else
        return x.val();
    }

    /// The values of a vector of double or AD numbers.
    template <typename Number>
    Tensor<1, 2>
    values_of(const Tensor<1, 2, Number> &x)
    {
      if constexpr (std::is_same_v<Number, double>)
        return x;
      else
        {
          Tensor<1, 2> v;
          v[0] = x[0].val();
          v[1] = x[1].val();
          return v;
        }
    }

    /// a x b in the plane.
    template <typename Number>
    Number
    cross(const Tensor<1, 2, Number> &a, const Tensor<1, 2, Number> &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }

    /// |t|, for double exactly Tensor::norm().
    template <typename Number>
    Number
    length(const Tensor<1, 2, Number> &t)
    {
      if constexpr (std::is_same_v<Number, double>)
        return t.norm();
      else
        {
          using std::sqrt;
          return sqrt(t[0] * t[0] + t[1] * t[1]);
        }
    }

    /// |t| in 3D, for double exactly Tensor::norm().
    template <typename Number>
    Number
    length(const Tensor<1, 3, Number> &t)
    {
      if constexpr (std::is_same_v<Number, double>)
        return t.norm();
      else
        {
          using std::sqrt;
          return sqrt(t * t);
        }
    }

    /**
     * The dual basis coefficients A = D_e M_e^{-1} in AD numbers from
     * their values @p A (the double path) and the AD integrals @p De and
     * @p Me: the value A; the derivative that of dA = (dD_e - A dM_e)
     * M_e^{-1}, carried by the AD numbers (D_e - A M_e) M_e^{-1}, whose
     * value is round-off.
     */
    template <typename Number>
    Table<2, Number>
    dual_coefficients_of(const FullMatrix<double> &A,
                         const Table<2, Number>   &De,
                         const Table<2, Number>   &Me)
    {
      const unsigned int n = A.m();
      FullMatrix<double> Me_values(n, n), Me_inverse(n, n);
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int k = 0; k < n; ++k)
          Me_values(j, k) = value_of(Me(j, k));
      Me_inverse.invert(Me_values);
      Table<2, Number> result(n, n);
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int k = 0; k < n; ++k)
          {
            Number a = 0.;
            for (unsigned int i = 0; i < n; ++i)
              {
                Number r = De(j, i);
                for (unsigned int m = 0; m < n; ++m)
                  r -= A(j, m) * Me(m, i);
                a += r * Me_inverse(i, k);
              }
            a.val()      = A(j, k);
            result(j, k) = a;
          }
      return result;
    }

    /// A LineFace whose node coordinates are numbers of type Number.
    template <typename Number>
    struct LineFaceOf : LineFaceNodes<Tensor<1, 2, Number>>
    {
      using LineFaceNodes<Tensor<1, 2, Number>>::nodes;
      using LineFaceNodes<Tensor<1, 2, Number>>::degree;

      Tensor<1, 2, Number>
      point(const Number &xi) const
      {
        return interpolate(xi, &lagrange_value<Number>);
      }
      Tensor<1, 2, Number>
      tangent(const Number &xi) const
      {
        return interpolate(xi, &lagrange_derivative<Number>);
      }

    private:
      /// sum_i shape(p, i, xi) x_i.
      Tensor<1, 2, Number>
      interpolate(const Number &xi,
                  Number (*shape)(const unsigned int, const unsigned int, const Number &)) const
      {
        Tensor<1, 2, Number> x;
        for (unsigned int i = 0; i < nodes.size(); ++i)
          x += shape(degree(), i, xi) * nodes[i];
        return x;
      }
    };

    /// Gauss rule on [-1, 1] (weights sum to 2).
    void
    gauss_rule(const unsigned int n, std::vector<double> &points, std::vector<double> &weights);

    /**
     * A root of f(x) = 0 whose value @p root was found in double (by
     * bracketing). For an AD number: one Newton step from it in AD
     * numbers, x = root - f(root) / f'(root). Its derivative part is
     * -(df/dp) / f', the derivative of the root that the implicit-function
     * theorem gives (f(root) = 0); its value is set back to @p root, which
     * the step moves by round-off only. @p f returns f and df/dx.
     */
    template <typename Number, typename Function>
    Number
    implicit_root(const double root, const Function &f)
    {
      if constexpr (std::is_same_v<Number, double>)
        return root;
      else
        {
          const std::pair<Number, Number> f_root = f(Number(root));
          Number                          x      = root - f_root.first / f_root.second.val();
          x.val()                                = root;
          return x;
        }
    }

    /// (face(eta) - x) x d: the offset of @p face at @p eta from the line
    /// through @p x along @p d. The differences x_i - x are formed first,
    /// so that the round-off is that of the face's size, not of the
    /// coordinates' distance from the origin.
    template <typename Face, typename Vector, typename Number>
    Number
    line_offset(const Face &face, const Vector &x, const Tensor<1, 2, Number> &d, const Number &eta)
    {
      Tensor<1, 2, Number> r;
      for (unsigned int i = 0; i < face.nodes.size(); ++i)
        r += lagrange_value(face.degree(), i, eta) * (face.nodes[i] - x);
      return cross(r, d);
    }

    /// (x - s(xi)) x n(xi), s the slave face, n its interpolated nodal
    /// normal, and its derivative; differences formed as in line_offset().
    template <typename Face, typename Vector, typename Number>
    std::pair<Number, Number>
    normal_line_offset(const Face                              &slave,
                       const std::vector<Tensor<1, 2, Number>> &normals,
                       const Vector                            &x,
                       const Number                            &xi)
    {
      const unsigned int   p = slave.shape_degree();
      Tensor<1, 2, Number> n, dn, r;
      for (unsigned int i = 0; i <= p; ++i)
        {
          n += lagrange_value(p, i, xi) * normals[i];
          dn += lagrange_derivative(p, i, xi) * normals[i];
        }
      for (unsigned int i = 0; i < slave.nodes.size(); ++i)
        r += lagrange_value(slave.degree(), i, xi) * (x - slave.nodes[i]);
      return {cross(r, n), cross(-slave.tangent(xi), n) + cross(r, dn)};
    }

    /// The nodal normals @p normals interpolated by the shapes of degree
    /// @p p at @p xi.
    template <typename Number>
    Tensor<1, 2, Number>
    interpolated_normal(const unsigned int                       p,
                        const std::vector<Tensor<1, 2, Number>> &normals,
                        const Number                            &xi)
    {
      Tensor<1, 2, Number> n;
      for (unsigned int i = 0; i <= p; ++i)
        n += lagrange_value(p, i, xi) * normals[i];
      return n;
    }

    /// The master parameter of the point @p x moved along @p d, whose value
    /// @p eta was found in double (project_along()).
    template <typename Face, typename Vector, typename Number>
    Number
    projected_parameter(const Face                 &master,
                        const Vector               &x,
                        const Tensor<1, 2, Number> &d,
                        const double                eta)
    {
      return implicit_root<Number>(eta, [&](const Number &e) {
        return std::make_pair(line_offset(master, x, d, e), cross(master.tangent(e), d));
      });
    }

    /**
     * The integrals D_e = diag(int N_j) and M_e = (int N_j N_k) of the dual
     * basis (dual_basis_coefficients()) over the slave parameter
     * @p intervals. @p De, @p Me: zero matrices of size n_shapes.
     */
    template <typename Face, typename Number, typename Matrix>
    void
    dual_basis_integrals(const Face                                   &slave,
                         const std::vector<std::pair<Number, Number>> &intervals,
                         Matrix                                       &De,
                         Matrix                                       &Me)
    {
      const unsigned int p = slave.shape_degree(), n = p + 1;
      // Exact for straight faces; curved faces have a non-polynomial
      // Jacobian, hence the generous rule.
      std::vector<double> xg, wg;
      gauss_rule(2 * p + 8, xg, wg);
      std::vector<Number> xq, wq;
      for (const auto &[a, b] : intervals)
        for (unsigned int q = 0; q < xg.size(); ++q)
          {
            xq.push_back(a + 0.5 * (xg[q] + 1.) * (b - a));
            wq.push_back(0.5 * (b - a) * wg[q]);
          }
      for (unsigned int q = 0; q < xq.size(); ++q)
        {
          const Number jxw = length(slave.tangent(xq[q])) * wq[q];
          for (unsigned int j = 0; j < n; ++j)
            {
              const Number Nj = lagrange_value(p, j, xq[q]);
              De(j, j) += Nj * jxw;
              for (unsigned int k = 0; k < n; ++k)
                Me(j, k) += Nj * lagrange_value(p, k, xq[q]) * jxw;
            }
        }
    }

    /// The master parameter of the slave point @p x moved along the normal
    /// @p n, found in double; throws if it misses the master (see
    /// integrate_overlap()).
    double
    master_parameter(const LineFace     &slave,
                     const LineFace     &master,
                     const Point<2>     &x,
                     const Tensor<1, 2> &n);

    /**
     * The blocks of one slave/master pair on the overlap [@p lower,
     * @p upper] of slave parameters (integrate_pair()): Gauss quadrature
     * with @p n_points, each point projected along the interpolated nodal
     * normal. @p slave_values, @p master_values: the faces in double, for
     * the projections.
     */
    template <typename Face, typename Number, typename Matrix, typename Operators>
    void
    integrate_overlap(const Face                              &slave,
                      const std::vector<Tensor<1, 2, Number>> &slave_normals,
                      const Matrix                            &dual_coefficients,
                      const Face                              &master,
                      const LineFace                          &slave_values,
                      const LineFace                          &master_values,
                      const unsigned int                       n_points,
                      const Number                            &lower,
                      const Number                            &upper,
                      Operators                               &result)
    {
      const unsigned int ps = slave.shape_degree(), pm = master.shape_degree();
      result.D.assign(ps + 1, Number(0.));
      result.weighted_gap.assign(ps + 1, Tensor<1, 2, Number>());
      result.M.reinit(ps + 1, pm + 1);
      result.overlap_length = 0.;
      result.xi_begin       = lower;
      result.xi_end         = upper;

      std::vector<double> xq, wq;
      std::vector<Number> phi(ps + 1);
      gauss_rule(n_points, xq, wq);
      for (unsigned int q = 0; q < xq.size(); ++q)
        {
          // Map the Gauss point into the overlap interval of the slave face.
          const Number xi  = lower + 0.5 * (xq[q] + 1.) * (upper - lower);
          const Number jxw = length(slave.tangent(xi)) * wq[q] * 0.5 * (upper - lower);

          const Tensor<1, 2, Number> n       = interpolated_normal(ps, slave_normals, xi);
          const auto                 x_slave = slave.point(xi);
          const Number               eta =
            projected_parameter(master, x_slave, n,
                                master_parameter(slave_values, master_values,
                                                 Point<2>(values_of(x_slave)), values_of(n)));
          const Tensor<1, 2, Number> separation = master.point(eta) - x_slave;

          result.overlap_length += jxw;
          add_quadrature_point<2>(dual_coefficients, ps, pm, xi, eta, jxw, separation, phi, result);
        }
    }
  } // namespace Mortar
} // namespace contact_fem

#endif
