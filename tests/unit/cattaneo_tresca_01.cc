// The Cattaneo solution under Tresca friction (postprocess/cattaneo_tresca.h
// through CattaneoSolution with CattaneoProblem::cylinders_tresca) on the loads of
// scenes/cattaneo_tresca_01 (P = 10, Q = 1.2256, g = 1, R* = 4, E* = 200 /
// (2 (1 - 0.3^2))): c/a = sqrt(1 - (Q/(2 a g))^2); q integrates to Q; q is
// continuous at +-c, g in the slip zones and below g in the stick zone;
// the stick condition holds: the tangential strain of the half-space,
// PV int q(s) / (x - s) ds, vanishes in |x| < c (and not in the slip zone).
// Unloaded to Q = 0 (Mindlin-Deresiewicz) the traction integrates to 0, and
// at the capacity 2 a g the stick zone is gone.

#include <contact_fem/postprocess/cattaneo_solution.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace contact_fem;

namespace
{
  /// Midpoint rule of @p f on [-a, a] with n points.
  template <typename F>
  double
  integral(const F &f, const double a, const unsigned int n = 200000)
  {
    double sum = 0.;
    for (unsigned int i = 0; i < n; ++i)
      sum += f(-a + (i + 0.5) * 2. * a / n);
    return sum * 2. * a / n;
  }

  /// PV int_{-a}^{a} q(s) / (x - s) ds, the singular part subtracted.
  double
  strain(const CattaneoSolution &exact, const double x)
  {
    const double a  = exact.a;
    const double qx = exact.tangential(x);
    return integral(
             [&](const double s) {
               return (exact.tangential(s) - qx) / (x - s);
             },
             a) +
           qx * std::log((a + x) / (a - x));
  }
} // namespace

int
main()
{
  const double           E_star = 200. / (2. * (1. - 0.09));
  const CattaneoSolution exact(10., 1.2256, 1., 4., E_star, CattaneoProblem::cylinders_tresca);
  std::cout << std::setprecision(6) << "a = " << exact.a << ", c/a = " << exact.c / exact.a
            << ", Q/(2 a g) = " << exact.Q / exact.capacity() << ", largest bound "
            << exact.largest_bound() << std::endl;
  std::cout << std::setprecision(4) << "int q = "
            << integral(
                 [&](const double x) {
                   return exact.tangential(x);
                 },
                 exact.a)
            << std::endl;
  const double e = 1e-9 * exact.a;
  std::cout << "q at c-, c+: " << exact.tangential(exact.c - e) << ", "
            << exact.tangential(exact.c + e) << "; q(0) = " << exact.tangential(0.)
            << "; q in the slip zone: " << exact.tangential(0.5 * (exact.c + exact.a)) << std::endl;
  for (const double f : {0.3, 0.7})
    std::cout << "strain at x = " << f << " c (stick): "
              << (std::abs(strain(exact, f * exact.c)) < 1e-6 ? "0 (< 1e-6)" : "not 0")
              << std::endl;
  std::cout << std::setprecision(4)
            << "strain at the middle of the slip zone: " << strain(exact, 0.5 * (exact.c + exact.a))
            << std::endl;

  const CattaneoSolution unloaded(10., 0., 1.2256, 1., 4., E_star,
                                  CattaneoProblem::cylinders_tresca);
  std::cout << "unloaded to 0: b/a = " << unloaded.c / unloaded.a << ", |int q| < 1e-6: "
            << (std::abs(integral(
                  [&](const double x) {
                    return unloaded.tangential(x);
                  },
                  unloaded.a)) < 1e-6 ?
                  "yes" :
                  "no")
            << std::endl;
  const CattaneoSolution full(10., 2. * exact.a, 1., 4., E_star, CattaneoProblem::cylinders_tresca);
  std::cout << "at the capacity: c = " << full.c << std::endl;
}
