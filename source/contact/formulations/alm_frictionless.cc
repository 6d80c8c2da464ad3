#include <contact_fem/contact/formulations/alm_frictionless.h>

#include <algorithm>
#include <cmath>

namespace contact_fem
{

  template <int dim>
  AlmFrictionless<dim>::AlmFrictionless(ParameterHandler &prm)
    : FrictionlessFormulation<dim>(
        FrictionlessFormulation<dim>::Parameters::parse_for_exact_gap(prm, "alm frictionless"))
  {}

  template <int dim>
  AlmFrictionless<dim>::AlmFrictionless(const Parameters &parameters)
    : FrictionlessFormulation<dim>(parameters)
  {}

  template <int dim>
  bool
  AlmFrictionless<dim>::decides_active(const typename ContactInterface<dim>::SlaveNode &s,
                                       const double                                     g,
                                       const bool      at_step_start,
                                       const StepStart start) const
  {
    return this->augmented_rule(s, g, at_step_start, start);
  }

  template <int dim>
  void
  AlmFrictionless<dim>::initialize(const ContactInterface<dim> &interface)
  {
    FrictionlessFormulation<dim>::initialize(interface);
    released_pressure.assign(interface.nodes.size(), 0.);
  }

  template <int dim>
  void
  AlmFrictionless<dim>::start_load_step(const ContactInterface<dim> &interface,
                                        const std::vector<double>   &u,
                                        const StepStart              start)
  {
    this->set_pair_scaling(interface, 1.);
    std::fill(released_pressure.begin(), released_pressure.end(), 0.);
    auto &pressure = this->pressure;
    auto &active   = this->active;
    for (const auto &s : interface.slave_nodes)
      {
        if (!s.paired)
          {
            active[s.node]   = false;
            pressure[s.node] = 0.;
            continue;
          }
        const double g = interface.gap(s, u);
        active[s.node] =
          decides_active(s, g, true, start) && this->eliminated_component(interface, s) < dim;
        if (!active[s.node])
          {
            released_pressure[s.node] = pressure[s.node];
            pressure[s.node]          = 0.;
          }
      }
    this->deactivate_master_nodes(interface);
  }

  template <int dim>
  void
  AlmFrictionless<dim>::add_constraints(const ContactInterface<dim> &interface,
                                        const std::vector<double>   &fixed_values,
                                        AffineConstraints<double>   &constraints,
                                        const bool                   all_candidates) const
  {
    this->add_gap_constraints(interface, fixed_values, constraints, !all_candidates);
  }

  template <int dim>
  void
  AlmFrictionless<dim>::recover_multipliers(const ContactInterface<dim> &interface,
                                            const std::vector<double>   &residual)
  {
    for (const auto &s : interface.slave_nodes)
      {
        if (!s.paired || !this->active[s.node])
          {
            this->pressure[s.node] = 0.;
            continue;
          }
        const unsigned int c   = this->eliminated_component(interface, s);
        const double       r   = residual[interface.position(interface.nodes[s.node].dofs[c])];
        this->pressure[s.node] = -r / (s.D * s.normal[c]);
      }
  }

  template <int dim>
  unsigned int
  AlmFrictionless<dim>::update_active_set(const ContactInterface<dim> &interface,
                                          const std::vector<double>   &u)
  {
    unsigned int changes = 0;
    std::fill(released_pressure.begin(), released_pressure.end(), 0.);
    auto &pressure = this->pressure;
    auto &active   = this->active;
    for (const auto &s : interface.slave_nodes)
      {
        if (!s.paired)
          continue;
        const bool now_active =
          decides_active(s, interface.gap(s, u), false, StepStart::continued) &&
          this->eliminated_component(interface, s) < dim;
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
    double    sum = 0.;
    for (const auto &s : interface.slave_nodes)
      {
        if (!s.paired)
          continue;
        // g = 0 on the active set, lambda = 0 elsewhere (the multiplier of
        // a node released in this update still counts).
        const double r = this->active[s.node] ? interface.gap(s, u) :
                                                released_pressure[s.node] / this->scale[s.pair];
        sum += r * r;
      }
    result.multiplier    = std::sqrt(sum);
    result.contact_force = this->contact_forces(interface);
    return result;
  }

  template class AlmFrictionless<2>;
  template class AlmFrictionless<3>;

  CONTACT_FEM_REGISTER_FORMULATION(AlmFrictionless, "alm frictionless", false, false, false)
} // namespace contact_fem
