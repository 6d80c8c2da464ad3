// What the frictional formulations share: which slave nodes carry a
// tangential condition, the weighted slip, and the stick/slip sets.
#ifndef contact_fem_stick_slip_sets_h
#define contact_fem_stick_slip_sets_h

#include <deal.II/base/tensor.h>

#include <contact_fem/contact/contact_interface.h>

#include <array>
#include <cmath>
#include <vector>

namespace contact_fem
{
  /// The Dirichlet component of interface node @p node if a support fixes
  /// exactly one (3D; a roller on a symmetry plane): it holds one
  /// tangential direction only, and the other carries friction
  /// (free_tangent()). dim otherwise (2D: the one tangent is held).
  template <int dim>
  unsigned int
  partly_held_component(const typename ContactInterface<dim>::Node &node)
  {
    unsigned int fixed = dim, count = 0;
    for (unsigned int d = 0; d < dim; ++d)
      if (node.fixed[d])
        {
          fixed = d;
          ++count;
        }
    return dim == 3 && count == 1 ? fixed : dim;
  }

  /// Whether slave node @p s carries a tangential condition: paired, and no
  /// Dirichlet component (a support holds it tangentially), or in 3D one
  /// (partly_held_component(): friction along free_tangent()).
  template <int dim>
  bool
  carries_friction(const ContactInterface<dim>                     &interface,
                   const typename ContactInterface<dim>::SlaveNode &s)
  {
    if (!s.paired)
      return false;
    const auto &node = interface.nodes[s.node];
    if (partly_held_component<dim>(node) < dim)
      return true;
    for (unsigned int d = 0; d < dim; ++d)
      if (node.fixed[d])
        return false;
    return true;
  }

  /// The tangent direction a support that fixes component @p f leaves free
  /// at a node with unit normal @p n (3D): n x e_f, in the tangent plane
  /// and normal to e_f (on a symmetry plane whose node normal tilts off it
  /// by ~h / 2R, the in-plane tangent turned into the tangent plane).
  template <int dim>
  Tensor<1, dim>
  free_tangent(const Tensor<1, dim> &n, const unsigned int f)
  {
    Tensor<1, dim> result;
    if constexpr (dim == 3)
      {
        Tensor<1, dim> axis;
        axis[f] = 1.;
        result  = cross_product_3d(n, axis);
        result /= result.norm();
      }
    return result;
  }

  /// The weighted relative displacement of slave node @p s from the
  /// interface displacement @p from to @p to: du_j - sum_l M_jl / D_j du_l,
  /// the slave relative to its mortar image on the master.
  template <int dim>
  Tensor<1, dim>
  weighted_relative_displacement(const ContactInterface<dim>                     &interface,
                                 const typename ContactInterface<dim>::SlaveNode &s,
                                 const std::vector<double>                       &from,
                                 const std::vector<double>                       &to)
  {
    Tensor<1, dim> relative =
      interface.displacement(s.node, to) - interface.displacement(s.node, from);
    for (const auto &[m, value] : s.M)
      relative -= (value / s.D) * (interface.displacement(m, to) - interface.displacement(m, from));
    return relative;
  }

  /// The weighted slip of slave node @p s along @p tau:
  /// tau . weighted_relative_displacement().
  template <int dim>
  double
  weighted_slip(const ContactInterface<dim>                     &interface,
                const typename ContactInterface<dim>::SlaveNode &s,
                const std::vector<double>                       &from,
                const std::vector<double>                       &to,
                const Tensor<1, dim>                            &tau)
  {
    return weighted_relative_displacement(interface, s, from, to) * tau;
  }

  /// A tangential quantity of a node (traction, slip, slip direction): its
  /// dim - 1 components in the node's tangent frame (tangent_frame()); in
  /// 2D one, along ContactFormulation::tangent().
  template <int dim>
  using TangentialVector = Tensor<1, dim - 1>;

  /**
   * The orthonormal tangents of the frame of a node with unit normal @p n.
   * 2D: the normal turned counterclockwise (ContactFormulation::tangent()).
   * 3D: tau_1 = the x axis projected onto the tangent plane (the y axis
   * where n is within 37 degrees of +-x), tau_2 = n x tau_1. The frame only
   * stores the components of a node's tangential state, which is isotropic
   * (Coulomb's disc), so no result depends on this choice; it is a fixed
   * function of n, so a node keeps its frame while its normal does.
   */
  template <int dim>
  std::array<Tensor<1, dim>, dim - 1>
  tangent_frame(const Tensor<1, dim> &n)
  {
    std::array<Tensor<1, dim>, dim - 1> frame;
    if constexpr (dim == 2)
      {
        frame[0][0] = -n[1];
        frame[0][1] = n[0];
      }
    else
      {
        Tensor<1, dim> axis;
        axis[std::abs(n[0]) > 0.8 ? 1 : 0] = 1.;
        frame[0]                           = axis - (axis * n) * n;
        frame[0] /= frame[0].norm();
        frame[1] = cross_product_3d(n, frame[0]);
      }
    return frame;
  }

  /// The global vector of the tangential quantity @p t of a node with unit
  /// normal @p n.
  template <int dim>
  Tensor<1, dim>
  to_global(const TangentialVector<dim> &t, const Tensor<1, dim> &n)
  {
    const auto     frame = tangent_frame(n);
    Tensor<1, dim> result;
    for (unsigned int k = 0; k < dim - 1; ++k)
      result += t[k] * frame[k];
    return result;
  }

  /// The components of @p v in the tangent frame of unit normal @p n (its
  /// normal part drops out).
  template <int dim>
  TangentialVector<dim>
  to_frame(const Tensor<1, dim> &v, const Tensor<1, dim> &n)
  {
    const auto            frame = tangent_frame(n);
    TangentialVector<dim> result;
    for (unsigned int k = 0; k < dim - 1; ++k)
      result[k] = v * frame[k];
    return result;
  }

  /// The part of the tangential vector @p t (in tangent_frame(@p n)) along
  /// free_tangent(@p n, @p f), the direction a support fixing component
  /// @p f leaves free; @p t for @p f = dim (no such support).
  template <int dim>
  TangentialVector<dim>
  free_part(const TangentialVector<dim> &t, const Tensor<1, dim> &n, const unsigned int f)
  {
    if (f == dim)
      return t;
    const TangentialVector<dim> free = to_frame(free_tangent(n, f), n);
    return (t * free) * free;
  }

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

  /// The unit direction of the trial traction @p trial of length @p size
  /// (2D: its sign, + for zero; 3D: the first tangent for zero), divided
  /// component by component: Tensor / double multiplies by the reciprocal,
  /// which leaves a 2D sign 1 - 1 ulp.
  template <int dim>
  TangentialVector<dim>
  unit_direction(const TangentialVector<dim> &trial, const double size)
  {
    TangentialVector<dim> direction;
    for (unsigned int k = 0; k < dim - 1; ++k)
      direction[k] = size > 0. ? trial[k] / size : (k == 0 ? 1. : 0.);
    return direction;
  }

  /// Whether a node's stick/slip state changed from @p old to @p now: in
  /// 2D any change of the sign, in 3D only stick <-> slip (the direction
  /// turns continuously and the Newton iteration linearises it).
  template <int dim>
  bool
  stick_slip_changed(const TangentialVector<dim> &old, const TangentialVector<dim> &now)
  {
    if constexpr (dim == 2)
      return now != old;
    else
      return (now.norm_square() == 0.) != (old.norm_square() == 0.);
  }

  /**
   * The stick/slip sets of the interface nodes: per node the slip direction
   * of the trial traction (zero = stick; in 2D +1 / -1), meaningful for
   * active nodes, and whether a support holds the node (it then neither
   * sticks nor slips; not a node a support holds along one tangential
   * direction only, whose slip direction is then along free_tangent(),
   * partly_held_component()).
   */
  template <int dim>
  struct StickSlipSets
  {
    std::vector<TangentialVector<dim>> direction;
    std::vector<bool>                  held;
    /// partly_held_component() of the nodes not held, dim for the others.
    std::vector<unsigned int> held_component;

    void
    initialize(const ContactInterface<dim> &interface)
    {
      direction.assign(interface.nodes.size(), TangentialVector<dim>());
      held.assign(interface.nodes.size(), false);
      held_component.assign(interface.nodes.size(), dim);
      for (unsigned int n = 0; n < held.size(); ++n)
        {
          for (unsigned int d = 0; d < dim; ++d)
            held[n] = held[n] || interface.nodes[n].fixed[d];
          if (partly_held_component<dim>(interface.nodes[n]) < dim)
            {
              held[n]           = false;
              held_component[n] = partly_held_component<dim>(interface.nodes[n]);
            }
        }
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

    /// One code per node for the detection of a cycling iteration:
    /// 0 inactive, 1 stick, 2 / 3 slip along + / - the tangent (2D); in 3D
    /// 2 for slip in any direction (the direction turns continuously, and
    /// the Newton iteration linearises it).
    std::vector<int>
    codes(const std::vector<bool> &active) const
    {
      std::vector<int> result(direction.size(), 0);
      for (unsigned int n = 0; n < direction.size(); ++n)
        if (active[n])
          result[n] =
            direction[n].norm_square() == 0. ? 1 : (dim == 3 || direction[n][0] > 0 ? 2 : 3);
      return result;
    }
  };
} // namespace contact_fem

#endif
