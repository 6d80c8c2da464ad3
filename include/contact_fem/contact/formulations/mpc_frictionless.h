// Frictionless contact as multipoint constraints: the normal displacement of
// an active slave node eliminated through the dual mortar relation, the
// active set from the recovered reactions and the gap (no penalty).
#ifndef contact_fem_mpc_frictionless_h
#define contact_fem_mpc_frictionless_h

#include <contact_fem/contact/formulations/alm_frictionless.h>

namespace contact_fem
{
  /**
   * "mpc frictionless": on an active slave node j the normal component of
   * the slave displacement is eliminated through the dual mortar relation
   *   n_j . u_j = n_j . (sum_l M_jl / D_j u_l) + g_j(X)
   * (the same affine constraint as "alm frictionless", solved for the
   * free component with the largest normal part), and the contact pressure
   * is the reaction of that eliminated DoF mapped back through D_j n_j.
   * The active set is the classical master-slave rule, with no penalty:
   * - an active node stays active while its recovered pressure compresses
   *   (lambda_j > 0), and is released when its reaction pulls;
   * - an inactive node becomes active when it penetrates (g_j < 0).
   * At the start of a load step the nodes active and in compression at the
   * last converged step stay active, penetrating nodes join, and at the
   * start of a load path or of a new mesh nodes about to touch too
   * (FrictionlessFormulation::about_to_touch()).
   * The converged state is the one of "alm frictionless" (both satisfy
   * g >= 0, lambda >= 0, lambda g = 0 with the same constraints); only the
   * path of the active set may differ. With Contact/Kinematics = current
   * the Newton system is the alm's on the iterate's configuration, and
   * lambda_j and g_j are that configuration's (the Cauchy pressure).
   */
  template <int dim>
  class MpcFrictionless : public AlmFrictionless<dim>
  {
  public:
    /// Reads the shared normal keys; refuses Contact/Penalty (there is
    /// none) and the penalty-only keys.
    explicit MpcFrictionless(ParameterHandler &prm);

    /// The base's results, with penalty 0: none decides anything here.
    void
    add_results(const ContactInterface<dim> &interface, Json &contact) const override;

  protected:
    bool
    decides_active(const typename ContactInterface<dim>::SlaveNode &s,
                   const double                                     g,
                   const bool                                       at_step_start,
                   const StepStart                                  start) const override;
  };
} // namespace contact_fem

#endif
