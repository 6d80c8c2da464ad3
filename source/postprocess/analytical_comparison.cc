#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/postprocess/analytical_comparison.h>
#include <contact_fem/simulator/scene_parameters.h>

#include <cmath>
#include <map>

namespace contact_fem
{
  namespace
  {
    /// The comparisons by name, filled by the registrations at load time
    /// (a function's static: whatever the order of the files' initialisation).
    template <int dim>
    std::map<std::string, typename AnalyticalComparison<dim>::Factory> &
    comparisons()
    {
      static std::map<std::string, typename AnalyticalComparison<dim>::Factory> registry;
      return registry;
    }
  } // namespace

  template <int dim>
  Point<dim>
  ContactState<dim>::position(const unsigned int node) const
  {
    return interface.nodes[node].reference + interface.displacement(node, displacement);
  }

  template <int dim>
  Tensor<1, dim>
  ContactState<dim>::contact_force() const
  {
    Tensor<1, dim> force;
    for (const auto &s : interface.slave_nodes)
      if (s.paired && contact.is_active(s.node))
        {
          if (contact.transmits_shear())
            force -= s.D * contact.traction(s);
          else
            force += contact.normal_pressure(s.node) * s.D * s.normal;
        }
    return force;
  }

  template <int dim>
  double
  pressure_l2_relative_error(const ContactState<dim>                         &state,
                             const std::vector<double>                       &pressure,
                             const std::function<double(const Point<dim> &)> &exact)
  {
    double l2_error = 0., l2_norm = 0.;
    for (const auto &s : state.interface.slave_nodes)
      if (s.paired)
        {
          const double p_exact = exact(state.position(s.node));
          l2_error += s.D * std::pow(pressure[s.node] - p_exact, 2);
          l2_norm += s.D * p_exact * p_exact;
        }
    return l2_norm > 0. ? std::sqrt(l2_error / l2_norm) : 0.;
  }

  template <int dim>
  void
  AnalyticalComparison<dim>::register_comparison(const std::string &name, const Factory &factory)
  {
    comparisons<dim>()[name] = factory;
  }

  template <int dim>
  std::unique_ptr<AnalyticalComparison<dim>>
  AnalyticalComparison<dim>::create(const AnalyticalSolution &analytical)
  {
    if (analytical.type == "none")
      return nullptr;
    const auto entry = comparisons<dim>().find(analytical.type);
    // The parameter's pattern admits registered names only.
    AssertThrow(entry != comparisons<dim>().end(),
                ExcMessage("Analytical solution/Type: no comparison called '" + analytical.type +
                           "' is registered"));
    return entry->second(analytical);
  }

  template struct ContactState<2>;
  template struct ContactState<3>;
  template class AnalyticalComparison<2>;
  template class AnalyticalComparison<3>;
  template double
  pressure_l2_relative_error(const ContactState<2> &,
                             const std::vector<double> &,
                             const std::function<double(const Point<2> &)> &);
  template double
  pressure_l2_relative_error(const ContactState<3> &,
                             const std::vector<double> &,
                             const std::function<double(const Point<3> &)> &);
} // namespace contact_fem
