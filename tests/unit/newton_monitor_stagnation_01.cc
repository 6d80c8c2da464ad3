// The "converged to linear-solver accuracy" rule of NewtonMonitor on a
// problem linear beyond its active set: a flat equilibrium residual with a
// settled active set is accepted only at the residual the linear solves
// themselves leave (set_linear_residual(), within a few times it). A flat
// residual far above it (1e-3 of the step's, after solves that left 1e-15)
// is a residual the solves do not see, and must never be called converged:
// the rule before accepted anything flat below 1e-2 of the step's.
// Nonlinear problems keep their own bound (flat at 1e-8 of the step's).

#include <contact_fem/solvers/newton_monitor.h>

#include <iostream>
#include <string>

using namespace contact_fem;

namespace
{
  // Runs the iteration of one step: residual 1 at the start, then
  // @p flat_ratio from the second iteration on, with no active-set changes
  // after the first; each solve leaves @p linear_residual. Returns what the
  // monitor made of it.
  std::string
  verdict(const bool nonlinear, const double flat_ratio, const double linear_residual)
  {
    NewtonParameters parameters;
    parameters.displacement_relative_tolerance = 1e-12; // only stagnation converges
    parameters.displacement_absolute_tolerance = 1e-300;
    parameters.multiplier_absolute_tolerance   = 1e-300;
    NewtonMonitor monitor(parameters, nonlinear);
    const double  r_lambda = 1e-20; // the contact conditions met
    monitor.assess(0, 1., 1., 1, false);
    for (unsigned int it = 1; it <= 20; ++it)
      {
        monitor.set_linear_residual(linear_residual);
        const NewtonMonitor::Assessment a =
          monitor.assess(it, it == 1 ? 0.1 : flat_ratio, r_lambda, it == 1 ? 1 : 0, false);
        if (a.converged)
          return std::string(a.residuals_small ? "converged" :
                                                 "converged to linear-solver accuracy") +
                 " at iteration " + std::to_string(it);
      }
    return "not converged in 20 iterations";
  }
} // namespace

int
main()
{
  std::cout << "linear, flat at 1e-3, solves leave 1e-3: " << verdict(false, 1e-3, 1e-3)
            << std::endl
            << "linear, flat at 1e-3, solves leave 4e-4: " << verdict(false, 1e-3, 4e-4)
            << std::endl
            << "linear, flat at 1e-3, solves leave 1e-15: " << verdict(false, 1e-3, 1e-15)
            << std::endl
            << "linear, flat at 2e-2, solves leave 2e-2: " << verdict(false, 2e-2, 2e-2)
            << std::endl
            << "nonlinear, flat at 1e-9, solves leave 1e-15: " << verdict(true, 1e-9, 1e-15)
            << std::endl
            << "nonlinear, flat at 1e-3, solves leave 1e-3: " << verdict(true, 1e-3, 1e-3)
            << std::endl;
}
