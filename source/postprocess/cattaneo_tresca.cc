#include <deal.II/base/numbers.h>

#include <contact_fem/postprocess/cattaneo_tresca.h>

#include <cmath>

namespace contact_fem
{
  double
  tresca_stick_half_width(const double a, const double Q, const double g)
  {
    const double fraction = Q / (2. * a * g);
    return fraction < 1. ? a * std::sqrt(1. - fraction * fraction) : 0.;
  }

  double
  tresca_traction(const double x, const double a, const double c, const double g)
  {
    if (std::abs(x) >= a)
      return 0.;
    if (std::abs(x) >= c)
      return g;
    return 2. * g / dealii::numbers::PI * std::atan(std::sqrt((a * a - c * c) / (c * c - x * x)));
  }
} // namespace contact_fem
