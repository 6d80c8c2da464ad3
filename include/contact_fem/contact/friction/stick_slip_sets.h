// What the frictional formulations share: which slave nodes carry a
// tangential condition, the weighted slip, and the stick/slip sets.
#ifndef contact_fem_stick_slip_sets_h
#define contact_fem_stick_slip_sets_h

#include <contact_fem/contact/contact_interface.h>

#include <cmath>
#include <vector>

namespace contact_fem
{
  /// Whether slave node @p s carries a tangential condition: paired, and no
  /// Dirichlet component (a support holds it tangentially).
  template <int dim>
  bool
  carries_friction(const ContactInterface<dim>                     &interface,
                   const typename ContactInterface<dim>::SlaveNode &s)
  {
    if (!s.paired)
      return false;
    for (unsigned int d = 0; d < dim; ++d)
      if (interface.nodes[s.node].fixed[d])
        return false;
    return true;
  }

  /// The weighted slip of slave node @p s along @p tau from the interface
  /// displacement @p from to @p to: tau . (du_j - sum_l M_jl / D_j du_l),
  /// the slave relative to its mortar image on the master.
  template <int dim>
  double
  weighted_slip(const ContactInterface<dim>                     &interface,
                const typename ContactInterface<dim>::SlaveNode &s,
                const std::vector<double>                       &from,
                const std::vector<double>                       &to,
                const Tensor<1, dim>                            &tau)
  {
    Tensor<1, dim> relative =
      interface.displacement(s.node, to) - interface.displacement(s.node, from);
    for (const auto &[m, value] : s.M)
      relative -=
        (value / s.D) * (interface.displacement(m, to) - interface.displacement(m, from));
    return relative * tau;
  }

  /// A tangential quantity of a node (traction, slip, slip direction): its
  /// dim - 1 components in the node's tangent frame; in 2D one, along
  /// ContactFormulation::tangent().
  template <int dim>
  using TangentialVector = Tensor<1, dim - 1>;

  /// The magnitude of @p t (in 2D |t[0]|, exactly).
  template <int dim>
  double
  magnitude(const TangentialVector<dim> &t)
  {
    if constexpr (dim == 2)
      return std::abs(t[0]);
    else
      return t.norm();
  }

  /**
   * The stick/slip sets of the interface nodes: per node the slip direction
   * of the trial traction (zero = stick; in 2D +1 / -1), meaningful for
   * active nodes, and whether a support holds the node (it then neither
   * sticks nor slips).
   */
  template <int dim>
  struct StickSlipSets
  {
    std::vector<TangentialVector<dim>> direction;
    std::vector<bool>                  held;

    void
    initialize(const ContactInterface<dim> &interface)
    {
      direction.assign(interface.nodes.size(), TangentialVector<dim>());
      held.assign(interface.nodes.size(), false);
      for (unsigned int n = 0; n < held.size(); ++n)
        for (unsigned int d = 0; d < dim; ++d)
          held[n] = held[n] || interface.nodes[n].fixed[d];
    }

    bool
    sticks(const unsigned int n, const std::vector<bool> &active) const
    {
      return active[n] && !held[n] && direction[n].norm_square() == 0.;
    }

    bool
    slips(const unsigned int n, const std::vector<bool> &active) const
    {
      return active[n] && !held[n] && direction[n].norm_square() != 0.;
    }

    unsigned int
    n_stick(const std::vector<bool> &active) const
    {
      unsigned int count = 0;
      for (unsigned int n = 0; n < direction.size(); ++n)
        count += sticks(n, active);
      return count;
    }

    unsigned int
    n_slip(const std::vector<bool> &active) const
    {
      unsigned int count = 0;
      for (unsigned int n = 0; n < direction.size(); ++n)
        count += slips(n, active);
      return count;
    }

    /// One code per node for the detection of a cycling iteration:
    /// 0 inactive, 1 stick, 2 / 3 slip along + / - the first tangent.
    std::vector<int>
    codes(const std::vector<bool> &active) const
    {
      std::vector<int> result(direction.size(), 0);
      for (unsigned int n = 0; n < direction.size(); ++n)
        if (active[n])
          result[n] = direction[n].norm_square() == 0. ? 1 : (direction[n][0] > 0 ? 2 : 3);
      return result;
    }
  };
} // namespace contact_fem

#endif
