// Frictionless contact by a penalty on the mortar gap, optionally with the
// adaptive nodal penalties of Bussetta, Marceau and Ponthot.
#ifndef contact_fem_penalty_frictionless_h
#define contact_fem_penalty_frictionless_h

#include <contact_fem/contact/formulations/frictionless_formulation.h>

namespace contact_fem
{
  /**
   * "penalty frictionless": the weighted gaps of the alm formulation are
   * penalised instead of constrained. An active node (g_j < 0) carries
   * lambda_j = eps_j (-g_j), from the energy sum_j 1/2 eps_j D_j g_j^2, whose
   * stiffness and load assemble() adds to the system; no constraints, no
   * multipliers. The bodies overlap by lambda / eps.
   *
   * With Adaptive penalty, eps_j is updated in every iteration from the
   * penetrations of this and the previous iteration until each is below the
   * allowed one; adapted penalties live as long as the mesh (a split step
   * keeps them: they describe the mesh, not the load path).
   *
   * Contact/Kinematics = current: D_j, M_jl, n_j and the gaps are those of
   * the iterate u_k. The contact force is lambda_j f_j, f_j = -D_j n_j on
   * the slave node and +M_jl n_j on master l (the virtual work of the
   * pressure, as for the alm formulations), lambda_j = eps_j (-G_j) / D_j;
   * its tangent, f_j (x) d lambda_j + lambda_j d f_j, with d lambda_j =
   * -(eps_j dG_j + lambda_j dD_j) / D_j, is unsymmetric
   * (matrix_symmetric()). The derivatives: ContactInterface::linearise().
   */
  template <int dim>
  class PenaltyFrictionless : public FrictionlessFormulation<dim>
  {
  public:
    using typename FrictionlessFormulation<dim>::Residuals;

    /// Adaptive penalty and Maximum penetration factor (subsection Contact).
    static void
    declare_parameters(ParameterHandler &prm);

    explicit PenaltyFrictionless(ParameterHandler &prm);

    void
    initialize(const ContactInterface<dim> &interface) override;
    /// False with current kinematics (the operators' derivatives).
    bool
    matrix_symmetric() const override
    {
      return !current;
    }

    void
    start_load_step(const ContactInterface<dim> &interface,
                    const std::vector<double>   &u,
                    const StepStart              start) override;

    /// Only with @p all_candidates: the gap constraints of every paired node,
    /// whose couplings (closed over hanging nodes) are those the penalty
    /// terms create, for the sparsity pattern.
    void
    add_constraints(const ContactInterface<dim> &interface,
                    const std::vector<double>   &fixed_values,
                    AffineConstraints<double>   &constraints,
                    const bool                   all_candidates) const override;

    void
    add_sparsity(const ContactInterface<dim>     &interface,
                 const AffineConstraints<double> &constraints,
                 const IndexSet                  &owned,
                 DynamicSparsityPattern          &pattern) const override;

    /// eps_j D_j grad g_j grad g_j^T into the matrix and -eps_j D_j g_j(0)
    /// grad g_j into the right-hand side, per active node.
    void
    assemble(const ContactInterface<dim>     &interface,
             const AffineConstraints<double> &constraints,
             const AffineConstraints<double> &test_constraints,
             const IndexSet                  &owned,
             TrilinosWrappers::SparseMatrix  &matrix,
             TrilinosWrappers::MPI::Vector   &rhs) const override;

    /// Nothing to recover: lambda_j = eps_j (-g_j) is set by
    /// update_active_set().
    void
    recover_multipliers(const ContactInterface<dim> &interface,
                        const std::vector<double>   &residual) override;

    unsigned int
    update_active_set(const ContactInterface<dim> &interface,
                      const std::vector<double>   &u) override;

    double
    largest_penalty_penetration() const override;

    bool
    limits_steps() const override
    {
      return current && entry_depth_factor > 0.;
    }

    /// Current kinematics: the fraction of the update from @p u_old to @p
    /// u_new after which no node open in the solve penetrates deeper than
    /// the deepest node active in it (or Entry depth factor * h_j).
    double
    step_fraction(const ContactInterface<dim> &interface,
                  const std::vector<double>   &u_old,
                  const std::vector<double>   &u_new) const override;

    /// Zero by construction; with adaptive penalties the penetration beyond
    /// the allowed one.
    Residuals
    residuals(const ContactInterface<dim> &interface, const std::vector<double> &u) const override;

    void
    add_results(const ContactInterface<dim> &interface, Json &contact) const override;

    void
    print_results(const ContactInterface<dim> &interface,
                  const std::vector<double>   &u,
                  const Json                  &contact,
                  const Json                  &reaction,
                  std::ostream                &out) const override;

  protected:
    /// Contact/Kinematics = current.
    bool current = false;

    /// The decisions of start_load_step() on the rows this rank owns,
    /// not yet shared (share_decisions()).
    void
    decide_step_start(const ContactInterface<dim> &interface,
                      const std::vector<double>   &u,
                      const StepStart              start);

    /// The decisions of update_active_set() on the rows this rank owns,
    /// not yet shared (share_decisions()); the changes on this rank.
    unsigned int
    decide_active_set(const ContactInterface<dim> &interface, const std::vector<double> &u);

    /// The owners' decisions, with the penalties and the derived class's
    /// @p key_fields, to the other ranks (share_states()). Collective.
    void
    share_decisions(const ContactInterface<dim>              &interface,
                    const std::vector<std::vector<double> *> &key_fields = {});

  private:
    /// Bussetta-Marceau-Ponthot update of a nodal penalty @p eps from the
    /// penetrations (> 0 when overlapping) of this and the previous iteration.
    double
    adapted_penalty(const double eps,
                    const double penetration,
                    const double previous_penetration,
                    const double allowed) const;

    /// The terms of active node @p s with current kinematics (see the
    /// class comment), at the iterate @p u (at the interface DoFs).
    void
    assemble_current(const ContactInterface<dim>                     &interface,
                     const typename ContactInterface<dim>::SlaveNode &s,
                     const std::vector<double>                       &u,
                     const AffineConstraints<double>                 &constraints,
                     TrilinosWrappers::SparseMatrix                  &matrix,
                     TrilinosWrappers::MPI::Vector                   &rhs) const;

    bool   adaptive           = false;
    double penetration_factor = 1e-3;
    /// Contact/Entry depth factor (step_fraction()).
    double entry_depth_factor = 1e-5;
    /// eps_j per interface node (adapted or the pair's).
    std::vector<double> node_penalty;
    /// The gap of the previous iteration, per node.
    std::vector<double> previous_gap;
  };
} // namespace contact_fem

#endif
