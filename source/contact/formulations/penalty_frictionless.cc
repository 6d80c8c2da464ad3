#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <contact_fem/contact/formulations/penalty_frictionless.h>

#include <algorithm>
#include <map>
#include <cmath>

namespace contact_fem
{
  template <int dim>
  void
  PenaltyFrictionless<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry("Adaptive penalty", "false", Patterns::Bool(),
                      "'penalty frictionless' only: adapt the penalty of every "
                      "slave node in every Newton iteration from the change of its "
                      "penetration (Bussetta, Marceau and Ponthot's rule) until "
                      "each penetration is below Maximum penetration factor * h; a "
                      "node whose penalty changed counts as an active-set change.");
    prm.declare_entry("Maximum penetration factor", "1e-3", Patterns::Double(0.),
                      "Adaptive penalty: the allowed penetration of a slave node, "
                      "as a fraction of its element size h.");
    prm.declare_entry("Entry depth factor", "1e-5", Patterns::Double(0.),
                      "Penalty formulations with Kinematics = current: a Newton update "
                      "that drives a slave node open at the iterate deeper into its "
                      "master than the deepest node in contact (or than this fraction "
                      "of its element size h, if deeper) is shortened so that the node "
                      "enters by that depth: the penalty's pressure of an overshooting "
                      "linear step would enter the next tangent's geometric and friction "
                      "terms. 0: never shortened.");
    prm.leave_subsection();
  }

  namespace
  {
    template <int dim>
    typename FrictionlessFormulation<dim>::Parameters
    read_shared_parameters(ParameterHandler &prm)
    {
      typename FrictionlessFormulation<dim>::Parameters parameters;
      parameters.parse_parameters(prm);
      return parameters;
    }
  } // namespace

  template <int dim>
  PenaltyFrictionless<dim>::PenaltyFrictionless(ParameterHandler &prm)
    : FrictionlessFormulation<dim>(read_shared_parameters<dim>(prm))
  {
    prm.enter_subsection("Contact");
    adaptive           = prm.get_bool("Adaptive penalty");
    current            = prm.get("Kinematics") == "current";
    penetration_factor = prm.get_double("Maximum penetration factor");
    entry_depth_factor = prm.get_double("Entry depth factor");
    prm.leave_subsection();
    AssertThrow(!adaptive || penetration_factor > 0.,
                ExcMessage("Contact/Maximum penetration factor: expected a value > 0."));
  }

  template <int dim>
  void
  PenaltyFrictionless<dim>::initialize(const ContactInterface<dim> &interface)
  {
    FrictionlessFormulation<dim>::initialize(interface);
    node_penalty.assign(interface.nodes.size(), 0.);
    previous_gap.assign(interface.nodes.size(), 0.);
  }

  template <int dim>
  void
  PenaltyFrictionless<dim>::start_load_step(const ContactInterface<dim> &interface,
                                            const std::vector<double>   &u,
                                            const StepStart              start)
  {
    decide_step_start(interface, u, start);
    share_decisions(interface);
    this->deactivate_master_nodes(interface);
    this->reduce_counts(interface, {});
  }

  template <int dim>
  void
  PenaltyFrictionless<dim>::share_decisions(const ContactInterface<dim>              &interface,
                                            const std::vector<std::vector<double> *> &key_fields)
  {
    // The penalties are read only at active nodes (add_results()); the
    // previous gaps only by the owner.
    this->share_states(interface, key_fields, {&node_penalty});
  }

  template <int dim>
  void
  PenaltyFrictionless<dim>::decide_step_start(const ContactInterface<dim> &interface,
                                              const std::vector<double>   &u,
                                              const StepStart              start)
  {
    // A stiff spring (penetration ~ 1e-4 h p / E) unless the adaptive rule
    // raises it where needed.
    this->set_pair_scaling(interface, adaptive ? 1. : 1e4);
    auto &pressure = this->pressure;
    auto &active   = this->active;
    // Each rank decides the nodes whose rows it owns (share_states()).
    for (const auto &s : interface.slave_nodes)
      {
        if (!interface.owns_row(s))
          continue;
        if (!s.paired)
          {
            active[s.node]   = false;
            pressure[s.node] = 0.;
            continue;
          }
        const double g = interface.gap(s, u);
        // Adapted penalties live as long as the mesh.
        if (node_penalty[s.node] == 0. || !adaptive)
          node_penalty[s.node] = this->penalty[s.pair];
        previous_gap[s.node] = g;
        active[s.node]       = this->starts_active(s, g, start);
        if (!active[s.node])
          pressure[s.node] = 0.;
      }
  }

  template <int dim>
  void
  PenaltyFrictionless<dim>::add_constraints(const ContactInterface<dim> &interface,
                                            const std::vector<double>   &fixed_values,
                                            AffineConstraints<double>   &constraints,
                                            const bool                   all_candidates) const
  {
    if (all_candidates)
      this->add_gap_constraints(interface, fixed_values, constraints, false);
    else
      this->dirichlet_values = fixed_values;
  }

  template <int dim>
  void
  PenaltyFrictionless<dim>::add_sparsity(const ContactInterface<dim>     &interface,
                                         const AffineConstraints<double> &constraints,
                                         const IndexSet                  &owned,
                                         DynamicSparsityPattern          &pattern) const
  {
    if (current)
      {
        // The couplings of the linearised patch of every paired node,
        // closed over the hanging nodes.
        for (const auto &[node, linearised] : interface.linearised_nodes)
          if (owned.is_element(interface.nodes[node].dofs[0]))
            constraints.add_entries_local_to_global(linearised.dofs, pattern, true);
        return;
      }
    std::vector<types::global_dof_index> dofs;
    std::vector<double>                  gradient;
    for (const auto &s : interface.slave_nodes)
      if (s.paired && owned.is_element(interface.nodes[s.node].dofs[0]))
        {
          this->gap_gradient(interface, s, dofs, gradient);
          constraints.add_entries_local_to_global(dofs, pattern, true);
        }
  }

  template <int dim>
  void
  PenaltyFrictionless<dim>::assemble(const ContactInterface<dim>     &interface,
                                     const AffineConstraints<double> &constraints,
                                     const AffineConstraints<double> &,
                                     const IndexSet                 &owned,
                                     TrilinosWrappers::SparseMatrix &matrix,
                                     TrilinosWrappers::MPI::Vector  &rhs) const
  {
    if (current)
      {
        // The operators were built on the iterate: its displacement is the
        // search configuration.
        const std::vector<double> &u = interface.search_configuration();
        for (const auto &s : interface.slave_nodes)
          if (s.paired && this->active[s.node] && owned.is_element(interface.nodes[s.node].dofs[0]))
            assemble_current(interface, s, u, constraints, matrix, rhs);
        return;
      }
    // g_j is affine in u within a load step: g_j(u) = g_j(0) + grad g_j . u.
    const std::vector<double>            zero(interface.dofs().size(), 0.);
    std::vector<types::global_dof_index> dofs;
    std::vector<double>                  gradient, force_gradient;
    for (const auto &s : interface.slave_nodes)
      {
        if (!s.paired || !this->active[s.node] ||
            !owned.is_element(interface.nodes[s.node].dofs[0]))
          continue;
        this->gap_gradient(interface, s, dofs, gradient);
        // The force -p n_f acts along the frame's normal n_f, the pressure
        // p = eps (-g) is of the slave-normal gap: the rows take the gap
        // gradient along n_f (unsymmetric unless n_f is the slave normal).
        const Tensor<1, dim> n_f = this->frame_normal(s);
        if (n_f == s.normal)
          force_gradient = gradient;
        else
          this->gap_gradient_along(interface, s, n_f, dofs, force_gradient);
        const double       stiffness = node_penalty[s.node] * s.D;
        const double       g0        = interface.gap(s, zero);
        const unsigned int n         = dofs.size();
        FullMatrix<double> local_matrix(n, n);
        Vector<double>     local_rhs(n);
        for (unsigned int a = 0; a < n; ++a)
          {
            for (unsigned int b = 0; b < n; ++b)
              local_matrix(a, b) = stiffness * force_gradient[a] * gradient[b];
            local_rhs(a) = -stiffness * g0 * force_gradient[a];
          }
        this->eliminate_fixed(interface, dofs, local_matrix, local_rhs);
        constraints.distribute_local_to_global(local_matrix, local_rhs, dofs, matrix, rhs);
      }
  }

  template <int dim>
  void
  PenaltyFrictionless<dim>::assemble_current(const ContactInterface<dim> &interface,
                                             const typename ContactInterface<dim>::SlaveNode &s,
                                             const std::vector<double>                       &u,
                                             const AffineConstraints<double> &constraints,
                                             TrilinosWrappers::SparseMatrix  &matrix,
                                             TrilinosWrappers::MPI::Vector   &rhs) const
  {
    const auto                          &linearised = interface.linearised_nodes.at(s.node);
    std::vector<types::global_dof_index> columns;
    std::vector<unsigned int>            kept;
    this->free_patch_dofs(interface, linearised, kept, columns);
    // f_j at u_k on the rows of linearised.force (the node's DoFs and its
    // masters'), along the frame normal n_f (penalty frictional: the
    // interface normal where the law has friction; the pressure stays that
    // of the slave-normal gap), with its derivative.
    const Tensor<1, dim> n_f = this->frame_normal(s);
    const auto          &force_derivatives =
      this->current_frame_on_interface(s) ? linearised.interface_force : linearised.force;
    std::map<types::global_dof_index, double> force;
    for (unsigned int d = 0; d < dim; ++d)
      force[interface.nodes[s.node].dofs[d]] -= s.D * n_f[d];
    for (const auto &[m, value] : s.M)
      for (unsigned int d = 0; d < dim; ++d)
        force[interface.nodes[m].dofs[d]] += value * n_f[d];

    const double eps    = node_penalty[s.node];
    const double lambda = this->pressure[s.node];
    // d lambda_j = -(eps dG_j + lambda dD_j) / D_j at the kept columns.
    std::vector<double> d_lambda(kept.size());
    for (unsigned int a = 0; a < kept.size(); ++a)
      d_lambda[a] = -(eps * linearised.gap[kept[a]] + lambda * linearised.D[kept[a]]) / s.D;

    // Newton for the total u: K (u - u_k) = -r(u_k) with the contact's
    // internal force r = -lambda_j f_j and K = dr/du = -(f_j (x) d lambda_j
    // + lambda_j d f_j); the right-hand side is lambda_j f_j + K u_k.
    std::vector<types::global_dof_index>     rows;
    std::vector<const std::vector<double> *> derivatives;
    for (const auto &[dof, values] : force_derivatives)
      if (!interface.dof_fixed(interface.position(dof)))
        {
          rows.push_back(dof);
          derivatives.push_back(&values);
        }
    FullMatrix<double> stiffness(rows.size(), kept.size());
    Vector<double>     stiffness_rhs(rows.size());
    for (unsigned int r = 0; r < rows.size(); ++r)
      {
        const auto   it  = force.find(rows[r]);
        const double f   = it == force.end() ? 0. : it->second;
        stiffness_rhs(r) = lambda * f;
        for (unsigned int a = 0; a < kept.size(); ++a)
          {
            stiffness(r, a) = -(f * d_lambda[a] + lambda * (*derivatives[r])[kept[a]]);
            stiffness_rhs(r) += stiffness(r, a) * u[interface.position(columns[a])];
          }
      }
    constraints.distribute_local_to_global(stiffness, rows, constraints, columns, matrix);
    constraints.distribute_local_to_global(stiffness_rhs, rows, rhs);
  }

  template <int dim>
  void
  PenaltyFrictionless<dim>::recover_multipliers(const ContactInterface<dim> &,
                                                const std::vector<double> &)
  {}

  template <int dim>
  unsigned int
  PenaltyFrictionless<dim>::update_active_set(const ContactInterface<dim> &interface,
                                              const std::vector<double>   &u)
  {
    const unsigned int changes = decide_active_set(interface, u);
    share_decisions(interface);
    return this->reduce_counts(interface, {changes})[0];
  }

  template <int dim>
  unsigned int
  PenaltyFrictionless<dim>::decide_active_set(const ContactInterface<dim> &interface,
                                              const std::vector<double>   &u)
  {
    unsigned int changes = 0;
    for (const auto &s : interface.slave_nodes)
      {
        if (!s.paired || !interface.owns_row(s))
          continue;
        const double g          = interface.gap(s, u);
        const bool   now_active = g < 0.;
        if (now_active != this->active[s.node])
          ++changes;
        // The pressure of the penalty this solution was computed with.
        this->pressure[s.node] = now_active ? node_penalty[s.node] * (-g) : 0.;
        if (adaptive && (now_active || this->active[s.node]))
          {
            // A penalty that vanishes or explodes would make the system
            // singular: it stays within 1e-6 ... 1e12 of the pair's value.
            const double eps =
              std::clamp(adapted_penalty(node_penalty[s.node], -g, -previous_gap[s.node],
                                         penetration_factor * s.size),
                         1e-6 * this->penalty[s.pair], 1e12 * this->penalty[s.pair]);
            if (eps != node_penalty[s.node])
              ++changes;
            node_penalty[s.node] = eps;
          }
        previous_gap[s.node] = g;
        this->active[s.node] = now_active;
      }
    return changes;
  }

  template <int dim>
  double
  PenaltyFrictionless<dim>::largest_penalty_penetration() const
  {
    // Every rank holds the states of the contact zone (share_node_values()).
    double largest = 0.;
    for (unsigned int n = 0; n < this->active.size(); ++n)
      if (this->active[n] && node_penalty[n] > 0.)
        largest = std::max(largest, this->pressure[n] / node_penalty[n]);
    return largest;
  }

  template <int dim>
  double
  PenaltyFrictionless<dim>::step_fraction(const ContactInterface<dim> &interface,
                                          const std::vector<double>   &u_old,
                                          const std::vector<double>   &u_new) const
  {
    // The linear step from an open node's state does not see its contact
    // and may drive it far into the master (measured: 200 times the
    // penetrations of its neighbours). With current kinematics the next
    // tangent carries that node's pressure eps (-g) in its geometric terms
    // (p dD, p dn) and in the Coulomb bound mu p, and can swamp the bulk.
    // Small kinematics: the contact terms are linear in u on a fixed set
    // (the slip bound linear in p), the overshoot costs nothing, and the
    // step is left alone. The gaps at u_new are those of the iterate's
    // operators (linear in u), as the solve saw them.
    // The node enters as deep as the deepest node in contact: with the
    // pressure of its neighbours, not more. (A floor of 1e-3 h, the first
    // version, gave it a pressure of 10 E under the automatic penalty: the
    // next solve pushed it out again and the next update was limited
    // again, a cycle of period 2 on the refined 3D block.) The floor
    // Entry depth factor * h_j holds where no node is in contact yet.
    if (!limits_steps())
      return 1.;
    double deepest = 0.;
    for (const auto &s : interface.slave_nodes)
      if (s.paired && interface.owns_row(s) && this->active[s.node])
        deepest = std::max(deepest, -interface.gap(s, u_new));
    deepest         = Utilities::MPI::max(deepest, interface.communicator());
    double fraction = 1.;
    for (const auto &s : interface.slave_nodes)
      if (s.paired && interface.owns_row(s) && !this->active[s.node])
        {
          const double depth = std::max(entry_depth_factor * s.size, deepest);
          const double g_old = interface.gap(s, u_old), g_new = interface.gap(s, u_new);
          // Along the update the gap is linear: the fraction that brings
          // the node to the depth.
          if (g_new < -depth && g_old > -depth)
            fraction = std::min(fraction, (g_old + depth) / (g_old - g_new));
        }
    return Utilities::MPI::min(fraction, interface.communicator());
  }

  template <int dim>
  typename PenaltyFrictionless<dim>::Residuals
  PenaltyFrictionless<dim>::residuals(const ContactInterface<dim> &interface,
                                      const std::vector<double>   &u) const
  {
    Residuals result;
    // Each rank the terms of the rows it owns, summed in node order.
    std::vector<std::pair<unsigned int, double>> terms;
    if (adaptive)
      for (unsigned int k = 0; k < interface.slave_nodes.size(); ++k)
        {
          const auto &s = interface.slave_nodes[k];
          if (s.paired && this->active[s.node] && interface.owns_row(s))
            {
              const double r = std::max(0., -interface.gap(s, u) - penetration_factor * s.size);
              terms.emplace_back(k, r * r);
            }
        }
    result.multiplier    = adaptive ? std::sqrt(interface.sum_in_node_order(terms)) : 0.;
    result.contact_force = this->contact_forces(interface);
    return result;
  }

  template <int dim>
  void
  PenaltyFrictionless<dim>::add_results(const ContactInterface<dim> &interface, Json &contact) const
  {
    FrictionlessFormulation<dim>::add_results(interface, contact);
    if (!adaptive)
      return;
    double largest = 0.;
    for (const auto &s : interface.slave_nodes)
      if (s.paired && this->active[s.node])
        largest = std::max(largest, node_penalty[s.node]);
    contact.set("largest_adapted_penalty", largest);
  }

  template <int dim>
  void
  PenaltyFrictionless<dim>::print_results(const ContactInterface<dim> &interface,
                                          const std::vector<double>   &u,
                                          const Json &,
                                          const Json &,
                                          std::ostream &out) const
  {
    if (!adaptive)
      return;
    double gap_max = 0., largest = 0.;
    for (const auto &s : interface.slave_nodes)
      if (s.paired && this->active[s.node])
        {
          gap_max = std::max(gap_max, std::abs(interface.gap(s, u)) / s.size);
          largest = std::max(largest, node_penalty[s.node]);
        }
    out << "    penetration within the allowed " << penetration_factor
        << " h: " << (gap_max <= penetration_factor ? "yes" : "no") << std::endl
        << "    largest adapted penalty / initial: "
        << largest / (this->penalty.empty() ? 0. : this->penalty[0]) << std::endl;
  }

  template <int dim>
  double
  PenaltyFrictionless<dim>::adapted_penalty(const double eps,
                                            const double penetration,
                                            const double previous_penetration,
                                            const double allowed) const
  {
    // A node that closes in this iteration counts as having had no
    // penetration before: the crossing rule is for a node pushed out again
    // (too stiff a penalty), not for one that makes first contact.
    const double p = penetration, q = std::max(previous_penetration, 0.);
    double       result = eps;
    if (q > 0. && p < 0.)
      // Pushed out: soften by the ratio of the two penetrations (more
      // strongly if the previous one was within the limit).
      result = std::abs(q) > allowed ? std::abs(eps * q / p * (std::abs(p) + allowed) / (p - q)) :
                                       std::abs(eps * q / (10. * p));
    else if (p > allowed)
      {
        if (std::abs(p - q) > std::max({p / 10., q / 10., 5. * allowed}))
          result = 2. * eps; // still moving a lot: double
        else if (std::abs(std::abs(p) - std::abs(q)) <= 0.01 * std::abs(q) && p < 10. * allowed)
          result = eps * std::pow(std::sqrt(p / allowed - 1.) + 1., 2); // stalled near the limit
        else if (p > 1.01 * std::abs(q))
          result = 2. * eps * std::abs(q) / p; // growing
        else
          result = eps * (std::sqrt(p / allowed - 1.) + 1.);
      }
    return result;
  }

  template class PenaltyFrictionless<2>;
  template class PenaltyFrictionless<3>;

  CONTACT_FEM_REGISTER_FORMULATION(PenaltyFrictionless, "penalty frictionless", false, false, true)
} // namespace contact_fem
