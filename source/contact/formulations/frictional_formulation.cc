#include <contact_fem/contact/formulations/frictional_formulation.h>
#include <contact_fem/contact/formulations/penalty_frictionless.h>

#include <algorithm>

namespace contact_fem
{
  template <int dim, class NormalPart>
  void
  FrictionalFormulation<dim, NormalPart>::initialize(const ContactInterface<dim> &interface)
  {
    NormalPart::initialize(interface);
    const unsigned int n = interface.nodes.size();
    tangential.assign(n, TangentialVector<dim>());
    sets.initialize(interface);
    last_step_slip.assign(n, TangentialVector<dim>());
    slip_history.initialize(n);
    converged_displacement.assign(interface.dofs().size(), 0.);
    last_stick_slip_changes = 0;
  }

  template <int dim, class NormalPart>
  bool
  FrictionalFormulation<dim, NormalPart>::slides_everywhere() const
  {
    const bool any_friction = std::any_of(laws.begin(), laws.end(), [](const auto &law) {
      return !law->frictionless();
    });
    return !pure_slip && any_friction && n_stick() == 0 && n_slip() > 0 &&
           n_slip() == this->n_active();
  }

  template <int dim, class NormalPart>
  std::string
  FrictionalFormulation<dim, NormalPart>::iteration_header() const
  {
    return friction_iteration_header();
  }

  template <int dim, class NormalPart>
  std::string
  FrictionalFormulation<dim, NormalPart>::iteration_cells(const unsigned int iteration) const
  {
    return friction_iteration_cells(iteration, n_stick(), n_slip(), last_stick_slip_changes);
  }

  template <int dim, class NormalPart>
  std::vector<typename ContactFormulation<dim>::NodalField>
  FrictionalFormulation<dim, NormalPart>::nodal_fields(const ContactInterface<dim> &interface) const
  {
    return friction_nodal_fields(interface, *this, last_step_slip, slip_history);
  }

  template <int dim, class NormalPart>
  std::vector<int>
  FrictionalFormulation<dim, NormalPart>::contact_sets() const
  {
    return sets.codes(this->active);
  }

  template <int dim, class NormalPart>
  unsigned int
  FrictionalFormulation<dim, NormalPart>::n_stick() const
  {
    return sets.n_stick(this->active);
  }

  template <int dim, class NormalPart>
  unsigned int
  FrictionalFormulation<dim, NormalPart>::n_slip() const
  {
    return sets.n_slip(this->active);
  }

  template <int dim, class NormalPart>
  Json
  FrictionalFormulation<dim, NormalPart>::law_names() const
  {
    Json names = Json::array();
    for (const auto &law : laws)
      names.push(law->description());
    return names;
  }

  template class FrictionalFormulation<2, FrictionlessFormulation<2>>;
  template class FrictionalFormulation<3, FrictionlessFormulation<3>>;
  template class FrictionalFormulation<2, PenaltyFrictionless<2>>;
  template class FrictionalFormulation<3, PenaltyFrictionless<3>>;
} // namespace contact_fem
