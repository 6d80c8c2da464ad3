// Linearisation of the 3D mortar operators of a slave face with each of its
// masters: the kernel of mortar_3d_number.h evaluated in Sacado forward-AD
// numbers, each evaluation in the few variables its result depends on
// directly, chained to the node coordinates. See mortar_3d_linearisation.h.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/differentiation/ad.h>

#include <contact_fem/contact/mortar_3d_linearisation.h>
#include <contact_fem/contact/mortar_3d_number.h>
#include <contact_fem/contact/mortar_number.h>

#include <algorithm>

namespace contact_fem
{
  namespace Mortar
  {
    QuadFace
    QuadFacePatch::quad_face(const Face &face) const
    {
      QuadFace result;
      for (const unsigned int i : face.nodes)
        result.nodes.push_back(points[i]);
      result.element_degree = face.element_degree;
      return result;
    }

    namespace
    {
      using ADNumber = Sacado::Fad::DFad<double>;

      template <typename Number>
      using Vectors = std::vector<Tensor<1, 3, Number>>;

      template <typename Number>
      QuadFaceFor<Number>
      face_of(const std::vector<Point<3, Number>> &x, const QuadFacePatch::Face &face)
      {
        QuadFaceFor<Number> result;
        for (const unsigned int i : face.nodes)
          result.nodes.push_back(x[i]);
        result.element_degree = face.element_degree;
        return result;
      }

      /// The area of @p face and its unit normal at @p xi times
      /// @p orientation, as ContactInterface computes them.
      template <typename Face>
      auto
      face_area(const Face &face)
      {
        using Number = std::decay_t<decltype(face.nodes[0][0])>;
        const QGauss<2> q(3);
        Number          area = 0.;
        for (unsigned int i = 0; i < q.size(); ++i)
          {
            const Point<2, Number> xi(Number(2. * q.point(i)[0] - 1.),
                                      Number(2. * q.point(i)[1] - 1.));
            const auto             t = face.tangents(xi);
            area += 4. * q.weight(i) * length(Tensor<1, 3, Number>(cross_product_3d(t[0], t[1])));
          }
        return area;
      }

      /// The unit normals at the DoF nodes of the slave face: at each, the
      /// area-weighted mean of the normals of the slave faces there
      /// (ContactInterface::surface_node_normals()).
      template <typename Number>
      Vectors<Number>
      nodal_normals(const QuadFacePatch &patch, const std::vector<Point<3, Number>> &x)
      {
        const QuadFacePatch::Face &slave = patch.slave_faces[0];
        Vectors<Number>            normals(face_of(x, slave).n_shape_nodes());
        for (const QuadFacePatch::Face &f : patch.slave_faces)
          {
            const QuadFaceFor<Number> face = face_of(x, f);
            const Number              area = face_area(face);
            const unsigned int        p    = face.shape_degree();
            for (unsigned int i = 0; i < face.n_shape_nodes(); ++i)
              for (unsigned int k = 0; k < normals.size(); ++k)
                if (f.nodes[i] == slave.nodes[k])
                  {
                    const Point<2>             xi = quad_node_parameter(p, i);
                    const auto                 t  = face.tangents(Point<2, Number>(xi[0], xi[1]));
                    const Tensor<1, 3, Number> n  = cross_product_3d(t[0], t[1]);
                    normals[k] += Number(area * f.orientation / length(n)) * n;
                  }
          }
        for (unsigned int k = 0; k < normals.size(); ++k)
          {
            // On a symmetry plane: the axis across it removed (a linear
            // projection, so its derivative is the projected derivative).
            if (!patch.symmetry_planes.empty())
              for (unsigned int d = 0; d < 3; ++d)
                if (patch.symmetry_planes[slave.nodes[k]][d])
                  normals[k][d] = Number(0.);
            normals[k] = normals[k] / length(normals[k]);
          }
        return normals;
      }

      /// The derivatives of one AD evaluation with respect to the patch
      /// coordinates: variable v of the evaluation is coordinate
      /// coordinate[v] of the patch, or for v >= coordinate.size() normal
      /// component v - coordinate.size() (node (v - size) / 3), whose
      /// derivatives are @p normal_derivatives.
      struct Chain
      {
        std::vector<unsigned int>                              coordinate;
        const std::vector<std::array<std::vector<double>, 3>> *normal_derivatives = nullptr;
        unsigned int                                           n_patch_variables  = 0;

        /// The variables: 3 per point of @p points, then (if
        /// normal_derivatives) the normal components.
        Chain(const std::vector<unsigned int>                       &points,
              const unsigned int                                     n_patch_variables,
              const std::vector<std::array<std::vector<double>, 3>> *normal_derivatives)
          : normal_derivatives(normal_derivatives)
          , n_patch_variables(n_patch_variables)
        {
          for (const unsigned int i : points)
            for (unsigned int d = 0; d < 3; ++d)
              coordinate.push_back(3 * i + d);
        }

        unsigned int
        size() const
        {
          return coordinate.size() + (normal_derivatives ? 3 * normal_derivatives->size() : 0);
        }

        /// Adds @p factor times the derivatives of @p x to @p result.
        template <typename AD>
        void
        add(const AD &x, const double factor, std::vector<double> &result) const
        {
          if (x.size() == 0)
            return;
          for (unsigned int v = 0; v < coordinate.size(); ++v)
            result[coordinate[v]] += factor * x.dx(v);
          if (normal_derivatives)
            for (unsigned int c = 0; c < 3 * normal_derivatives->size(); ++c)
              if (const double dn = factor * x.dx(coordinate.size() + c); dn != 0.)
                {
                  const std::vector<double> &dx = (*normal_derivatives)[c / 3][c % 3];
                  for (unsigned int i = 0; i < dx.size(); ++i)
                    result[i] += dn * dx[i];
                }
        }

        template <typename AD>
        Linearised
        operator()(const AD &x) const
        {
          Linearised result{x.val(), std::vector<double>(n_patch_variables, 0.)};
          add(x, 1., result.derivatives);
          return result;
        }
      };

      /// @p x as AD variable @p v of @p chain (a constant for double).
      template <typename Number>
      Number
      variable(const Chain &chain, const unsigned int v, const double x)
      {
        if constexpr (std::is_same_v<Number, double>)
          return x;
        else if constexpr (std::is_same_v<Number, ADNumber>)
          return Number(chain.size(), v, x);
        else
          {
            // A FixedADNumber may have more derivatives than the chain
            // variables: those stay zero.
            AssertIndexRange(v, Number().size());
            Number result(x);
            result.fastAccessDx(v) = 1.;
            return result;
          }
      }

      template <typename Number>
      double
      value(const Number &x)
      {
        return value_of(x);
      }

      /// The face @p face with the coordinates of its nodes the AD
      /// variables of @p chain from @p first on (3 per node).
      template <typename Number>
      QuadFaceFor<Number>
      face_variables(const QuadFacePatch       &patch,
                     const QuadFacePatch::Face &face,
                     const Chain               &chain,
                     const unsigned int         first)
      {
        QuadFaceFor<Number> result;
        for (unsigned int i = 0; i < face.nodes.size(); ++i)
          {
            Point<3, Number> x;
            for (unsigned int d = 0; d < 3; ++d)
              x[d] = variable<Number>(chain, first + 3 * i + d, patch.points[face.nodes[i]][d]);
            result.nodes.push_back(x);
          }
        result.element_degree = face.element_degree;
        if constexpr (!std::is_same_v<Number, double>)
          result.first_variable = first;
        return result;
      }

      /// One master's part of the slave face (compute_face()), in the AD
      /// variables of its chain: the slave face's coordinates, the nodal
      /// normals, the master's coordinates.
      template <typename Number>
      struct MasterPart
      {
        Chain                                   chain;
        QuadFaceFor<Number>                     slave, master;
        Vectors<Number>                         normals;
        std::vector<ParameterPolygonOf<Number>> polygons;
        Table<2, Number>                        De, Me;
      };

      /// linearise_slave_face() with derivatives if @p ad: the nodal
      /// normals in DFad numbers (as many variables as the slave faces have
      /// coordinates), each master's part in @p PairNumber (a
      /// FixedADNumber with at least as many derivatives as the part has
      /// variables).
      template <bool ad, typename PairNumber>
      bool
      compute_face(const QuadFacePatch             &patch,
                   const bool                       with_vertices,
                   std::vector<LinearisedQuadPair> &pairs)
      {
        using NormalNumber                   = std::conditional_t<ad, ADNumber, double>;
        using Number                         = std::conditional_t<ad, PairNumber, double>;
        const unsigned int n_patch_variables = 3 * patch.points.size();
        const QuadFace     slave_values      = patch.quad_face(patch.slave_faces[0]);

        // The nodal normals, in the coordinates of the slave faces' nodes.
        std::vector<unsigned int> slave_points;
        for (const QuadFacePatch::Face &f : patch.slave_faces)
          for (const unsigned int i : f.nodes)
            if (std::find(slave_points.begin(), slave_points.end(), i) == slave_points.end())
              slave_points.push_back(i);
        const Chain                         normal_chain(slave_points, n_patch_variables, nullptr);
        std::vector<Point<3, NormalNumber>> x(patch.points.size());
        for (unsigned int v = 0; v < normal_chain.coordinate.size(); ++v)
          {
            const unsigned int c = normal_chain.coordinate[v];
            x[c / 3][c % 3] = variable<NormalNumber>(normal_chain, v, patch.points[c / 3][c % 3]);
          }
        const Vectors<NormalNumber>                     normals = nodal_normals(patch, x);
        const unsigned int                              n       = normals.size();
        std::vector<Tensor<1, 3>>                       normal_values(n);
        std::vector<std::array<std::vector<double>, 3>> normal_derivatives(n);
        std::vector<std::array<Linearised, 3>>          linearised_normals(n);
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int d = 0; d < 3; ++d)
            {
              normal_values[j][d] = value(normals[j][d]);
              if constexpr (ad)
                linearised_normals[j][d] = normal_chain(normals[j][d]);
              else
                linearised_normals[j][d].value = normals[j][d];
              normal_derivatives[j][d] = linearised_normals[j][d].derivatives;
            }

        // Each master's overlap and dual basis integrals, in its own
        // variables.
        std::vector<MasterPart<Number>> parts;
        std::vector<ParameterPolygon>   all_polygons;
        // With derivatives, the double sums of dual_basis_coefficients()
        // over all_polygons, added by dual_basis_integrals_of() from its
        // points (master by master, the order of all_polygons).
        FullMatrix<double>        De_values(n, n), Me_values(n, n);
        std::vector<unsigned int> polygon_sizes;
        bool                      any = false;
        for (const QuadFacePatch::Face &m : patch.masters)
          {
            std::vector<unsigned int> points = patch.slave_faces[0].nodes;
            points.insert(points.end(), m.nodes.begin(), m.nodes.end());
            MasterPart<Number> part{Chain(points, n_patch_variables, &normal_derivatives),
                                    {},
                                    {},
                                    Vectors<Number>(n),
                                    {},
                                    Table<2, Number>(n, n),
                                    Table<2, Number>(n, n)};
            // Table leaves the derivatives of an SFad uninitialised.
            part.De.fill(Number(0.));
            part.Me.fill(Number(0.));
            if constexpr (ad)
              AssertThrow(part.chain.size() <= PairNumber().size(), ExcInternalError());
            part.slave = face_variables<Number>(patch, patch.slave_faces[0], part.chain, 0);
            part.master =
              face_variables<Number>(patch, m, part.chain, 3 * patch.slave_faces[0].nodes.size());
            for (unsigned int j = 0; j < n; ++j)
              for (unsigned int d = 0; d < 3; ++d)
                part.normals[j][d] =
                  variable<Number>(part.chain, part.chain.coordinate.size() + 3 * j + d,
                                   normal_values[j][d]);
            if (overlap_of<Number>(part.slave, slave_values, part.normals, part.master,
                                   part.polygons))
              {
                any = true;
                for (const ParameterPolygonOf<Number> &polygon : part.polygons)
                  {
                    polygon_sizes.push_back(polygon.size());
                    all_polygons.emplace_back();
                    for (const Point<2, Number> &xi : polygon)
                      all_polygons.back().emplace_back(value(xi[0]), value(xi[1]));
                  }
                if constexpr (ad)
                  dual_basis_integrals_of<Number>(part.slave, slave_values, part.normals,
                                                  part.polygons, part.De, part.Me, &De_values,
                                                  &Me_values);
              }
            parts.push_back(std::move(part));
          }
        if (!any)
          return false;

        // A = D_e M_e^{-1} in double (the double path's values); dA =
        // (dD_e - A dM_e) M_e^{-1}, D_e and M_e summed over the masters.
        const FullMatrix<double> A =
          ad ? dual_basis_from_integrals(De_values, Me_values) :
               dual_basis_coefficients(slave_values, normal_values, all_polygons);
        std::vector<std::vector<Linearised>> dual(n, std::vector<Linearised>(n));
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int k = 0; k < n; ++k)
            dual[j][k] = {A(j, k),
                          ad ? std::vector<double>(n_patch_variables, 0.) : std::vector<double>()};
        if constexpr (ad)
          {
            FullMatrix<double> Me(n, n), Me_inverse(n, n);
            for (const MasterPart<Number> &part : parts)
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int k = 0; k < n; ++k)
                  Me(i, k) += value(part.Me(i, k));
            Me_inverse.invert(Me);
            for (const MasterPart<Number> &part : parts)
              if (!part.polygons.empty())
                for (unsigned int j = 0; j < n; ++j)
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      Number r = part.De(j, i);
                      for (unsigned int l = 0; l < n; ++l)
                        r -= A(j, l) * part.Me(l, i);
                      for (unsigned int k = 0; k < n; ++k)
                        part.chain.add(r, Me_inverse(i, k), dual[j][k].derivatives);
                    }
          }

        // Each master's operators at fixed A, in its variables; they are
        // linear in A: dD_j = ... + sum_k dA_jk int N_k (and so on), the
        // integrals of the standard basis (A = identity) in double.
        Table<2, double> A_fixed(n, n);
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int k = 0; k < n; ++k)
            A_fixed(j, k) = A(j, k);
        pairs.assign(patch.masters.size(), LinearisedQuadPair());
        for (unsigned int i = 0; i < parts.size(); ++i)
          {
            const MasterPart<Number> &part = parts[i];
            if (part.polygons.empty())
              continue;
            const QuadFace     master_values = patch.quad_face(patch.masters[i]);
            const unsigned int n_points      = n_quadrature_points(slave_values, master_values);
            // With derivatives, the integrals of the standard basis
            // (A = identity) in double come from the same points.
            QuadOperatorsOf<Number> ops;
            QuadOperatorsOf<double> basis;
            integrate_polygons_of<Number>(part.slave, slave_values, part.normals, A_fixed,
                                          part.master, master_values, n_points, part.polygons, ops,
                                          ad ? &basis : nullptr);
            // The value of x, its derivatives at fixed A plus those of
            // sum_k A_jk basis_k.
            const auto linearised = [&](const Number &x, const unsigned int j,
                                        const auto &basis_k) {
              Linearised result;
              result.value = value(x);
              if constexpr (ad)
                {
                  result = part.chain(x);
                  for (unsigned int k = 0; k < n; ++k)
                    if (const double b = basis_k(k); b != 0.)
                      for (unsigned int v = 0; v < n_patch_variables; ++v)
                        result.derivatives[v] += dual[j][k].derivatives[v] * b;
                }
              return result;
            };
            LinearisedQuadPair &pair = pairs[i];
            pair.normals             = linearised_normals;
            pair.polygon_sizes       = polygon_sizes;
            pair.dual_coefficients   = dual;
            if (with_vertices)
              for (const ParameterPolygonOf<Number> &polygon : part.polygons)
                {
                  pair.vertices.emplace_back();
                  for (const Point<2, Number> &xi : polygon)
                    {
                      std::array<Linearised, 2> vertex;
                      for (unsigned int d = 0; d < 2; ++d)
                        {
                          vertex[d].value = value(xi[d]);
                          if constexpr (ad)
                            vertex[d] = part.chain(xi[d]);
                        }
                      pair.vertices.back().push_back(vertex);
                    }
                }
            for (unsigned int j = 0; j < n; ++j)
              {
                pair.D.push_back(linearised(ops.D[j], j, [&](const unsigned int k) {
                  return basis.D[k];
                }));
                pair.M.emplace_back();
                for (unsigned int l = 0; l < ops.M.n_cols(); ++l)
                  pair.M.back().push_back(linearised(ops.M(j, l), j, [&](const unsigned int k) {
                    return basis.M(k, l);
                  }));
                pair.weighted_gap.emplace_back();
                for (unsigned int d = 0; d < 3; ++d)
                  pair.weighted_gap.back()[d] =
                    linearised(ops.weighted_gap[j][d], j, [&](const unsigned int k) {
                      return basis.weighted_gap[k][d];
                    });
                // g_j = n_j . weighted_gap_j, its value as in double.
                Tensor<1, 3> gap;
                for (unsigned int d = 0; d < 3; ++d)
                  gap[d] = pair.weighted_gap[j][d].value;
                Linearised g{normal_values[j] * gap, {}};
                if constexpr (ad)
                  {
                    g.derivatives.assign(n_patch_variables, 0.);
                    for (unsigned int d = 0; d < 3; ++d)
                      for (unsigned int v = 0; v < n_patch_variables; ++v)
                        g.derivatives[v] +=
                          normal_values[j][d] * pair.weighted_gap[j][d].derivatives[v] +
                          gap[d] * normal_derivatives[j][d][v];
                  }
                pair.normal_gap.push_back(g);
              }
          }
        return true;
      }
    } // namespace

    bool
    linearise_slave_face(const QuadFacePatch             &patch,
                         const bool                       derivatives,
                         std::vector<LinearisedQuadPair> &pairs,
                         const bool                       with_vertices)
    {
      // The AD number by the largest number of variables of a master's
      // part: the coordinates of the slave face and the master, and the
      // components of the slave's nodal normals.
      const unsigned int n_normals = patch.quad_face(patch.slave_faces[0]).n_shape_nodes();
      unsigned int       n_pair    = 0;
      for (const QuadFacePatch::Face &face : patch.masters)
        n_pair = std::max<unsigned int>(n_pair, 3 * (patch.slave_faces[0].nodes.size() +
                                                     face.nodes.size() + n_normals));
      pairs.clear();
      if (!derivatives)
        return compute_face<false, double>(patch, with_vertices, pairs);
      if (n_pair <= static_cast<unsigned int>(PairADNumber().size()))
        return compute_face<true, PairADNumber>(patch, with_vertices, pairs);
      if (n_pair <= static_cast<unsigned int>(CurvedPairADNumber().size()))
        return compute_face<true, CurvedPairADNumber>(patch, with_vertices, pairs);
      AssertThrow(n_pair <= static_cast<unsigned int>(QuadraticPairADNumber().size()),
                  ExcNotImplemented());
      return compute_face<true, QuadraticPairADNumber>(patch, with_vertices, pairs);
    }

    std::vector<std::array<Linearised, 3>>
    linearise_nodal_normals(const QuadFacePatch &patch)
    {
      const unsigned int        n = 3 * patch.points.size();
      std::vector<unsigned int> all(patch.points.size());
      for (unsigned int i = 0; i < all.size(); ++i)
        all[i] = i;
      const Chain                     chain(all, n, nullptr);
      std::vector<Point<3, ADNumber>> x(patch.points.size());
      for (unsigned int v = 0; v < n; ++v)
        x[v / 3][v % 3] = variable<ADNumber>(chain, v, patch.points[v / 3][v % 3]);
      std::vector<std::array<Linearised, 3>> result;
      for (const Tensor<1, 3, ADNumber> &normal : nodal_normals(patch, x))
        result.push_back({{chain(normal[0]), chain(normal[1]), chain(normal[2])}});
      return result;
    }
  } // namespace Mortar
} // namespace contact_fem
