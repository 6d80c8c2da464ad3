// HertzContact: the pressure integrates to the load (2D: int p dx = P per
// unit thickness; 3D: int 2 pi rho p drho = F), checked by a midpoint rule
// with 200000 intervals (error ~1e-8 relative at the square-root edge),
// and a textbook case by hand: a steel ball (E = 210 GPa, nu = 0.3, both
// bodies: E* = E / (2 (1 - nu^2)) = 115384.6 MPa), R = 10 mm, F = 100 N:
// a = (3 F R / (4 E*))^(1/3) = 0.18663 mm, p0 = 3 F / (2 pi a^2) = 1370.9
// MPa; the same pair as cylinders, P = 100 N/mm: a = sqrt(4 P R / (pi E*))
// = 0.10505 mm, p0 = 2 P / (pi a) = 606.0 MPa.

#include <contact_fem/postprocess/hertz_solution.h>

#include <cmath>
#include <iomanip>
#include <iostream>

int
main()
{
  using contact_fem::HertzContact;
  const double       E_star = 210e3 / (2. * (1. - 0.3 * 0.3));
  const double       pi     = std::acos(-1.);
  const unsigned int n      = 200000;

  const HertzContact ball  = HertzContact::sphere(100., 10., E_star);
  double             force = 0.;
  for (unsigned int i = 0; i < n; ++i)
    {
      const double rho = (i + 0.5) * ball.a / n;
      force += 2. * pi * rho * ball.pressure(rho) * ball.a / n;
    }
  std::cout << std::setprecision(5) << "sphere: a = " << ball.a << " mm, p0 = " << ball.p_max
            << " MPa, int p dA / F - 1 within 1e-6: " << (std::abs(force / 100. - 1.) < 1e-6)
            << '\n';

  const HertzContact roller = HertzContact::cylinder(100., 10., E_star);
  double             load   = 0.;
  for (unsigned int i = 0; i < n; ++i)
    {
      const double x = -roller.a + (i + 0.5) * 2. * roller.a / n;
      load += roller.pressure(x) * 2. * roller.a / n;
    }
  std::cout << "cylinder: a = " << roller.a << " mm, p0 = " << roller.p_max
            << " MPa, int p dx / P - 1 within 1e-6: " << (std::abs(load / 100. - 1.) < 1e-6)
            << '\n';
  std::cout << "pressure outside the contact: " << roller.pressure(1.01 * roller.a) << ", "
            << ball.pressure(-1.01 * ball.a) << '\n';
}
