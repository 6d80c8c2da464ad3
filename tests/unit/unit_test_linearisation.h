// The quantities ContactInterface::linearise() differentiates, read from
// the interface after update(), for the unit tests that check the
// linearisation against central differences (contact_interface_linearisation_*).
#ifndef contact_fem_unit_test_linearisation_h
#define contact_fem_unit_test_linearisation_h

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <contact_fem/contact/contact_interface.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <string>
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

  /// Central differences by (node, key) and DoF.
  using Differences =
    std::map<std::pair<unsigned int, Key>, std::map<types::global_dof_index, double>>;

  /// Central differences at step @p h of every entry of @p values (of the
  /// interface updated to a configuration, and that configuration) along
  /// each of @p directions (positions in the interface vector @p u; @p
  /// conform moves the DoFs that follow a perturbed one), by entry and DoF;
  /// and whether every perturbed configuration found the face pairs @p
  /// coupled.
  template <int dim, typename Conform, typename ValuesOf>
  std::pair<Differences, bool>
  central_differences(const ContactInterface<dim>                              &interface,
                      const std::vector<double>                                &u,
                      const std::vector<unsigned int>                          &directions,
                      const std::vector<std::pair<unsigned int, unsigned int>> &coupled,
                      const double                                              h,
                      const Conform                                            &conform,
                      const ValuesOf                                           &values)
  {
    Differences result;
    bool        same_pairs = true;
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
            at[side]   = values(moved, v);
          }
        for (const auto &[n, entries] : at[0])
          for (const auto &[key, value] : entries)
            result[{n, key}][interface.dofs()[i]] = (value - at[1][n][key]) / (2. * h);
      }
    return std::make_pair(result, same_pairs);
  }

  /// The same for the entries of values_of() in @p frames.
  template <int dim, typename Conform>
  std::pair<Differences, bool>
  central_differences(const ContactInterface<dim>                              &interface,
                      const std::vector<double>                                &u,
                      const std::vector<unsigned int>                          &directions,
                      const Frames<dim>                                        &frames,
                      const std::vector<std::pair<unsigned int, unsigned int>> &coupled,
                      const double                                              h,
                      const Conform                                            &conform)
  {
    return central_differences(interface, u, directions, coupled, h, conform,
                               [&](const ContactInterface<dim> &moved,
                                   const std::vector<double>   &v) {
                                 return values_of(moved, v, frames);
                               });
  }

  /// How the differences at h (@p coarse), h / 2 (@p fine) and a small
  /// step (@p tight) meet the analytic derivatives.
  struct Verdict
  {
    /// At the small step, every error below 1e-6 of its entry's scale (the
    /// node's largest derivative of that entry).
    bool small = true;
    /// Beyond round-off (error above 1e-7), the error falls by 4 from h to
    /// h / 2.
    bool second_order = true;
    /// Outside the node's patch the differences vanish (no coupling
    /// missed).
    bool   complete = true;
    double worst    = 0.;
    /// The largest scale of each kind of entry.
    std::map<int, double> largest;

    /// The verdict's lines, with whether every perturbed configuration
    /// kept the face pairs (@p same_pairs) and what was differenced (@p
    /// what).
    void
    print(const bool same_pairs, const std::string &what) const
    {
      const auto yes = [](const bool b) {
        return b ? "yes" : "no";
      };
      std::cout << "  same face pairs at every perturbed configuration: " << yes(same_pairs)
                << std::endl
                << "  " << what
                << " against central differences, error below 1e-6 of the node's largest "
                   "derivative: "
                << yes(small) << std::endl
                << "  error falling at second order (or round-off): " << yes(second_order)
                << std::endl
                << "  no coupling outside the node's patch: " << yes(complete) << std::endl;
      if (!small)
        std::cout << "  largest error " << worst << std::endl;
    }
  };

  /// The verdict on the differences of the linearised nodes of @p
  /// interface against @p analytic(node, key, dof).
  template <int dim, typename Analytic>
  Verdict
  judge(const ContactInterface<dim> &interface,
        const Differences           &coarse,
        const Differences           &fine,
        const Differences           &tight,
        const Analytic              &analytic)
  {
    Verdict verdict;
    for (const auto &[entry, by_dof] : coarse)
      {
        const auto &node  = interface.linearised_nodes.at(entry.first);
        double      scale = 0.;
        for (const auto &[dof, value] : by_dof)
          scale = std::max(scale, std::abs(analytic(entry.first, entry.second, dof)));
        double &largest = verdict.largest[entry.second.first];
        largest         = std::max(largest, scale);
        for (const auto &[dof, value] : by_dof)
          {
            const double exact = analytic(entry.first, entry.second, dof);
            const double e1    = std::abs(value - exact) / scale;
            const double e2    = std::abs(fine.at(entry).at(dof) - exact) / scale;
            const double e3    = std::abs(tight.at(entry).at(dof) - exact) / scale;
            const bool   inside =
              std::find(node.dofs.begin(), node.dofs.end(), dof) != node.dofs.end();
            verdict.complete =
              verdict.complete && (inside || std::abs(value - exact) < 1e-10 * scale);
            verdict.small = verdict.small && e3 < 1e-6;
            verdict.worst = std::max(verdict.worst, e3);
            if (e1 > 1e-7)
              verdict.second_order = verdict.second_order && e1 / e2 > 3.5 && e1 / e2 < 4.5;
          }
      }
    return verdict;
  }

} // namespace unit_test_linearisation

#endif
