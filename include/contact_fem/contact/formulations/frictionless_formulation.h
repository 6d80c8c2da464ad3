// What the frictionless formulations share: one scalar normal multiplier
// (the contact pressure) per slave node, its active set, and the per-pair
// penalty and scale factor from E/h of the interface.
#ifndef contact_fem_frictionless_formulation_h
#define contact_fem_frictionless_formulation_h

#include <contact_fem/contact/formulations/contact_formulation.h>

namespace contact_fem
{
  /// 'auto' (0) or a finite number > 0 (a penalty or scale key), else an
  /// error naming @p key.
  double
  parse_auto_or_positive(const std::string &text, const std::string &key);

  /// Whether Contact/Kinematics = current: the operators of every Newton
  /// iterate on its configuration, linearised in the tangent.
  bool
  current_kinematics(ParameterHandler &prm);

  /**
   * Base of the frictionless formulations: the contact pressure lambda_j of
   * every slave node j (positive in compression), the active set, and
   * eps / k per contact pair (given, or stiffness factor * min(E/h) over
   * the overlapping faces of the two sides).
   *
   * The pressure acts on the slave node as -lambda_j D_j n_j and on the
   * master nodes as +lambda_j M_jl n_j (the contact forces of residuals()).
   */
  template <int dim>
  class FrictionlessFormulation : public ContactFormulation<dim>
  {
  public:
    using typename ContactFormulation<dim>::Residuals;
    using typename ContactFormulation<dim>::State;

    /// The keys both frictionless formulations read (subsection Contact).
    struct Parameters
    {
      double penalty             = 0.; ///< 0: automatic
      double scale_factor        = 0.; ///< 0: automatic
      double stiffness_factor    = 1.;
      double active_check_factor = 1e-2;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /// The keys of a formulation whose gap is an exact constraint
      /// (@p formulation, for the message): Adaptive penalty is refused,
      /// since the penalty only scales the active-set test there.
      static Parameters
      parse_for_exact_gap(ParameterHandler &prm, const std::string &formulation);

      /// The keys of an exact-gap formulation without a penalty (the
      /// multipoint-constraint ones): Contact/Penalty is refused too.
      static Parameters
      parse_without_penalty(ParameterHandler &prm, const std::string &formulation);
    };

    explicit FrictionlessFormulation(const Parameters &parameters);

    void
    initialize(const ContactInterface<dim> &interface) override;

    /// Counted over the owned rows at each decision (reduce_counts()).
    unsigned int
    n_active() const override
    {
      return active_count;
    }

    bool
    is_active(const unsigned int n) const override
    {
      return active[n];
    }

    double
    normal_pressure(const unsigned int n) const override
    {
      return pressure[n];
    }

    Tensor<1, dim>
    traction(const typename ContactInterface<dim>::SlaveNode &s) const override
    {
      return -pressure[s.node] * s.normal;
    }

    double
    penalty_over_automatic() const override
    {
      return penalty_ratio;
    }

    std::unique_ptr<State>
    save_state() const override;

    void
    restore_state(const State &state) override;

    void
    add_results(const ContactInterface<dim> &interface, Json &contact) const override;

  protected:
    /// Sets eps and k of every pair from the statistics of the last search;
    /// the automatic eps is @p penalty_factor * stiffness factor * E/h.
    void
    set_pair_scaling(const ContactInterface<dim> &interface, const double penalty_factor);

    /// The start-of-step rule: lambda_j - eps g_j > 0, or about_to_touch().
    bool
    starts_active(const typename ContactInterface<dim>::SlaveNode &s,
                  const double                                     g,
                  const StepStart                                  start) const
    {
      return pressure[s.node] - penalty[s.pair] * g > 0. || about_to_touch(s, g, start);
    }

    /// Whether slave node @p s at gap @p g joins the first active set of a
    /// step that starts as @p start: from the unloaded state when g_j <=
    /// Active check factor * h_j; from a solution transferred to a new mesh
    /// when g_j <= 1e-2 h_j at most (that solution is in equilibrium at this
    /// load: its contact nodes hold g = 0 to round-off, which the margin
    /// keeps active, and a wider one would activate a rim of nodes around
    /// its contact zone); never within a load path.
    bool
    about_to_touch(const typename ContactInterface<dim>::SlaveNode &s,
                   const double                                     g,
                   const StepStart                                  start) const
    {
      if (start == StepStart::unloaded)
        return g <= parameters.active_check_factor * s.size;
      if (start == StepStart::transferred)
        return g <= std::min(parameters.active_check_factor, 1e-2) * s.size;
      return false;
    }

    /// The active-set rule of the augmented Lagrangian for paired slave
    /// node @p s at gap @p g: lambda_j - eps g_j > 0; at the start of a
    /// step (@p at_step_start) starts_active().
    bool
    augmented_rule(const typename ContactInterface<dim>::SlaveNode &s,
                   const double                                     g,
                   const bool                                       at_step_start,
                   const StepStart                                  start) const
    {
      return at_step_start ? starts_active(s, g, start) :
                             pressure[s.node] - penalty[s.pair] * g > 0.;
    }

    /// The master-slave (multipoint-constraint) rule, without a penalty: an
    /// active node stays active while its recovered pressure compresses
    /// (an active gap is held at zero, so only the reaction can release
    /// it), an inactive one becomes active when it penetrates; at the start
    /// of a step also when about_to_touch().
    bool
    reaction_rule(const typename ContactInterface<dim>::SlaveNode &s,
                  const double                                     g,
                  const bool                                       at_step_start,
                  const StepStart                                  start) const
    {
      const bool compressed = active[s.node] && pressure[s.node] > 0.;
      if (at_step_start)
        return compressed || g < 0. || about_to_touch(s, g, start);
      return active[s.node] ? compressed : g < 0.;
    }

    /// Interface nodes that are only master nodes are never active.
    void
    deactivate_master_nodes(const ContactInterface<dim> &interface)
    {
      for (unsigned int n = 0; n < interface.nodes.size(); ++n)
        if (!interface.nodes[n].slave)
          active[n] = false;
    }

    /// Contact/Kinematics = current: the DoFs of @p linearised that are not
    /// Dirichlet components, as @p columns, with their indices into
    /// linearised.dofs in @p kept. The Dirichlet DoFs already hold their
    /// values in the iterate u_k, so their columns (u - u_k = 0 there) and
    /// rows (zero test functions) drop out of the linearised terms.
    void
    free_patch_dofs(const ContactInterface<dim>                          &interface,
                    const typename ContactInterface<dim>::LinearisedNode &linearised,
                    std::vector<unsigned int>                            &kept,
                    std::vector<types::global_dof_index>                 &columns) const;

    /// A local system over interface DoFs @p dofs without its Dirichlet
    /// components: their values (dirichlet_values) times their columns
    /// move to @p rhs, their rows and columns go. For assemblies that add
    /// to the matrix directly: the constraints of a rank do not know the
    /// Dirichlet DoFs of another rank's part of a master surface, whose
    /// rows would be assembled.
    void
    eliminate_fixed(const ContactInterface<dim>          &interface,
                    std::vector<types::global_dof_index> &dofs,
                    FullMatrix<double>                   &matrix,
                    Vector<double>                       &rhs) const;

    /// The Dirichlet values at the interface DoFs (by position in
    /// interface.dofs()) of the present Newton iteration, kept by the
    /// add_constraints() of a formulation whose assembly eliminates
    /// Dirichlet components itself (eliminate_fixed(), the frictional
    /// cone term).
    mutable std::vector<double> dirichlet_values;

    /// The DoFs of slave node @p s and its masters, with grad g_j there:
    /// -n_j at the slave node, n_j M_jl / D_j at master l.
    void
    gap_gradient(const ContactInterface<dim>                     &interface,
                 const typename ContactInterface<dim>::SlaveNode &s,
                 std::vector<types::global_dof_index>            &dofs,
                 std::vector<double>                             &gradient) const;

    /// The same DoFs as gap_gradient() with the gradient of the gap
    /// measured along the fixed unit vector @p n instead of n_j: -n at the
    /// slave node, n M_jl / D_j at master l (the direction of the normal
    /// force when the frame's normal is not the slave normal).
    void
    gap_gradient_along(const ContactInterface<dim>                     &interface,
                       const typename ContactInterface<dim>::SlaveNode &s,
                       const Tensor<1, dim>                            &n,
                       std::vector<types::global_dof_index>            &dofs,
                       std::vector<double>                             &gradient) const;

    /// The component eliminated for an active node, or dim if none can be:
    /// the free component with the largest normal part (a node whose free
    /// components are nearly tangential cannot carry a normal constraint).
    unsigned int
    eliminated_component(const ContactInterface<dim>                     &interface,
                         const typename ContactInterface<dim>::SlaveNode &s) const;

    /// Adds g_j(u) = 0, solved for the eliminated component of node j, for
    /// every paired node (only the active ones with @p only_active), except
    /// those @p skip selects.
    void
    add_gap_constraints(const ContactInterface<dim> &interface,
                        const std::vector<double>   &fixed_values,
                        AffineConstraints<double>   &constraints,
                        const bool                   only_active,
                        const std::function<bool(const typename ContactInterface<dim>::SlaveNode &)>
                          &skip = {}) const;

    /// Adds g_j(u) = 0 for slave node @p s, solved for its component @p c,
    /// unless that DoF is constrained already.
    void
    add_gap_line(const ContactInterface<dim>                     &interface,
                 const typename ContactInterface<dim>::SlaveNode &s,
                 const unsigned int                               c,
                 const std::vector<double>                       &fixed_values,
                 AffineConstraints<double>                       &constraints) const;

    /// The contact forces at the interface DoFs (add_force_terms()) from
    /// the slave nodes whose rows this rank owns, summed by the owners of
    /// the DoFs (ContactInterface::sum_forces()), or from every slave node
    /// here if @p all: the serial values at every DoF either way.
    std::vector<double>
    contact_forces(const ContactInterface<dim> &interface, const bool all = false) const;

    /// The terms of the contact forces of the current pressures, along
    /// frame_normal() (the slave normal unless a frictional formulation
    /// takes the interface normal): -p_j D_j n on slave node j, p_j M_jl n
    /// on master l; of the nodes whose rows this rank owns, or of every
    /// node if @p all. A formulation with more forces adds their terms
    /// after these, keyed after them.
    virtual void
    add_force_terms(const ContactInterface<dim>                            &interface,
                    const bool                                              all,
                    std::vector<typename ContactInterface<dim>::ForceTerm> &terms) const;

    /// After the owners of the rows decided their nodes (active, pressure
    /// and the derived class's @p key_fields, per node; @p other_fields
    /// read only where a key value is set), the other ranks get them
    /// (ContactInterface::share_node_values()). Collective.
    void
    share_states(const ContactInterface<dim>              &interface,
                 const std::vector<std::vector<double> *> &key_fields   = {},
                 const std::vector<std::vector<double> *> &other_fields = {});

    /**
     * After a decision on the rows this rank owns: the decision's own
     * counts @p changes (this rank's: active-set changes, ...) and the
     * counts of the state over the owned rows (count_owned_rows()) summed
     * over the ranks in one reduction; the state's sums are kept
     * (take_counts(): n_active() and the derived class's counts and flags),
     * the changes' sums returned. Collective.
     */
    std::vector<unsigned int>
    reduce_counts(const ContactInterface<dim> &interface, std::vector<unsigned int> changes);

    /// The counts of the state over the rows this rank owns: the active
    /// nodes; a derived class appends its own.
    virtual std::vector<unsigned int>
    count_owned_rows(const ContactInterface<dim> &interface) const;

    /// Keeps the sums of count_owned_rows() over the ranks, read from
    /// @p next in the order they were appended.
    virtual void
    take_counts(std::vector<unsigned int>::const_iterator &next);

    Parameters          parameters;
    std::vector<double> pressure;           ///< lambda per interface node
    std::vector<bool>   active;             ///< per interface node
    std::vector<double> penalty;            ///< eps per pair
    std::vector<double> scale;              ///< k per pair
    double              penalty_ratio = 1.; ///< see penalty_over_automatic()
    unsigned int        active_count  = 0;  ///< n_active()

  private:
    struct PressureState : public State
    {
      std::vector<double> pressure;
      std::vector<bool>   active;
      unsigned int        active_count = 0;
    };
  };
} // namespace contact_fem

#endif
