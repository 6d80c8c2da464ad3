// Frictionless contact by the augmented Lagrangian with exact active
// constraints (semi-smooth Newton, dual mortar multipliers condensed).
#ifndef contact_fem_alm_frictionless_h
#define contact_fem_alm_frictionless_h

#include <contact_fem/contact/formulations/frictionless_formulation.h>

namespace contact_fem
{
  /**
   * "alm frictionless": the normal contact conditions of every paired slave
   * node j,
   *   lambda_j >= 0,  g_j >= 0,  lambda_j g_j = 0,
   * written as the nonlinear complementarity function
   *   C_j = lambda_j - max(0, lambda_j - eps g_j) = 0,
   * where lambda_j is the contact pressure, g_j the normalised weighted gap
   * and eps the penalty. Its semi-smooth Newton linearisation is: on the
   * active set A = {lambda_j - eps g_j > 0} the gap vanishes, elsewhere
   * lambda_j = 0.
   *
   * Because the dual basis makes D diagonal, the condition g_j = 0 of an
   * active node fixes one displacement component of that node in terms of
   * the master DoFs, so it is imposed as an affine constraint (exact static
   * condensation of the multipliers), and lambda_j is recovered afterwards
   * from the residual of that eliminated DoF: lambda_j = -r_c / (D_j n_j,c).
   * eps only decides the active set; it cannot change the converged answer.
   */
  template <int dim>
  class AlmFrictionless : public FrictionlessFormulation<dim>
  {
  public:
    using typename FrictionlessFormulation<dim>::Residuals;
    using typename FrictionlessFormulation<dim>::Parameters;

    /// Reads the shared frictionless keys; refuses the penalty-only ones.
    explicit AlmFrictionless(ParameterHandler &prm);

    void
    initialize(const ContactInterface<dim> &interface) override;

    void
    start_load_step(const ContactInterface<dim> &interface,
                    const std::vector<double>   &u,
                    const StepStart              start) override;

    void
    add_constraints(const ContactInterface<dim> &interface,
                    const std::vector<double>   &fixed_values,
                    AffineConstraints<double>   &constraints,
                    const bool                   all_candidates) const override;

    void
    recover_multipliers(const ContactInterface<dim> &interface,
                        const std::vector<double>   &residual) override;

    unsigned int
    update_active_set(const ContactInterface<dim> &interface,
                      const std::vector<double>   &u) override;

    /// |(g_A, lambda_I / k)|: the gap of the active nodes and the released
    /// multipliers of the others, a length.
    Residuals
    residuals(const ContactInterface<dim> &interface, const std::vector<double> &u) const override;

    /// With current kinematics the test space (the contact force
    /// directions) differs from the linearised gap of the trial space.
    bool
    symmetric() const override
    {
      return !current;
    }

    void
    add_test_constraints(const ContactInterface<dim> &interface,
                         const std::vector<double>   &fixed_values,
                         AffineConstraints<double>   &constraints) const override;

    void
    add_sparsity(const ContactInterface<dim>     &interface,
                 const AffineConstraints<double> &constraints,
                 const IndexSet                  &owned,
                 DynamicSparsityPattern          &pattern) const override;

    /// Current kinematics: the linearised gap rows and the geometric
    /// stiffness (nothing otherwise).
    void
    assemble(const ContactInterface<dim>     &interface,
             const AffineConstraints<double> &constraints,
             const AffineConstraints<double> &test_constraints,
             const IndexSet                  &owned,
             TrilinosWrappers::SparseMatrix  &matrix,
             TrilinosWrappers::MPI::Vector   &rhs) const override;

  protected:
    /// For a formulation that shares the exact gap constraints and only
    /// decides the active set otherwise (mpc frictionless); @p current:
    /// Contact/Kinematics = current.
    AlmFrictionless(const Parameters &parameters, const bool current_kinematics);

    /// Whether paired slave node @p s is active at gap @p g, from the
    /// current pressures and active set: lambda - eps g > 0, and at the
    /// start of a step (@p at_step_start) also about to touch, depending
    /// on how the step starts (@p start: about_to_touch()).
    virtual bool
    decides_active(const typename ContactInterface<dim>::SlaveNode &s,
                   const double                                     g,
                   const bool                                       at_step_start,
                   const StepStart                                  start) const;

  private:
    /// Contact/Kinematics = current: the operators of every Newton iterate
    /// on its configuration, with their linearisation (the interface's
    /// linearised_nodes). The gap of an active node j is then no constraint
    /// of the trial space: its linearised form G_j(u_k) + dG_j/du (u - u_k)
    /// = 0 is the matrix row of the DoF its force direction eliminates from
    /// the test space (the two differ at finite deformation), and
    /// -lambda_j df_j/du is the geometric stiffness.
    bool current = false;

    /// The row of the linearised gap of active node @p s and the geometric
    /// stiffness of its pressure, at the interface displacement @p u.
    void
    assemble_current(const ContactInterface<dim>                     &interface,
                     const typename ContactInterface<dim>::SlaveNode &s,
                     const std::vector<double>                       &u,
                     const AffineConstraints<double>                 &constraints,
                     const AffineConstraints<double>                 &test_constraints,
                     TrilinosWrappers::SparseMatrix                  &matrix,
                     TrilinosWrappers::MPI::Vector                   &rhs) const;

    /// Multipliers of the nodes released in the last update (for the
    /// residual).
    std::vector<double> released_pressure;
  };
} // namespace contact_fem

#endif
