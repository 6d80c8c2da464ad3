// The 3D mortar kernel (mortar_3d.cc) written once over the number type:
// double in the operators (integrate_pair()) and a forward
// automatic-differentiation number in their linearisation
// (mortar_3d_linearisation.cc). As in 2D (mortar_number.h), every decision
// (clipping sides, duplicate vertices, which points project) and every
// Newton root is taken in double; an AD number only adds the derivatives
// to those values. Instantiated in mortar_3d.cc for double and
// Sacado::Fad::DFad<double> and the FixedADNumber types.
#ifndef contact_fem_mortar_3d_number_h
#define contact_fem_mortar_3d_number_h

#include <deal.II/base/table.h>
#include <deal.II/differentiation/ad.h>

#include <contact_fem/contact/mortar.h>
#include <contact_fem/contact/mortar_3d.h>

#include <array>
#include <type_traits>
#include <vector>

namespace contact_fem
{
  namespace Mortar
  {
    /// The AD number of one slave/master pair in its own variables
    /// (mortar_3d_linearisation.cc): the coordinates of both faces and the
    /// components of the slave's nodal normals, at most @p N of them.
    /// Derivatives of fixed length, on the stack: no allocation per
    /// operation (DFad allocates for every temporary).
    template <int N>
    using FixedADNumber = Sacado::Fad::SFad<double, N>;

    /// Bilinear faces: 12 + 12 + 12 variables.
    using PairADNumber = FixedADNumber<36>;
    /// 9-node faces with a bilinear shape (Q1 on a quadratic mapping):
    /// 27 + 27 + 12 (a bilinear face with a 9-node one: 51, padded).
    using CurvedPairADNumber = FixedADNumber<66>;
    /// Biquadratic faces (Q2): 27 + 27 + 27.
    using QuadraticPairADNumber = FixedADNumber<81>;
  } // namespace Mortar
} // namespace contact_fem

// deal.II knows the product types of DFad only (sacado_product_types.h).
namespace dealii
{
  namespace internal
  {
    template <int N>
    struct ProductTypeImpl<contact_fem::Mortar::FixedADNumber<N>, double>
    {
      using type = contact_fem::Mortar::FixedADNumber<N>;
    };
    template <int N>
    struct ProductTypeImpl<double, contact_fem::Mortar::FixedADNumber<N>>
    {
      using type = contact_fem::Mortar::FixedADNumber<N>;
    };
    template <int N>
    struct ProductTypeImpl<contact_fem::Mortar::FixedADNumber<N>,
                           contact_fem::Mortar::FixedADNumber<N>>
    {
      using type = contact_fem::Mortar::FixedADNumber<N>;
    };
  } // namespace internal
  template <int N>
  struct EnableIfScalar<contact_fem::Mortar::FixedADNumber<N>>
  {
    using type = contact_fem::Mortar::FixedADNumber<N>;
  };
} // namespace dealii

namespace contact_fem
{
  namespace Mortar
  {
    /// quad_shape_value() for a double or an AD parameter @p xi.
    template <typename Number>
    Number
    quad_shape_value_of(const unsigned int p, const unsigned int i, const Point<2, Number> &xi)
    {
      if constexpr (std::is_same_v<Number, double>)
        return quad_shape_value(p, i, xi);
      else
        {
          const auto [a, b] = quad_line_indices(p, i);
          return lagrange_value(p, a, xi[0]) * lagrange_value(p, b, xi[1]);
        }
    }

    /// quad_shape_gradient() for an AD parameter @p xi.
    template <typename Number>
    Tensor<1, 2, Number>
    quad_shape_gradient_of(const unsigned int p, const unsigned int i, const Point<2, Number> &xi)
    {
      const auto [a, b] = quad_line_indices(p, i);
      Tensor<1, 2, Number> g;
      g[0] = lagrange_derivative(p, a, xi[0]) * lagrange_value(p, b, xi[1]);
      g[1] = lagrange_value(p, a, xi[0]) * lagrange_derivative(p, b, xi[1]);
      return g;
    }

    /// A QuadFace whose node coordinates are AD numbers.
    template <typename Number>
    struct QuadFaceOf
    {
      std::vector<Point<3, Number>> nodes;
      unsigned int                  element_degree = 0;

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
      unsigned int
      n_shape_nodes() const
      {
        return (shape_degree() + 1) * (shape_degree() + 1);
      }
      /// If set (linearise_slave_face()): coordinate d of node i is the AD
      /// variable first_variable + 3 i + d itself (unit derivative), and
      /// point() and tangents() at an AD parameter take their derivatives
      /// by the chain rule in double (chained()) instead of AD products.
      int first_variable = -1;

      // point() and tangents() evaluate the 1D shapes once per direction
      // (the nodes share them) and add component by component, without
      // temporary vectors: the same operations on each number as
      // quad_shape_value_of() and quad_shape_gradient_of() node by node.
      Point<3, Number>
      point(const Point<2, Number> &xi) const
      {
        if (first_variable >= 0)
          {
            Point<3, Number> x;
            chained(xi, 0, 1, &x);
            return x;
          }
        const unsigned int    p = degree();
        std::array<Number, 3> l0, l1;
        for (unsigned int a = 0; a <= p; ++a)
          {
            l0[a] = lagrange_value(p, a, xi[0]);
            l1[a] = lagrange_value(p, a, xi[1]);
          }
        Point<3, Number> x;
        for (unsigned int i = 0; i < nodes.size(); ++i)
          {
            const auto [a, b] = quad_line_indices(p, i);
            const Number N    = l0[a] * l1[b];
            for (unsigned int d = 0; d < 3; ++d)
              x[d] += N * nodes[i][d];
          }
        return x;
      }
      std::array<Tensor<1, 3, Number>, 2>
      tangents(const Point<2, Number> &xi) const
      {
        if (first_variable >= 0)
          {
            std::array<Tensor<1, 3, Number>, 2> t;
            chained(xi, 1, 2, t.data());
            return t;
          }
        const unsigned int    p = degree();
        std::array<Number, 3> l0, l1, dl0, dl1;
        for (unsigned int a = 0; a <= p; ++a)
          {
            l0[a]  = lagrange_value(p, a, xi[0]);
            l1[a]  = lagrange_value(p, a, xi[1]);
            dl0[a] = lagrange_derivative(p, a, xi[0]);
            dl1[a] = lagrange_derivative(p, a, xi[1]);
          }
        std::array<Tensor<1, 3, Number>, 2> t;
        for (unsigned int i = 0; i < nodes.size(); ++i)
          {
            const auto [a, b] = quad_line_indices(p, i);
            const Number g0   = dl0[a] * l1[b];
            const Number g1   = l0[a] * dl1[b];
            for (unsigned int d = 0; d < 3; ++d)
              {
                t[0][d] += g0 * nodes[i][d];
                t[1][d] += g1 * nodes[i][d];
              }
          }
        return t;
      }

      /**
       * The point (r = 0) or the tangents (r = 1, 2) at @p xi for
       * nodes that are AD variables (first_variable), results @p first to
       * @p first + @p n_results - 1 into @p result: y = sum_i S_i(xi) x_i
       * with S_i the shape or its xi or eta derivative, values as point()
       * and tangents() form them; dy = sum_i (dS_i/dxi_c x_i) dxi_c +
       * S_i dx_i, the first sums in double, then one pass over the
       * derivatives (the AD products of point(), tangents() pass over
       * them once per node and component). The shapes are tabulated once
       * per call (the same products as node by node).
       */
      void
      chained(const Point<2, Number> &xi,
              const unsigned int      first,
              const unsigned int      n_results,
              Tensor<1, 3, Number>   *result) const
      {
        const unsigned int    p = degree();
        const double          u = xi[0].val(), v = xi[1].val();
        std::array<double, 3> l0, l1, dl0, dl1, ddl0, ddl1;
        for (unsigned int a = 0; a <= p; ++a)
          {
            l0[a]   = lagrange_value(p, a, u);
            l1[a]   = lagrange_value(p, a, v);
            dl0[a]  = lagrange_derivative(p, a, u);
            dl1[a]  = lagrange_derivative(p, a, v);
            ddl0[a] = p == 1 ? 0. : (a == 2 ? -2. : 1.);
            ddl1[a] = ddl0[a];
          }
        // shapes[c][i] for result r: S_i, and its derivatives in xi and eta.
        const unsigned int                   n_nodes = nodes.size();
        std::array<std::array<double, 9>, 3> shapes;
        const int                            n = xi[0].size();
        for (unsigned int k = 0; k < n_results; ++k)
          {
            const unsigned int r = first + k;
            for (unsigned int i = 0; i < n_nodes; ++i)
              {
                const auto [a, b] = quad_line_indices(p, i);
                if (r == 0)
                  {
                    shapes[0][i] = l0[a] * l1[b];
                    shapes[1][i] = dl0[a] * l1[b];
                    shapes[2][i] = l0[a] * dl1[b];
                  }
                else if (r == 1)
                  {
                    shapes[0][i] = dl0[a] * l1[b];
                    shapes[1][i] = ddl0[a] * l1[b];
                    shapes[2][i] = dl0[a] * dl1[b];
                  }
                else
                  {
                    shapes[0][i] = l0[a] * dl1[b];
                    shapes[1][i] = dl0[a] * dl1[b];
                    shapes[2][i] = l0[a] * ddl1[b];
                  }
              }
            for (unsigned int d = 0; d < 3; ++d)
              {
                double value = 0., by_xi = 0., by_eta = 0.;
                for (unsigned int i = 0; i < n_nodes; ++i)
                  {
                    const double x = nodes[i][d].val();
                    value += shapes[0][i] * x;
                    by_xi += shapes[1][i] * x;
                    by_eta += shapes[2][i] * x;
                  }
                Number &y = result[k][d];
                y.val()   = value;
                for (int w = 0; w < n; ++w)
                  y.fastAccessDx(w) =
                    by_xi * xi[0].fastAccessDx(w) + by_eta * xi[1].fastAccessDx(w);
                for (unsigned int i = 0; i < n_nodes; ++i)
                  y.fastAccessDx(first_variable + 3 * i + d) += shapes[0][i];
              }
          }
      }
      /// The point at a parameter @p xi that is not differentiated (a root
      /// found in double): the shapes in double.
      Point<3, Number>
      point(const Point<2> &xi) const
      {
        if (first_variable >= 0)
          {
            // The same numbers as the sums below (whose other terms are
            // zero).
            std::array<double, 9> N;
            for (unsigned int i = 0; i < nodes.size(); ++i)
              N[i] = quad_shape_value(degree(), i, xi);
            Point<3, Number> x;
            for (unsigned int d = 0; d < 3; ++d)
              {
                double value = 0.;
                for (unsigned int i = 0; i < nodes.size(); ++i)
                  value += N[i] * nodes[i][d].val();
                x[d] = Number(value);
                for (unsigned int i = 0; i < nodes.size(); ++i)
                  x[d].fastAccessDx(first_variable + 3 * i + d) = N[i];
              }
            return x;
          }
        Point<3, Number> x;
        for (unsigned int i = 0; i < nodes.size(); ++i)
          {
            const double N = quad_shape_value(degree(), i, xi);
            for (unsigned int d = 0; d < 3; ++d)
              x[d] += N * nodes[i][d];
          }
        return x;
      }
    };

    /// The face type of the kernel for numbers of type Number.
    template <typename Number>
    using QuadFaceFor =
      std::conditional_t<std::is_same_v<Number, double>, QuadFace, QuadFaceOf<Number>>;

    template <typename Number>
    using ParameterPolygonOf = std::vector<Point<2, Number>>;

    /// The blocks of integrate_pair() in numbers of type Number.
    template <typename Number>
    struct QuadOperatorsOf
    {
      std::vector<Number>               D;
      Table<2, Number>                  M;
      std::vector<Tensor<1, 3, Number>> weighted_gap;
      Number                            overlap_area;
    };

    /**
     * overlap() with @p slave, @p master and @p slave_normals in numbers of
     * type Number (@p slave_values: the slave in double, for the
     * decisions and roots): the vertices of @p polygons as
     * functions of the nodes, bilinear or biquadratic (a vertex where a
     * master edge crosses a curved slave edge, found by bisection in double,
     * gets its derivatives from the implicit-function theorem).
     */
    template <typename Number>
    bool
    overlap_of(const QuadFaceFor<Number>               &slave,
               const QuadFace                          &slave_values,
               const std::vector<Tensor<1, 3, Number>> &slave_normals,
               const QuadFaceFor<Number>               &master,
               std::vector<ParameterPolygonOf<Number>> &polygons);

    /// D_e = diag(int N_j) and M_e = (int N_j N_k) over @p polygons, as
    /// dual_basis_coefficients() integrates them. @p De, @p Me: zero n x n.
    /// If given, @p De_values and @p Me_values (n x n) get the same sums
    /// added in double from the values of the points: what
    /// dual_basis_coefficients() sums over these polygons, bit for bit
    /// (the AD values are those of the double path), without a second
    /// pass over the points.
    template <typename Number>
    void
    dual_basis_integrals_of(const QuadFaceFor<Number>                     &slave,
                            const QuadFace                                &slave_values,
                            const std::vector<Tensor<1, 3, Number>>       &slave_normals,
                            const std::vector<ParameterPolygonOf<Number>> &polygons,
                            Table<2, Number>                              &De,
                            Table<2, Number>                              &Me,
                            FullMatrix<double>                            *De_values = nullptr,
                            FullMatrix<double>                            *Me_values = nullptr);

    /// A = D_e M_e^{-1} from the integrals of dual_basis_integrals_of()
    /// in double (as dual_basis_coefficients() forms it).
    FullMatrix<double>
    dual_basis_from_integrals(const FullMatrix<double> &De, const FullMatrix<double> &Me);

    /// integrate_pair() on the given overlap @p polygons (overlap_of()),
    /// with dual basis coefficients @p dual_coefficients; the quadrature
    /// points are projected onto the master as there. If given, @p basis
    /// gets, in double from the values of the same points, the operators
    /// of the standard basis (dual coefficients the identity): what
    /// integrate_polygons_of<double>() with the identity gives on the
    /// polygons' values, bit for bit, without a second pass.
    template <typename Number>
    void
    integrate_polygons_of(const QuadFaceFor<Number>                     &slave,
                          const QuadFace                                &slave_values,
                          const std::vector<Tensor<1, 3, Number>>       &slave_normals,
                          const Table<2, double>                        &dual_coefficients,
                          const QuadFaceFor<Number>                     &master,
                          const QuadFace                                &master_values,
                          const unsigned int                             n_quadrature_points,
                          const std::vector<ParameterPolygonOf<Number>> &polygons,
                          QuadOperatorsOf<Number>                       &result,
                          QuadOperatorsOf<double>                       *basis = nullptr);
  } // namespace Mortar
} // namespace contact_fem

#endif
