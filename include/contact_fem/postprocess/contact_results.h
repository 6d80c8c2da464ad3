// The results of a converged contact state that every scene with contact
// pairs reports: the active set, the pressure range, the gaps, the contact
// force, the penetration check; and the balance of the applied load
// against the support reactions that every scene reports.
#ifndef contact_fem_contact_results_h
#define contact_fem_contact_results_h

#include <deal.II/base/tensor.h>

#include <contact_fem/core/json.h>
#include <contact_fem/postprocess/analytical_comparison.h>
#include <contact_fem/postprocess/forces.h>

#include <functional>
#include <map>
#include <string>

namespace contact_fem
{
  using namespace dealii;

  /// The cycle's "contact" record of @p state; @p penetration_excess is the
  /// largest unexplained penetration over h of the last check against the
  /// whole master surface (SearchControl).
  template <int dim>
  Json
  contact_results(const ContactState<dim> &state, const double penetration_excess);

  /// The lines of the "contact" record @p contact of @p state, with the
  /// formulation's own results (which may read the "reaction" record
  /// @p reaction); @p penetration_tolerance: Contact/Penetration tolerance.
  /// With @p round_off_pressures (bodies that touch without pressing, which
  /// the caller has warned about) the ratios of pressures and the
  /// formulation's friction checks are round-off over round-off: left out.
  template <int dim>
  std::string
  contact_results_text(const ContactState<dim> &state,
                       const Json              &contact,
                       const Json              &reaction,
                       const double             penetration_tolerance,
                       const bool               round_off_pressures);

  /// What the balance of the loads against the support reactions reads.
  template <int dim>
  struct BalanceInputs
  {
    /// The residual, the prescribed DoFs and the contact force.
    const ForceInputs<dim> &forces;
    /// Whether an owned DoF is held by a support (a prescribed component or
    /// a roller).
    const std::function<bool(types::global_dof_index)> &held;
    /// The resultant of the applied loads on each body.
    const std::map<types::material_id, Tensor<1, dim>> &body_loads;
    /// The smallest Young's modulus and the largest displacement component,
    /// which set the size of a force that is round-off.
    double youngs_min;
    double largest_displacement;
  };

  /// The cycle's "reaction" record: the applied load, the support reaction
  /// and their relative imbalance (against the applied load, the largest
  /// load on one body or, for displacement-driven scenes, half the sum of
  /// the reaction magnitudes). Collective.
  template <int dim>
  Json
  reaction_results(const BalanceInputs<dim> &in);

  /// The lines of the "reaction" record @p reaction. Without
  /// @p balance_meaningful (no load, bodies touching without pressure: the
  /// forces are round-off) the relative imbalance is not printed as a
  /// number.
  std::string
  reaction_results_text(const Json &reaction, const bool balance_meaningful);
} // namespace contact_fem

#endif
