// The quantities ContactInterface::linearise() differentiates, read from
// the interface after update(), for the unit tests that check the
// linearisation against central differences (contact_interface_linearisation_*).
#ifndef contact_fem_unit_test_linearisation_h
#define contact_fem_unit_test_linearisation_h

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <contact_fem/contact/contact_interface.h>

#include <array>
#include <map>
#include <utility>
#include <vector>

namespace unit_test_linearisation
{
  using namespace dealii;
  using namespace contact_fem;

  /// The quantities of a node: (kind, index), kind gap (index 0), force
  /// or tangent_force + k (tangent k of the frame; index the row DoF),
  /// normal or operators (index the component).
  enum Kind
  {
    gap,
    force,
    normal,
    operators,
    weight, ///< D_j (index 0)
    tangent_force
  };
  using Key = std::pair<int, types::global_dof_index>;

  /// Per paired slave node: the quantities by key, at the last update().
  using Values = std::map<unsigned int, std::map<Key, double>>;

  /// The tangents of the frame of every paired slave node at the
  /// linearisation's configuration.
  template <int dim>
  using Frames = std::map<unsigned int, std::array<Tensor<1, dim>, dim - 1>>;

  template <int dim>
  Values
  values_of(const ContactInterface<dim> &interface,
            const std::vector<double>   &u,
            const Frames<dim>           &frames)
  {
    Values result;
    for (const auto &s : interface.slave_nodes)
      if (s.paired)
        {
          auto &node        = result[s.node];
          node[{gap, 0}]    = s.D * interface.gap(s, u);
          node[{weight, 0}] = s.D;
          const auto x      = [&](const unsigned int n) {
            return interface.nodes[n].reference + interface.displacement(n, u);
          };
          for (unsigned int k = 0; k < dim - 1; ++k)
            {
              // The frame tangent held in the tangent plane of n(u).
              const Tensor<1, dim> &tau = frames.at(s.node)[k];
              const Tensor<1, dim>  t   = tau - (tau * s.normal) * s.normal;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  node[{tangent_force + k, interface.nodes[s.node].dofs[d]}] += s.D * t[d];
                  for (const auto &[m, value] : s.M)
                    node[{tangent_force + k, interface.nodes[m].dofs[d]}] += -value * t[d];
                }
            }
          for (unsigned int d = 0; d < dim; ++d)
            {
              node[{force, interface.nodes[s.node].dofs[d]}] += -s.D * s.normal[d];
              node[{normal, d}]    = s.normal[d];
              node[{operators, d}] = s.D * x(s.node)[d];
              for (const auto &[m, value] : s.M)
                {
                  node[{force, interface.nodes[m].dofs[d]}] += value * s.normal[d];
                  node[{operators, d}] -= value * x(m)[d];
                }
            }
        }
    return result;
  }

  /// The derivative of component @p d of D_j x_j - sum_l M_jl x_l along
  /// @p dof through the positions themselves (the linearisation holds them).
  template <int dim>
  double
  direct_part(const ContactInterface<dim>                     &interface,
              const typename ContactInterface<dim>::SlaveNode &s,
              const unsigned int                               d,
              const types::global_dof_index                    dof)
  {
    double result = interface.nodes[s.node].dofs[d] == dof ? s.D : 0.;
    for (const auto &[m, value] : s.M)
      if (interface.nodes[m].dofs[d] == dof)
        result -= value;
    return result;
  }

  /// Central differences at step @p h of every entry of values_of() along
  /// each of @p directions (positions in the interface vector @p u; @p
  /// conform moves the DoFs that follow a perturbed one), by entry and DoF;
  /// and whether every perturbed configuration found the face pairs @p
  /// coupled.
  template <int dim, typename Conform>
  std::pair<std::map<std::pair<unsigned int, Key>, std::map<types::global_dof_index, double>>, bool>
  central_differences(const ContactInterface<dim>                              &interface,
                      const std::vector<double>                                &u,
                      const std::vector<unsigned int>                          &directions,
                      const Frames<dim>                                        &frames,
                      const std::vector<std::pair<unsigned int, unsigned int>> &coupled,
                      const double                                              h,
                      const Conform                                            &conform)
  {
    std::map<std::pair<unsigned int, Key>, std::map<types::global_dof_index, double>> result;
    bool same_pairs = true;
    for (const unsigned int i : directions)
      {
        std::array<Values, 2> at;
        for (const int side : {0, 1})
          {
            std::vector<double> v = u;
            v[i] += side == 0 ? h : -h;
            conform(v);
            ContactInterface<dim> moved = interface;
            moved.update(v, 3.);
            same_pairs = same_pairs && moved.coupled_faces == coupled;
            at[side]   = values_of(moved, v, frames);
          }
        for (const auto &[n, entries] : at[0])
          for (const auto &[key, value] : entries)
            result[{n, key}][interface.dofs()[i]] = (value - at[1][n][key]) / (2. * h);
      }
    return std::make_pair(result, same_pairs);
  }

} // namespace unit_test_linearisation

#endif
