// The mortar kernel of each dimension behind one set of names, for the code
// written once over the dimension (ContactInterface): 2D line faces
// (mortar.h) and 3D quadrilateral faces (mortar_3d.h), their parameters,
// shapes and measure, and the overlaps of a slave face with its masters
// (intervals cut on a line, polygons clipped in a plane).
#ifndef contact_fem_mortar_kernel_h
#define contact_fem_mortar_kernel_h

#include <contact_fem/contact/mortar.h>
#include <contact_fem/contact/mortar_3d.h>
#include <contact_fem/contact/mortar_3d_number.h>

#include <array>
#include <cmath>
#include <type_traits>
#include <utility>
#include <vector>

namespace contact_fem
{
  namespace Mortar
  {
    template <int dim>
    struct Kernel;

    /// Line faces, parameter xi in [-1, 1].
    template <>
    struct Kernel<2>
    {
      using Face      = LineFace;
      using Parameter = double;
      using Operators = SegmentOperators;
      /// The overlaps of a slave face with its masters: the slave parameter
      /// intervals, and which master end bounds each (overlap()).
      struct Overlaps
      {
        std::vector<std::pair<double, double>> intervals;
        std::vector<std::array<int, 2>>        bounding_ends;
      };
      static constexpr unsigned int n_vertices = 2;
      /// The edges of a face (pairs of vertex positions): in 2D its
      /// vertices, so that an edge on the rim is a vertex of one face.
      static constexpr std::array<std::array<unsigned int, 2>, 2> edges = {{{{0, 0}}, {{1, 1}}}};
      /// Measure of the parameter domain over that of the unit one.
      static constexpr double reference_measure = 2.;

      static Parameter
      centre()
      {
        return 0.;
      }
      /// The parameter of a point of the unit domain (of a QGauss<1>).
      static Parameter
      parameter(const Point<1> &unit)
      {
        return 2. * unit[0] - 1.;
      }
      /// The point of the unit domain of a parameter (parameter()'s inverse).
      static Point<1>
      unit(const Parameter xi)
      {
        return Point<1>(0.5 * (xi + 1.));
      }
      static Parameter
      node_parameter(const unsigned int p, const unsigned int i)
      {
        return Mortar::node_parameter(p, i);
      }
      /// For a double or an AD number @p xi (mortar_number.h).
      template <typename Number>
      static Number
      shape_value(const unsigned int p, const unsigned int i, const Number &xi)
      {
        if constexpr (std::is_same_v<Number, double>)
          return Mortar::shape_value(p, i, xi);
        else
          return lagrange_value(p, i, xi);
      }
      /// |dx/dxi|: the length element of the face at @p xi.
      static double
      area_element(const Face &face, const Parameter xi)
      {
        return face.tangent(xi).norm();
      }
      /// Whether @p xi lies inside the face, off its boundary.
      static bool
      inside(const Parameter xi)
      {
        return std::abs(xi) < 1.;
      }
      /// The vertex positions of the boundary point @p xi (a vertex).
      static std::vector<unsigned int>
      boundary_vertices(const Parameter xi)
      {
        return {xi < 0. ? 0u : 1u};
      }
      /// The side of a face (or of the mean face) of @p measure.
      static double
      side(const double measure)
      {
        return measure;
      }
      /// Adds the overlap of @p slave with @p master, if any.
      static bool
      add_overlap(const Face                      &slave,
                  const std::vector<Tensor<1, 2>> &slave_normals,
                  const Face                      &master,
                  Overlaps                        &overlaps)
      {
        double             lower, upper;
        std::array<int, 2> ends;
        if (!overlap(slave, slave_normals, master, lower, upper, &ends))
          return false;
        overlaps.intervals.emplace_back(lower, upper);
        overlaps.bounding_ends.push_back(ends);
        return true;
      }
      /// The dual basis of @p slave on its @p overlaps.
      static FullMatrix<double>
      dual_basis(const Face &slave, const std::vector<Tensor<1, 2>> &, const Overlaps &overlaps)
      {
        return dual_basis_coefficients(slave, overlaps.intervals);
      }
    };

    /// Quadrilateral faces, parameters in [-1, 1]^2.
    template <>
    struct Kernel<3>
    {
      using Face      = QuadFace;
      using Parameter = Point<2>;
      using Operators = QuadSegmentOperators;
      /// The overlap polygons of a slave face with all its masters.
      using Overlaps = std::vector<ParameterPolygon>;
      static constexpr unsigned int                               n_vertices = 4;
      static constexpr std::array<std::array<unsigned int, 2>, 4> edges      = {
             {{{0, 1}}, {{1, 3}}, {{3, 2}}, {{2, 0}}}};
      static constexpr double reference_measure = 4.;

      static Parameter
      centre()
      {
        return Point<2>();
      }
      static Parameter
      parameter(const Point<2> &unit)
      {
        return Point<2>(2. * unit[0] - 1., 2. * unit[1] - 1.);
      }
      static Point<2>
      unit(const Parameter &xi)
      {
        return Point<2>(0.5 * (xi[0] + 1.), 0.5 * (xi[1] + 1.));
      }
      static Parameter
      node_parameter(const unsigned int p, const unsigned int i)
      {
        return quad_node_parameter(p, i);
      }
      /// For a double or an AD parameter @p xi (mortar_3d_number.h).
      template <typename Number>
      static Number
      shape_value(const unsigned int p, const unsigned int i, const Point<2, Number> &xi)
      {
        return quad_shape_value_of(p, i, xi);
      }
      /// |dx/dxi x dx/deta|: the area element of the face at @p xi.
      static double
      area_element(const Face &face, const Parameter &xi)
      {
        const auto t = face.tangents(xi);
        return cross_product_3d(t[0], t[1]).norm();
      }
      static bool
      inside(const Parameter &xi)
      {
        return std::abs(xi[0]) < 1. && std::abs(xi[1]) < 1.;
      }
      static std::vector<unsigned int>
      boundary_vertices(const Parameter &xi)
      {
        return Mortar::boundary_vertices(xi);
      }
      /// The side of a square of @p measure.
      static double
      side(const double measure)
      {
        return std::sqrt(measure);
      }
      static bool
      add_overlap(const Face                      &slave,
                  const std::vector<Tensor<1, 3>> &slave_normals,
                  const Face                      &master,
                  Overlaps                        &overlaps)
      {
        std::vector<ParameterPolygon> polygons;
        if (!overlap(slave, slave_normals, master, polygons))
          return false;
        overlaps.insert(overlaps.end(), polygons.begin(), polygons.end());
        return true;
      }
      static FullMatrix<double>
      dual_basis(const Face                      &slave,
                 const std::vector<Tensor<1, 3>> &slave_normals,
                 const Overlaps                  &overlaps)
      {
        return dual_basis_coefficients(slave, slave_normals, overlaps);
      }
    };
    /**
     * Adds one quadrature point of the overlap of a slave face with a master
     * face to the blocks of @p result (integrate_pair(), both dimensions):
     * the slave point at parameter @p xi with weight @p jxw, projected to
     * @p eta on the master, apart from it by @p separation. @p phi: room
     * for the dual functions there (one per slave DoF node). Number: double,
     * or an AD number (mortar_number.h, mortar_3d_number.h).
     */
    template <int dim, typename Matrix, typename Parameter, typename Number, typename Operators>
    void
    add_quadrature_point(const Matrix                 &dual_coefficients,
                         const unsigned int            slave_degree,
                         const unsigned int            master_degree,
                         const Parameter              &xi,
                         const Parameter              &eta,
                         const Number                 &jxw,
                         const Tensor<1, dim, Number> &separation,
                         std::vector<Number>          &phi,
                         Operators                    &result)
    {
      // The slave's shapes once (at most 9 nodes), not once per dual function.
      std::array<Number, 9> shapes;
      AssertIndexRange(result.D.size(), shapes.size() + 1);
      for (unsigned int k = 0; k < result.D.size(); ++k)
        shapes[k] = Kernel<dim>::shape_value(slave_degree, k, xi);
      for (unsigned int j = 0; j < result.D.size(); ++j)
        {
          phi[j] = 0.;
          for (unsigned int k = 0; k < result.D.size(); ++k)
            phi[j] += dual_coefficients(j, k) * shapes[k];
          result.D[j] += phi[j] * jxw;
          result.weighted_gap[j] += Number(phi[j] * jxw) * separation;
        }
      for (unsigned int l = 0; l < result.M.n_cols(); ++l)
        {
          const Number N_l = Kernel<dim>::shape_value(master_degree, l, eta);
          for (unsigned int j = 0; j < result.D.size(); ++j)
            result.M(j, l) += phi[j] * N_l * jxw;
        }
    }
  } // namespace Mortar
} // namespace contact_fem

#endif
