#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/postprocess/analytical_comparison.h>
#include <contact_fem/postprocess/owned_rows.h>
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
    // Each rank the nodes whose rows it owns, summed in node order.
    std::vector<std::pair<unsigned int, Tensor<1, dim>>> terms;
    for (unsigned int k = 0; k < interface.slave_nodes.size(); ++k)
      if (const auto &s = interface.slave_nodes[k];
          s.paired && interface.owns_row(s) && contact.is_active(s.node))
        terms.emplace_back(k, contact.transmits_shear() ?
                                -(s.D * contact.traction(s)) :
                                contact.normal_pressure(s.node) * s.D * s.normal);
    return sum_in_node_order(interface, terms);
  }

  template <int dim>
  double
  pressure_l2_relative_error(const ContactState<dim>                         &state,
                             const std::vector<double>                       &pressure,
                             const std::function<double(const Point<dim> &)> &exact)
  {
    // Each rank the nodes whose rows it owns; the sums (of terms >= 0) in
    // node order.
    const ContactInterface<dim>                 &interface = state.interface;
    std::vector<std::pair<unsigned int, double>> errors, norms;
    for (unsigned int k = 0; k < interface.slave_nodes.size(); ++k)
      if (const auto &s = interface.slave_nodes[k]; s.paired && interface.owns_row(s))
        {
          const double p_exact = exact(state.position(s.node));
          errors.emplace_back(k, s.D * std::pow(pressure[s.node] - p_exact, 2));
          norms.emplace_back(k, s.D * p_exact * p_exact);
        }
    const double l2_error = interface.sum_in_node_order(errors);
    const double l2_norm  = interface.sum_in_node_order(norms);
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
