// The Mindlin-Deresiewicz unloading solution of postprocess/cattaneo_solution.h on the
// values of prm/cattaneo.prm (P = 10, mu = 0.2, R* = 4, E* = 200 / (2 (1 -
// 0.3^2))), unloaded from Q* = 1.6: the traction integrates to Q, equals
// the Cattaneo traction of Q* at Q = Q* and its opposite at Q = -Q*, is
// -mu p (reverse slip) for b < |x| < a and is continuous at +-b. Then
// classify_tangential_path() on load paths: monotone, one reversal (with
// its peak), a reversal past -Q* (monotone the other way), and a second
// reversal (no solution).

#include <contact_fem/postprocess/cattaneo_solution.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace contact_fem;

namespace
{
  /// Midpoint rule on [-a, a] (square-root ends: 1e-5 relative with 1e5 points).
  double
  resultant(const CattaneoSolution &s)
  {
    const unsigned int n = 100000;
    double             Q = 0.;
    for (unsigned int i = 0; i < n; ++i)
      Q += s.tangential(-s.a + (i + 0.5) * 2. * s.a / n) * 2. * s.a / n;
    return Q;
  }

  double
  largest_difference(const CattaneoSolution &s, const CattaneoSolution &t, const double sign)
  {
    double difference = 0.;
    for (int i = -100; i <= 100; ++i)
      {
        const double x = 0.0099 * i * s.a;
        difference     = std::max(difference, std::abs(s.tangential(x) - sign * t.tangential(x)));
      }
    return difference;
  }

  const char *
  name(const TangentialPath::Kind kind)
  {
    return kind == TangentialPath::Kind::monotone  ? "monotone" :
           kind == TangentialPath::Kind::unloading ? "unloading" :
                                                     "none";
  }
} // namespace

int
main()
{
  const double           E_star = 200. / (2. * (1. - 0.09)), P = 10., mu = 0.2, R = 4., Qs = 1.6;
  const CattaneoSolution peak(P, Qs, mu, R, E_star);
  std::cout << std::setprecision(4);
  for (const double Q : {1.6, 0.8, 0., -0.4, -1.6})
    {
      const CattaneoSolution s(P, Q, Qs, mu, R, E_star);
      std::cout << "Q = " << Q << ": int q = Q (to 1e-5 Q*): "
                << (std::abs(resultant(s) - Q) < 1e-5 * Qs ? "yes" : "no")
                << ", b/a = " << s.c / s.a << ", c*/a = " << s.c_star / s.a << std::endl;
    }
  std::cout << "at Q = Q*, |q - q_C(Q*)| < 1e-12: "
            << (largest_difference(CattaneoSolution(P, Qs, Qs, mu, R, E_star), peak, 1.) < 1e-12 ?
                  "yes" :
                  "no")
            << std::endl;
  std::cout << "at Q = -Q*, |q + q_C(Q*)| < 1e-12: "
            << (largest_difference(CattaneoSolution(P, -Qs, Qs, mu, R, E_star), peak, -1.) < 1e-12 ?
                  "yes" :
                  "no")
            << std::endl;
  const CattaneoSolution s(P, -0.4, Qs, mu, R, E_star);
  const double           x_slip = 0.5 * (s.c + s.a), e = 1e-9 * s.a;
  std::cout << "q = -mu p in the reverse slip zone: "
            << (std::abs(s.tangential(x_slip) + mu * s.pressure(x_slip)) < 1e-12 ? "yes" : "no")
            << std::endl
            << "q continuous at b: "
            << (std::abs(s.tangential(s.c - e) - s.tangential(s.c + e)) < 1e-3 ? "yes" : "no")
            << std::endl;

  const std::vector<std::vector<double>> paths = {{0., 0., 0.5, 1., 1.6},
                                                  {0., 0.8, 1.6, 1.2, 0.4, -0.4},
                                                  {0., -0.8, -1.6, -0.4},
                                                  {0., 1.6, 0., -1.6, -1.8},
                                                  {0., 1.6, 0.4, 1.}};
  for (const auto &path : paths)
    {
      const TangentialPath p = classify_tangential_path(path, 1e-6);
      std::cout << "path ending at " << path.back() << ": " << name(p.kind) << ", direction "
                << p.direction << ", Q " << p.Q << ", Q* " << p.Q_star << std::endl;
    }
}
