// Frictional contact by the augmented Lagrangian: exact normal and stick
// constraints, Coulomb or Tresca slip through the test space (semi-smooth
// Newton on the stick/slip complementarity, dual mortar, 2D and 3D).
#ifndef contact_fem_alm_frictional_h
#define contact_fem_alm_frictional_h

#include <contact_fem/contact/formulations/frictional_formulation.h>
#include <contact_fem/contact/formulations/frictionless_formulation.h>

namespace contact_fem
{
  /**
   * "alm frictional": the contact traction of slave node j is the vector
   * lambda_j = -p_j n_j + t_j (on the slave; t_j in the tangent plane, dim
   * - 1 components in the node's tangent_frame()), whose force is D_j
   * lambda_j on the slave node and -M_jl lambda_j on master node l. The
   * normal part is that of "alm frictionless" (the base class). The
   * tangential part follows the frictional law of the pair (slip bound
   * T(p)) through the complementarity of Hueber and Wohlmuth:
   *
   *   trial traction t*_j = t_j - c xi_j, with xi_j the weighted slip of the
   *   slave relative to the master since the last converged load step,
   *   stick  if |t*_j| < T(p_j - eps g_j):  xi_j = 0,
   *   slip   otherwise:                     t_j = T(p_j) d_j,
   *                                         d_j = t*_j / |t*_j|
   *
   * (the return mapping onto the disc |t| <= T; in 2D d_j is the sign
   * sigma_j),
   * c = eps, the pair's penalty (E/h). Like the gap, each condition is
   * linear in the displacements once the sets and slip signs are fixed, so
   * every iteration is one linear solve:
   * - a stick node satisfies g_j = 0 and xi_j = 0: both components of its
   *   displacement are constrained to the masters (u_j = sum_l M_jl/D_j u_l
   *   + the slip and gap offsets);
   * - a slip node satisfies g_j = 0 (one component constrained, as
   *   frictionless) and the slip condition, linearised in p consistently:
   *   (tau + sigma T'(p) n) . lambda_j = sigma (T(p) - T'(p) p). Its test
   *   functions move along w = tau + sigma T' n instead of tau, and the
   *   known part sigma (T - T' p) tau of its traction is a load. The
   *   system is then unsymmetric (symmetric()), Tresca's too (its test
   *   space follows the interface normal, the trial space the slave's).
   * lambda_j is recovered from the residual of the slave node, r_j = D_j
   * lambda_j. In 2D the slip direction is a sign, so its linearisation
   * vanishes. In 3D the slip condition t = T(p) d(t - c xi) has two
   * components; linearised, along d it is the 2D condition (w = d + T' n),
   * and across it, along e = n x d,
   *   (1 - a) e . t + a c e . xi = 0,   a = T(p) / |t*|,
   * the derivative of the direction d. The test functions of a slip node
   * then move in the plane of w and e (normal n - T' d), and the term
   * D_j beta (e . v)(e . xi(u)), beta = c a / (1 - a), joins the matrix
   * (assemble_cone_term()): Newton's quadratic convergence for a turning
   * slip direction. At the solution e . t = e . xi = 0 whatever beta.
   *
   * Nodes with a Dirichlet component carry no tangential condition (the
   * support holds them tangentially): they are treated as frictionless.
   * The slip is measured from the last accepted load step with the current
   * operators (small sliding): a load step is a physical increment.
   *
   * Contact/Kinematics = current (2D, 3D on bilinear faces): the operators
   * of every Newton iterate on its configuration, the frame the slave
   * normal n_j (frame_on_interface(); the interface normal of the small
   * path and of "penalty frictional" made four postprocess scenes cycle,
   * doc/finite_strain.md), and the objective slip of Gitterle, Popp et al.
   * per unit D_j: xi_j = -P_j ((D_j - D_j^n) x_j - sum_l (M_jl - M_jl^n)
   * x_l) / D_j (P_j onto the tangent plane, in the frame), the change of
   * the operators since the last accepted step (^n) at the
   * current positions, zero under any rigid motion of the pair. The trial space is free; the
   * test space is that of the small path (stick: v_j = sum_l M_jl / D_j
   * v_l; slip: normal to the test normal), and the rows it eliminates hold
   * the linearised gap and, for a stick node, the linearised xi_j = 0 (per
   * frame component). The geometric stiffness -p_j df_j/du - t . dh_j/du
   * (f_j the force per unit pressure along the frame normal, h_j per unit
   * tangential traction held in its tangent plane; t_j = T(p_j) d_j when
   * slipping; FrictionalFormulation::frame_force(), frame_tangent_force())
   * makes the tangent consistent (assemble_current()); in 3D the cone term
   * takes d(e . xi_j)/du of the objective slip. The multiplier is the
   * unknown (no history traction is carried), so no transport of a history
   * to the current normal is needed.
   */
  template <int dim>
  class AlmFrictional : public FrictionalFormulation<dim, FrictionlessFormulation<dim>>
  {
    using Base = FrictionalFormulation<dim, FrictionlessFormulation<dim>>;

  public:
    using typename FrictionlessFormulation<dim>::Residuals;
    using typename FrictionlessFormulation<dim>::State;
    using Parameters = typename FrictionlessFormulation<dim>::Parameters;
    using SlaveNode  = typename ContactInterface<dim>::SlaveNode;

    /// Reads the shared normal keys; @p friction: the laws and Pure slip.
    AlmFrictional(ParameterHandler &prm, const FrictionParameters &friction);

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
    add_test_constraints(const ContactInterface<dim> &interface,
                         const std::vector<double>   &fixed_values,
                         AffineConstraints<double>   &constraints) const override;

    /// The known traction (T - T' p) d of the slip nodes (Tresca's bound)
    /// as a load; in 3D the cone term of the slip nodes.
    void
    assemble(const ContactInterface<dim>     &interface,
             const AffineConstraints<double> &constraints,
             const AffineConstraints<double> &test_constraints,
             const IndexSet                  &owned,
             TrilinosWrappers::SparseMatrix  &matrix,
             TrilinosWrappers::MPI::Vector   &rhs) const override;

    void
    recover_multipliers(const ContactInterface<dim> &interface,
                        const std::vector<double>   &residual) override;

    unsigned int
    update_active_set(const ContactInterface<dim> &interface,
                      const std::vector<double>   &u) override;

    /// |(g_A, lambda_I / k, xi_stick, (t - sigma T) / k of the slip
    /// nodes)|, a length.
    Residuals
    residuals(const ContactInterface<dim> &interface, const std::vector<double> &u) const override;

    Tensor<1, dim>
    traction(const SlaveNode &s) const override
    {
      const Tensor<1, dim> n = frame_normal(s);
      return -this->pressure[s.node] * n + to_global(tangential[s.node], n);
    }

    /// The frame (FrictionalFormulation::frame_normal()): the shared
    /// interface normal where the law has friction on the small path; the
    /// slave normal with current kinematics (frame_on_interface()), at
    /// nodes held by a support and under a law without friction.
    using Base::current_frame_on_interface;
    using Base::frame_normal;

    void
    accept_load_step(const ContactInterface<dim> &interface, const std::vector<double> &u) override;

    bool
    symmetric() const override;

    /// The sets of FrictionalFormulation, + 4 on a node released in tension
    /// with friction in the step (on its way to grazing, as the flag + 8).
    std::vector<int>
    contact_sets() const override;

    /// Current kinematics: the patches of the linearised nodes and the
    /// masters of their last accepted step (the objective slip).
    void
    add_sparsity(const ContactInterface<dim>     &interface,
                 const AffineConstraints<double> &constraints,
                 const IndexSet                  &owned,
                 DynamicSparsityPattern          &pattern) const override;

    std::unique_ptr<State>
    save_state() const override;

    void
    restore_state(const State &state) override;

    void
    add_results(const ContactInterface<dim> &interface, Json &contact) const override;

    /// The friction cone check, then the friction totals.
    void
    print_results(const ContactInterface<dim> &interface,
                  const std::vector<double>   &u,
                  const Json                  &contact,
                  const Json                  &reaction,
                  std::ostream                &out) const override;

  protected:
    /// Nodes released in tension with friction in this load step (a node
    /// that then penetrates again grazes: Base::grazing).
    std::vector<bool> released_in_tension;
    using Base::grazing;
    using Base::slip_bound;
    using Base::slip_bound_derivative;

    /// Per pair: the stiffer side's E / h over the softer side's (the
    /// penalty's), which sets the largest beta (slip_cone_stiffness()).
    std::vector<double> stiffness_ratio;
    /// For a formulation that shares the constraints and only decides the
    /// sets otherwise (mpc frictional); @p name for the messages; @p
    /// current: Contact/Kinematics = current.
    AlmFrictional(const FrictionParameters &friction,
                  const Parameters         &parameters,
                  const std::string        &name,
                  const bool                current_kinematics);

    /// Whether paired slave node @p s is active at gap @p g (see
    /// FrictionlessFormulation::augmented_rule()).
    virtual bool
    decides_active(const SlaveNode &s,
                   const double     g,
                   const bool       at_step_start,
                   const StepStart  start) const
    {
      return this->augmented_rule(s, g, at_step_start, start);
    }

    /// The pressure of the slip bound of active node @p s at gap @p g in
    /// the stick/slip decision: the augmented lambda - eps g.
    virtual double
    bound_pressure(const SlaveNode &s, const double g) const
    {
      return this->pressure[s.node] - this->penalty[s.pair] * g;
    }

    /// The stick/slip decision of an active frictional node with slip @p xi
    /// and the pressure @p p_bound of its slip bound: zero = stick,
    /// else the unit direction d of the trial traction t - c xi (2D: +1 /
    /// -1).
    virtual TangentialVector<dim>
    stick_or_slip(const SlaveNode &s, const double p_bound, const TangentialVector<dim> &xi) const;

    /// The stick/slip decision on the trial traction @p trial against the
    /// bound T(@p p_bound): stick inside it (or with neither traction nor
    /// slip, or when the trial turns against the slip), else slip along
    /// the trial.
    TangentialVector<dim>
    decide_on_trial(const SlaveNode             &s,
                    const double                 p_bound,
                    const TangentialVector<dim> &trial) const;

    /// The part of the tangential vector @p t of node @p s along the
    /// direction its support leaves free (free_tangent()) if a support
    /// holds it along the other (StickSlipSets::held_component); @p t
    /// otherwise.
    TangentialVector<dim>
    free_part(const SlaveNode &s, const TangentialVector<dim> &t) const;

    /// beta of the cone term of active node @p s (0 unless it slips under
    /// a law with friction in 3D) at slip @p xi.
    virtual double
    slip_cone_stiffness(const SlaveNode &s, const TangentialVector<dim> &xi) const;

    using Base::frictionless_law;
    using Base::laws;
    using Base::pure_slip;
    using Base::sets;
    using Base::tangential;

    bool
    on_current_configuration() const override
    {
      return current;
    }

    /// The interface normal frames the small path only: with current
    /// kinematics the alm and the mpc stay in the slave normal's frame.
    /// In the interface frame (tangent verified, unit/
    /// alm_frictional_linearisation_01 at the commit that introduced it)
    /// four postprocess scenes cycle between stick/slip sets at unconverged
    /// iterates (doc/finite_strain.md, "The interface frame for alm and mpc
    /// frictional").
    bool
    frame_on_interface(const SlaveNode &s) const override
    {
      return !current && Base::frame_on_interface(s);
    }

  private:
    /// The terms of the contact forces of the tractions (D_j lambda_j on
    /// the slave, -M_jl lambda_j on the masters) in place of the pressures'.
    void
    add_force_terms(const ContactInterface<dim>                            &interface,
                    const bool                                              all,
                    std::vector<typename ContactInterface<dim>::ForceTerm> &terms) const override;

    /// The friction cone check: slip nodes on the bound (|t - sigma T(p)|),
    /// stick nodes inside it (|t| - T(p)), relative to the largest bound.
    void
    print_cone_check(const ContactInterface<dim> &interface, std::ostream &out) const;
    /// Whether print_cone_check() has warned (once per run).
    mutable bool cone_check_warned = false;

    /// The weighted tangential slip of slave node @p s at @p u since the
    /// last accepted load step, in the tangent frame of frame_normal(s).
    TangentialVector<dim>
    slip_increment(const ContactInterface<dim> &interface,
                   const SlaveNode             &s,
                   const std::vector<double>   &u) const;

    /// The stick lines of a node a support holds along one tangential
    /// direction (3D): gap and free tangent on the two free components.
    void
    add_partly_held_stick(const ContactInterface<dim> &interface,
                          const SlaveNode             &s,
                          const double                 normal_offset,
                          const Tensor<1, dim>        &old_relative,
                          const std::vector<double>   &fixed_values,
                          AffineConstraints<double>   &constraints) const;

    /// recover_multipliers() of such a node.
    void
    recover_partly_held(const ContactInterface<dim> &interface,
                        const SlaveNode             &s,
                        const std::vector<double>   &residual);

    /// The direction w of the slip condition w . lambda = T - T' p (along
    /// d) of slip node @p s: 2D tau + sigma T'(p) n (the condition times
    /// sigma), 3D d + T'(p) n.
    Tensor<1, dim>
    slip_direction(const SlaveNode &s) const;

    /// The normal of the test space of slip node @p s: normal to w (2D),
    /// to w and e = n x d (3D).
    Tensor<1, dim>
    test_normal(const SlaveNode &s) const;

    /// The cone term of slip node @p s (3D): rows by @p test_constraints,
    /// columns by @p constraints.
    void
    assemble_cone_term(const ContactInterface<dim>     &interface,
                       const SlaveNode                 &s,
                       const AffineConstraints<double> &constraints,
                       const AffineConstraints<double> &test_constraints,
                       TrilinosWrappers::SparseMatrix  &matrix,
                       TrilinosWrappers::MPI::Vector   &rhs) const;

    /// After the owners of the rows decided their nodes (active set,
    /// multipliers, released multipliers, stick/slip sets, cone factors),
    /// the other ranks get them (share_frictional_states()). Collective.
    void
    share_decisions(const ContactInterface<dim> &interface);

    /// Whether node @p s slips under a law with friction or a pressure-
    /// dependent bound (pressure_dependent_slip).
    bool
    slips_dependent_on_pressure(const ContactInterface<dim> &interface, const SlaveNode &s) const;

    /// The frictional counts, then the owned nodes that
    /// slips_dependent_on_pressure().
    std::vector<unsigned int>
    count_owned_rows(const ContactInterface<dim> &interface) const override;

    void
    take_counts(std::vector<unsigned int>::const_iterator &next) override;

    /// The component a slip node eliminates: both the gap (normal part) and
    /// the test line (w part of the other component) must be well posed.
    unsigned int
    slip_eliminated_component(const SlaveNode &s) const;

    /// The stick/slip set and the cone term of active node @p s at @p u.
    void
    set_direction(const ContactInterface<dim> &interface,
                  const SlaveNode             &s,
                  const double                 p_bound,
                  const std::vector<double>   &u);

    /// u_j = sum_l M_jl / D_j u_l + offsets: the gap and the stick condition
    /// of node @p s, both components.
    void
    add_stick_constraint(const ContactInterface<dim> &interface,
                         const SlaveNode             &s,
                         const std::vector<double>   &fixed_values,
                         AffineConstraints<double>   &constraints) const;

    /// g_j = 0 solved for the component slip_eliminated_component() picks
    /// (trial space), or the test line of the slip node (@p test).
    void
    add_slip_constraint(const ContactInterface<dim> &interface,
                        const SlaveNode             &s,
                        const std::vector<double>   &fixed_values,
                        AffineConstraints<double>   &constraints,
                        const bool                   test) const;

    using Base::converged_displacement;
    using Base::last_step_slip;
    using Base::last_stick_slip_changes;
    using Base::n_slip;
    using Base::n_stick;
    using Base::slip_history;

    /// Whether any node slips under a law with friction: only then do its
    /// test functions leave the trial space (symmetric()). Found at the
    /// decisions of start_load_step() and update_active_set().
    bool pressure_dependent_slip = false;

    /// Contact/Kinematics = current (see the class comment).
    bool current    = false;
    using Operators = typename Base::Operators;
    using Row       = typename Base::Row;
    using Base::converged_operators;
    using Base::objective_slip;

    /// Current kinematics: the rows of the linearised gap and (stick) slip
    /// of active node @p s and its geometric stiffness, at @p u.
    void
    assemble_current(const ContactInterface<dim>     &interface,
                     const SlaveNode                 &s,
                     const std::vector<double>       &u,
                     const AffineConstraints<double> &constraints,
                     const AffineConstraints<double> &test_constraints,
                     TrilinosWrappers::SparseMatrix  &matrix,
                     TrilinosWrappers::MPI::Vector   &rhs) const;
    /// Multipliers of the nodes released in the last update.
    std::vector<double>                released_pressure;
    std::vector<TangentialVector<dim>> released_tangential;
    /// beta of the cone term per interface node (3D slip nodes).
    std::vector<double> cone_stiffness;

    struct FrictionState : public State
    {
      std::unique_ptr<State>             normal;
      std::vector<TangentialVector<dim>> tangential, last_step_slip;
      std::vector<double>                converged_displacement;
      SlipHistory<dim>                   slip_history;
      StickSlipSets<dim>                 sets;
      std::vector<Operators>             converged_operators;
      unsigned int                       stick_count = 0, slip_count = 0;
      bool                               pressure_dependent_slip = false;
    };
  };
} // namespace contact_fem

#endif
