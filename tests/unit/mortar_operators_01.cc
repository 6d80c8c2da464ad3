// Mortar operators of one slave face against shifted and misaligned master
// faces (source/mortar.cc). Checks, each against an independent value:
//  - sum_j D_j and sum_jl M_jl equal the overlapped length of the slave face
//    (the dual functions sum to one; exact for straight faces);
//  - the dual basis is biorthogonal to the standard one on the whole face:
//    int Phi_j N_k = delta_jk int N_k (computed here by 24-point Gauss);
//  - a flat master parallel to the slave at distance d gives the nodal gap
//    d at every fully covered node: sum_l M_jl y_l - D_j y_j = d D_j;
//  - degree 1 and 2 slave faces, degree 1 and 2 master faces;
//  - a degree-1 element on a curved (quadratic) face geometry: the dual basis
//    stays biorthogonal, and the weighted gap vector int Phi_j (x_m - x_s)
//    equals the gap of the curve integrated here by 24-point Gauss (the
//    nodal form sum M y - D y only sees the straight chord).
#include <deal.II/base/quadrature_lib.h>

#include <contact_fem/contact/mortar.h>

#include <cmath>
#include <iostream>

using namespace dealii;
using namespace contact_fem;

namespace
{
  void
  check(const std::string &what, const double value, const double expected, const double tol)
  {
    const double error = std::abs(value - expected) / std::max(1., std::abs(expected));
    std::cout << "  " << what << ": " << (error < tol ? "ok" : "FAILED") << " (expected "
              << expected << ", tolerance " << tol << ")" << std::endl;
    if (!(error < tol))
      std::cout << "    got " << value << std::endl;
  }

  Mortar::LineFace
  line(const Point<2> &a, const Point<2> &b, const unsigned int degree)
  {
    Mortar::LineFace f;
    f.nodes = {a, b};
    if (degree == 2)
      f.nodes.push_back(0.5 * (a + b));
    return f;
  }

  void
  biorthogonality(const Mortar::LineFace &slave)
  {
    const unsigned int       p = slave.shape_degree();
    const FullMatrix<double> A = Mortar::dual_basis_coefficients(slave);
    const QGauss<1>          q(24);
    double                   worst = 0.;
    for (unsigned int j = 0; j <= p; ++j)
      for (unsigned int k = 0; k <= p; ++k)
        {
          double integral = 0., reference = 0.;
          for (unsigned int i = 0; i < q.size(); ++i)
            {
              const double xi  = 2. * q.point(i)[0] - 1.;
              const double jxw = 2. * q.weight(i) * slave.tangent(xi).norm();
              double       phi = 0.;
              for (unsigned int m = 0; m <= p; ++m)
                phi += A(j, m) * Mortar::shape_value(p, m, xi);
              integral += phi * Mortar::shape_value(p, k, xi) * jxw;
              if (j == k)
                reference += Mortar::shape_value(p, k, xi) * jxw;
            }
          worst = std::max(worst, std::abs(integral - reference));
        }
    check("biorthogonality, max |int Phi_j N_k - delta_jk int N_k|", worst, 0., 1e-10);
  }

  void
  pair(const std::string      &name,
       const Mortar::LineFace &slave,
       const Mortar::LineFace &master,
       const double            overlap,
       const double            distance)
  {
    std::cout << name << " (slave degree " << slave.degree() << ", master degree "
              << master.degree() << ")" << std::endl;
    const std::vector<Tensor<1, 2>> normals(slave.nodes.size(), Tensor<1, 2>({0., 1.}));
    Mortar::SegmentOperators        ops;
    const bool                      overlapping =
      Mortar::integrate_pair(slave, normals, Mortar::dual_basis_coefficients(slave), master, 6,
                             ops);
    std::cout << "  overlapping: " << (overlapping ? "yes" : "no") << std::endl;
    if (!overlapping)
      return;
    double sum_D = 0., sum_M = 0.;
    for (unsigned int j = 0; j < ops.D.size(); ++j)
      {
        sum_D += ops.D[j];
        for (unsigned int l = 0; l < master.nodes.size(); ++l)
          sum_M += ops.M(j, l);
      }
    check("sum D = overlapped length", sum_D, overlap, 1e-12);
    check("sum M = overlapped length", sum_M, overlap, 1e-12);
    check("overlap length reported", ops.overlap_length, overlap, 1e-12);
    if (distance > 0.)
      for (unsigned int j = 0; j < ops.D.size(); ++j)
        {
          double weighted = -ops.D[j] * slave.nodes[j][1];
          for (unsigned int l = 0; l < master.nodes.size(); ++l)
            weighted += ops.M(j, l) * master.nodes[l][1];
          check("gap of node " + std::to_string(j), weighted / ops.D[j], distance, 1e-12);
        }
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(10);
  for (const unsigned int ps : {1u, 2u})
    {
      const Mortar::LineFace slave = line(Point<2>(0., 0.), Point<2>(1., 0.), ps);
      std::cout << "Slave face [0,1] x {0}, degree " << ps << std::endl;
      biorthogonality(slave);
      for (const unsigned int pm : {1u, 2u})
        {
          // Master above, reversed orientation (normal pointing down).
          pair("  master covering the whole face", slave,
               line(Point<2>(1.5, 0.1), Point<2>(-0.5, 0.1), pm), 1., 0.1);
          pair("  master shifted by 0.3", slave, line(Point<2>(1.3, 0.1), Point<2>(0.3, 0.1), pm),
               0.7, 0.);
          pair("  master inside the face", slave, line(Point<2>(0.8, 0.2), Point<2>(0.25, 0.2), pm),
               0.55, 0.);
          pair("  misaligned (tilted) master", slave,
               line(Point<2>(0.6, 0.15), Point<2>(-0.2, 0.05), pm), 0.6, 0.);
          pair("  master beside the face", slave, line(Point<2>(2.5, 0.1), Point<2>(1.5, 0.1), pm),
               0., 0.);
        }
    }
  // A curved (degree 2) slave face: biorthogonality holds with its Jacobian.
  Mortar::LineFace arc = line(Point<2>(0., 0.), Point<2>(1., 0.), 2);
  arc.nodes[2]         = Point<2>(0.5, -0.1);
  std::cout << "Curved slave face, degree 2" << std::endl;
  biorthogonality(arc);

  // Degree-1 element on that curved face, master y = 0.1 above it: the gap
  // is g(xi) = 0.1 + 0.1 (1 - xi^2) along the face.
  arc.element_degree = 1;
  std::cout << "Curved slave face, degree-1 element" << std::endl;
  biorthogonality(arc);
  const Mortar::LineFace          flat_master = line(Point<2>(1.5, 0.1), Point<2>(-0.5, 0.1), 1);
  const FullMatrix<double>        A           = Mortar::dual_basis_coefficients(arc);
  const std::vector<Tensor<1, 2>> normals(2, Tensor<1, 2>({0., 1.}));
  Mortar::SegmentOperators        ops;
  Mortar::integrate_pair(arc, normals, A, flat_master, 6, ops);
  const QGauss<1> q(24);
  for (unsigned int j = 0; j < 2; ++j)
    {
      double expected = 0., nodal = -ops.D[j] * arc.nodes[j][1];
      for (unsigned int i = 0; i < q.size(); ++i)
        {
          const double xi  = 2. * q.point(i)[0] - 1.;
          const double jxw = 2. * q.weight(i) * arc.tangent(xi).norm();
          const double phi =
            A(j, 0) * Mortar::shape_value(1, 0, xi) + A(j, 1) * Mortar::shape_value(1, 1, xi);
          expected += phi * (0.1 - arc.point(xi)[1]) * jxw;
        }
      for (unsigned int l = 0; l < 2; ++l)
        nodal += ops.M(j, l) * flat_master.nodes[l][1];
      check("weighted gap of node " + std::to_string(j) + " on the curve", ops.weighted_gap[j][1],
            expected, 1e-6);
      check("nodal form of node " + std::to_string(j) + " (chord: gap 0.1 D_j)", nodal,
            0.1 * ops.D[j], 1e-12);
      std::cout << "  curvature part of node " << j << ": "
                << (ops.weighted_gap[j][1] - nodal) / ops.D[j] << std::endl;
    }
}
