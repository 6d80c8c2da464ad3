// The contact pressure profile of a converged state as CSV: one row per
// paired slave node with its position, pressure, the analytical pressure
// where known, gap, state and the formulation's own fields.
#ifndef contact_fem_pressure_profile_h
#define contact_fem_pressure_profile_h

#include <contact_fem/geometry/model_frame.h>
#include <contact_fem/postprocess/analytical_comparison.h>

#include <functional>
#include <string>
#include <vector>

namespace contact_fem
{
  struct AnalyticalSolution;

  /**
   * Columns: the deformed position (x in 2D, x,y,z in 3D), pressure,
   * hertz_pressure (@p exact at the deformed position, 0 without it), gap
   * (the weighted gap), active, the formulation's nodal fields, then pair
   * (its index in Contact/Pairs), in 2D the deformed y, and the reference
   * position reference_x, reference_y(, reference_z). Positions are in the
   * user's coordinates (@p frame). Rows are sorted by pair, then by
   * position. The first columns are those a reference profile is read
   * from (Analytical solution/Reference pressure profile). Each rank
   * gives the nodes whose rows it owns; the text is whole on rank 0 only.
   * Collective.
   */
  template <int dim>
  std::string
  pressure_profile_csv(const ContactState<dim>                         &state,
                       const ModelFrame<dim>                           &frame,
                       const std::function<double(const Point<dim> &)> &exact);

  /// Relative L2 error (pressure_l2_relative_error()) of a pressure per
  /// interface node against Analytical solution/Reference pressure profile,
  /// whose coordinate is x (2D) or the distance from the axis (3D).
  template <int dim>
  double
  reference_pressure_error(const AnalyticalSolution  &analytical,
                           const ContactState<dim>   &state,
                           const std::vector<double> &pressure);
} // namespace contact_fem

#endif
