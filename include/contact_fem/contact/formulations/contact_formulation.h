// The plug-in point of the contact formulations: what the driver needs from
// a contact law, and the registry that makes one from its .prm name.
#ifndef contact_fem_contact_formulation_h
#define contact_fem_contact_formulation_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/core/json.h>

#include <functional>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace contact_fem
{
  struct FrictionParameters;

  using namespace dealii;

  /**
   * A contact formulation: the conditions imposed at the slave nodes of a
   * ContactInterface, their multipliers and their active set, seen by the
   * driver only through this interface.
   *
   * Per load step the driver calls start_load_step() after each search;
   * per Newton iteration it imposes add_constraints() (formulations with
   * exact constraints) and/or adds assemble() (formulations with matrix and
   * residual contributions) to the bulk system, solves, and calls
   * recover_multipliers(), update_active_set() and residuals(). The state
   * of the iteration (multipliers, active and stick/slip sets, ...) lives in
   * the formulation; save_state() / restore_state() take it back to the last
   * converged step when a step is split.
   *
   * A new formulation is one new class derived from this one and one line in
   * the registry (source/contact/formulations/contact_formulation.cc).
   */
  /// How a load step starts: from the unloaded state (the first step of a
  /// load path), from a solution transferred to a refined mesh at the same
  /// load (a later adaptive cycle), or from the last converged step.
  enum class StepStart
  {
    unloaded,
    transferred,
    continued
  };

  template <int dim>
  class ContactFormulation
  {
  public:
    virtual ~ContactFormulation() = default;

    /// Residuals of the current iterate for the active set just computed.
    struct Residuals
    {
      double              multiplier = 0.; ///< of the contact conditions, a length
      std::vector<double> contact_force;   ///< at the interface DoFs
    };

    /// The state restore_state() takes back (opaque to the driver).
    struct State
    {
      virtual ~State() = default;
    };

    /// Resets the state for a new mesh of @p interface.
    virtual void
    initialize(const ContactInterface<dim> &interface) = 0;

    /// After a search: scaling and active set at the start of a load step
    /// (or after a wider search during it), at the interface displacement
    /// @p u; how the step starts (@p start) decides whether nodes about to
    /// touch start active.
    virtual void
    start_load_step(const ContactInterface<dim> &interface,
                    const std::vector<double>   &u,
                    const StepStart              start) = 0;

    /// Adds the conditions imposed as affine constraints (of the active set,
    /// or of every paired node with @p all_candidates, for the sparsity
    /// pattern); @p fixed_values are the Dirichlet values at the interface
    /// DoFs. Default: none.
    virtual void
    add_constraints(const ContactInterface<dim> &interface,
                    const std::vector<double>   &fixed_values,
                    AffineConstraints<double>   &constraints,
                    const bool                   all_candidates) const;

    /// Adds the couplings assemble() may create, for the nodes whose first
    /// DoF is in @p owned. Default: none.
    virtual void
    add_sparsity(const ContactInterface<dim>     &interface,
                 const AffineConstraints<double> &constraints,
                 const IndexSet                  &owned,
                 DynamicSparsityPattern          &pattern) const;

    /// Adds the contact stiffness and load of the nodes whose first DoF is
    /// in @p owned to the system: rows through @p test_constraints, columns
    /// through @p constraints (the same object when symmetric()); the
    /// caller compresses. Default: none.
    virtual void
    assemble(const ContactInterface<dim>     &interface,
             const AffineConstraints<double> &constraints,
             const AffineConstraints<double> &test_constraints,
             const IndexSet                  &owned,
             TrilinosWrappers::SparseMatrix  &matrix,
             TrilinosWrappers::MPI::Vector   &rhs) const;

    /// The multipliers of the new iterate, from the bulk residual
    /// C_h^T (K u - f) at the interface DoFs.
    virtual void
    recover_multipliers(const ContactInterface<dim> &interface,
                        const std::vector<double>   &residual) = 0;

    /**
     * Recovers the multipliers by @p recover (the formulation's own pass
     * over the slave nodes, residual / D_j, shared with the other ranks),
     * then again once per further pair when a chain of pairs passes
     * through a node (ContactInterface::has_chained_nodes()): the residual
     * at a slave node j that is also a master of another pair's slave k
     * holds -M_kj lambda_k besides D_j lambda_j, so each further pass adds
     * back the master forces of the multipliers of the pass before. A pass
     * settles one more link of the chain (the outer slaves' residuals hold
     * their own force only), and a chain through acyclic pairs has at most
     * as many links as there are pairs. Collective.
     */
    void
    recover_through_chains(const ContactInterface<dim>                            &interface,
                           const std::vector<double>                              &residual,
                           const std::function<void(const std::vector<double> &)> &recover) const;

    /// Updates the active (and stick/slip) sets at @p u; returns the number
    /// of changes (the iteration has converged only without any).
    virtual unsigned int
    update_active_set(const ContactInterface<dim> &interface, const std::vector<double> &u) = 0;

    virtual Residuals
    residuals(const ContactInterface<dim> &interface, const std::vector<double> &u) const = 0;

    /// Whether step_fraction() may return less than 1 (the interface
    /// values are gathered for it only then).
    virtual bool
    limits_steps() const
    {
      return false;
    }

    /// The fraction (0, 1] of the Newton update from @p u_old to @p u_new
    /// (at the interface DoFs) that the iteration takes: 1 unless the
    /// formulation limits it (PenaltyFrictionless: an open node driven deep
    /// into the master).
    virtual double
    step_fraction(const ContactInterface<dim> &,
                  const std::vector<double> &,
                  const std::vector<double> &) const
    {
      return 1.;
    }

    /// Number of active slave nodes.
    virtual unsigned int
    n_active() const = 0;

    /// Whether interface node @p n is an active slave node.
    virtual bool
    is_active(const unsigned int n) const = 0;

    /// The contact pressure (normal traction, positive in compression) of
    /// interface node @p n.
    virtual double
    normal_pressure(const unsigned int n) const = 0;

    /// The largest ratio of a given Contact/Penalty to the automatic value
    /// it replaces, over the pairs (1 when automatic): a penalty far above
    /// it leaves the system too few digits. For the diagnosis of failures.
    virtual double
    penalty_over_automatic() const
    {
      return 1.;
    }

    /// The largest penetration a penalty allows at the current pressures
    /// (p / eps over the active nodes), 0 for formulations that close the
    /// gaps exactly. For the diagnosis of failures.
    virtual double
    largest_penalty_penetration() const
    {
      return 0.;
    }

    /// The contact traction on the slave at slave node @p s: -p_n n plus the
    /// tangential traction of a frictional law (zero when frictionless).
    virtual Tensor<1, dim>
    traction(const typename ContactInterface<dim>::SlaveNode &s) const = 0;

    /// The unit normal of the frame in which the formulation splits the
    /// traction of slave node @p s into pressure and tangential traction:
    /// the slave normal, or for a frictional law the shared interface
    /// normal (ContactInterface::SlaveNode::interface_normal).
    virtual Tensor<1, dim>
    frame_normal(const typename ContactInterface<dim>::SlaveNode &s) const
    {
      return s.normal;
    }

    /// With Contact/Kinematics = current: whether frame_normal(@p s) is the
    /// interface normal, whose linearisation is then the one of
    /// LinearisedNode::interface_normal, interface_force and
    /// interface_tangent_force (else normal, force and tangent_force).
    virtual bool
    current_frame_on_interface(const typename ContactInterface<dim>::SlaveNode &) const
    {
      return false;
    }

    /// normal_pressure() of every interface node.
    std::vector<double>
    pressures(const ContactInterface<dim> &interface) const;

    /// Whether the answer depends on the load path (a history such as the
    /// slip of friction): the driver then re-solves the whole path on every
    /// mesh.
    virtual bool
    path_dependent() const
    {
      return false;
    }

    /// Whether the contact traction has a tangential part (traction() is
    /// not -p n): the driver then recovers, checks and refines with the
    /// whole traction vector.
    virtual bool
    transmits_shear() const
    {
      return false;
    }

    /// Whether interface node @p n is active and held tangentially by the
    /// contact (friction: it sticks): such nodes tie the bodies together.
    virtual bool
    held_tangentially(const unsigned int) const
    {
      return false;
    }

    /// Whether every active node slips under a law with friction (none
    /// sticks, none is held by a support): the contact then holds the
    /// bodies tangentially nowhere, and a body held by nothing else is
    /// free to slide (the load exceeds the friction capacity, or an
    /// iterate overshot). False by default.
    virtual bool
    slides_everywhere() const
    {
      return false;
    }

    /// The formulation's own cells of the Newton table (after the active
    /// count): the header, and the row of the current iterate at
    /// @p iteration. None by default.
    virtual std::string
    iteration_header() const
    {
      return "";
    }

    virtual std::string
    iteration_cells(const unsigned int) const
    {
      return "";
    }

    /// What the formulation's own settings add to the message of a Newton
    /// iteration that did not converge (a sentence with a leading space),
    /// or nothing.
    virtual std::string
    non_convergence_note() const
    {
      return "";
    }

    /// A value per interface node, named, for the pressure profile and the
    /// VTU output (friction: tangential traction, slip, stick).
    struct NodalField
    {
      std::string         name;
      std::vector<double> values; ///< per interface node
    };

    /// The formulation's own nodal fields beyond the pressure. None by
    /// default.
    virtual std::vector<NodalField>
    nodal_fields(const ContactInterface<dim> &) const
    {
      return {};
    }

    /// The contact sets of every interface node as one code each, for the
    /// detection of a cycling iteration (friction: stick/slip cycles). Empty
    /// (the default): no detection.
    virtual std::vector<int>
    contact_sets() const;

    /// A load step converged at interface displacement @p u: the history
    /// (slip reference) moves on. Default: nothing.
    virtual void
    accept_load_step(const ContactInterface<dim> &, const std::vector<double> &)
    {}

    /// Whether the constrained system is tested with the trial space
    /// (C^T K C). A Coulomb slip node is not: its test functions follow the
    /// friction cone (add_test_constraints()), and the system matrix is
    /// unsymmetric.
    virtual bool
    symmetric() const
    {
      return true;
    }

    /// Whether the Newton matrix is symmetric, so that CG may solve it.
    /// Default: symmetric(); a formulation tested with its trial space may
    /// still assemble unsymmetric terms (the penalty's Coulomb slip).
    virtual bool
    matrix_symmetric() const
    {
      return symmetric();
    }

    /// The constraints of the test space when !symmetric(): the same DoFs
    /// as add_constraints() constrains, other coefficients. Default: those
    /// of add_constraints().
    virtual void
    add_test_constraints(const ContactInterface<dim> &interface,
                         const std::vector<double>   &fixed_values,
                         AffineConstraints<double>   &constraints) const
    {
      add_constraints(interface, fixed_values, constraints, false);
    }

    /// The DoFs beyond the interface's lines (ContactInterface::line_dofs())
    /// at whose constraint lines assemble() reads: seeds of the lines a rank
    /// stores. Sorted, unique. Default: none.
    virtual std::vector<types::global_dof_index>
    line_seeds(const ContactInterface<dim> &) const
    {
      return {};
    }

    /// The DoFs a rank stores the contact constraint lines at, before the
    /// closure under the masters (ContactInterface::close_line_dofs()): the
    /// interface's line_dofs() and line_seeds().
    IndexSet
    line_dofs(const ContactInterface<dim> &interface) const
    {
      IndexSet   lines = interface.line_dofs();
      const auto seeds = line_seeds(interface);
      lines.add_indices(seeds.begin(), seeds.end());
      return lines;
    }

    /// The unit tangent of the 2D contact kinematics at a node with unit
    /// normal @p normal (out of the slave): the normal turned by 90 degrees
    /// counterclockwise, so that the frame turns with the model (for a
    /// slave above its master, normal -y, the tangent is +x).
    static Tensor<1, dim>
    tangent(const Tensor<1, dim> &normal);

    /// Couples every pair of @p dofs and of the masters @p constraints
    /// (the candidate constraints of the pattern) give them, both ways:
    /// the couplings of any subset of those constraints, with rows and
    /// columns distributed through it or not (add_entries_local_to_global()
    /// replaces a constrained DoF by its masters, and misses a column that
    /// the assembly's own constraints leave free).
    static void
    add_closed_couplings(const std::vector<types::global_dof_index> &dofs,
                         const AffineConstraints<double>            &constraints,
                         DynamicSparsityPattern                     &pattern);

    virtual std::unique_ptr<State>
    save_state() const = 0;

    virtual void
    restore_state(const State &state) = 0;

    /// Adds what the formulation chose (penalties, scale factors, ...) to
    /// the contact results.
    virtual void
    add_results(const ContactInterface<dim> &interface, Json &contact) const = 0;

    /// Prints the formulation's own checks and results, if any, after the
    /// driver's contact results: @p contact is what add_results() (and the
    /// driver) wrote, @p reaction the run's reaction results (force_scale,
    /// applied_load_components, support_reaction_components,
    /// relative_imbalance_components).
    virtual void
    print_results(const ContactInterface<dim> &interface,
                  const std::vector<double>   &u,
                  const Json                  &contact,
                  const Json                  &reaction,
                  std::ostream                &out) const;

    /// What the registry knows of a formulation.
    struct Registration
    {
      /// Its value of Contact/Formulation.
      std::string name;
      /// It reads Contact/Friction and Pure slip (parsed once, by create()).
      bool takes_friction;
      /// It reads Contact/Tangential penalty.
      bool takes_tangential_penalty;
      /// Declares its own keys (empty: it has none).
      std::function<void(ParameterHandler &)> declare;
      std::function<std::unique_ptr<ContactFormulation<dim>>(ParameterHandler &,
                                                             const FrictionParameters &)>
        create;
    };

    /// Adds a formulation; see CONTACT_FEM_REGISTER_FORMULATION.
    static void
    register_formulation(const Registration &registration);

    /// Declares the parameters of every registered formulation.
    static void
    declare_parameters(ParameterHandler &prm);

    /// The formulation named by Contact/Formulation, with its parameters
    /// read from @p prm (throws naming the key on bad input).
    static std::unique_ptr<ContactFormulation<dim>>
    create(ParameterHandler &prm);

    /// The names Contact/Formulation accepts, separated by '|'.
    static std::string
    names();

    /// The names of the formulations with friction, separated by ", ".
    static std::string
    frictional_names();
  };

  /// Registers class template @p classname (a ContactFormulation<dim> for
  /// dim 2 and 3) under @p formulation_name when the library is loaded.
  /// @p friction_keys: it reads the shared friction keys and is made from
  /// (prm, friction), else from (prm); @p tangential_penalty_key: it reads
  /// Contact/Tangential penalty; @p own_keys: classname<dim>::
  /// declare_parameters() declares keys of its own.
#define CONTACT_FEM_REGISTER_FORMULATION(classname, formulation_name, friction_keys, \
                                         tangential_penalty_key, own_keys)           \
  namespace                                                                          \
  {                                                                                  \
    template <int dim>                                                               \
    typename ContactFormulation<dim>::Registration classname##_registration()        \
    {                                                                                \
      typename ContactFormulation<dim>::Registration r;                              \
      r.name                     = formulation_name;                                 \
      r.takes_friction           = friction_keys;                                    \
      r.takes_tangential_penalty = tangential_penalty_key;                           \
      if constexpr (own_keys)                                                        \
        r.declare = classname<dim>::declare_parameters;                              \
      r.create = [](ParameterHandler &prm, const auto &friction) {                   \
        std::unique_ptr<ContactFormulation<dim>> formulation;                        \
        if constexpr (friction_keys)                                                 \
          formulation = std::make_unique<classname<dim>>(prm, friction);             \
        else                                                                         \
          formulation = std::make_unique<classname<dim>>(prm);                       \
        return formulation;                                                          \
      };                                                                             \
      return r;                                                                      \
    }                                                                                \
    const bool classname##_registered = [] {                                         \
      ContactFormulation<2>::register_formulation(classname##_registration<2>());    \
      ContactFormulation<3>::register_formulation(classname##_registration<3>());    \
      return true;                                                                   \
    }();                                                                             \
  }
} // namespace contact_fem

#endif
