// One affine constraint of a contact formulation, built term by term.
#ifndef contact_fem_constraint_line_h
#define contact_fem_constraint_line_h

#include <deal.II/lac/affine_constraints.h>

#include <contact_fem/contact/contact_interface.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace contact_fem
{
  /// The free component of slave node @p s that a normal line eliminates:
  /// the one with the largest normal part, dim if none is above 0.1 (a
  /// nearly tangential component cannot carry the line).
  template <int dim>
  unsigned int
  normal_line_component(const ContactInterface<dim>                     &interface,
                        const typename ContactInterface<dim>::SlaveNode &s)
  {
    unsigned int best       = dim;
    double       best_value = 0.1;
    for (unsigned int d = 0; d < dim; ++d)
      if (!interface.nodes[s.node].fixed[d] && std::abs(s.normal[d]) > best_value)
        {
          best       = d;
          best_value = std::abs(s.normal[d]);
        }
    return best;
  }

  /// Whether @p constraints may store a line at some DoF of @p node. The
  /// loops that build lines skip the other slave nodes before reading
  /// their operators: a rank will not hold those (issue 32 item 1).
  template <int dim>
  bool
  may_store_line_of(const typename ContactInterface<dim>::Node &node,
                    const AffineConstraints<double>            &constraints)
  {
    return std::any_of(node.dofs.begin(), node.dofs.end(), [&](const auto dof) {
      return constraints.can_store_line(dof);
    });
  }

  /**
   * A line u_dof = sum coefficient * u + inhomogeneity, built term by term:
   * a Dirichlet DoF moves its value into the inhomogeneity (trial space) or
   * drops out (test space, where test functions vanish).
   */
  struct ConstraintLine
  {
    std::vector<std::pair<types::global_dof_index, double>> entries;
    double                                                  inhomogeneity = 0.;

    /// Adds coefficient * u of component @p d of interface node @p node;
    /// @p fixed_values are the Dirichlet values at the interface DoFs.
    template <int dim>
    void
    add(const typename ContactInterface<dim>::Node &node,
        const unsigned int                          d,
        const double                                coefficient,
        const ContactInterface<dim>                &interface,
        const std::vector<double>                  &fixed_values,
        const bool                                  test = false)
    {
      // Entries at round-off of the unit normal carry no coupling.
      constexpr double negligible = 1e-14;
      if (std::abs(coefficient) < negligible)
        return;
      if (!node.fixed[d])
        entries.emplace_back(node.dofs[d], coefficient);
      else if (!test)
        inhomogeneity += coefficient * fixed_values[interface.position(node.dofs[d])];
    }

    /// Stores the line as the constraint of @p dof.
    void
    store(const types::global_dof_index dof, AffineConstraints<double> &constraints)
    {
      // The same DoF may appear through two master faces: merge entries.
      std::sort(entries.begin(), entries.end());
      std::vector<std::pair<types::global_dof_index, double>> merged;
      for (const auto &e : entries)
        if (!merged.empty() && merged.back().first == e.first)
          merged.back().second += e.second;
        else
          merged.push_back(e);
      constraints.add_line(dof);
      constraints.add_entries(dof, merged);
      constraints.set_inhomogeneity(dof, inhomogeneity);
    }
  };
} // namespace contact_fem

#endif
