// The comparison of a run with an analytical solution (Analytical
// solution/Type), one plug-in per solution: each registers itself by name
// in its own file (hertz_comparison.cc, cattaneo_comparison.cc), so that a
// new benchmark is one new file and the driver never asks which one runs.
#ifndef contact_fem_analytical_comparison_h
#define contact_fem_analytical_comparison_h

#include <deal.II/base/point.h>

#include <contact_fem/core/json.h>

#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  template <int dim>
  class ContactInterface;
  template <int dim>
  class ContactFormulation;
  struct AnalyticalSolution;

  /// The converged contact state a comparison reads (read only).
  template <int dim>
  struct ContactState
  {
    const ContactInterface<dim>   &interface;
    const ContactFormulation<dim> &contact;
    /// The displacement of every interface node (ContactInterface::gather()).
    const std::vector<double> &displacement;

    /// The deformed position of interface node @p node.
    Point<dim>
    position(const unsigned int node) const;
    /// The resultant of the contact tractions on the slave side, from the
    /// rows each rank owns summed in node order: the same on every rank.
    /// Collective.
    Tensor<1, dim>
    contact_force() const;
  };

  /**
   * Relative L2 error of a pressure per interface node against @p exact(x)
   * over the paired slave nodes, with the mortar weights D_j as nodal
   * quadrature weights, at the deformed positions x of the nodes:
   *   sqrt(sum D_j (p_j - p(x_j))^2 / sum D_j p(x_j)^2).
   * Each rank reads @p pressure at the nodes whose rows it owns; the sums
   * go in node order (ContactInterface::sum_in_node_order()). Collective.
   */
  template <int dim>
  double
  pressure_l2_relative_error(const ContactState<dim>                         &state,
                             const std::vector<double>                       &pressure,
                             const std::function<double(const Point<dim> &)> &exact);

  template <int dim>
  class AnalyticalComparison
  {
  public:
    explicit AnalyticalComparison(const AnalyticalSolution &analytical)
      : analytical(analytical)
    {}
    virtual ~AnalyticalComparison() = default;

    /// A cycle starts its load path (from the unloaded state or from the
    /// transferred solution).
    virtual void
    start_load_path()
    {}
    /// A load step of the path converged at @p state (a solution that
    /// depends on the load history records it).
    virtual void
    record_load_step(const ContactState<dim> &state)
    {
      (void)state;
    }

    /// The cycle's "analytical" record of the converged @p state: the exact
    /// values and the errors. @p contact and @p reaction are the cycle's
    /// records of the same names.
    virtual Json
    compare(const ContactState<dim> &state, const Json &contact, const Json &reaction) const = 0;

    /// Prints compare()'s @p record (with the results of the cycle).
    virtual void
    print(const Json &record, std::ostream &out) const = 0;

    /// The exact contact pressure at a deformed position, or an empty
    /// function if the solution gives none.
    virtual std::function<double(const Point<dim> &)>
    exact_pressure(const ContactState<dim> &state) const
    {
      (void)state;
      return {};
    }

    /// The errors of a recovered traction (SPR): @p pressure and the
    /// tangential traction @p tangential per interface node. Prints lines
    /// that start with @p label, records keys prefixed with @p prefix.
    virtual void
    report_recovered(const ContactState<dim>   &state,
                     const std::vector<double> &pressure,
                     const std::vector<double> &tangential,
                     const std::string         &label,
                     const std::string         &prefix,
                     Json                      &record,
                     std::ostream              &out) const = 0;

    using Factory =
      std::function<std::unique_ptr<AnalyticalComparison<dim>>(const AnalyticalSolution &)>;
    /// Adds the comparison called @p name (the value of Analytical
    /// solution/Type); see CONTACT_FEM_REGISTER_ANALYTICAL_COMPARISON.
    static void
    register_comparison(const std::string &name, const Factory &factory);
    /// The comparison of @p analytical's type, or null for "none".
    static std::unique_ptr<AnalyticalComparison<dim>>
    create(const AnalyticalSolution &analytical);

  protected:
    const AnalyticalSolution &analytical;
  };

  /// Registers class template @p classname (an AnalyticalComparison<dim>
  /// for dim 2 and 3) under @p name when the library is loaded.
#define CONTACT_FEM_REGISTER_ANALYTICAL_COMPARISON(classname, name)                        \
  namespace                                                                                \
  {                                                                                        \
    const bool classname##_registered = [] {                                               \
      AnalyticalComparison<2>::register_comparison(name, [](const AnalyticalSolution &a) { \
        return std::make_unique<classname<2>>(a);                                          \
      });                                                                                  \
      AnalyticalComparison<3>::register_comparison(name, [](const AnalyticalSolution &a) { \
        return std::make_unique<classname<3>>(a);                                          \
      });                                                                                  \
      return true;                                                                         \
    }();                                                                                   \
  }
} // namespace contact_fem

#endif
