#include <contact_fem/contact/formulations/mpc_frictional.h>

#include <algorithm>

namespace contact_fem
{
  template <int dim>
  MpcFrictional<dim>::MpcFrictional(ParameterHandler &prm, const FrictionParameters &friction)
    : AlmFrictional<dim>(
        friction,
        FrictionlessFormulation<dim>::Parameters::parse_without_penalty(prm, "mpc frictional"),
        "mpc",
        current_kinematics(prm))
  {}

  template <int dim>
  TangentialVector<dim>
  MpcFrictional<dim>::stick_or_slip(const SlaveNode             &s,
                                    const double                 p_bound,
                                    const TangentialVector<dim> &xi) const
  {
    const TangentialVector<dim> old      = this->sets.direction[s.node];
    const double                slip     = magnitude<dim>(xi);
    const bool                  moved    = slip > negligible_slip * s.size;
    const bool                  slipping = magnitude<dim>(old) > 0.;
    // Without traction and slip direction the node has just come into
    // contact: if it moved in the step and its bound holds nothing yet
    // (Coulomb at p = 0) it slides in (stuck, it would be pulled back to
    // where it was at the last step, and off again); with a bound (Tresca)
    // it sticks.
    const bool entering = !slipping && magnitude<dim>(this->tangential[s.node]) == 0. &&
                          this->slip_bound(s, std::max(p_bound, 0.)) == 0.;
    if ((slipping || entering) && moved)
      {
        // The traction on the slave opposes its slip; a slip that turns
        // back against the old direction passes through stick.
        const TangentialVector<dim> direction = unit_direction<dim>(-xi, slip);
        if (old * direction < 0. && !this->pure_slip && !this->frictionless_law(s))
          return TangentialVector<dim>();
        return direction;
      }
    // Sticking (or slipping but not moved yet in this step: at its start):
    // the recovered traction against the bound, as the augmented test with
    // a vanishing tangential penalty.
    return this->decide_on_trial(s, p_bound, this->tangential[s.node]);
  }

  template <int dim>
  double
  MpcFrictional<dim>::slip_cone_stiffness(const SlaveNode &s, const TangentialVector<dim> &xi) const
  {
    if (dim == 2 || !this->sets.slips(s.node, this->active) || this->frictionless_law(s))
      return 0.;
    // The derivative of t = -T xi / |xi| across the slip: T / |xi|, capped
    // as alm's at 1e4 times the stiffer side's E / h.
    const double bound   = this->slip_bound(s, std::max(this->pressure[s.node], 0.));
    const double largest = 1e4 * this->penalty[s.pair] * this->stiffness_ratio[s.pair];
    const double slip    = magnitude<dim>(xi);
    return slip * largest > bound ? bound / slip : largest;
  }

  template <int dim>
  void
  MpcFrictional<dim>::add_results(const ContactInterface<dim> &interface, Json &contact) const
  {
    AlmFrictional<dim>::add_results(interface, contact);
    contact.set("penalty", 0.);
  }

  template class MpcFrictional<2>;
  template class MpcFrictional<3>;

  CONTACT_FEM_REGISTER_FORMULATION(MpcFrictional, "mpc frictional", true, false, false)
} // namespace contact_fem
