// The Cattaneo-Mindlin formulas of postprocess/cattaneo_solution.h on the values of
// prm/cattaneo.prm (P = 10, Q = 0.93616, mu = 0.2, R* = 4, E* = 200 /
// (2 (1 - 0.3^2))): a, p_max, c/a; the tangential traction integrates to Q
// and the pressure to P; q is continuous at +-c and equals mu p in the
// slip zones. Then compare_with_cattaneo() on synthetic nodes that carry
// the exact traction with the exact stick set: no L2 error, and the
// measured stick half-width c_h within one node spacing of c.

#include <contact_fem/postprocess/cattaneo_solution.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace contact_fem;

int
main()
{
  const double           E_star = 200. / (2. * (1. - 0.09));
  const CattaneoSolution exact(10., 0.93616, 0.2, 4., E_star);
  std::cout << std::setprecision(6) << "a = " << exact.a << ", p_max = " << exact.p_max
            << ", c/a = " << exact.c / exact.a << std::endl;

  // Midpoint rule on [-a, a] (square-root ends: 1e-5 relative with 1e5 points).
  const unsigned int n = 100000;
  double             P = 0., Q = 0.;
  for (unsigned int i = 0; i < n; ++i)
    {
      const double x = -exact.a + (i + 0.5) * 2. * exact.a / n;
      P += exact.pressure(x) * 2. * exact.a / n;
      Q += exact.tangential(x) * 2. * exact.a / n;
    }
  std::cout << std::setprecision(4) << "int p = " << P << ", int q = " << Q << std::endl;
  const double e = 1e-9 * exact.a;
  std::cout << "q jump at c: "
            << std::abs(exact.tangential(exact.c - e) - exact.tangential(exact.c + e))
            << " (< 1e-3: "
            << (std::abs(exact.tangential(exact.c - e) - exact.tangential(exact.c + e)) < 1e-3 ?
                  "yes" :
                  "no")
            << ")" << std::endl;
  const double x_slip = 0.5 * (exact.c + exact.a);
  std::cout << "q = mu p in the slip zone: "
            << (std::abs(exact.tangential(x_slip) - 0.2 * exact.pressure(x_slip)) < 1e-12 ? "yes" :
                                                                                            "no")
            << std::endl;

  // 41 nodes on [-1, 1], spacing 0.05: the exact traction (negative: on the
  // slave, against the load), the stick set |x| < c.
  std::vector<CattaneoNode> nodes;
  for (int i = 20; i >= -20; --i)
    {
      CattaneoNode node;
      node.x      = 0.05 * i;
      node.t      = -exact.tangential(node.x);
      node.weight = 0.05;
      node.active = std::abs(node.x) < exact.a;
      node.stick  = std::abs(node.x) < exact.c;
      nodes.push_back(node);
    }
  const CattaneoComparison c = compare_with_cattaneo(nodes, exact);
  std::cout << std::setprecision(4) << "stick / slip nodes: " << c.n_stick << " / " << c.n_slip
            << ", c_h = " << c.c_h << ", c = " << exact.c
            << ", |c_h - c| / h = " << c.c_error_in_slave_elements
            << ", L2 error = " << c.tangential_l2_relative_error << std::endl;
  std::cout << cattaneo_report(to_json(c));
}
