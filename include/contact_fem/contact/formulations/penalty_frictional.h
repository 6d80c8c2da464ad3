// Frictional contact by penalties: the normal penalty of "penalty
// frictionless" plus a tangential penalty on the slip increment, with the
// return mapping of elastoplasticity for Coulomb or Tresca slip (2D, 3D).
#ifndef contact_fem_penalty_frictional_h
#define contact_fem_penalty_frictional_h

#include <contact_fem/contact/formulations/frictional_formulation.h>
#include <contact_fem/contact/formulations/penalty_frictionless.h>

namespace contact_fem
{
  /**
   * "penalty frictional": the contact traction of slave node j on the slave
   * is lambda_j = -p_j n_j + t_j (t_j in the tangent plane, dim - 1
   * components in tangent_frame(n_j)),
   * whose force is D_j lambda_j on the slave node and -M_jl lambda_j on
   * master node l. n_j is frame_normal(): under a law with friction the
   * shared interface normal, as "alm frictional" (the slave normal at held
   * nodes and for laws without friction), with current kinematics too. The
   * pressure is that of "penalty frictionless" (the base class): p_j =
   * eps_n (-g_j) on active nodes (g_j < 0, the gap along the slave
   * normal). The tangential
   * part is a penalty on the weighted slip increment xi_j since the last
   * accepted load step (slip_increment()), with the return mapping
   *
   *   trial  t*_j = t_n,j - eps_t xi_j     (t_n,j: of the last accepted step)
   *   stick  if |t*_j| <= T(p_j):  t_j = t*_j
   *   slip   otherwise:            t_j = T(p_j) d_j, d_j = t*_j / |t*_j|
   *                                 (2D: the sign sigma_j)
   *
   * with T the slip bound of the pair's frictional law. eps_t is
   * Contact/Tangential penalty, by default the pair's normal penalty (1e4 *
   * stiffness factor * E/h). Once the active set, the stick set and the slip
   * signs are fixed, every term is linear in u (Coulomb: T = mu p, p linear
   * in u; Tresca: T constant), so each iteration is one linear solve of the
   * total displacement; assemble() adds per active node
   *   normal: eps_n D grad_n g grad g^T (grad_n g: grad g with n_j for
   *           the slave normal; symmetric where they coincide),
   *   stick:  eps_t D grad xi grad xi^T (symmetric),
   *   slip:   sigma T'(p) eps_n D grad xi grad g^T (unsymmetric) and the load
   *           D sigma (T - T' p - T' eps_n g(0)) grad xi,
   * where grad xi = tau at the slave node, -M_jl / D_j tau at master l (per
   * tangent in 3D, sigma -> d). In 3D the slip direction d(t*) is
   * linearised too: T d(t*(u)) ~ T d + (T / |t*|) P t*(u), P = I - d d^T,
   * which adds (T / |t*|) eps_t D P grad xi grad xi^T and its load. The
   * matrix is unsymmetric while a node slips or an active node's frame is
   * turned off its slave normal (matrix_symmetric(): the
   * iterative solver then takes GMRES instead of CG); no test-space
   * constraints are used (symmetric() stays true: it concerns constraints
   * only).
   *
   * The stick/slip iteration: every frictional node starts a load step
   * sticking (the elastic predictor of plasticity; a node that slipped has
   * its trial traction on the bound, where round-off would decide), and a
   * slipping node whose trial traction passes the opposite bound sticks
   * first instead of reversing at once: with eps_t ~ 1e4 E/h the slip
   * solve of a node that should stick overshoots, and direct reversals
   * swing it between +T and -T forever (period 2).
   * With Contact/Kinematics = current the stick problem is nonlinear
   * too, and its first iterate (the step's predictor: the linearised
   * response to the new Dirichlet data) is off at second order in the
   * increment; eps_t turns that into trial tractions far outside the cone
   * (a rigid rotation of 5 degrees per step: nodes that stick slip at
   * iteration 1, the next correction is 10 to 1e4 times the step's and an
   * element inverts). So the step's first update keeps every sticking
   * node sticking: the second solve is the stick problem's Newton step,
   * and the return mapping decides from its iterate
   * (doc/finite_strain.md, "Penalty frictional under large rotation
   * steps"). With small kinematics the stick problem is linear, its first
   * iterate exact, and the sets are decided at once.
   *
   * A node whose law has no friction (mu = 0, or bound 0) slips with
   * T = 0: exactly the "penalty frictionless" system and results. Nodes
   * with a Dirichlet component carry no tangential penalty (the support
   * holds them tangentially), as in "alm frictional", except a 3D node
   * with exactly one (a roller on a symmetry plane,
   * partly_held_component()): its trial traction is projected onto the
   * tangent its support leaves free (free_part(), free_tangent()), so it
   * sticks or slips along that tangent (no cone term) and the support
   * carries the other. Adaptive penalties are refused (Contact/Adaptive
   * penalty).
   *
   * Contact/Kinematics = current: D_j, M_jl, n_j and the gaps are those of
   * the iterate u_k (the normal part: "penalty frictionless"), xi_j is the
   * objective slip (FrictionalFormulation::objective_slip(), as "alm
   * frictional"), and the history traction t_n,j is carried from the
   * normal n^n of the accepted step to the current one by the smallest
   * rotation between them (parallel transport: h_j = t_n - (n . t_n) / (1
   * + n^n . n) (n^n + n), in the frame of n), in 3D followed by the spin
   * of the slave surface about n since that step (spin_about_normal()), so
   * that t*_j = h_j - eps_t xi_j is unchanged by any rigid rotation of the
   * contact within a step (frame indifference; in 2D the transport alone
   * is that rotation). The tangential force t_j h_j (D_j t on the slave,
   * -M_jl t on master l, t = sum_k t_k tau_k) is linearised in full
   * (assemble_current()): d t_k from d xi_j (with the change of D_j), d h_j
   * (the turn of n) and, on a slip node, T'(p) dp (dp of the penalty
   * pressure eps_n (-G_j) / D_j) and (T / |t*|) P dt* (3D); the force's
   * own change with D_j, M_jl and n_j comes from
   * ContactInterface::LinearisedNode::tangent_force. n is the frame normal
   * n_f: where it is the interface normal every derivative takes its
   * linearisation (LinearisedNode::interface_normal, interface_force,
   * interface_tangent_force; current_frame_on_interface()). The matrix is
   * unsymmetric.
   */
  template <int dim>
  class PenaltyFrictional : public FrictionalFormulation<dim, PenaltyFrictionless<dim>>
  {
    using Base = FrictionalFormulation<dim, PenaltyFrictionless<dim>>;

  public:
    using typename PenaltyFrictionless<dim>::Residuals;
    using State     = typename ContactFormulation<dim>::State;
    using SlaveNode = typename ContactInterface<dim>::SlaveNode;
    using Row       = typename Base::Row;

    /// Tangential penalty (subsection Contact).
    static void
    declare_parameters(ParameterHandler &prm);

    /// Reads the penalty keys and Tangential penalty; @p friction: the laws
    /// and Pure slip.
    PenaltyFrictional(ParameterHandler &prm, const FrictionParameters &friction);

    /// False while a node slips (the slip terms are unsymmetric), while an
    /// active node's frame is the interface normal (the normal force along
    /// it, the pressure from the slave-normal gap) and with current
    /// kinematics.
    /// The sets of FrictionalFormulation, + 4 on a node released with
    /// friction in the step and + 16 on one entering as it grazes (on its
    /// way to grazing, as the flag + 8).
    std::vector<int>
    contact_sets() const override;

    bool
    matrix_symmetric() const override
    {
      return !this->current && this->n_slip() == 0 && !frame_turned;
    }

    void
    initialize(const ContactInterface<dim> &interface) override;

    void
    start_load_step(const ContactInterface<dim> &interface,
                    const std::vector<double>   &u,
                    const StepStart              start) override;

    /// The couplings of every component of the slave node and its masters
    /// (the gap gradient drops the components normal to n, the slip
    /// gradient needs them); those of "penalty frictionless" when no pair
    /// has friction.
    void
    add_sparsity(const ContactInterface<dim>     &interface,
                 const AffineConstraints<double> &constraints,
                 const IndexSet                  &owned,
                 DynamicSparsityPattern          &pattern) const override;

    /// The normal penalty of the base class plus the stick or slip terms.
    void
    assemble(const ContactInterface<dim>     &interface,
             const AffineConstraints<double> &constraints,
             const AffineConstraints<double> &test_constraints,
             const IndexSet                  &owned,
             TrilinosWrappers::SparseMatrix  &matrix,
             TrilinosWrappers::MPI::Vector   &rhs) const override;

    /// Active set and pressures of the base class, then the return mapping
    /// at @p u; returns the active changes plus the stick/slip changes.
    unsigned int
    update_active_set(const ContactInterface<dim> &interface,
                      const std::vector<double>   &u) override;

    /// The normal forces' terms, then the tangential tractions': D_j t_j
    /// on the slave, -M_jl t_j on the masters.
    void
    add_force_terms(const ContactInterface<dim>                            &interface,
                    const bool                                              all,
                    std::vector<typename ContactInterface<dim>::ForceTerm> &terms) const override;

    Tensor<1, dim>
    traction(const SlaveNode &s) const override
    {
      const Tensor<1, dim> n = frame_normal(s);
      return -this->pressure[s.node] * n + to_global(tangential[s.node], n);
    }

    /// The frame (FrictionalFormulation::frame_normal()): the shared
    /// interface normal where the law has friction, with current
    /// kinematics too (linearised, LinearisedNode::interface_normal); the
    /// frame of the slip, of the tangential traction and of the normal
    /// force.
    using Base::current_frame_on_interface;
    using Base::frame_normal;

    /// The slip reference (interface displacement) and the tangential
    /// tractions of the accepted step become the history.
    void
    accept_load_step(const ContactInterface<dim> &interface, const std::vector<double> &u) override;

    std::unique_ptr<State>
    save_state() const override;

    void
    restore_state(const State &state) override;

    void
    add_results(const ContactInterface<dim> &interface, Json &contact) const override;

    /// The checks of the base class and print_slip_checks(), then the
    /// friction totals.
    void
    print_results(const ContactInterface<dim> &interface,
                  const std::vector<double>   &u,
                  const Json                  &contact,
                  const Json                  &reaction,
                  std::ostream                &out) const override;

  protected:
    bool
    on_current_configuration() const override
    {
      return this->current;
    }

  private:
    /// The largest elastic slip of the stick nodes, and from the total
    /// tangential and normal contact forces sum_j D_j t_j and sum_j D_j p_j,
    /// with one Coulomb law and every active node slipping one way, the
    /// check ratio = mu.
    void
    print_slip_checks(const ContactInterface<dim> &interface, std::ostream &out) const;

    /// The weighted slip increment xi_j of slave node @p s at @p u since
    /// the last accepted load step, in tangent_frame(s.normal).
    TangentialVector<dim>
    slip_increment(const ContactInterface<dim> &interface,
                   const SlaveNode             &s,
                   const std::vector<double>   &u) const;

    /// t*_j = t_n,j - eps_t xi_j (current kinematics: h_j - eps_t xi_j),
    /// its free_part() where a support holds one tangent.
    TangentialVector<dim>
    trial_traction(const ContactInterface<dim> &interface,
                   const SlaveNode             &s,
                   const TangentialVector<dim> &xi) const;

    /// The history traction of @p s in the frame of its normal: t_n,j, or
    /// with current kinematics h_j, t_n,j transported to the current normal
    /// and, in 3D, turned by the spin about it (see the class comment).
    TangentialVector<dim>
    history(const ContactInterface<dim> &interface, const SlaveNode &s) const;

    /// Current kinematics, 3D: the rotation of the slave surface about the
    /// current normal n_j since the last accepted step, after the smallest
    /// rotation S taking n^n to n_j. Its angle phi maximises sum_f a_f .
    /// Rot_n(phi) S A_f over the chords A_f (then), a_f (now) from node j
    /// to the centroids of its slave faces (the rotation of the polar
    /// decomposition of the surface's deformation, Kabsch): phi =
    /// atan2(Y, X), X = sum_f b_f . a_f, Y = sum_f n . (b_f x a_f), b_f = S
    /// A_f. The rotation of n^n to n_j with the least in-plane turn of the
    /// chords: a rigid rotation R of the contact gives R exactly, whatever
    /// the axis. Returns (X, Y) and the chords (b_f, a_f).
    struct Spin
    {
      double                      X = 1., Y = 0.;
      std::vector<Tensor<1, dim>> before, now;
    };
    Spin
    spin_about_normal(const ContactInterface<dim> &interface, const SlaveNode &s) const;

    /// The chords from slave node @p node to the centroids of its slave
    /// faces at the search configuration.
    std::vector<Tensor<1, dim>>
    face_chords(const ContactInterface<dim> &interface, const unsigned int node) const;

    /// Current kinematics: d h_j,k / du at the DoFs of the linearised patch
    /// of @p s, added to @p rows.
    void
    add_history_derivative(const ContactInterface<dim> &interface,
                           const SlaveNode             &s,
                           std::array<Row, dim - 1>    &rows) const;

    /// Current kinematics: the tangential force of active frictional node
    /// @p s at the iterate @p u and its tangent (see the class comment).
    void
    assemble_current(const ContactInterface<dim>     &interface,
                     const SlaveNode                 &s,
                     const std::vector<double>       &u,
                     const AffineConstraints<double> &constraints,
                     TrilinosWrappers::SparseMatrix  &matrix,
                     TrilinosWrappers::MPI::Vector   &rhs) const;

    /// The return mapping of active node @p s at pressure @p p and slip
    /// increment @p xi: zero = stick, else the unit direction of the trial
    /// traction (2D: +1 / -1; a frictionless law always "slips", with T =
    /// 0).
    TangentialVector<dim>
    stick_or_slip(const ContactInterface<dim> &interface,
                  const SlaveNode             &s,
                  const double                 p,
                  const TangentialVector<dim> &xi) const;

    /// The tangential traction of the return mapping with @p direction.
    TangentialVector<dim>
    tangential_traction(const ContactInterface<dim> &interface,
                        const SlaveNode             &s,
                        const TangentialVector<dim> &direction,
                        const double                 p,
                        const TangentialVector<dim> &xi) const;

    /// T / |t*| of a 3D slip node (the linearised slip direction), else 0.
    double
    slip_cone_factor(const ContactInterface<dim> &interface,
                     const SlaveNode             &s,
                     const TangentialVector<dim> &direction,
                     const double                 p,
                     const TangentialVector<dim> &xi) const;

    /// grad xi_j,k at the DoFs of gap_gradient() (same order): tau_k at the
    /// slave node, -M_jl / D_j tau_k at master l.
    void
    slip_gradient(const ContactInterface<dim> &interface,
                  const SlaveNode             &s,
                  const unsigned int           k,
                  std::vector<double>         &gradient) const;

    using Base::converged_displacement;
    using Base::converged_operators;
    using Base::frictionless_law;
    using Base::last_step_slip;
    using Base::last_stick_slip_changes;
    using Base::laws;
    using Base::n_slip;
    using Base::n_stick;
    using Base::pure_slip;
    using Base::sets;
    using Base::slip_history;
    using Base::tangential;

    double              tangential_penalty = 0.; ///< given; 0: the pair's normal penalty
    std::vector<double> tangent_penalty;         ///< eps_t per pair
    /// Tangential tractions of the last accepted load step (the history).
    std::vector<TangentialVector<dim>> accepted_tangential;
    /// Current kinematics: the tangential traction (global) and the normal
    /// of every node at the last accepted load step.
    std::vector<Tensor<1, dim>> accepted_traction, accepted_normal;
    /// Current kinematics, 3D: per node the face_chords() of the last
    /// accepted step, projected onto the plane of its normal.
    std::vector<std::vector<Tensor<1, dim>>> accepted_chords;
    /// The slave faces (indices in interface.faces) of every node.
    std::vector<std::vector<unsigned int>> slave_faces_of_node;
    /// slip_cone_factor() per interface node, of the last update.
    std::vector<double> cone_factor;
    /// Tresca at lift-off, as in "alm frictional" (Base::grazing).
    using Base::grazing;
    using Base::slip_bound;
    using Base::slip_bound_derivative;
    /// Nodes released with friction in this load step (1: a double, shared
    /// with the ghosts; contact_sets() tells it).
    std::vector<double> released_with_friction;
    /// 1 on a grazing node that entered at the last update: its penalty
    /// pressure is that of an iterate solved without it (a penetration
    /// far above the grazing state's), so its bound is linearised at p = 0,
    /// on the branch of slope 1 / grazing_fraction, for that solve.
    std::vector<double> entering;

    /// The pressure at which the bound of active node @p s is evaluated.
    double
    bound_pressure(const SlaveNode &s) const
    {
      return entering[s.node] != 0. ? 0. : std::max(this->pressure[s.node], 0.);
    }
    /// The elastic-slip warning was printed (once per run).
    mutable bool elastic_slip_warned = false;
    /// Some active node's frame_normal() is not its slave normal (the
    /// normal penalty is then unsymmetric): found at the decisions of
    /// start_load_step() and update_active_set().
    bool frame_turned = false;
    /// After the owners of the rows decided their nodes, the normal states
    /// (share_decisions()) and the tangential ones (tangential traction,
    /// stick/slip set, cone factor) to the other ranks in one exchange.
    /// Collective.
    void
    share_tangential(const ContactInterface<dim> &interface);

    /// The frictional counts, then the owned active nodes whose
    /// frame_normal() is not their slave normal (frame_turned).
    std::vector<unsigned int>
    count_owned_rows(const ContactInterface<dim> &interface) const override;

    void
    take_counts(std::vector<unsigned int>::const_iterator &next) override;
    /// update_active_set() calls since the step's start (current
    /// kinematics: the first keeps every sticking node sticking).
    unsigned int updates_in_step = 0;

    struct FrictionState : public State
    {
      std::unique_ptr<State>                   normal;
      std::vector<TangentialVector<dim>>       tangential, accepted_tangential;
      std::vector<double>                      converged_displacement;
      SlipHistory<dim>                         slip_history;
      StickSlipSets<dim>                       sets;
      std::vector<TangentialVector<dim>>       last_step_slip;
      std::vector<Tensor<1, dim>>              accepted_traction, accepted_normal;
      std::vector<std::vector<Tensor<1, dim>>> accepted_chords;
      std::vector<typename Base::Operators>    converged_operators;
      unsigned int                             stick_count = 0, slip_count = 0;
      bool                                     frame_turned = false;
    };
  };
} // namespace contact_fem

#endif
