// Hertz' solutions of an elastic cylinder (2D, plane strain) or sphere (3D)
// pressed onto a half-space: the reference of the Hertz scenes.
#ifndef contact_fem_hertz_solution_h
#define contact_fem_hertz_solution_h

#include <deal.II/base/numbers.h>

#include <cmath>

namespace contact_fem
{
  /**
   * Contact half-width (cylinder) or radius (sphere) a, peak pressure p_max
   * and the pressure p(rho) = p_max sqrt(1 - rho^2 / a^2), rho the distance
   * from the first point of contact (along x for the cylinder, from the
   * axis for the sphere). E* = 1 / ((1 - nu_1^2) / E_1 + (1 - nu_2^2) / E_2)
   * of the two bodies; a rigid plate has 1 / E_2 = 0.
   */
  struct HertzContact
  {
    double a = 0., p_max = 0.;

    /// Plane strain, load P per unit thickness: a = sqrt(4 P R / (pi E*)),
    /// p_max = 2 P / (pi a).
    static HertzContact
    cylinder(const double load_per_thickness, const double radius, const double E_star)
    {
      HertzContact h;
      h.a     = std::sqrt(4. * load_per_thickness * radius / (dealii::numbers::PI * E_star));
      h.p_max = 2. * load_per_thickness / (dealii::numbers::PI * h.a);
      return h;
    }

    /// Total load F on the whole sphere: a = (3 F R / (4 E*))^(1/3),
    /// p_max = p0 = 3 F / (2 pi a^2).
    static HertzContact
    sphere(const double load, const double radius, const double E_star)
    {
      HertzContact h;
      h.a     = std::cbrt(3. * load * radius / (4. * E_star));
      h.p_max = 3. * load / (2. * dealii::numbers::PI * h.a * h.a);
      return h;
    }

    double
    pressure(const double rho) const
    {
      return std::abs(rho) < a ? p_max * std::sqrt(1. - rho * rho / (a * a)) : 0.;
    }
  };
} // namespace contact_fem

#endif
