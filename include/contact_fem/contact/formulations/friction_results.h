// What the frictional formulations report alike: the friction totals of the
// results, their printout, the nodal fields and the Newton table cells.
#ifndef contact_fem_friction_results_h
#define contact_fem_friction_results_h

#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/contact/friction/stick_slip_sets.h>

namespace contact_fem
{
  /// The tangential traction of slave node @p s along the tangent of the
  /// formulation's frame (2D: one component).
  template <int dim>
  double
  frame_tangential_traction(const ContactFormulation<dim>                   &contact,
                            const typename ContactInterface<dim>::SlaveNode &s)
  {
    return contact.traction(s) * ContactFormulation<dim>::tangent(contact.frame_normal(s));
  }

  /// The tangential part of the traction of slave node @p s on the slave,
  /// in the formulation's frame, as a global vector.
  template <int dim>
  Tensor<1, dim>
  tangential_traction_vector(const ContactFormulation<dim>                   &contact,
                             const typename ContactInterface<dim>::SlaveNode &s)
  {
    const Tensor<1, dim> n      = contact.frame_normal(s);
    const Tensor<1, dim> lambda = contact.traction(s);
    return lambda - (lambda * n) * n;
  }

  /// The slip of every interface node summed over the accepted load steps
  /// of the load path: its length (sum of the |slip increments|) and the
  /// accumulated tangential relative displacement (sum of the increments,
  /// as global vectors, so that a turning frame does not mix them up).
  template <int dim>
  struct SlipHistory
  {
    std::vector<double>         length;
    std::vector<Tensor<1, dim>> displacement;

    void
    initialize(const unsigned int n_nodes)
    {
      length.assign(n_nodes, 0.);
      displacement.assign(n_nodes, Tensor<1, dim>());
    }

    /// Adds @p step_slip (per interface node, in the frame of the node's
    /// normal in @p contact) to the sums of the paired nodes whose rows
    /// this rank owns (ContactInterface::owns_row()).
    void
    add(const ContactInterface<dim>              &interface,
        const ContactFormulation<dim>            &contact,
        const std::vector<TangentialVector<dim>> &step_slip)
    {
      for (const auto &s : interface.slave_nodes)
        if (s.paired && interface.owns_row(s))
          {
            length[s.node] += magnitude<dim>(step_slip[s.node]);
            displacement[s.node] += to_global(step_slip[s.node], contact.frame_normal(s));
          }
    }
  };

  /// Adds the totals over the active slave nodes (normal and tangential
  /// contact force, their ratio, the force components, the active length,
  /// the largest tangential traction and the largest slip of the last
  /// accepted step, @p accepted_slip per interface node) to @p result.
  template <int dim>
  void
  add_friction_totals(const ContactInterface<dim>              &interface,
                      const ContactFormulation<dim>            &contact,
                      const std::vector<TangentialVector<dim>> &accepted_slip,
                      const SlipHistory<dim>                   &history,
                      Json                                     &result);

  /// Prints the stick/slip counts and the totals of add_friction_totals()
  /// from @p contact, and the balance per component from @p reaction.
  void
  print_friction_totals(const Json        &contact,
                        const Json        &reaction,
                        const unsigned int dim,
                        std::ostream      &out);

  /// The nodal fields tangential_traction, slip_increment (of the last
  /// accepted step), accumulated_tangential_displacement (in 3D their
  /// global components, tangential_traction_x ...), accumulated_slip (the
  /// path length) and stick.
  template <int dim>
  std::vector<typename ContactFormulation<dim>::NodalField>
  friction_nodal_fields(const ContactInterface<dim>              &interface,
                        const ContactFormulation<dim>            &contact,
                        const std::vector<TangentialVector<dim>> &accepted_slip,
                        const SlipHistory<dim>                   &history);

  /// The stick / slip / stick-slip-change cells of the Newton table.
  std::string
  friction_iteration_header();

  std::string
  friction_iteration_cells(const unsigned int iteration,
                           const unsigned int n_stick,
                           const unsigned int n_slip,
                           const unsigned int changes);
} // namespace contact_fem

#endif
