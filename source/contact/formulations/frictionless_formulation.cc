#include <deal.II/lac/full_matrix.h>

#include <contact_fem/contact/formulations/constraint_line.h>
#include <contact_fem/contact/formulations/frictionless_formulation.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>

namespace contact_fem
{
  double
  parse_auto_or_positive(const std::string &text, const std::string &key)
  {
    if (Utilities::trim(text) == "auto")
      return 0.;
    double value = -1.;
    try
      {
        std::size_t pos = 0;
        value           = std::stod(Utilities::trim(text), &pos);
        if (pos != Utilities::trim(text).size())
          value = -1.;
      }
    catch (...)
      {
        value = -1.;
      }
    AssertThrow(value > 0. && std::isfinite(value),
                ExcMessage(key + ": got '" + text + "'; expected 'auto' or a number > 0."));
    return value;
  }

  bool
  current_kinematics(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    const bool current = prm.get("Kinematics") == "current";
    prm.leave_subsection();
    return current;
  }

  template <int dim>
  void
  FrictionlessFormulation<dim>::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry("Penalty", "auto", Patterns::Anything(),
                      "Penalty eps. 'alm frictionless': of the augmented pressure "
                      "lambda - eps * gap that decides the active set (it cannot "
                      "change the converged answer); 'auto' = stiffness factor * "
                      "min(E/h) over the two sides. 'penalty frictionless': the "
                      "contact stiffness, pressure = eps * penetration; 'auto' = "
                      "1e4 * stiffness factor * min(E/h) (penetrations ~1e-4 h * "
                      "pressure / E), or, with Adaptive penalty, the starting value "
                      "stiffness factor * min(E/h). Units: stress / length.");
    prm.declare_entry("Scale factor", "auto", Patterns::Anything(),
                      "Scale factor k of the multipliers (the multiplier residual "
                      "is reported as (lambda - max(0, lambda - eps g)) / k, a "
                      "length). 'auto' = stiffness factor * min(E/h). Units: stress "
                      "/ length.");
    prm.declare_entry("Stiffness factor", "1", Patterns::Double(0.),
                      "Multiplies the automatic penalty and scale factor.");
    prm.declare_entry("Active check factor", "1e-2", Patterns::Double(0.),
                      "At the first load step, slave nodes whose gap is below this "
                      "factor times their nodal size start in the active set. On a "
                      "refined mesh of an adaptive cycle, which starts from the "
                      "transferred solution at the same load, at most 1e-2.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  FrictionlessFormulation<dim>::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    penalty             = parse_auto_or_positive(prm.get("Penalty"), "Contact/Penalty");
    scale_factor        = parse_auto_or_positive(prm.get("Scale factor"), "Contact/Scale factor");
    stiffness_factor    = prm.get_double("Stiffness factor");
    active_check_factor = prm.get_double("Active check factor");
    prm.leave_subsection();
    AssertThrow(stiffness_factor > 0.,
                ExcMessage("Contact/Stiffness factor: expected a value > 0."));
  }

  template <int dim>
  typename FrictionlessFormulation<dim>::Parameters
  FrictionlessFormulation<dim>::Parameters::parse_for_exact_gap(ParameterHandler  &prm,
                                                                const std::string &formulation)
  {
    Parameters parameters;
    parameters.parse_parameters(prm);
    // A key of the penalty formulations set with this one is a mistake
    // worth a message, not a silent no-op.
    prm.enter_subsection("Contact");
    const bool adaptive = prm.get_bool("Adaptive penalty");
    prm.leave_subsection();
    AssertThrow(!adaptive, ExcMessage("Contact/Adaptive penalty = true needs a penalty formulation "
                                      "(penalty frictionless or penalty frictional): in '" +
                                      formulation +
                                      "' the gap of an active node is an exact constraint and the "
                                      "penalty only scales the active-set test, so adapting it "
                                      "changes nothing."));
    return parameters;
  }

  template <int dim>
  typename FrictionlessFormulation<dim>::Parameters
  FrictionlessFormulation<dim>::Parameters::parse_without_penalty(ParameterHandler  &prm,
                                                                  const std::string &formulation)
  {
    const Parameters parameters = parse_for_exact_gap(prm, formulation);
    AssertThrow(parameters.penalty == 0.,
                ExcMessage("Contact/Penalty is set, but Contact/Formulation = " + formulation +
                           " has no penalty: its active set comes from the recovered "
                           "reactions (released in tension) and the gap (activated on "
                           "penetration). Leave Contact/Penalty = auto."));
    return parameters;
  }

  template <int dim>
  FrictionlessFormulation<dim>::FrictionlessFormulation(const Parameters &parameters)
    : parameters(parameters)
  {}

  template <int dim>
  void
  FrictionlessFormulation<dim>::initialize(const ContactInterface<dim> &interface)
  {
    pressure.assign(interface.nodes.size(), 0.);
    active.assign(interface.nodes.size(), false);
    active_count = 0;
  }

  template <int dim>
  std::unique_ptr<typename ContactFormulation<dim>::State>
  FrictionlessFormulation<dim>::save_state() const
  {
    auto state          = std::make_unique<PressureState>();
    state->pressure     = pressure;
    state->active       = active;
    state->active_count = active_count;
    return state;
  }

  template <int dim>
  void
  FrictionlessFormulation<dim>::restore_state(const State &state)
  {
    const auto &saved = dynamic_cast<const PressureState &>(state);
    pressure          = saved.pressure;
    active            = saved.active;
    active_count      = saved.active_count;
  }

  template <int dim>
  void
  FrictionlessFormulation<dim>::add_results(const ContactInterface<dim> &, Json &contact) const
  {
    contact.set("penalty", penalty.empty() ? 0. : penalty[0])
      .set("scale_factor", scale.empty() ? 0. : scale[0]);
  }

  template <int dim>
  void
  FrictionlessFormulation<dim>::set_pair_scaling(const ContactInterface<dim> &interface,
                                                 const double                 penalty_factor)
  {
    const unsigned int n_pairs = interface.pairs.size();
    penalty.assign(n_pairs, 0.);
    penalty_ratio = 1.;
    scale.assign(n_pairs, 0.);
    for (unsigned int p = 0; p < n_pairs; ++p)
      {
        const auto &stat     = interface.statistics[p];
        double      E_over_h = 0.;
        if (stat.mean_slave_size > 0.)
          E_over_h =
            parameters.stiffness_factor * std::min(stat.slave_modulus / stat.mean_slave_size,
                                                   stat.master_modulus / stat.mean_master_size);
        const double automatic = penalty_factor * E_over_h;
        penalty[p]             = parameters.penalty > 0. ? parameters.penalty : automatic;
        if (parameters.penalty > 0. && automatic > 0.)
          penalty_ratio = std::max(penalty_ratio, parameters.penalty / automatic);
        scale[p] = parameters.scale_factor > 0. ? parameters.scale_factor : E_over_h;
        if (scale[p] <= 0.)
          scale[p] = 1.;
      }
  }

  template <int dim>
  void
  FrictionlessFormulation<dim>::gap_gradient(const ContactInterface<dim> &interface,
                                             const typename ContactInterface<dim>::SlaveNode &s,
                                             std::vector<types::global_dof_index>            &dofs,
                                             std::vector<double> &gradient) const
  {
    gap_gradient_along(interface, s, s.normal, dofs, gradient);
  }

  template <int dim>
  void
  FrictionlessFormulation<dim>::gap_gradient_along(
    const ContactInterface<dim>                     &interface,
    const typename ContactInterface<dim>::SlaveNode &s,
    const Tensor<1, dim>                            &n,
    std::vector<types::global_dof_index>            &dofs,
    std::vector<double>                             &gradient) const
  {
    dofs.clear();
    gradient.clear();
    for (unsigned int d = 0; d < dim; ++d)
      {
        dofs.push_back(interface.nodes[s.node].dofs[d]);
        gradient.push_back(-n[d]);
      }
    for (const auto &[m, value] : s.M)
      for (unsigned int d = 0; d < dim; ++d)
        {
          dofs.push_back(interface.nodes[m].dofs[d]);
          gradient.push_back(value * n[d] / s.D);
        }
  }

  template <int dim>
  void
  FrictionlessFormulation<dim>::free_patch_dofs(
    const ContactInterface<dim>                          &interface,
    const typename ContactInterface<dim>::LinearisedNode &linearised,
    std::vector<unsigned int>                            &kept,
    std::vector<types::global_dof_index>                 &columns) const
  {
    kept.clear();
    columns.clear();
    for (unsigned int i = 0; i < linearised.dofs.size(); ++i)
      if (!interface.dof_fixed(interface.position(linearised.dofs[i])))
        {
          kept.push_back(i);
          columns.push_back(linearised.dofs[i]);
        }
  }

  template <int dim>
  void
  FrictionlessFormulation<dim>::eliminate_fixed(const ContactInterface<dim>          &interface,
                                                std::vector<types::global_dof_index> &dofs,
                                                FullMatrix<double>                   &matrix,
                                                Vector<double>                       &rhs) const
  {
    std::vector<unsigned int> kept;
    for (unsigned int a = 0; a < dofs.size(); ++a)
      {
        const unsigned int position = interface.position(dofs[a]);
        if (!interface.dof_fixed(position))
          kept.push_back(a);
        else
          for (unsigned int b = 0; b < dofs.size(); ++b)
            rhs(b) -= matrix(b, a) * dirichlet_values[position];
      }
    if (kept.size() == dofs.size())
      return;
    FullMatrix<double>                   reduced_matrix(kept.size(), kept.size());
    Vector<double>                       reduced_rhs(kept.size());
    std::vector<types::global_dof_index> reduced_dofs(kept.size());
    for (unsigned int i = 0; i < kept.size(); ++i)
      {
        reduced_dofs[i] = dofs[kept[i]];
        reduced_rhs(i)  = rhs(kept[i]);
        for (unsigned int j = 0; j < kept.size(); ++j)
          reduced_matrix(i, j) = matrix(kept[i], kept[j]);
      }
    dofs   = std::move(reduced_dofs);
    matrix = std::move(reduced_matrix);
    rhs    = std::move(reduced_rhs);
  }

  template <int dim>
  unsigned int
  FrictionlessFormulation<dim>::eliminated_component(
    const ContactInterface<dim>                     &interface,
    const typename ContactInterface<dim>::SlaveNode &s) const
  {
    return normal_line_component(interface, s);
  }

  template <int dim>
  void
  FrictionlessFormulation<dim>::add_gap_constraints(
    const ContactInterface<dim>                                                  &interface,
    const std::vector<double>                                                    &fixed_values,
    AffineConstraints<double>                                                    &constraints,
    const bool                                                                    only_active,
    const std::function<bool(const typename ContactInterface<dim>::SlaveNode &)> &skip) const
  {
    for (const auto &s : interface.slave_nodes)
      {
        if (!s.paired || (only_active && !active[s.node]) ||
            !may_store_line_of<dim>(interface.nodes[s.node], constraints) || (skip && skip(s)))
          continue;
        const unsigned int c = eliminated_component(interface, s);
        if (c == dim)
          continue;
        add_gap_line(interface, s, c, fixed_values, constraints);
      }
  }

  template <int dim>
  void
  FrictionlessFormulation<dim>::add_gap_line(const ContactInterface<dim> &interface,
                                             const typename ContactInterface<dim>::SlaveNode &s,
                                             const unsigned int                               c,
                                             const std::vector<double> &fixed_values,
                                             AffineConstraints<double> &constraints) const
  {
    const auto &slave = interface.nodes[s.node];
    if (!constraints.can_store_line(slave.dofs[c]) || constraints.is_constrained(slave.dofs[c]))
      return;
    // g_j(u) = (n . (sum_l M_jl (X_l + u_l) - D (X_j + u_j)) + c_j) / D = 0
    // (c_j the curvature gap), solved for u_j,c.
    const double   denominator = s.D * s.normal[c];
    ConstraintLine line;
    line.inhomogeneity = s.curvature_gap / denominator;
    for (const auto &[m, value] : s.M)
      {
        const auto &master = interface.nodes[m];
        line.inhomogeneity += value * (s.normal * master.reference) / denominator;
        for (unsigned int d = 0; d < dim; ++d)
          line.add(master, d, value * s.normal[d] / denominator, interface, fixed_values);
      }
    line.inhomogeneity -= s.normal * slave.reference / s.normal[c];
    for (unsigned int d = 0; d < dim; ++d)
      if (d != c)
        line.add(slave, d, -s.normal[d] / s.normal[c], interface, fixed_values);
    line.store(slave.dofs[c], constraints);
  }

  template <int dim>
  std::vector<double>
  FrictionlessFormulation<dim>::contact_forces(const ContactInterface<dim> &interface,
                                               const bool                   all) const
  {
    std::vector<typename ContactInterface<dim>::ForceTerm> terms;
    add_force_terms(interface, all, terms);
    std::vector<double> force = interface.sum_forces(terms, all);
    if (!all && ContactInterface<dim>::checking_held_state())
      interface.check_held_forces(force, contact_forces(interface, true));
    return force;
  }

  template <int dim>
  void
  FrictionlessFormulation<dim>::add_force_terms(
    const ContactInterface<dim>                            &interface,
    const bool                                              all,
    std::vector<typename ContactInterface<dim>::ForceTerm> &terms) const
  {
    for (unsigned int k = 0; k < interface.slave_nodes.size(); ++k)
      {
        const auto &s = interface.slave_nodes[k];
        if (!all && !interface.owns_row(s))
          continue;
        const double lambda = pressure[s.node];
        if (!s.paired || lambda == 0.)
          continue;
        const Tensor<1, dim> n = this->frame_normal(s);
        for (unsigned int d = 0; d < dim; ++d)
          terms.push_back({static_cast<double>(k),
                           interface.position(interface.nodes[s.node].dofs[d]),
                           -(lambda * s.D * n[d])});
        for (const auto &[m, value] : s.M)
          for (unsigned int d = 0; d < dim; ++d)
            terms.push_back({static_cast<double>(k), interface.position(interface.nodes[m].dofs[d]),
                             lambda * value * n[d]});
      }
  }

  template <int dim>
  void
  FrictionlessFormulation<dim>::share_states(const ContactInterface<dim>              &interface,
                                             const std::vector<std::vector<double> *> &key_fields,
                                             const std::vector<std::vector<double> *> &other_fields)
  {
    std::vector<double>                active_values(active.begin(), active.end());
    std::vector<std::vector<double> *> fields = {&active_values, &pressure};
    fields.insert(fields.end(), key_fields.begin(), key_fields.end());
    const unsigned int n_key = fields.size();
    fields.insert(fields.end(), other_fields.begin(), other_fields.end());
    interface.share_node_values(fields, n_key);
    for (unsigned int n = 0; n < active.size(); ++n)
      active[n] = active_values[n] != 0.;
  }

  template <int dim>
  std::vector<unsigned int>
  FrictionlessFormulation<dim>::reduce_counts(const ContactInterface<dim> &interface,
                                              std::vector<unsigned int>    changes)
  {
    // Every active node is a regular slave node whose row one rank owns
    // (the others hold copies or +0), so the owners' counts add up to the
    // counts over the whole state.
    const unsigned int n_changes = changes.size();
    for (const unsigned int count : count_owned_rows(interface))
      changes.push_back(count);
    Utilities::MPI::sum(changes, interface.communicator(), changes);
    auto next = changes.cbegin() + n_changes;
    take_counts(next);
    changes.resize(n_changes);
    return changes;
  }

  template <int dim>
  std::vector<unsigned int>
  FrictionlessFormulation<dim>::count_owned_rows(const ContactInterface<dim> &interface) const
  {
    unsigned int n = 0;
    for (const auto &s : interface.slave_nodes)
      n += interface.owns_row(s) && active[s.node];
    return {n};
  }

  template <int dim>
  void
  FrictionlessFormulation<dim>::take_counts(std::vector<unsigned int>::const_iterator &next)
  {
    active_count = *next++;
  }

  template class FrictionlessFormulation<2>;
  template class FrictionlessFormulation<3>;
} // namespace contact_fem
