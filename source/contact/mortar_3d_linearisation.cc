// Linearisation of the 3D mortar operators of one face pair: the kernel of
// mortar_3d_number.h evaluated in Sacado forward-AD numbers, one derivative
// per node coordinate. See mortar_3d_linearisation.h.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/differentiation/ad.h>

#include <contact_fem/contact/mortar_3d_linearisation.h>
#include <contact_fem/contact/mortar_3d_number.h>
#include <contact_fem/contact/mortar_number.h>

namespace contact_fem
{
  namespace Mortar
  {
    QuadFace
    QuadPairPatch::quad_face(const Face &face) const
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
      face_of(const std::vector<Point<3, Number>> &x, const QuadPairPatch::Face &face)
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
            const auto t = face.tangents(xi);
            area += 4. * q.weight(i) * length(Tensor<1, 3, Number>(cross_product_3d(t[0], t[1])));
          }
        return area;
      }

      /// The unit normals at the DoF nodes of the slave face: at each, the
      /// area-weighted mean of the normals of the slave faces there
      /// (ContactInterface::surface_node_normals()).
      template <typename Number>
      Vectors<Number>
      nodal_normals(const QuadPairPatch &patch, const std::vector<Point<3, Number>> &x)
      {
        const QuadPairPatch::Face &slave = patch.slave_faces[0];
        Vectors<Number>            normals(face_of(x, slave).n_shape_nodes());
        for (const QuadPairPatch::Face &f : patch.slave_faces)
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
        for (Tensor<1, 3, Number> &n : normals)
          n = n / length(n);
        return normals;
      }

      /**
       * The dual basis coefficients A = D_e M_e^{-1} on @p polygons
       * (dual_basis_coefficients()). Values: those of the double path; the
       * derivative: dual_coefficients_of().
       */
      template <typename Number>
      Table<2, Number>
      dual_coefficients(const QuadFaceFor<Number>                     &slave,
                        const QuadFace                                &slave_values,
                        const Vectors<Number>                         &normals,
                        const std::vector<ParameterPolygonOf<Number>> &polygons)
      {
        std::vector<Tensor<1, 3>>     normal_values;
        std::vector<ParameterPolygon> polygon_values;
        for (const Tensor<1, 3, Number> &n : normals)
          normal_values.push_back(Tensor<1, 3>({value_of(n[0]), value_of(n[1]), value_of(n[2])}));
        for (const ParameterPolygonOf<Number> &polygon : polygons)
          {
            polygon_values.emplace_back();
            for (const Point<2, Number> &xi : polygon)
              polygon_values.back().emplace_back(value_of(xi[0]), value_of(xi[1]));
          }
        const FullMatrix<double> A =
          dual_basis_coefficients(slave_values, normal_values, polygon_values);
        const unsigned int n = A.m();
        Table<2, Number>   result(n, n);
        if constexpr (std::is_same_v<Number, double>)
          {
            for (unsigned int j = 0; j < n; ++j)
              for (unsigned int k = 0; k < n; ++k)
                result(j, k) = A(j, k);
            return result;
          }
        else
          {
            Table<2, Number> De(n, n), Me(n, n);
            dual_basis_integrals_of<Number>(slave, slave_values, normals, polygons, De, Me);
            return dual_coefficients_of(A, De, Me);
          }
      }

      template <typename Number>
      Linearised
      linearised(const Number &x, const unsigned int n_variables)
      {
        Linearised result;
        result.value = value_of(x);
        if constexpr (!std::is_same_v<Number, double>)
          for (unsigned int i = 0; i < n_variables; ++i)
            result.derivatives.push_back(x.size() > 0 ? x.dx(i) : 0.);
        return result;
      }

      template <typename Number>
      std::array<Linearised, 3>
      linearised(const Tensor<1, 3, Number> &x, const unsigned int n_variables)
      {
        return {{linearised(x[0], n_variables), linearised(x[1], n_variables),
                 linearised(x[2], n_variables)}};
      }

      /// linearise_pair() on the coordinates @p x.
      template <typename Number>
      bool
      compute_pair(const QuadPairPatch                 &patch,
                   const std::vector<Point<3, Number>> &x,
                   LinearisedQuadPair                  &result)
      {
        const QuadFaceFor<Number> slave = face_of(x, patch.slave_faces[0]),
                                  master = face_of(x, patch.master);
        const QuadFace slave_values  = patch.quad_face(patch.slave_faces[0]),
                       master_values = patch.quad_face(patch.master);
        const Vectors<Number>                   normals = nodal_normals(patch, x);
        std::vector<ParameterPolygonOf<Number>> polygons, all;
        if (!overlap_of<Number>(slave, slave_values, normals, master, polygons))
          return false;
        all = polygons;
        for (const QuadPairPatch::Face &other : patch.other_masters)
          {
            std::vector<ParameterPolygonOf<Number>> more;
            if (overlap_of<Number>(slave, slave_values, normals, face_of(x, other), more))
              all.insert(all.end(), more.begin(), more.end());
          }
        result.polygon_sizes.clear();
        for (const auto &polygon : all)
          result.polygon_sizes.push_back(polygon.size());

        const unsigned int      n = 3 * patch.points.size();
        const Table<2, Number>  A = dual_coefficients(slave, slave_values, normals, all);
        QuadOperatorsOf<Number> operators;
        integrate_polygons_of<Number>(slave, slave_values, normals, A, master, master_values,
                                      n_quadrature_points(slave_values, master_values), polygons,
                                      operators);
        result = LinearisedQuadPair{{}, result.polygon_sizes, {}, {}, {}, {}, {}};
        for (unsigned int j = 0; j < normals.size(); ++j)
          {
            result.normals.push_back(linearised(normals[j], n));
            result.D.push_back(linearised(operators.D[j], n));
            result.weighted_gap.push_back(linearised(operators.weighted_gap[j], n));
            const Number g = normals[j] * operators.weighted_gap[j];
            result.normal_gap.push_back(linearised(g, n));
            result.M.emplace_back();
            for (unsigned int l = 0; l < operators.M.n_cols(); ++l)
              result.M.back().push_back(linearised(operators.M(j, l), n));
            result.dual_coefficients.emplace_back();
            for (unsigned int k = 0; k < A.n_cols(); ++k)
              result.dual_coefficients.back().push_back(linearised(A(j, k), n));
          }
        return true;
      }

      /// The coordinates of @p patch as numbers of type Number: with
      /// derivatives (one per coordinate) for AD numbers.
      template <typename Number>
      std::vector<Point<3, Number>>
      coordinates(const QuadPairPatch &patch)
      {
        const unsigned int            n = 3 * patch.points.size();
        std::vector<Point<3, Number>> x(patch.points.size());
        for (unsigned int i = 0; i < patch.points.size(); ++i)
          for (unsigned int d = 0; d < 3; ++d)
            if constexpr (std::is_same_v<Number, double>)
              x[i][d] = patch.points[i][d];
            else
              x[i][d] = Number(n, 3 * i + d, patch.points[i][d]);
        return x;
      }
    } // namespace

    bool
    linearise_pair(const QuadPairPatch &patch, const bool derivatives, LinearisedQuadPair &result)
    {
      if (derivatives)
        return compute_pair(patch, coordinates<ADNumber>(patch), result);
      return compute_pair(patch, coordinates<double>(patch), result);
    }
  } // namespace Mortar
} // namespace contact_fem
