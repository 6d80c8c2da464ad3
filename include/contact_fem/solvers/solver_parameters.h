// The load path and the Newton iteration of a scene (subsections Load
// stepping and Newton).
#ifndef contact_fem_solver_parameters_h
#define contact_fem_solver_parameters_h

#include <deal.II/base/parameter_handler.h>

namespace contact_fem
{
  using namespace dealii;

  struct LoadStepping
  {
    double       end_time     = 1.;
    unsigned int n_steps      = 1;
    unsigned int max_splits   = 4; ///< times a failing step may be split
    unsigned int split_factor = 2; ///< sub-steps a failing step is split into

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  struct NewtonParameters
  {
    unsigned int max_iterations                  = 20;
    double       displacement_relative_tolerance = 1e-4;
    double       displacement_absolute_tolerance = 1e-9;
    double       multiplier_relative_tolerance   = 1e-4;
    double       multiplier_absolute_tolerance   = 1e-9;
    double       damping                         = 1.; ///< step length of every update

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };
} // namespace contact_fem

#endif
