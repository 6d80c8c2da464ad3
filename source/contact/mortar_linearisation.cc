// Linearisation of the 2D mortar operators of one face pair: the kernel of
// mortar_number.h evaluated in Sacado forward-AD numbers, one derivative per
// node coordinate. See mortar_linearisation.h.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/differentiation/ad.h>

#include <contact_fem/contact/mortar_linearisation.h>
#include <contact_fem/contact/mortar_number.h>

namespace contact_fem
{
  namespace Mortar
  {
    LineFace
    PairPatch::line_face(const Face &face) const
    {
      LineFace result;
      for (const unsigned int i : face.nodes)
        result.nodes.push_back(points[i]);
      result.element_degree = face.element_degree;
      return result;
    }

    namespace
    {
      using ADNumber = Sacado::Fad::DFad<double>;

      template <typename Number>
      using Vectors = std::vector<Tensor<1, 2, Number>>;

      /// The blocks of integrate_overlap() in numbers of type Number.
      template <typename Number>
      struct OperatorsOf
      {
        std::vector<Number> D;
        Table<2, Number>    M;
        Vectors<Number>     weighted_gap;
        Number              overlap_length, xi_begin, xi_end;
      };

      template <typename Number>
      LineFaceOf<Number>
      face_of(const Vectors<Number> &x, const PairPatch::Face &face)
      {
        LineFaceOf<Number> result;
        for (const unsigned int i : face.nodes)
          result.nodes.push_back(x[i]);
        result.element_degree = face.element_degree;
        return result;
      }

      /// The slave and master face of a pair in numbers of type Number and
      /// in double (for the decisions and roots), and the slave's nodal
      /// normals.
      template <typename Number>
      struct PairFaces
      {
        LineFaceOf<Number> slave, master;
        LineFace           slave_values, master_values;
        Vectors<Number>    normals;
      };

      /// face_normal() in numbers of type Number.
      template <typename Number>
      Tensor<1, 2, Number>
      face_normal_of(const LineFaceOf<Number> &face, const double xi, const double orientation)
      {
        const Tensor<1, 2, Number> t = face.tangent(Number(xi));
        Tensor<1, 2, Number>       n;
        n[0] = t[1];
        n[1] = -t[0];
        return Number(orientation / length(n)) * n;
      }

      /// The length of @p face, as ContactInterface weighs the normals.
      template <typename Number>
      Number
      face_measure(const LineFaceOf<Number> &face)
      {
        const QGauss<1> q(3);
        Number          measure = 0.;
        for (unsigned int i = 0; i < q.size(); ++i)
          measure += 2. * q.weight(i) * length(face.tangent(Number(2. * q.point(i)[0] - 1.)));
        return measure;
      }

      /// The unit normals at the DoF nodes of the slave face: at each, the
      /// length-weighted mean of the normals of the slave faces there
      /// (ContactInterface::surface_node_normals()).
      template <typename Number>
      Vectors<Number>
      nodal_normals(const PairPatch &patch, const Vectors<Number> &x)
      {
        const PairPatch::Face &slave = patch.slave_faces[0];
        Vectors<Number>        normals(face_of(x, slave).shape_degree() + 1);
        for (const PairPatch::Face &f : patch.slave_faces)
          {
            const LineFaceOf<Number> face    = face_of(x, f);
            const Number             measure = face_measure(face);
            const unsigned int       p       = face.shape_degree();
            for (unsigned int i = 0; i <= p; ++i)
              for (unsigned int k = 0; k < normals.size(); ++k)
                if (f.nodes[i] == slave.nodes[k])
                  normals[k] += measure * face_normal_of(face, node_parameter(p, i), f.orientation);
          }
        for (unsigned int k = 0; k < normals.size(); ++k)
          {
            // On a symmetry plane: the axis across it removed (a linear
            // projection, so its derivative is the projected derivative).
            if (!patch.symmetry_planes.empty())
              for (unsigned int d = 0; d < 2; ++d)
                if (patch.symmetry_planes[slave.nodes[k]][d])
                  normals[k][d] = Number(0.);
            normals[k] = normals[k] / length(normals[k]);
          }
        return normals;
      }

      /// The overlap ends @p values (overlap()) as functions of the nodes:
      /// constant at a slave end, the slave image of the master end node
      /// that bounds them otherwise (a root of normal_line_offset()).
      template <typename Number>
      std::array<Number, 2>
      overlap_ends(const LineFaceOf<Number>    &slave,
                   const Vectors<Number>       &normals,
                   const LineFaceOf<Number>    &master,
                   const std::array<double, 2> &values,
                   const std::array<int, 2>    &bounding_master_ends)
      {
        std::array<Number, 2> xi;
        for (const unsigned int side : {0, 1})
          {
            if (bounding_master_ends[side] < 0)
              {
                xi[side] = values[side];
                continue;
              }
            const Tensor<1, 2, Number> &x = master.nodes[bounding_master_ends[side]];
            xi[side] = implicit_root<Number>(values[side], [&](const Number &s) {
              return normal_line_offset(slave, normals, x, s);
            });
          }
        return xi;
      }

      /// The master parameter of the overlap end @p xi: +-1 where master
      /// end node @p bounding_master_end bounds it, else the projection of
      /// the slave point along its normal.
      template <typename Number>
      Number
      end_on_master(const PairFaces<Number> &faces, const Number &xi, const int bounding_master_end)
      {
        if (bounding_master_end >= 0)
          return Number(bounding_master_end == 0 ? -1. : 1.);
        const Tensor<1, 2, Number> n =
          interpolated_normal(faces.slave.shape_degree(), faces.normals, xi);
        const Tensor<1, 2, Number> x = faces.slave.point(xi);
        return projected_parameter(faces.master, x, n,
                                   master_parameter(faces.slave_values, faces.master_values,
                                                    Point<2>(values_of(x)), values_of(n)));
      }

      /// The overlap of the slave face of @p faces with their master
      /// (overlap()), its ends linearised into @p xi; false if there is
      /// none.
      template <typename Number>
      bool
      linearised_overlap(const PairFaces<Number>   &faces,
                         std::pair<Number, Number> &xi,
                         std::array<int, 2>        &ends)
      {
        std::vector<Tensor<1, 2>> normal_values;
        for (const Tensor<1, 2, Number> &n : faces.normals)
          normal_values.push_back(values_of(n));
        std::array<double, 2> bounds;
        if (!overlap(faces.slave_values, normal_values, faces.master_values, bounds[0], bounds[1],
                     &ends))
          return false;
        const std::array<Number, 2> ends_xi =
          overlap_ends(faces.slave, faces.normals, faces.master, bounds, ends);
        xi = {ends_xi[0], ends_xi[1]};
        return true;
      }

      /**
 * The dual basis coefficients A = D_e M_e^{-1} on @p intervals
 * (dual_basis_coefficients()). Values: those of the double path. The
 * derivative is that of dA = (dD_e - A dM_e) M_e^{-1}: the AD numbers
 * (D_e - A M_e) M_e^{-1}, whose value is round-off, carry it.
 */
      template <typename Number>
      Table<2, Number>
      dual_coefficients(const LineFaceOf<Number>                     &slave,
                        const LineFace                               &slave_values,
                        const std::vector<std::pair<Number, Number>> &intervals)
      {
        std::vector<std::pair<double, double>> interval_values;
        for (const auto &[a, b] : intervals)
          interval_values.emplace_back(value_of(a), value_of(b));
        const FullMatrix<double> A = dual_basis_coefficients(slave_values, interval_values);
        const unsigned int       n = A.m();
        Table<2, Number>         result(n, n);
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
            dual_basis_integrals(slave, intervals, De, Me);
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
      std::array<Linearised, 2>
      linearised(const Tensor<1, 2, Number> &x, const unsigned int n_variables)
      {
        return {{linearised(x[0], n_variables), linearised(x[1], n_variables)}};
      }

      /// The rows j of @p table, linearised.
      template <typename Number>
      std::vector<std::vector<Linearised>>
      linearised(const Table<2, Number> &table, const unsigned int n_variables)
      {
        std::vector<std::vector<Linearised>> result(table.n_rows());
        for (unsigned int j = 0; j < table.n_rows(); ++j)
          for (unsigned int l = 0; l < table.n_cols(); ++l)
            result[j].push_back(linearised(table(j, l), n_variables));
        return result;
      }

      /// The nodal quantities of @p operators and @p normals into @p result.
      template <typename Number>
      void
      store(const OperatorsOf<Number> &operators,
            const Vectors<Number>     &normals,
            const unsigned int         n,
            LinearisedPair            &result)
      {
        result.normals.clear();
        result.D.clear();
        result.weighted_gap.clear();
        result.normal_gap.clear();
        for (unsigned int j = 0; j < normals.size(); ++j)
          {
            result.normals.push_back(linearised(normals[j], n));
            result.D.push_back(linearised(operators.D[j], n));
            result.weighted_gap.push_back(linearised(operators.weighted_gap[j], n));
            const Number g = normals[j] * operators.weighted_gap[j];
            result.normal_gap.push_back(linearised(g, n));
          }
        result.M = linearised(operators.M, n);
      }

      /// linearise_pair() on the coordinates @p x.
      template <typename Number>
      bool
      compute_pair(const PairPatch &patch, const Vectors<Number> &x, LinearisedPair &result)
      {
        PairFaces<Number>   faces{face_of(x, patch.slave_faces[0]), face_of(x, patch.master),
                                patch.line_face(patch.slave_faces[0]),
                                patch.line_face(patch.master), nodal_normals(patch, x)};
        std::array<int, 2> &ends = result.bounding_master_ends;
        std::vector<std::pair<Number, Number>> intervals(1);
        if (!linearised_overlap(faces, intervals[0], ends))
          return false;
        const std::pair<Number, Number> xi = intervals[0];
        for (const PairPatch::Face &other : patch.other_masters)
          {
            PairFaces<Number> other_faces = faces;
            other_faces.master            = face_of(x, other);
            other_faces.master_values     = patch.line_face(other);
            std::array<int, 2> other_ends;
            if (linearised_overlap(other_faces, intervals.emplace_back(), other_ends))
              continue;
            intervals.pop_back();
          }

        const unsigned int     n = 2 * patch.points.size();
        const Table<2, Number> A = dual_coefficients(faces.slave, faces.slave_values, intervals);
        OperatorsOf<Number>    operators;
        integrate_overlap(faces.slave, faces.normals, A, faces.master, faces.slave_values,
                          faces.master_values,
                          n_quadrature_points(faces.slave_values, faces.master_values), xi.first,
                          xi.second, operators);
        result.xi_begin          = linearised(xi.first, n);
        result.xi_end            = linearised(xi.second, n);
        result.eta_begin         = linearised(end_on_master(faces, xi.first, ends[0]), n);
        result.eta_end           = linearised(end_on_master(faces, xi.second, ends[1]), n);
        result.dual_coefficients = linearised(A, n);
        store(operators, faces.normals, n, result);
        return true;
      }

      /// The coordinates of @p patch as numbers of type Number: with
      /// derivatives (one per coordinate) for AD numbers.
      template <typename Number>
      Vectors<Number>
      coordinates(const PairPatch &patch)
      {
        const unsigned int n = 2 * patch.points.size();
        Vectors<Number>    x(patch.points.size());
        for (unsigned int i = 0; i < patch.points.size(); ++i)
          for (unsigned int d = 0; d < 2; ++d)
            if constexpr (std::is_same_v<Number, double>)
              x[i][d] = patch.points[i][d];
            else
              x[i][d] = Number(n, 2 * i + d, patch.points[i][d]);
        return x;
      }
    } // namespace

    bool
    linearise_pair(const PairPatch &patch, const bool derivatives, LinearisedPair &result)
    {
      if (derivatives)
        return compute_pair(patch, coordinates<ADNumber>(patch), result);
      return compute_pair(patch, coordinates<double>(patch), result);
    }

    std::vector<std::array<Linearised, 2>>
    linearise_nodal_normals(const PairPatch &patch)
    {
      const unsigned int      n       = 2 * patch.points.size();
      const Vectors<ADNumber> normals = nodal_normals(patch, coordinates<ADNumber>(patch));
      std::vector<std::array<Linearised, 2>> result;
      for (const Tensor<1, 2, ADNumber> &normal : normals)
        result.push_back(linearised(normal, n));
      return result;
    }
  } // namespace Mortar
} // namespace contact_fem
