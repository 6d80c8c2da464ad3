// The contact pairs and the search and check settings of a scene
// (subsection Contact; the formulations declare their own keys).
#ifndef contact_fem_contact_parameters_h
#define contact_fem_contact_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <optional>
#include <string>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /// One contact pair: the slave and master surfaces by boundary id.
  struct ContactPair
  {
    types::boundary_id slave;
    types::boundary_id master;
  };

  struct ContactParameters
  {
    std::vector<ContactPair> pairs; ///< empty: no contact code runs
    /// Surfaces glued by mesh tying (Tied pairs); empty: no tying code runs.
    std::vector<ContactPair> tied_pairs;
    /// Tied nodes released where the tying pulls (Tied release in tension),
    /// beyond this fraction of the pair's traction scale; none: never.
    std::optional<double> tied_release_threshold;
    double                search_factor = 3.;
    /// Mortar operators rebuilt at every load step (else once, on the
    /// reference configuration): Kinematics = updated or current.
    bool updated_kinematics = false;
    /// Kinematics = current: also rebuilt and linearised at every Newton
    /// iteration (2D, alm frictionless).
    bool current_kinematics = false;
    /// Unexplained penetration allowed after convergence, over the element size.
    double penetration_tolerance = 0.05;
    bool   allow_loss_of_contact = false;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };
} // namespace contact_fem

#endif
