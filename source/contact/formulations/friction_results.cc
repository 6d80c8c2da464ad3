#include <deal.II/base/mpi.h>

#include <contact_fem/contact/formulations/friction_results.h>
#include <contact_fem/core/format.h>
#include <contact_fem/postprocess/owned_rows.h>

#include <iomanip>
#include <sstream>

namespace contact_fem
{
  template <int dim>
  void
  add_friction_totals(const ContactInterface<dim>              &interface,
                      const ContactFormulation<dim>            &contact,
                      const std::vector<TangentialVector<dim>> &accepted_slip,
                      const SlipHistory<dim>                   &history,
                      Json                                     &result)
  {
    // Totals over the active slave nodes of the force the slave exerts on
    // the master, split along each node's own normal and tangent (2D); in
    // 3D the tangential force is the length of the sum of the tangential
    // tractions (on the slave) times D_j, also given by its components.
    // Each rank the rows it owns: the sums (signed ones too) in node order
    // (sum_in_node_order(): an MPI sum would change their last bits), the
    // maxima reduced exactly.
    double t_max = 0., slip_max = 0.;
    // 3D: the part of tangential_force along the component a support fixes
    // at the nodes it holds in one direction only (a roller on a symmetry
    // plane). It pushes the slave node against its support and the master
    // across the plane: by mirror symmetry the contact traction of the
    // whole body has none. "alm frictional" keeps its stick nodes' gap
    // force along the slave normal, whose one-sided average tilts off the
    // plane by ~h / 2R; "penalty frictional" has none (doc/design.md,
    // "Kinematics = updated").
    std::vector<std::pair<unsigned int, double>>         lengths, normals, tangentials;
    std::vector<std::pair<unsigned int, Tensor<1, dim>>> forces, tangential_forces, held_forces;
    for (unsigned int k = 0; k < interface.slave_nodes.size(); ++k)
      if (const auto &s = interface.slave_nodes[k];
          s.paired && interface.owns_row(s) && contact.is_active(s.node))
        {
          const Tensor<1, dim> lambda   = contact.traction(s);
          const Tensor<1, dim> t_vector = tangential_traction_vector(contact, s);
          const double t = dim == 2 ? frame_tangential_traction(contact, s) : t_vector.norm();
          normals.emplace_back(k, s.D * contact.normal_pressure(s.node));
          tangentials.emplace_back(k, s.D * t);
          tangential_forces.emplace_back(k, s.D * t_vector);
          if (const unsigned int f = partly_held_component<dim>(interface.nodes[s.node]); f < dim)
            {
              // Only component f: the others' sums stay +0.
              Tensor<1, dim> held;
              held[f] = s.D * t_vector[f];
              held_forces.emplace_back(k, held);
            }
          forces.emplace_back(k, -(s.D * lambda));
          lengths.emplace_back(k, s.D);
          t_max    = std::max(t_max, std::abs(t));
          slip_max = std::max(slip_max, magnitude<dim>(accepted_slip[s.node]));
        }
    const double         length = interface.sum_in_node_order(lengths);
    const double         normal = interface.sum_in_node_order(normals);
    const Tensor<1, dim> force  = sum_in_node_order(interface, forces);
    // 2D: the tangential force along each node's tangent; 3D: the length of
    // the summed vectors (below).
    double         tangential = dim == 2 ? interface.sum_in_node_order(tangentials) : 0.;
    Tensor<1, dim> tangential_force, held_force;
    if (dim == 3)
      {
        tangential_force = sum_in_node_order(interface, tangential_forces);
        held_force       = sum_in_node_order(interface, held_forces);
      }
    // Over every paired node: one that slid out of contact keeps its slip.
    double accumulated_max = 0.;
    for (const auto &s : interface.slave_nodes)
      if (s.paired && interface.owns_row(s))
        accumulated_max = std::max(accumulated_max, history.length[s.node]);
    double largest[3] = {t_max, slip_max, accumulated_max};
    Utilities::MPI::max(largest, interface.communicator(), largest);
    t_max           = largest[0];
    slip_max        = largest[1];
    accumulated_max = largest[2];
    Json components = Json::array();
    for (unsigned int d = 0; d < dim; ++d)
      components.push(force[d]);
    if (dim == 3)
      {
        tangential                 = tangential_force.norm();
        Json tangential_components = Json::array();
        for (unsigned int d = 0; d < dim; ++d)
          tangential_components.push(tangential_force[d]);
        result.set("tangential_contact_force_components", tangential_components);
        Json held_components = Json::array();
        for (unsigned int d = 0; d < dim; ++d)
          held_components.push(held_force[d]);
        result.set("held_tangential_force_components", held_components);
      }
    result.set("total_normal_contact_force", normal)
      .set("total_tangential_contact_force", tangential)
      .set("tangential_over_normal_force", normal > 0. ? tangential / normal : 0.)
      .set("contact_force_components", components)
      .set("active_contact_length", length)
      .set("max_tangential_traction", t_max)
      .set("max_slip_increment", slip_max)
      .set("max_accumulated_slip", accumulated_max);
  }

  void
  print_friction_totals(const Json        &contact,
                        const Json        &reaction,
                        const unsigned int dim,
                        std::ostream      &out)
  {
    const double normal     = contact["total_normal_contact_force"].number_value();
    const double tangential = contact["total_tangential_contact_force"].number_value();
    const double scale      = reaction["force_scale"].number_value();
    out << "    stick / slip nodes:           " << contact["stick_nodes"].number_value() << " / "
        << contact["slip_nodes"].number_value() << std::endl
        << "    normal contact force:         " << force_text(normal, scale) << std::endl
        << "    tangential contact force:     " << force_text(tangential, scale) << std::endl
        << (dim == 3 ? "    active contact area:          " : "    active contact length:        ")
        << contact["active_contact_length"].number_value()
        << std::endl
        << "    tangential / normal force:    "
        << (std::abs(tangential) < 1e-10 * scale || normal <= 0. ?
              std::string("0 (no tangential force)") :
              significant(tangential / normal, 10))
        << std::endl
        << "    largest slip in the last step: "
        << value_or_ok(contact["max_slip_increment"].number_value(), 1e-12) << std::endl;
    const Json &load      = reaction["applied_load_components"];
    const Json &support   = reaction["support_reaction_components"];
    const Json &imbalance = reaction["relative_imbalance_components"];
    for (unsigned int d = 0; d < dim; ++d)
      out << "    balance in "
          << "xyz"[d] << ": load " << force_text(load[d].number_value(), scale)
          << ", support reaction " << force_text(support[d].number_value(), scale)
          << ", relative imbalance " << value_or_ok(imbalance[d].number_value(), 1e-10)
          << std::endl;
  }

  template <int dim>
  std::vector<typename ContactFormulation<dim>::NodalField>
  friction_nodal_fields(const ContactInterface<dim>              &interface,
                        const ContactFormulation<dim>            &contact,
                        const std::vector<TangentialVector<dim>> &accepted_slip,
                        const SlipHistory<dim>                   &history)
  {
    const unsigned int                                        n_nodes = interface.nodes.size();
    std::vector<double>                                       stick(n_nodes, 0.);
    std::vector<typename ContactFormulation<dim>::NodalField> fields;
    if constexpr (dim == 2)
      {
        std::vector<double> tangential(n_nodes, 0.), slip(n_nodes, 0.), accumulated(n_nodes, 0.);
        for (const auto &s : interface.slave_nodes)
          if (s.paired)
            {
              tangential[s.node]  = frame_tangential_traction(contact, s);
              accumulated[s.node] = history.displacement[s.node] *
                                    ContactFormulation<dim>::tangent(contact.frame_normal(s));
            }
        for (unsigned int n = 0; n < n_nodes; ++n)
          slip[n] = accepted_slip[n][0];
        fields = {{"tangential_traction", tangential},
                  {"slip_increment", slip},
                  {"accumulated_tangential_displacement", accumulated}};
      }
    else
      {
        // Global components: the tangent frame is a storage choice.
        std::vector<Tensor<1, dim>> tangential(n_nodes), slip(n_nodes);
        for (const auto &s : interface.slave_nodes)
          if (s.paired)
            {
              tangential[s.node] = tangential_traction_vector(contact, s);
              slip[s.node]       = to_global(accepted_slip[s.node], contact.frame_normal(s));
            }
        using Vectors = const std::vector<Tensor<1, dim>> *;
        for (const auto &[name, values] :
             {std::make_pair("tangential_traction_", Vectors(&tangential)),
              std::make_pair("slip_increment_", Vectors(&slip)),
              std::make_pair("accumulated_tangential_displacement_", &history.displacement)})
          for (unsigned int d = 0; d < dim; ++d)
            {
              fields.push_back({name + std::string(1, "xyz"[d]), std::vector<double>(n_nodes)});
              for (unsigned int n = 0; n < n_nodes; ++n)
                fields.back().values[n] = (*values)[n][d];
            }
      }
    fields.push_back({"accumulated_slip", history.length});
    for (unsigned int n = 0; n < n_nodes; ++n)
      stick[n] = contact.held_tangentially(n) ? 1. : 0.;
    fields.push_back({"stick", stick});
    return fields;
  }

  std::string
  friction_iteration_header()
  {
    return " stick |  slip | s/s ch. |";
  }

  std::string
  friction_iteration_cells(const unsigned int iteration,
                           const unsigned int n_stick,
                           const unsigned int n_slip,
                           const unsigned int changes)
  {
    std::ostringstream s;
    s << " " << std::setw(5) << n_stick << " | " << std::setw(5) << n_slip << " | " << std::setw(7)
      << (iteration == 0 ? std::string("-") : std::to_string(changes)) << " |";
    return s.str();
  }

  template void
  add_friction_totals(const ContactInterface<2> &,
                      const ContactFormulation<2> &,
                      const std::vector<TangentialVector<2>> &,
                      const SlipHistory<2> &,
                      Json &);
  template void
  add_friction_totals(const ContactInterface<3> &,
                      const ContactFormulation<3> &,
                      const std::vector<TangentialVector<3>> &,
                      const SlipHistory<3> &,
                      Json &);
  template std::vector<ContactFormulation<2>::NodalField>
  friction_nodal_fields(const ContactInterface<2> &,
                        const ContactFormulation<2> &,
                        const std::vector<TangentialVector<2>> &,
                        const SlipHistory<2> &);
  template std::vector<ContactFormulation<3>::NodalField>
  friction_nodal_fields(const ContactInterface<3> &,
                        const ContactFormulation<3> &,
                        const std::vector<TangentialVector<3>> &,
                        const SlipHistory<3> &);
} // namespace contact_fem
