#include <deal.II/base/mpi.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/core/format.h>
#include <contact_fem/postprocess/contact_results.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>

namespace contact_fem
{
  template <int dim>
  Json
  contact_results(const ContactState<dim> &state, const double penetration_excess)
  {
    const ContactInterface<dim>   &interface = state.interface;
    const ContactFormulation<dim> &contact   = state.contact;
    const auto [n_slave, n_hanging]          = interface.count_slave_nodes();
    // Each rank the active nodes whose rows it owns; the count, the
    // extremes and the sizes' sum (terms > 0, in node order) reduced
    // exactly, so every rank gets the serial values.
    unsigned int n_active = 0;
    double       p_max = 0., p_min = std::numeric_limits<double>::max();
    double       gap_max = 0.;
    double       x_min = std::numeric_limits<double>::max(), x_max = -x_min;
    std::vector<std::pair<unsigned int, double>> sizes;
    for (unsigned int k = 0; k < interface.slave_nodes.size(); ++k)
      if (const auto &s = interface.slave_nodes[k];
          s.paired && interface.owns_row(s) && contact.is_active(s.node))
        {
          ++n_active;
          p_max   = std::max(p_max, contact.normal_pressure(s.node));
          p_min   = std::min(p_min, contact.normal_pressure(s.node));
          gap_max = std::max(gap_max, std::abs(interface.gap(s, state.displacement)) / s.size);
          sizes.emplace_back(k, s.size);
          const double x = state.position(s.node)[0];
          x_min          = std::min(x_min, x);
          x_max          = std::max(x_max, x);
        }
    const MPI_Comm comm = interface.communicator();
    n_active            = Utilities::MPI::sum(n_active, comm);
    double largest[5]   = {p_max, -p_min, gap_max, -x_min, x_max};
    Utilities::MPI::max(largest, comm, largest);
    p_max                 = largest[0];
    p_min                 = -largest[1];
    gap_max               = largest[2];
    x_min                 = -largest[3];
    x_max                 = largest[4];
    const double size_sum = interface.sum_in_node_order(sizes);
    Json         result   = Json::object();
    result.set("slave_nodes", n_slave)
      .set("hanging_slave_vertices", n_hanging)
      .set("active_slave_nodes", n_active)
      .set("contact_half_width", n_active > 0 ? 0.5 * (x_max - x_min) : 0.)
      .set("max_contact_pressure", p_max)
      .set("min_active_contact_pressure", n_active > 0 ? p_min : 0.)
      .set("max_gap_over_h_on_active_nodes", gap_max)
      .set("total_contact_force", state.contact_force().norm())
      .set("slave_element_size", n_active > 0 ? size_sum / n_active : 0.);
    contact.add_results(interface, result);
    result.set("largest_unexplained_penetration_over_h", penetration_excess);
    Json slave_split = Json::array(), master_split = Json::array();
    for (const unsigned int n : interface.slave_faces_per_rank)
      slave_split.push(n);
    for (const unsigned int n : interface.master_faces_per_rank)
      master_split.push(n);
    result.set("slave_faces_per_rank", slave_split).set("master_faces_per_rank", master_split);
    // What each rank holds of the interface (the per-rank contact data).
    const auto                held  = interface.count_held();
    std::vector<unsigned int> mine  = {held.faces,
                                       held.slave_nodes,
                                       held.rows_owned,
                                       held.row_ghosts,
                                       held.interface_dofs,
                                       held.interface_dofs_owned,
                                       held.zone_nodes_received,
                                       held.closed_ghosts,
                                       held.line_nodes,
                                       held.line_dofs,
                                       held.faces_within_reach,
                                       held.dofs_within_reach};
    std::vector<const char *> names = {"faces",
                                       "slave_nodes",
                                       "rows_owned",
                                       "row_ghosts",
                                       "interface_dofs",
                                       "interface_dofs_owned",
                                       "zone_nodes_received",
                                       "closed_ghosts",
                                       "line_nodes",
                                       "line_dofs",
                                       "faces_within_reach",
                                       "dofs_within_reach"};
    if (ContactInterface<dim>::checking_held_state())
      {
        mine.insert(mine.end(), {held.check_dofs_compared, held.check_dofs_left_out,
                                 held.check_lines_compared, held.check_lines_left_out});
        names.insert(names.end(), {"check_dofs_compared", "check_dofs_left_out",
                                   "check_lines_compared", "check_lines_left_out"});
      }
    const auto all           = Utilities::MPI::all_gather(comm, mine);
    const auto kib           = Utilities::MPI::all_gather(comm, held.bytes / 1024.);
    Json       held_per_rank = Json::object();
    for (unsigned int k = 0; k < mine.size(); ++k)
      {
        Json values = Json::array();
        for (const auto &rank : all)
          values.push(rank[k]);
        held_per_rank.set(names[k], values);
      }
    Json kib_per_rank = Json::array();
    for (const double k : kib)
      kib_per_rank.push(std::round(k));
    held_per_rank.set("interface_kib", kib_per_rank);
    result.set("held_per_rank", held_per_rank);
    return result;
  }

  template <int dim>
  std::string
  contact_results_text(const ContactState<dim> &state,
                       const Json              &contact,
                       const Json              &reaction,
                       const double             penetration_tolerance,
                       const bool               round_off_pressures)
  {
    std::ostringstream out;
    out << std::setprecision(6);
    const auto   n_slave  = static_cast<unsigned int>(contact["slave_nodes"].number_value());
    const auto   n_active = static_cast<unsigned int>(contact["active_slave_nodes"].number_value());
    const double p_max    = contact["max_contact_pressure"].number_value();
    const double p_min    = contact["min_active_contact_pressure"].number_value();
    const double gap_max  = contact["max_gap_over_h_on_active_nodes"].number_value();
    out << "    slave nodes:                  " << n_slave << std::endl
        << "    active slave nodes:           " << n_active << std::endl;
    if (n_active > 0)
      out << "    max contact pressure:         " << p_max << std::endl
          << "    min active contact pressure:  " << p_min << std::endl
          << "    pressure spread (max-min)/max: "
          << (round_off_pressures ? std::string("not computed (round-off pressures)") :
                                    value_or_ok((p_max - p_min) / p_max, 1e-8))
          << std::endl
          << "    max |gap|/h on active nodes:  " << value_or_ok(gap_max, 1e-10) << std::endl;
    // Round-off-free: at or below 1e-6 h the excess is not printed as a
    // number (an exactly resolved contact gives noise there).
    const double excess = contact["largest_unexplained_penetration_over_h"].number_value();
    out << "    penetration check:            every slave node "
        << (state.interface.hanging_slave_vertices.empty() ? "" : "and hanging slave vertex ")
        << "against the whole master surface, unexplained penetration "
        << (excess < 1e-6 ? std::string("< 1e-6") : scientific(excess, 1)) << " h (tolerance "
        << penetration_tolerance << " h)" << std::endl;
    if (round_off_pressures)
      out << "    formulation checks:           not made: the pressures are round-off (see the "
             "warning above)"
          << std::endl;
    else
      state.contact.print_results(state.interface, state.displacement, contact, reaction, out);
    return out.str();
  }

  template <int dim>
  Json
  reaction_results(const BalanceInputs<dim> &in)
  {
    // Reactions are the residual K u - f at the held DoFs, less the contact
    // force where such a DoF belongs to the interface (a fixed component of
    // a contact node): contact forces are internal.
    const DoFHandler<dim>               &dof_handler = in.forces.dof_handler;
    const MPI_Comm                       comm        = dof_handler.get_communicator();
    const IndexSet                      &owned       = dof_handler.locally_owned_dofs();
    Tensor<1, dim>                       reaction;
    double                               absolute_sum = 0., h_max = 0.;
    std::vector<types::global_dof_index> dofs(dof_handler.get_fe().n_dofs_per_cell());
    std::set<types::global_dof_index>    seen;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          h_max = std::max(h_max, cell->diameter());
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (owned.is_element(dofs[i]) &&
                (in.forces.dirichlet.is_constrained(dofs[i]) || in.held(dofs[i])) &&
                seen.insert(dofs[i]).second)
              {
                const double r = held_dof_reaction(in.forces.residual, in.forces.interface,
                                                   in.forces.contact_force, dofs[i]);
                reaction[dof_handler.get_fe().system_to_component_index(i).first] += r;
                absolute_sum += std::abs(r);
              }
        }
    for (unsigned int d = 0; d < dim; ++d)
      reaction[d] = Utilities::MPI::sum(reaction[d], comm);
    absolute_sum = Utilities::MPI::sum(absolute_sum, comm);
    h_max        = Utilities::MPI::max(h_max, comm);
    // Scale of the balance: the applied load, or for displacement-driven
    // scenes (no applied load, reactions that cancel) half the sum of the
    // reaction magnitudes. When even that is below 1e-10 E_min |u|_max
    // h^(dim-2), no force acts (bodies pulled apart, rigid motion): the
    // forces are round-off and there is no balance to check.
    const double no_force =
      1e-10 * in.youngs_min * in.largest_displacement * std::pow(h_max, dim - 2.);
    // Loads that balance each other (two bodies pressed together by
    // opposite forces) have a net of round-off: their scale is the largest
    // load on one body.
    Tensor<1, dim> load;
    double         largest_body_load = 0.;
    for (const auto &[id, body_load] : in.body_loads)
      {
        load += body_load;
        largest_body_load = std::max(largest_body_load, body_load.norm());
      }
    const double scale           = std::max({load.norm(), largest_body_load, 0.5 * absolute_sum});
    Json         result          = Json::object();
    Json         load_components = Json::array(), reaction_components = Json::array(),
         imbalance_components = Json::array();
    for (unsigned int d = 0; d < dim; ++d)
      {
        load_components.push(load[d]);
        reaction_components.push(reaction[d]);
        imbalance_components.push(scale > no_force ? (load[d] + reaction[d]) / scale : 0.);
      }
    result.set("applied_load", load.norm())
      .set("applied_load_components", load_components)
      .set("support_reaction_components", reaction_components)
      .set("relative_imbalance_components", imbalance_components)
      .set("support_reaction", reaction.norm())
      .set("force_scale", scale)
      .set("largest_body_load", largest_body_load)
      .set("relative_imbalance", scale > no_force ? (load + reaction).norm() / scale : 0.);
    return result;
  }

  std::string
  reaction_results_text(const Json &reaction, const bool balance_meaningful)
  {
    // A plain "0" when nothing is loaded. The net of loads that balance
    // is round-off, or exactly 0 depending on the summation order (on the
    // partition): printed alike either way.
    const double       scale = reaction["force_scale"].number_value();
    std::ostringstream out;
    out << std::setprecision(6) << "    applied load:                 "
        << (reaction["largest_body_load"].number_value() == 0. ?
              std::string("0") :
              force_text(reaction["applied_load"].number_value(), scale))
        << std::endl
        << "    support reaction:             "
        << force_text(reaction["support_reaction"].number_value(), scale) << std::endl
        << "    relative imbalance:           "
        << (balance_meaningful ? value_or_ok(reaction["relative_imbalance"].number_value(), 1e-10) :
                                 std::string("not computed (no load: the forces are round-off)"))
        << std::endl;
    return out.str();
  }

  template Json
  contact_results(const ContactState<2> &, const double);
  template Json
  contact_results(const ContactState<3> &, const double);
  template std::string
  contact_results_text(const ContactState<2> &,
                       const Json &,
                       const Json &,
                       const double,
                       const bool);
  template std::string
  contact_results_text(const ContactState<3> &,
                       const Json &,
                       const Json &,
                       const double,
                       const bool);
  template Json
  reaction_results(const BalanceInputs<2> &);
  template Json
  reaction_results(const BalanceInputs<3> &);
} // namespace contact_fem
