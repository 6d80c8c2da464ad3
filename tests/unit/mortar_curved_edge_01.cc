// A curved slave face whose edges a master edge crosses (source/contact/
// mortar_3d.cc, overlap()): the segmentation clips in the auxiliary plane,
// where the curved slave edges are chords. A vertex where a master edge
// crosses such a chord used to be mapped back along n0 into the face (by the
// chord's sag), so the overlap no longer followed the slave edge there and
// lost the lens between chord and edge. Two symptoms, both checked here:
//  - a biquadratic face on a sphere (the pole face of the 3D Hertz scene,
//    R = 6.1237) fully covered by 2 or 4 flat masters whose edges cross it:
//    sum of the overlap areas, sum D = sum M and each D_j against the
//    values of the whole face (int N_j dA, own Gauss rule and own shapes):
//    1.5e-4 of the area was lost;
//  - the same face with its pole corner at the corner of a flat master (the
//    quarter model's symmetry planes), at initial gaps g = +-1e-5: with
//    g < 0 the master edges, projected along n0, cut off the corner by a
//    sliver of width |g| tan(n0, edge); D of the pole node fell by 1.1e-3
//    (a jump of the pole pressure at g = 0), it now stays that of the whole
//    face to the sliver (1e-6).
// And the 2D counterpart (source/contact/mortar.cc), which segments in the
// slave parameter along the normal field and has no chords: a quadratic arc
// against flat masters, D_j at g = +-1e-5 and split by a master end, against
// int N_j ds.
#include <deal.II/base/quadrature_lib.h>

#include <contact_fem/contact/mortar.h>
#include <contact_fem/contact/mortar_3d.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace dealii;
using namespace contact_fem;

namespace
{
  constexpr double R = 6.1237;

  void
  check(const std::string &what, const double value, const double expected, const double tol)
  {
    const double error = std::abs(value - expected) / std::max(1e-300, std::abs(expected));
    std::cout << "  " << what << ": " << (error < tol ? "ok" : "FAILED") << " (relative tolerance "
              << tol << ")" << std::endl;
    if (!(error < tol))
      std::cout << "    got " << value << ", expected " << expected << std::endl;
  }

  // ---- Own Lagrange shapes (nodes -1, 1, 0 per direction) -----------------

  double
  lagrange(const double a, const double x)
  {
    double value = 1.;
    for (const double b : {-1., 0., 1.})
      if (b != a)
        value *= (x - b) / (a - b);
    return value;
  }

  double
  lagrange_derivative(const double a, const double x)
  {
    double value = 0.;
    for (const double skip : {-1., 0., 1.})
      if (skip != a)
        {
          double term = 1. / (a - skip);
          for (const double b : {-1., 0., 1.})
            if (b != a && b != skip)
              term *= (x - b) / (a - b);
          value += term;
        }
    return value;
  }

  /// Parameters of the 9 nodes in deal.II's face order (as Mortar::QuadFace).
  Point<2>
  node(const unsigned int i)
  {
    static const double q2[9][2] = {{-1, -1}, {1, -1}, {-1, 1}, {1, 1}, {-1, 0},
                                    {1, 0},   {0, -1}, {0, 1},  {0, 0}};
    return Point<2>(q2[i][0], q2[i][1]);
  }

  // ---- 3D ------------------------------------------------------------------

  /// The sphere of radius R whose lowest point is (0, 0, g).
  Point<3>
  centre(const double g)
  {
    return Point<3>(0., 0., g + R);
  }

  /// The pole face: the sphere above the square [0, 0.08 R]^2 of directions
  /// (gnomonic), node 0 at the pole; the nodal normals point out of the
  /// sphere (down).
  Mortar::QuadFace
  pole_face(const double g, std::vector<Tensor<1, 3>> &normals)
  {
    Mortar::QuadFace face;
    normals.clear();
    for (unsigned int i = 0; i < 9; ++i)
      {
        const Point<2> xi = node(i);
        Tensor<1, 3>   d({0.04 * (xi[0] + 1.), 0.04 * (xi[1] + 1.), -1.});
        d /= d.norm();
        face.nodes.push_back(centre(g) + R * d);
        normals.push_back(d);
      }
    return face;
  }

  /// The flat square [x0, x1] x [y0, y1] at z = 0, as a biquadratic face.
  Mortar::QuadFace
  plate(const double x0, const double x1, const double y0, const double y1)
  {
    Mortar::QuadFace face;
    for (unsigned int i = 0; i < 9; ++i)
      {
        const Point<2> xi = node(i);
        face.nodes.emplace_back(x0 + 0.5 * (xi[0] + 1.) * (x1 - x0),
                                y0 + 0.5 * (xi[1] + 1.) * (y1 - y0), 0.);
      }
    return face;
  }

  /// int N_j dA over the whole (interpolated) face: own shapes, 20 x 20
  /// Gauss points.
  std::vector<double>
  whole_face_integrals(const Mortar::QuadFace &face)
  {
    const QGauss<2>     rule(20);
    std::vector<double> integrals(9, 0.);
    for (unsigned int q = 0; q < rule.size(); ++q)
      {
        const Point<2> x(2. * rule.point(q)[0] - 1., 2. * rule.point(q)[1] - 1.);
        Tensor<1, 3>   t_xi, t_eta;
        for (unsigned int i = 0; i < 9; ++i)
          {
            const Point<2> a = node(i);
            t_xi += lagrange_derivative(a[0], x[0]) * lagrange(a[1], x[1]) * face.nodes[i];
            t_eta += lagrange(a[0], x[0]) * lagrange_derivative(a[1], x[1]) * face.nodes[i];
          }
        const double jxw = 4. * rule.weight(q) * cross_product_3d(t_xi, t_eta).norm();
        for (unsigned int j = 0; j < 9; ++j)
          integrals[j] += lagrange(node(j)[0], x[0]) * lagrange(node(j)[1], x[1]) * jxw;
      }
    return integrals;
  }

  struct Operators3D
  {
    std::vector<double> D    = std::vector<double>(9, 0.);
    double              area = 0., sum_M = 0.;
  };

  /// The slave against all @p masters, as ContactInterface<3> does: the
  /// dual basis on the union of the overlaps, then each pair (7 points per
  /// direction, those of curved faces).
  Operators3D
  operators(const Mortar::QuadFace              &slave,
            const std::vector<Tensor<1, 3>>     &normals,
            const std::vector<Mortar::QuadFace> &masters)
  {
    std::vector<Mortar::ParameterPolygon> all;
    for (const auto &master : masters)
      {
        std::vector<Mortar::ParameterPolygon> polygons;
        if (Mortar::overlap(slave, normals, master, polygons))
          all.insert(all.end(), polygons.begin(), polygons.end());
      }
    const FullMatrix<double> A = Mortar::dual_basis_coefficients(slave, normals, all);
    Operators3D              result;
    for (const auto &master : masters)
      {
        Mortar::QuadSegmentOperators ops;
        if (!Mortar::integrate_pair(slave, normals, A, master, 7, ops))
          continue;
        result.area += ops.overlap_area;
        for (unsigned int j = 0; j < 9; ++j)
          {
            result.D[j] += ops.D[j];
            for (unsigned int l = 0; l < ops.M.n(); ++l)
              result.sum_M += ops.M(j, l);
          }
      }
    return result;
  }

  double
  largest_relative_difference(const std::vector<double> &a, const std::vector<double> &b)
  {
    double largest = 0.;
    for (unsigned int j = 0; j < a.size(); ++j)
      largest = std::max(largest, std::abs(a[j] - b[j]) / std::abs(b[j]));
    return largest;
  }

  void
  sphere_face_3d()
  {
    std::vector<Tensor<1, 3>> normals;
    const Mortar::QuadFace    slave    = pole_face(1e-5, normals);
    const std::vector<double> integral = whole_face_integrals(slave);
    double                    area     = 0.;
    for (const double value : integral)
      area += value;

    // The face spans about [0, 0.49]^2: split at x = 0.2 and y = 0.3.
    const std::vector<std::pair<std::string, std::vector<Mortar::QuadFace>>> coverings = {
      {"2 masters, split at x = 0.2", {plate(-1., 0.2, -1., 1.), plate(0.2, 1., -1., 1.)}},
      {"4 masters, split at x = 0.2 and y = 0.3",
       {plate(-1., 0.2, -1., 0.3), plate(0.2, 1., -1., 0.3), plate(-1., 0.2, 0.3, 1.),
        plate(0.2, 1., 0.3, 1.)}}};
    for (const auto &[name, masters] : coverings)
      {
        std::cout << "3D sphere face (gap 1e-5) covered by " << name << std::endl;
        const Operators3D ops = operators(slave, normals, masters);
        check("sum of the overlap areas = face area", ops.area, area, 1e-9);
        check("sum M = face area", ops.sum_M, area, 1e-9);
        check("max_j |D_j / int N_j dA - 1|", largest_relative_difference(ops.D, integral) + 1., 1.,
              1e-9);
      }

    // The pole corner at the corner of the plate [0, 1]^2 (the symmetry
    // planes x = 0 and y = 0 of the quarter model).
    for (const double g : {1e-5, -1e-5})
      {
        std::cout << "3D sphere face, pole at the plate corner, gap " << g << std::endl;
        const Mortar::QuadFace face = pole_face(g, normals);
        const Operators3D      ops  = operators(face, normals, {plate(0., 1., 0., 1.)});
        check("D of the pole node = int N_pole dA of the whole face", ops.D[0], integral[0], 1e-5);
        check("max_j |D_j / int N_j dA - 1|", largest_relative_difference(ops.D, integral) + 1., 1.,
              1e-5);
        check("sum M = sum D", ops.sum_M,
              ops.D[0] + ops.D[1] + ops.D[2] + ops.D[3] + ops.D[4] + ops.D[5] + ops.D[6] +
                ops.D[7] + ops.D[8],
              1e-12);
      }
  }

  // ---- 2D ------------------------------------------------------------------

  /// The quadratic arc of the circle of radius R whose lowest point is
  /// (0, g): from the pole (node 0) to the angle 0.08.
  Mortar::LineFace
  arc(const double g, std::vector<Tensor<1, 2>> &normals)
  {
    Mortar::LineFace face;
    for (const double angle : {0., 0.08, 0.04})
      face.nodes.push_back(Point<2>(0., g + R) +
                           R * Tensor<1, 2>({std::sin(angle), -std::cos(angle)}));
    // The face normals at the nodes, as ContactInterface<2> gives a node
    // with one slave face (the pole on the symmetry line): slightly tilted.
    normals.clear();
    for (const double xi : {-1., 1., 0.})
      normals.push_back(Mortar::face_normal(face, xi, 1.));
    return face;
  }

  Mortar::LineFace
  line(const double x0, const double x1)
  {
    Mortar::LineFace face;
    face.nodes = {Point<2>(x0, 0.), Point<2>(x1, 0.), Point<2>(0.5 * (x0 + x1), 0.)};
    return face;
  }

  /// int N_j ds over the whole arc: own shapes, 20 Gauss points.
  std::vector<double>
  whole_arc_integrals(const Mortar::LineFace &face)
  {
    const QGauss<1>     rule(20);
    std::vector<double> integrals(3, 0.);
    const double        a[3] = {-1., 1., 0.};
    for (unsigned int q = 0; q < rule.size(); ++q)
      {
        const double x = 2. * rule.point(q)[0] - 1.;
        Tensor<1, 2> t;
        for (unsigned int i = 0; i < 3; ++i)
          t += lagrange_derivative(a[i], x) * face.nodes[i];
        for (unsigned int j = 0; j < 3; ++j)
          integrals[j] += lagrange(a[j], x) * 2. * rule.weight(q) * t.norm();
      }
    return integrals;
  }

  void
  arc_2d()
  {
    const std::vector<std::pair<std::string, std::vector<Mortar::LineFace>>> coverings = {
      {"the flat master [0, 1]", {line(0., 1.)}},
      {"masters [0, 0.2] and [0.2, 1]", {line(0., 0.2), line(0.2, 1.)}}};
    for (const double g : {1e-5, -1e-5})
      for (const auto &[name, masters] : coverings)
        {
          std::cout << "2D arc, pole at the master end, gap " << g << ", against " << name
                    << std::endl;
          std::vector<Tensor<1, 2>>              normals;
          const Mortar::LineFace                 slave = arc(g, normals);
          std::vector<std::pair<double, double>> intervals;
          for (const auto &master : masters)
            {
              double lower, upper;
              if (Mortar::overlap(slave, normals, master, lower, upper))
                intervals.emplace_back(lower, upper);
            }
          const FullMatrix<double> A = Mortar::dual_basis_coefficients(slave, intervals);
          std::vector<double>      D(3, 0.);
          for (const auto &master : masters)
            {
              Mortar::SegmentOperators ops;
              if (Mortar::integrate_pair(slave, normals, A, master, 5, ops))
                for (unsigned int j = 0; j < 3; ++j)
                  D[j] += ops.D[j];
            }
          check("max_j |D_j / int N_j ds - 1|",
                largest_relative_difference(D, whole_arc_integrals(slave)) + 1., 1., 1e-5);
        }
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(10);
  sphere_face_3d();
  arc_2d();
}
