#include <contact_fem/contact/formulations/mpc_frictionless.h>

namespace contact_fem
{
  namespace
  {
    /// The normal keys of @p formulation, an exact-gap formulation without
    /// a penalty: a given Contact/Penalty would be ignored, so it is refused.
    template <int dim>
    typename FrictionlessFormulation<dim>::Parameters
    parse_without_penalty(ParameterHandler &prm, const std::string &formulation)
    {
      const auto parameters =
        FrictionlessFormulation<dim>::Parameters::parse_for_exact_gap(prm, formulation);
      AssertThrow(parameters.penalty == 0.,
                  ExcMessage("Contact/Penalty is set, but Contact/Formulation = " + formulation +
                             " has no penalty: its active set comes from the recovered "
                             "reactions (released in tension) and the gap (activated on "
                             "penetration). Leave Contact/Penalty = auto."));
      return parameters;
    }
  } // namespace

  template <int dim>
  MpcFrictionless<dim>::MpcFrictionless(ParameterHandler &prm)
    : AlmFrictionless<dim>(parse_without_penalty<dim>(prm, "mpc frictionless"))
  {}

  template <int dim>
  bool
  MpcFrictionless<dim>::decides_active(const typename ContactInterface<dim>::SlaveNode &s,
                                       const double                                     g,
                                       const bool at_step_start,
                                       const bool first_step) const
  {
    const bool compressed = this->active[s.node] && this->pressure[s.node] > 0.;
    if (at_step_start)
      return compressed || g < 0. ||
             (first_step && g <= this->parameters.active_check_factor * s.size);
    // An active node's gap is held at zero: only its reaction can release
    // it; an inactive node carries no pressure: only its gap can take it in.
    return this->active[s.node] ? compressed : g < 0.;
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
