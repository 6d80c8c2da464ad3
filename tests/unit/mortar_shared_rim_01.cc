// Curved slave and master faces that share their rims (issue 29,
// source/contact/mortar_3d.cc, remove_straight_vertices()): 9-node faces of
// Q1 on a quadratic mapping on two touching cylinders of radius 8 (as in
// current_kinematics_cylinders_3d_01), extruded over z in [0, 1], the
// master's edges crossing the slave. The rims z = 0 and 1 of the two faces
// coincide, so the clipping kept or dropped vertices on them (a master rim
// node on the slave's rim, crossings of collinear chords) by the sign of
// round-off, and the fan integration follows the vertices (its centre is
// their centroid); on the deformed faces of that scene its error, far above
// round-off, then moved D by up to 1e-6 between DoF numberings. Checked:
// moving the master's rim nodes by round-off in z (+-1 and +-0.5 ulp of 1,
// 16 combinations) leaves the overlap's vertex count the same (before the
// fix it did not: this check failed), and D, M and the weighted gaps the
// same to 1e-12 of their largest entry (they were on this undeformed pair
// too: its integrand is smooth enough for the fan), and the z-symmetry of
// the setting holds to 1e-12 (D_j equal on both rims, M of a slave node to
// the master node on the other rim zero).
#include <deal.II/base/point.h>

#include <contact_fem/contact/mortar_3d.h>

#include <cmath>
#include <iostream>
#include <limits>

using namespace dealii;
using namespace contact_fem;

namespace
{
  constexpr double R = 8.;

  /// A 9-node face (Mortar::QuadFace node order) on the cylinder of
  /// centre (0, cy) and radius R, the arc from angle a0 to a1 (measured
  /// from the cylinder's lowest point if @p lower, else its highest), z in
  /// [0, 1]; @p dz0 and @p dz1 move the rim nodes at z = 0 and z = 1.
  Mortar::QuadFace
  face(const double cy,
       const bool   lower,
       const double a0,
       const double a1,
       const double dz0,
       const double dz1)
  {
    Mortar::QuadFace result;
    result.element_degree = 1;
    for (unsigned int i = 0; i < 9; ++i)
      {
        const Point<2> xi    = Mortar::quad_node_parameter(2, i);
        const double   angle = a0 + 0.5 * (xi[0] + 1.) * (a1 - a0);
        const double   y     = lower ? cy - R * std::cos(angle) : cy + R * std::cos(angle);
        double         z     = 0.5 * (xi[1] + 1.);
        if (xi[1] == -1.)
          z += dz0;
        if (xi[1] == 1.)
          z += dz1;
        result.nodes.emplace_back(R * std::sin(angle), y, z);
      }
    return result;
  }

  struct Result
  {
    unsigned int                 n_vertices = 0;
    Mortar::QuadSegmentOperators ops;
  };

  Result
  integrate(const double dz0, const double dz1)
  {
    // The slave on the upper cylinder (its lowest point at the origin), the
    // master on the lower one 0.1 below it (the overlap is that of the
    // projections along the slave's normals).
    const Mortar::QuadFace    slave  = face(R, true, -0.1, 0.05, 0., 0.);
    const Mortar::QuadFace    master = face(-R - 0.1, false, -0.04, 0.11, dz0, dz1);
    std::vector<Tensor<1, 3>> normals;
    for (unsigned int i = 0; i < 4; ++i)
      {
        const Tensor<1, 3> r = slave.nodes[i] - Point<3>(0., R, slave.nodes[i][2]);
        normals.push_back(r / r.norm());
      }
    Result                                result;
    std::vector<Mortar::ParameterPolygon> polygons;
    if (!Mortar::overlap(slave, normals, master, polygons))
      return result;
    for (const auto &polygon : polygons)
      result.n_vertices += polygon.size();
    const FullMatrix<double> A = Mortar::dual_basis_coefficients(slave, normals, polygons);
    Mortar::integrate_pair(slave, normals, A, master, Mortar::n_quadrature_points(slave, master),
                           result.ops);
    return result;
  }

  /// The entries of D, M and the weighted gaps.
  std::vector<double>
  entries(const Mortar::QuadSegmentOperators &ops)
  {
    std::vector<double> result(ops.D.begin(), ops.D.end());
    for (unsigned int j = 0; j < ops.M.m(); ++j)
      for (unsigned int l = 0; l < ops.M.n(); ++l)
        result.push_back(ops.M(j, l));
    for (const auto &g : ops.weighted_gap)
      for (unsigned int d = 0; d < 3; ++d)
        result.push_back(g[d]);
    return result;
  }

  double
  largest(const std::vector<double> &v)
  {
    double m = 0.;
    for (const double x : v)
      m = std::max(m, std::abs(x));
    return m;
  }
} // namespace

int
main()
{
  const Result              reference = integrate(0., 0.);
  const std::vector<double> values    = entries(reference.ops);
  const double              scale     = largest(values);
  std::cout << "overlap of the two curved faces found: "
            << (reference.n_vertices >= 4 && scale > 0. ? "ok" : "FAILED") << std::endl;

  // Rim nodes moved by +-1 ulp of z = 0 (the smallest normal double's
  // scale there: 1e-16 of the face) and of z = 1.
  const double eps        = std::numeric_limits<double>::epsilon();
  bool         same_count = true;
  double       difference = 0.;
  for (const double dz0 : {-eps, -0.5 * eps, 0.5 * eps, eps})
    for (const double dz1 : {-eps, -0.5 * eps, 0.5 * eps, eps})
      {
        const Result              moved = integrate(dz0, dz1);
        const std::vector<double> v     = entries(moved.ops);
        same_count =
          same_count && moved.n_vertices == reference.n_vertices && v.size() == values.size();
        if (v.size() == values.size())
          for (unsigned int i = 0; i < v.size(); ++i)
            difference = std::max(difference, std::abs(v[i] - values[i]) / scale);
      }
  std::cout << "rims moved by round-off (16 variants): the same overlap vertex count: "
            << (same_count ? "ok" : "FAILED") << std::endl;
  std::cout << "rims moved by round-off: D, M and weighted gaps the same to 1e-12: "
            << (difference < 1e-12 ? "ok" : "FAILED") << std::endl;
  if (!(difference < 1e-12))
    std::cout << "  largest difference " << difference << " of the largest entry" << std::endl;

  // z-symmetry: slave vertex nodes 0, 1 at z = 0 and 2, 3 at z = 1; the
  // master's DoF nodes the same.
  const auto  &D = reference.ops.D;
  const auto  &M = reference.ops.M;
  const double symmetry =
    std::max({std::abs(D[0] - D[2]), std::abs(D[1] - D[3]), std::abs(M(0, 2)), std::abs(M(0, 3)),
              std::abs(M(1, 2)), std::abs(M(1, 3)), std::abs(M(2, 0)), std::abs(M(2, 1)),
              std::abs(M(3, 0)), std::abs(M(3, 1))}) /
    scale;
  std::cout << "z-symmetry (D on both rims, M across the rims zero) to 1e-12: "
            << (symmetry < 1e-12 ? "ok" : "FAILED") << std::endl;
  if (!(symmetry < 1e-12))
    std::cout << "  largest asymmetry " << symmetry << " of the largest entry" << std::endl;
}
