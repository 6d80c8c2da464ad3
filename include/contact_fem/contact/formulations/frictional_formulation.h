// What the frictional formulations share on top of their normal part: the
// laws, the frictional state of every node and how it is reported.
#ifndef contact_fem_frictional_formulation_h
#define contact_fem_frictional_formulation_h

#include <contact_fem/contact/formulations/friction_results.h>
#include <contact_fem/contact/friction/frictional_law.h>
#include <contact_fem/contact/friction/stick_slip_sets.h>

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <utility>

namespace contact_fem
{
  /**
   * A frictional formulation over the normal part @p NormalPart (a
   * FrictionlessFormulation: pressure, active set, penalties): the law of
   * every pair, and per interface node the tangential multiplier, the slip
   * of the last accepted load step and the stick/slip set, each a
   * TangentialVector (dim - 1 components). It answers the driver's general
   * questions for friction (path dependent, shear, stick = held
   * tangentially, cycle codes) and reports the state (stick / slip columns
   * of the Newton table, nodal fields). The derived class decides the
   * conditions (constraints or penalties) and the history it keeps.
   */
  template <int dim, class NormalPart>
  class FrictionalFormulation : public NormalPart
  {
  public:
    using SlaveNode = typename ContactInterface<dim>::SlaveNode;

    /// The normal part is made from @p args.
    template <typename... Args>
    explicit FrictionalFormulation(const FrictionParameters &friction, Args &&...args)
      : NormalPart(std::forward<Args>(args)...)
      , laws(friction.laws)
      , pure_slip(friction.pure_slip)
    {}

    /// The normal part's, and a frictional state of zero for every node.
    void
    initialize(const ContactInterface<dim> &interface) override;

    bool
    path_dependent() const override
    {
      return true;
    }

    bool
    transmits_shear() const override
    {
      return true;
    }

    std::string
    non_convergence_note() const override
    {
      return pure_slip ? " Contact/Pure slip = true makes every active node slip in the "
                         "direction of its trial traction: where the scene sticks, or moves "
                         "no node tangentially at all, no such state exists (set it false)." :
                         "";
    }

    /// The frame of the frictional conditions of every frictional
    /// formulation (alm, mpc, penalty; small and current kinematics): the
    /// shared interface normal (SlaveNode::interface_normal) where the law
    /// has friction at a node no support holds (frame_on_interface()); the
    /// slave normal at held nodes and under a law without friction (mu = 0
    /// then is exactly the frictionless formulation).
    Tensor<1, dim>
    frame_normal(const SlaveNode &s) const override
    {
      return frame_on_interface(s) ? s.interface_normal : s.normal;
    }

    /// With current kinematics where frame_normal() is the interface
    /// normal: its derivatives are then LinearisedNode::interface_normal,
    /// interface_force and interface_tangent_force.
    bool
    current_frame_on_interface(const SlaveNode &s) const override
    {
      return on_current_configuration() && frame_on_interface(s);
    }

    /// Whether node @p n is active and sticks.
    bool
    held_tangentially(const unsigned int n) const override
    {
      return sets.sticks(n, this->active);
    }

    /// Every active node slips under a law with friction (not with Pure
    /// slip, which asks for that).
    bool
    slides_everywhere() const override;

    std::string
    iteration_header() const override;

    /// Stick and slip counts and the stick/slip changes of the last
    /// update_active_set() (part of the changes it returned).
    std::string
    iteration_cells(const unsigned int iteration) const override;

    /// tangential_traction, slip_increment (of the last accepted step),
    /// the accumulated slip and tangential displacement, and stick.
    std::vector<typename ContactFormulation<dim>::NodalField>
    nodal_fields(const ContactInterface<dim> &interface) const override;

    /// 0 inactive, 1 stick, 2 / 3 slip with sign + / -; + 8 on a grazing
    /// node (a node that comes back to its sets of two iterations before
    /// with a new flag is on its way to the grazing state, not round a
    /// cycle: the flags are set once a step, so a real cycle is still found
    /// two iterations later).
    std::vector<int>
    contact_sets() const override;

    /// Number of active nodes that stick / slip (active nodes held
    /// tangentially by a support neither stick nor slip), counted over the
    /// owned rows at each decision (reduce_counts()).
    unsigned int
    n_stick() const
    {
      return stick_count;
    }

    unsigned int
    n_slip() const
    {
      return slip_count;
    }

    /// Current kinematics: every DoF of the masters of the converged
    /// operators of the linearised nodes, which the objective-slip patches
    /// (objective_slip_patch()) read the constraint lines at and which may
    /// lie outside every linearised patch. None otherwise.
    std::vector<types::global_dof_index>
    line_seeds(const ContactInterface<dim> &interface) const override;

  protected:
    /// The normal part's counts, then the stick and slip nodes.
    std::vector<unsigned int>
    count_owned_rows(const ContactInterface<dim> &interface) const override;

    void
    take_counts(std::vector<unsigned int>::const_iterator &next) override;

    /// Whether Contact/Kinematics = current (the derived class reads it).
    virtual bool
    on_current_configuration() const = 0;

    /// Whether frame_normal(@p s) is the interface normal: a law with
    /// friction at a node no support holds. (AlmFrictional narrows it.)
    virtual bool
    frame_on_interface(const SlaveNode &s) const
    {
      return !sets.held[s.node] && !frictionless_law(s);
    }

    /// Current kinematics: d n_f/du of the frame normal n_f =
    /// frame_normal(@p s), per component at the DoFs of the node's
    /// LinearisedNode.
    const std::array<std::vector<double>, dim> &
    frame_normal_derivative(const ContactInterface<dim> &interface, const SlaveNode &s) const
    {
      const auto &linearised = interface.linearised_nodes.at(s.node);
      return this->current_frame_on_interface(s) ? linearised.interface_normal : linearised.normal;
    }

    /// Current kinematics: the force rows per unit pressure along the frame
    /// normal, -D_j n_f and M_jl n_f, with their derivatives
    /// (LinearisedNode::interface_force or force).
    const auto &
    frame_force(const ContactInterface<dim> &interface, const SlaveNode &s) const
    {
      const auto &linearised = interface.linearised_nodes.at(s.node);
      return this->current_frame_on_interface(s) ? linearised.interface_force : linearised.force;
    }

    /// Current kinematics: the force derivatives per unit tangential
    /// traction component held in the tangent plane of the frame normal
    /// (LinearisedNode::interface_tangent_force or tangent_force).
    const auto &
    frame_tangent_force(const ContactInterface<dim> &interface, const SlaveNode &s) const
    {
      const auto &linearised = interface.linearised_nodes.at(s.node);
      return this->current_frame_on_interface(s) ? linearised.interface_tangent_force :
                                                   linearised.tangent_force;
    }

    /// Whether the law of node @p s has no friction at all (mu = 0, bound
    /// 0): its slip sign then changes nothing.
    bool
    frictionless_law(const SlaveNode &s) const
    {
      return laws[s.pair]->frictionless();
    }

    /// The laws by their .prm names, as the results list them.
    Json
    law_names() const;

    /// D_j and M_jl of a slave node at the last accepted load step
    /// (Contact/Kinematics = current: the objective slip).
    struct Operators
    {
      double                                       D = 0.;
      std::vector<std::pair<unsigned int, double>> M;
    };

    /// A row of derivatives by DoF.
    using Row = std::map<types::global_dof_index, double>;

    /// Current kinematics: the objective slip of Gitterle, Popp et al. per
    /// unit D_j, xi_j = -P_j ((D_j - D_j^n) x_j - sum_l (M_jl - M_jl^n)
    /// x_l) / D_j, of @p s at @p u in the tangent frame of its normal (P_j
    /// onto the tangent plane; ^n: converged_operators), zero under any
    /// rigid motion of the pair; if @p derivatives is not null, also d xi_j
    /// / du by DoF per frame component, with D_j held (the caller adds
    /// -xi_j dD_j / D_j where xi_j need not vanish).
    TangentialVector<dim>
    objective_slip(const ContactInterface<dim> &interface,
                   const SlaveNode             &s,
                   const std::vector<double>   &u,
                   std::array<Row, dim - 1>    *derivatives) const;

    /// Current kinematics, at a step's start: a node paired for the first
    /// time measures its slip from the operators of this start.
    void
    keep_operators_of_new_pairs(const ContactInterface<dim> &interface);

    /// Current kinematics, when a step is accepted: the operators of the
    /// slave nodes whose rows this rank owns become the reference of their
    /// objective slip (only their owner reads it).
    void
    keep_operators(const ContactInterface<dim> &interface);

    /**
     * When a step is accepted: the slip of the step (@p slip of each
     * paired node) and the slip history of the nodes whose rows this rank
     * owns, then shared with the other ranks as share_node_values() shares
     * the decisions (every value a key value: the nodes that ever slipped
     * all-gathered), for the readers of the whole interface (the results,
     * the nodal fields). Collective.
     */
    void
    accept_slip(const ContactInterface<dim>                                   &interface,
                const std::function<TangentialVector<dim>(const SlaveNode &)> &slip);

    /**
     * After the owners of the rows decided their nodes (ContactInterface::
     * owns_row()), the other ranks get the frictional fields @p
     * tangential_fields (per node, dim - 1 components each) and @p
     * double_fields, as doubles, through @p share_normal: the normal
     * part's sharing (FrictionlessFormulation::share_states() or the
     * penalty's share_decisions()), which adds its own fields, so that all
     * go in one exchange. Every field is a key field (a node with any
     * value other than +0 is sent to every rank): exact copies of every
     * value, read or not. Nothing in serial. Collective.
     */
    void
    share_frictional_states(
      const ContactInterface<dim>                                           &interface,
      const std::vector<std::vector<TangentialVector<dim>> *>               &tangential_fields,
      const std::vector<std::vector<double> *>                              &double_fields,
      const std::function<void(const std::vector<std::vector<double> *> &)> &share_normal) const;

    /// Current kinematics: the DoFs the terms of linearised node @p node
    /// couple, its patch and the masters of its last accepted step (the
    /// objective slip), sorted.
    std::vector<types::global_dof_index>
    objective_slip_patch(const ContactInterface<dim> &interface, const unsigned int node) const;

    std::vector<std::shared_ptr<const FrictionalLaw>> laws; ///< per pair
    bool                                              pure_slip = false;

    /// Tresca at lift-off (doc/design.md, "Tresca at lift-off"): a node
    /// released in tension while it carried a constant bound T, which then
    /// penetrates again without it, has no state of the strict law (T in
    /// contact, none out of it). It grazes for the rest of the load step:
    /// its bound is T min(1, p / (grazing_fraction T)), the set-valued
    /// bound [0, T] at p = 0 made single-valued (a Coulomb branch of slope
    /// 1 / grazing_fraction), so that it settles at g = 0, p ~ 0 with a
    /// traction below T. Per interface node, 1 = grazing (a double: shared
    /// with the ghosts); set by the derived formulation, reset at the start
    /// of a load step.
    std::vector<double>     grazing;
    static constexpr double grazing_fraction = 1e-3;
    /// comes_back_grazing()'s fraction, measured (doc/design.md, "Tresca
    /// at lift-off, a third time"): at 0.1 the sphere's node, back by 0.19
    /// T / (E/h), cycles; at 1 the 3D chain's first step diverges.
    static constexpr double grazing_depth = 0.3;

    /// The slip bound of node @p s at pressure @p p: its law's, reduced
    /// near p = 0 while it grazes.
    double
    slip_bound(const SlaveNode &s, const double p) const
    {
      const double bound = laws[s.pair]->threshold(p);
      if (grazing[s.node] == 0. || p >= grazing_fraction * bound)
        return bound;
      return std::max(p, 0.) / grazing_fraction;
    }

    /// Whether a node released while it carried friction (Tresca), which
    /// penetrates again by @p depth, comes back to the surface (grazes)
    /// rather than being driven into it: a depth the friction force it
    /// lost can explain, below grazing_depth T / (E/h) (E/h the pair's
    /// scale: the depth at which the bound T alone would press a node).
    bool
    comes_back_grazing(const SlaveNode &s, const double depth) const
    {
      return this->scale[s.pair] * depth < grazing_depth * laws[s.pair]->threshold(0.);
    }

    /// d slip_bound() / d p.
    double
    slip_bound_derivative(const SlaveNode &s, const double p) const
    {
      if (grazing[s.node] == 0. || p >= grazing_fraction * laws[s.pair]->threshold(p))
        return laws[s.pair]->threshold_derivative(p);
      return 1. / grazing_fraction;
    }

    /// Whether the law of node @p s keeps a bound as its pressure falls to
    /// zero (Tresca): only such a node can graze.
    bool
    bound_without_pressure(const SlaveNode &s) const
    {
      return !frictionless_law(s) && laws[s.pair]->threshold_derivative(0.) == 0.;
    }

    /// t_j per interface node, in the formulation's frame.
    std::vector<TangentialVector<dim>> tangential;
    StickSlipSets<dim>                 sets;
    /// Slip of every interface node in the last accepted load step.
    std::vector<TangentialVector<dim>> last_step_slip;
    /// Slip of every interface node summed over the load path.
    SlipHistory<dim> slip_history;
    /// Interface displacement of the last accepted load step.
    std::vector<double> converged_displacement;
    /// Stick/slip changes of the last update_active_set().
    unsigned int last_stick_slip_changes = 0;
    /// n_stick(), n_slip().
    unsigned int stick_count = 0, slip_count = 0;
    /// Operators of every slave node at the last accepted load step
    /// (current kinematics).
    std::vector<Operators> converged_operators;
  };
} // namespace contact_fem

#endif
