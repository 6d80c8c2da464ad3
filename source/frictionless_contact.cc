#include <contact_fem/alm_contact.h>

#include <algorithm>
#include <cmath>

namespace contact_fem
{
  template <int dim>
  AlmFrictionless<dim>::AlmFrictionless(const ContactParameters &parameters)
    : parameters(parameters)
  {}

  template <int dim>
  void
  AlmFrictionless<dim>::initialize(const ContactInterface<dim> &interface)
  {
    pressure.assign(interface.nodes.size(), 0.);
    released_pressure.assign(interface.nodes.size(), 0.);
    active.assign(interface.nodes.size(), false);
  }

  template <int dim>
  void
  AlmFrictionless<dim>::start_load_step(const ContactInterface<dim> &interface,
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
        penalty[p] = parameters.penalty > 0. ? parameters.penalty : E_over_h;
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
        bool         a = pressure[s.node] - penalty[s.pair] * g > 0.;
        if (first_step && g <= parameters.active_check_factor * s.size)
          a = true;
        active[s.node] = a && eliminated_component(interface, s) < dim;
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
  AlmFrictionless<dim>::eliminated_component(
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
  AlmFrictionless<dim>::add_constraints(const ContactInterface<dim> &interface,
                                        const std::vector<double>   &fixed_values,
                                        AffineConstraints<double>   &constraints,
                                        const bool                   all_candidates) const
  {
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

        // g_j(u) = n . (sum_l M_jl (X_l + u_l) - D (X_j + u_j)) / D = 0,
        // solved for u_j,c.
        const double denominator = s.D * s.normal[c];
        double       inhomogeneity = 0.;
        std::vector<std::pair<types::global_dof_index, double>> entries;
        for (const auto &[m, value] : s.M)
          {
            const auto &master = interface.nodes[m];
            inhomogeneity += value * (s.normal * master.reference) / denominator;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double coefficient = value * s.normal[d] / denominator;
                if (std::abs(coefficient) < 1e-14)
                  continue;
                if (master.fixed[d])
                  inhomogeneity +=
                    coefficient * fixed_values[interface.position(master.dofs[d])];
                else
                  entries.emplace_back(master.dofs[d], coefficient);
              }
          }
        inhomogeneity -= s.normal * slave.reference / s.normal[c];
        for (unsigned int d = 0; d < dim; ++d)
          if (d != c)
            {
              const double coefficient = -s.normal[d] / s.normal[c];
              if (std::abs(coefficient) < 1e-14)
                continue;
              if (slave.fixed[d])
                inhomogeneity +=
                  coefficient * fixed_values[interface.position(slave.dofs[d])];
              else
                entries.emplace_back(slave.dofs[d], coefficient);
            }
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
  AlmFrictionless<dim>::recover_multipliers(const ContactInterface<dim> &interface,
                                            const std::vector<double>   &residual)
  {
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
  AlmFrictionless<dim>::update_active_set(const ContactInterface<dim> &interface,
                                          const std::vector<double>   &u)
  {
    unsigned int changes = 0;
    std::fill(released_pressure.begin(), released_pressure.end(), 0.);
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
  typename AlmFrictionless<dim>::Residuals
  AlmFrictionless<dim>::residuals(const ContactInterface<dim> &interface,
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
        // multiplier of a node released in this update still counts).
        const double r = active[s.node] ?
                           interface.gap(s, u) :
                           released_pressure[s.node] / scale[s.pair];
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
  unsigned int
  AlmFrictionless<dim>::n_active() const
  {
    return std::count(active.begin(), active.end(), true);
  }

  template class AlmFrictionless<2>;
  template class AlmFrictionless<3>;
} // namespace contact_fem
