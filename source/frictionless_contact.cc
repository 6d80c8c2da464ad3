#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <contact_fem/frictionless_contact.h>

#include <algorithm>
#include <cmath>

namespace contact_fem
{
  template <int dim>
  FrictionlessContact<dim>::FrictionlessContact(const ContactParameters &parameters)
    : parameters(parameters)
  {}

  template <int dim>
  void
  FrictionlessContact<dim>::initialize(const ContactInterface<dim> &interface)
  {
    pressure.assign(interface.nodes.size(), 0.);
    released_pressure.assign(interface.nodes.size(), 0.);
    active.assign(interface.nodes.size(), false);
    node_penalty.assign(interface.nodes.size(), 0.);
    previous_gap.assign(interface.nodes.size(), 0.);
  }

  template <int dim>
  void
  FrictionlessContact<dim>::start_load_step(const ContactInterface<dim> &interface,
                                            const std::vector<double>   &u,
                                            const bool                   first_step)
  {
    const unsigned int n_pairs = interface.pairs.size();
    penalty.assign(n_pairs, 0.);
    scale.assign(n_pairs, 0.);
    for (unsigned int p = 0; p < n_pairs; ++p)
      {
        const auto &stat = interface.statistics[p];
        double      E_over_h = 0.;
        if (stat.mean_slave_size > 0.)
          E_over_h = parameters.stiffness_factor *
                     std::min(stat.slave_modulus / stat.mean_slave_size,
                              stat.master_modulus / stat.mean_master_size);
        // The penalty formulation needs a stiff spring (penetration ~ 1e-4 h
        // p / E) unless the adaptive rule raises it where needed.
        const double automatic =
          parameters.regularised() && !parameters.adaptive_penalty ? 1e4 * E_over_h : E_over_h;
        penalty[p] = parameters.penalty > 0. ? parameters.penalty : automatic;
        scale[p]   = parameters.scale_factor > 0. ? parameters.scale_factor : E_over_h;
        if (scale[p] <= 0.)
          scale[p] = 1.;
      }

    std::fill(released_pressure.begin(), released_pressure.end(), 0.);
    for (const auto &s : interface.slave_nodes)
      {
        if (!s.paired)
          {
            active[s.node]   = false;
            pressure[s.node] = 0.;
            continue;
          }
        const double g = interface.gap(s, u);
        if (parameters.regularised())
          {
            // Adapted penalties live as long as the mesh.
            if (node_penalty[s.node] == 0. || !parameters.adaptive_penalty)
              node_penalty[s.node] = penalty[s.pair];
            previous_gap[s.node] = g;
          }
        bool a = pressure[s.node] - penalty[s.pair] * g > 0.;
        if (first_step && g <= parameters.active_check_factor * s.size)
          a = true;
        active[s.node] =
          a && (parameters.regularised() || eliminated_component(interface, s) < dim);
        if (!active[s.node])
          {
            released_pressure[s.node] = pressure[s.node];
            pressure[s.node]          = 0.;
          }
      }
    // Nodes that lost their master projection since the last search.
    for (unsigned int n = 0; n < interface.nodes.size(); ++n)
      if (!interface.nodes[n].slave)
        active[n] = false;
  }

  template <int dim>
  unsigned int
  FrictionlessContact<dim>::eliminated_component(
    const ContactInterface<dim>                    &interface,
    const typename ContactInterface<dim>::SlaveNode &s) const
  {
    // The free component with the largest normal part: the constraint
    // n . u = ... is solved for it. A node whose free components are nearly
    // tangential cannot carry a normal constraint.
    unsigned int best = dim;
    double       best_value = 0.1;
    for (unsigned int d = 0; d < dim; ++d)
      if (!interface.nodes[s.node].fixed[d] && std::abs(s.normal[d]) > best_value)
        {
          best       = d;
          best_value = std::abs(s.normal[d]);
        }
    return best;
  }

  template <int dim>
  void
  FrictionlessContact<dim>::add_constraints(const ContactInterface<dim> &interface,
                                            const std::vector<double>   &fixed_values,
                                            AffineConstraints<double>   &constraints,
                                            const bool                   all_candidates) const
  {
    // The penalty formulation has no constraints; its candidates still
    // give the sparsity pattern the slave-master couplings it needs.
    if (parameters.regularised() && !all_candidates)
      return;
    for (const auto &s : interface.slave_nodes)
      {
        if (!s.paired || (!all_candidates && !active[s.node]))
          continue;
        const unsigned int c = eliminated_component(interface, s);
        if (c == dim)
          continue;
        const auto &slave = interface.nodes[s.node];
        if (!constraints.can_store_line(slave.dofs[c]) ||
            constraints.is_constrained(slave.dofs[c]))
          continue;

        // g_j(u) = (n . (sum_l M_jl (X_l + u_l) - D (X_j + u_j)) + c_j) / D = 0
        // (c_j the curvature gap), solved for u_j,c.
        const double denominator = s.D * s.normal[c];
        double       inhomogeneity = s.curvature_gap / denominator;
        std::vector<std::pair<types::global_dof_index, double>> entries;
        // A term coefficient * u of component d of interface node `node`: a
        // fixed DoF moves its known value into the inhomogeneity.
        const auto add_term = [&](const typename ContactInterface<dim>::Node &node,
                                  const unsigned int                          d,
                                  const double                                coefficient) {
          if (std::abs(coefficient) < 1e-14)
            return;
          if (node.fixed[d])
            inhomogeneity += coefficient * fixed_values[interface.position(node.dofs[d])];
          else
            entries.emplace_back(node.dofs[d], coefficient);
        };
        for (const auto &[m, value] : s.M)
          {
            const auto &master = interface.nodes[m];
            inhomogeneity += value * (s.normal * master.reference) / denominator;
            for (unsigned int d = 0; d < dim; ++d)
              add_term(master, d, value * s.normal[d] / denominator);
          }
        inhomogeneity -= s.normal * slave.reference / s.normal[c];
        for (unsigned int d = 0; d < dim; ++d)
          if (d != c)
            add_term(slave, d, -s.normal[d] / s.normal[c]);
        // The same DoF may appear through two master faces: merge entries.
        std::sort(entries.begin(), entries.end());
        std::vector<std::pair<types::global_dof_index, double>> merged;
        for (const auto &e : entries)
          if (!merged.empty() && merged.back().first == e.first)
            merged.back().second += e.second;
          else
            merged.push_back(e);
        constraints.add_line(slave.dofs[c]);
        constraints.add_entries(slave.dofs[c], merged);
        constraints.set_inhomogeneity(slave.dofs[c], inhomogeneity);
      }
  }

  template <int dim>
  void
  FrictionlessContact<dim>::gap_gradient(const ContactInterface<dim>                     &interface,
                                         const typename ContactInterface<dim>::SlaveNode &s,
                                         std::vector<types::global_dof_index>            &dofs,
                                         std::vector<double> &gradient) const
  {
    dofs.clear();
    gradient.clear();
    for (unsigned int d = 0; d < dim; ++d)
      {
        dofs.push_back(interface.nodes[s.node].dofs[d]);
        gradient.push_back(-s.normal[d]);
      }
    for (const auto &[m, value] : s.M)
      for (unsigned int d = 0; d < dim; ++d)
        {
          dofs.push_back(interface.nodes[m].dofs[d]);
          gradient.push_back(value * s.normal[d] / s.D);
        }
  }

  template <int dim>
  void
  FrictionlessContact<dim>::add_penalty_sparsity(const ContactInterface<dim>    &interface,
                                                 const AffineConstraints<double> &constraints,
                                                 const IndexSet                  &owned,
                                                 DynamicSparsityPattern          &pattern) const
  {
    std::vector<types::global_dof_index> dofs;
    std::vector<double>                  gradient;
    for (const auto &s : interface.slave_nodes)
      if (s.paired && owned.is_element(interface.nodes[s.node].dofs[0]))
        {
          gap_gradient(interface, s, dofs, gradient);
          constraints.add_entries_local_to_global(dofs, pattern, true);
        }
  }

  template <int dim>
  void
  FrictionlessContact<dim>::assemble_penalty(const ContactInterface<dim>    &interface,
                                             const AffineConstraints<double> &constraints,
                                             const IndexSet                  &owned,
                                             TrilinosWrappers::SparseMatrix  &matrix,
                                             TrilinosWrappers::MPI::Vector   &rhs) const
  {
    // g_j is affine in u within a load step: g_j(u) = g_j(0) + grad g_j . u,
    // with grad g_j = -n_j at the slave node and n_j M_jl / D_j at master l.
    const std::vector<double>            zero(interface.dofs().size(), 0.);
    std::vector<types::global_dof_index> dofs;
    std::vector<double>                  gradient;
    for (const auto &s : interface.slave_nodes)
      {
        if (!s.paired || !active[s.node] ||
            !owned.is_element(interface.nodes[s.node].dofs[0]))
          continue;
        gap_gradient(interface, s, dofs, gradient);
        const double       stiffness = node_penalty[s.node] * s.D;
        const double       g0        = interface.gap(s, zero);
        const unsigned int n         = dofs.size();
        FullMatrix<double> local_matrix(n, n);
        Vector<double>     local_rhs(n);
        for (unsigned int a = 0; a < n; ++a)
          {
            for (unsigned int b = 0; b < n; ++b)
              local_matrix(a, b) = stiffness * gradient[a] * gradient[b];
            local_rhs(a) = -stiffness * g0 * gradient[a];
          }
        constraints.distribute_local_to_global(local_matrix, local_rhs, dofs, matrix, rhs);
      }
  }

  template <int dim>
  void
  FrictionlessContact<dim>::recover_multipliers(const ContactInterface<dim> &interface,
                                                const std::vector<double>   &residual)
  {
    if (parameters.regularised())
      return; // lambda_j = eps_j (-g_j), set by update_active_set()
    for (const auto &s : interface.slave_nodes)
      {
        if (!s.paired || !active[s.node])
          {
            pressure[s.node] = 0.;
            continue;
          }
        const unsigned int c = eliminated_component(interface, s);
        const double       r = residual[interface.position(interface.nodes[s.node].dofs[c])];
        pressure[s.node]     = -r / (s.D * s.normal[c]);
      }
  }

  template <int dim>
  unsigned int
  FrictionlessContact<dim>::update_active_set(const ContactInterface<dim> &interface,
                                              const std::vector<double>   &u)
  {
    unsigned int changes = 0;
    std::fill(released_pressure.begin(), released_pressure.end(), 0.);
    if (parameters.regularised())
      {
        for (const auto &s : interface.slave_nodes)
          {
            if (!s.paired)
              continue;
            const double g          = interface.gap(s, u);
            const bool   now_active = g < 0.;
            if (now_active != active[s.node])
              ++changes;
            // The pressure of the penalty this solution was computed with.
            pressure[s.node] = now_active ? node_penalty[s.node] * (-g) : 0.;
            if (parameters.adaptive_penalty && (now_active || active[s.node]))
              {
                // A penalty that vanishes or explodes would make the system
                // singular: it stays within 1e-6 ... 1e12 of the pair's value.
                const double eps =
                  std::clamp(adapted_penalty(node_penalty[s.node], -g, -previous_gap[s.node],
                                             parameters.penetration_factor * s.size),
                             1e-6 * penalty[s.pair],
                             1e12 * penalty[s.pair]);
                if (eps != node_penalty[s.node])
                  ++changes;
                node_penalty[s.node] = eps;
              }
            previous_gap[s.node] = g;
            active[s.node]       = now_active;
          }
        return changes;
      }
    for (const auto &s : interface.slave_nodes)
      {
        if (!s.paired)
          continue;
        const double augmented =
          pressure[s.node] - penalty[s.pair] * interface.gap(s, u);
        const bool now_active =
          augmented > 0. && eliminated_component(interface, s) < dim;
        if (now_active != active[s.node])
          ++changes;
        if (!now_active)
          {
            released_pressure[s.node] = pressure[s.node];
            pressure[s.node]          = 0.;
          }
        active[s.node] = now_active;
      }
    return changes;
  }

  template <int dim>
  typename FrictionlessContact<dim>::Residuals
  FrictionlessContact<dim>::residuals(const ContactInterface<dim> &interface,
                                      const std::vector<double>   &u) const
  {
    Residuals result;
    result.contact_force.assign(interface.dofs().size(), 0.);
    double sum = 0.;
    for (const auto &s : interface.slave_nodes)
      {
        if (!s.paired)
          continue;
        // Complementarity: g = 0 on the active set, lambda = 0 elsewhere (the
        // multiplier of a node released in this update still counts). The
        // penalty formulation satisfies it by construction; with adaptive
        // penalties its residual is the penetration beyond the allowed one.
        double r = 0.;
        if (!parameters.regularised())
          r = active[s.node] ? interface.gap(s, u) : released_pressure[s.node] / scale[s.pair];
        else if (parameters.adaptive_penalty && active[s.node])
          r = std::max(0., -interface.gap(s, u) - parameters.penetration_factor * s.size);
        sum += r * r;

        // Contact forces of the current multipliers: -lambda D n on the
        // slave, +lambda M n on the masters.
        const double lambda = pressure[s.node];
        if (lambda == 0.)
          continue;
        for (unsigned int d = 0; d < dim; ++d)
          result.contact_force[interface.position(interface.nodes[s.node].dofs[d])] -=
            lambda * s.D * s.normal[d];
        for (const auto &[m, value] : s.M)
          for (unsigned int d = 0; d < dim; ++d)
            result.contact_force[interface.position(interface.nodes[m].dofs[d])] +=
              lambda * value * s.normal[d];
      }
    result.multiplier = std::sqrt(sum);
    return result;
  }

  template <int dim>
  double
  FrictionlessContact<dim>::adapted_penalty(const double eps,
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
      result = std::abs(q) > allowed ?
                 std::abs(eps * q / p * (std::abs(p) + allowed) / (p - q)) :
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

  template <int dim>
  unsigned int
  FrictionlessContact<dim>::n_active() const
  {
    return std::count(active.begin(), active.end(), true);
  }

  template class FrictionlessContact<2>;
  template class FrictionlessContact<3>;
} // namespace contact_fem
