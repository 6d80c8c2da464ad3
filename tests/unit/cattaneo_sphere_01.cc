// Mindlin's sphere in postprocess/cattaneo_solution.h (CattaneoProblem::spheres) on the
// values of prm/cattaneo_3d.prm (P = 4e4 pi R^2, R = 6.1237, mu = 0.5, E* =
// 1 / (0.91 / 1e8 + 1 / 1.9230769e8)): a, p0 and c/a = (1 - Q/(mu P))^(1/3)
// at Q/(mu P) = 0.25, 0.5, 0.75, 0.875; the pressure integrates to P and the
// traction to Q over the disc (2 pi r dr); q is continuous at r = c and mu p
// in the slip annulus. Then compare_with_cattaneo() on a synthetic half
// disc of nodes (a square grid, y >= 0, nodes on y = 0 with half weight,
// symmetry fraction 0.5) that carry the exact traction with the exact stick
// set: no L2 error, c_h from the stick nodes' area within one node spacing
// of c, and a traction across the load counted as error.

#include <deal.II/base/numbers.h>

#include <contact_fem/postprocess/cattaneo_solution.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace contact_fem;

int
main()
{
  const double pi = dealii::numbers::PI, R = 6.1237, P = 4e4 * pi * R * R, mu = 0.5;
  const double E_star = 1. / (0.91 / 1e8 + 1. / 1.9230769e8);
  std::cout << std::setprecision(6);
  for (const double ratio : {0.25, 0.5, 0.75, 0.875})
    {
      const CattaneoSolution exact(P, ratio * mu * P, mu, R, E_star, CattaneoProblem::spheres);
      // Midpoint rule in r on [0, a] with 2 pi r dr.
      const unsigned int n     = 100000;
      double             p_int = 0., q_int = 0.;
      for (unsigned int i = 0; i < n; ++i)
        {
          const double r = (i + 0.5) * exact.a / n, w = 2. * pi * r * exact.a / n;
          p_int += exact.pressure(r) * w;
          q_int += exact.tangential(r) * w;
        }
      const double e = 1e-9 * exact.a, r_slip = 0.5 * (exact.c + exact.a);
      std::cout << "Q/(mu P) = " << ratio << ": a = " << exact.a << ", p0 = " << exact.p_max
                << ", c/a = " << exact.c / exact.a
                << " (cbrt(1 - Q/(mu P)) = " << std::cbrt(1. - ratio)
                << "), int p / P = " << std::setprecision(5) << p_int / P
                << ", int q / Q = " << q_int / (ratio * mu * P) << ", q continuous at c: "
                << (std::abs(exact.tangential(exact.c - e) - exact.tangential(exact.c + e)) <
                        1e-3 * mu * exact.p_max ?
                      "yes" :
                      "no")
                << ", q = mu p in the slip annulus: "
                << (std::abs(exact.tangential(r_slip) - mu * exact.pressure(r_slip)) <
                        1e-12 * exact.p_max ?
                      "yes" :
                      "no")
                << std::setprecision(6) << std::endl;
    }

  // A half disc of nodes at spacing h, y >= 0 (the y = 0 row with half
  // weight, as a symmetry plane gives it), the exact traction along x.
  const CattaneoSolution    exact(P, 0.5 * mu * P, mu, R, E_star, CattaneoProblem::spheres);
  const double              h = exact.a / 20.;
  std::vector<CattaneoNode> nodes;
  for (int i = -25; i <= 25; ++i)
    for (int j = 0; j <= 25; ++j)
      {
        CattaneoNode node;
        const double x = i * h, y = j * h;
        node.x      = std::hypot(x, y);
        node.along  = x;
        node.t      = exact.tangential(node.x);
        node.weight = (j == 0 ? 0.5 : 1.) * h * h;
        node.size   = h;
        node.active = node.x < exact.a;
        node.stick  = node.x < exact.c;
        nodes.push_back(node);
      }
  CattaneoComparison c = compare_with_cattaneo(nodes, exact, 0., 0.5);
  std::cout << std::setprecision(4) << "stick / slip nodes: " << c.n_stick << " / " << c.n_slip
            << ", c_h / a = " << c.c_h / exact.a << ", c / a = " << exact.c / exact.a
            << ", |c_h - c| / h = " << c.c_error_in_slave_elements
            << ", L2 error = " << c.tangential_l2_relative_error << std::endl;
  std::cout << cattaneo_report(to_json(c));
  // A traction across the load of 0.1 mu p0 at every active node is error.
  for (auto &node : nodes)
    node.t_across = node.active ? 0.1 * mu * exact.p_max : 0.;
  c = compare_with_cattaneo(nodes, exact, 0., 0.5);
  std::cout << "with 0.1 mu p0 across the load: L2 error = " << c.tangential_l2_relative_error
            << " (> 0: " << (c.tangential_l2_relative_error > 0.05 ? "yes" : "no") << ")"
            << std::endl;

  // The check of the load steps (Analytical solution/Tangential error
  // bounds): step 1 the exact traction, step 2 with the traction across
  // the load (L2 error 0.28), step 3 the exact traction with a stick zone
  // of half the radius (c 7.9 spacings off).
  Json steps = Json::array();
  for (auto &node : nodes)
    node.t_across = 0.;
  steps.push(to_json(compare_with_cattaneo(nodes, exact, 0., 0.5)));
  steps.push(to_json(c));
  std::cout << "steps 1, 2, bounds 0.3 for all:" << std::endl
            << cattaneo_steps_report(steps, {0.3});
  for (auto &node : nodes)
    node.stick = node.x < 0.5 * exact.c;
  steps.push(to_json(compare_with_cattaneo(nodes, exact, 0., 0.5)));
  std::cout << "bounds 0.3, 0.1, 0.3:" << std::endl
            << cattaneo_steps_report(steps, {0.3, 0.1, 0.3}) << "bounds 0.1, 0.3:" << std::endl
            << cattaneo_steps_report(steps, {0.1, 0.3});
}
