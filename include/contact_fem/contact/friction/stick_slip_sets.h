// What the frictional formulations share: which slave nodes carry a
// tangential condition, the weighted slip, and the stick/slip sets.
#ifndef contact_fem_stick_slip_sets_h
#define contact_fem_stick_slip_sets_h

#include <contact_fem/contact/contact_interface.h>

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

  /**
   * The stick/slip sets of the interface nodes: per node the slip sign
   * (0 = stick, +1 / -1 = slip with that sign of the trial traction),
   * meaningful for active nodes, and whether a support holds the node (it
   * then neither sticks nor slips).
   */
  struct StickSlipSets
  {
    std::vector<int>  sign;
    std::vector<bool> held;

    template <int dim>
    void
    initialize(const ContactInterface<dim> &interface)
    {
      sign.assign(interface.nodes.size(), 0);
      held.assign(interface.nodes.size(), false);
      for (unsigned int n = 0; n < held.size(); ++n)
        for (unsigned int d = 0; d < dim; ++d)
          held[n] = held[n] || interface.nodes[n].fixed[d];
    }

    bool
    sticks(const unsigned int n, const std::vector<bool> &active) const
    {
      return active[n] && !held[n] && sign[n] == 0;
    }

    bool
    slips(const unsigned int n, const std::vector<bool> &active) const
    {
      return active[n] && !held[n] && sign[n] != 0;
    }

    unsigned int
    n_stick(const std::vector<bool> &active) const
    {
      unsigned int count = 0;
      for (unsigned int n = 0; n < sign.size(); ++n)
        count += sticks(n, active);
      return count;
    }

    unsigned int
    n_slip(const std::vector<bool> &active) const
    {
      unsigned int count = 0;
      for (unsigned int n = 0; n < sign.size(); ++n)
        count += slips(n, active);
      return count;
    }

    /// One code per node for the detection of a cycling iteration:
    /// 0 inactive, 1 stick, 2 / 3 slip with sign + / -.
    std::vector<int>
    codes(const std::vector<bool> &active) const
    {
      std::vector<int> result(sign.size(), 0);
      for (unsigned int n = 0; n < sign.size(); ++n)
        if (active[n])
          result[n] = sign[n] == 0 ? 1 : (sign[n] > 0 ? 2 : 3);
      return result;
    }
  };
} // namespace contact_fem

#endif
