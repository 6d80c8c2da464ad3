#include <contact_fem/contact/formulations/mpc_frictionless.h>

namespace contact_fem
{
  template <int dim>
  MpcFrictionless<dim>::MpcFrictionless(ParameterHandler &prm)
    : AlmFrictionless<dim>(
        FrictionlessFormulation<dim>::Parameters::parse_without_penalty(prm, "mpc frictionless"),
        current_kinematics(prm))
  {}

  template <int dim>
  bool
  MpcFrictionless<dim>::decides_active(const typename ContactInterface<dim>::SlaveNode &s,
                                       const double                                     g,
                                       const bool      at_step_start,
                                       const StepStart start) const
  {
    return this->reaction_rule(s, g, at_step_start, start);
  }

  template <int dim>
  void
  MpcFrictionless<dim>::add_results(const ContactInterface<dim> &interface, Json &contact) const
  {
    AlmFrictionless<dim>::add_results(interface, contact);
    contact.set("penalty", 0.);
  }

  template class MpcFrictionless<2>;
  template class MpcFrictionless<3>;

  CONTACT_FEM_REGISTER_FORMULATION(MpcFrictionless, "mpc frictionless", false, false, false)
} // namespace contact_fem
