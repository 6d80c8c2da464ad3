#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>

#include <contact_fem/postprocess/forces.h>
#include <contact_fem/postprocess/pressure_profile.h>
#include <contact_fem/simulator/contact_problem.h>
#include <contact_fem/core/format.h>
#include <contact_fem/postprocess/output_files.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace contact_fem
{
  template <int dim>
  Tensor<1, dim>
  ContactProblem<dim>::applied_load(const double time) const
  {
    Tensor<1, dim> force;
    for (const auto &[id, load] : diagnosis().body_loads(time))
      force += load;
    return force;
  }

  template <int dim>
  Json
  ContactProblem<dim>::contact_results() const
  {
    Json result = Json::object();
    if (!contact)
      return result;
    const auto [n_slave, n_hanging] = interface->count_slave_nodes();
    unsigned int n_active           = 0;
    double       p_max = 0., p_min = std::numeric_limits<double>::max(), size_sum = 0.;
    double       gap_max = 0.;
    double       x_min = std::numeric_limits<double>::max(), x_max = -x_min;
    for (const auto &s : interface->slave_nodes)
      if (s.paired && contact->is_active(s.node))
        {
          ++n_active;
          p_max   = std::max(p_max, contact->normal_pressure(s.node));
          p_min   = std::min(p_min, contact->normal_pressure(s.node));
          gap_max = std::max(gap_max, std::abs(interface->gap(s, interface_displacement)) / s.size);
          size_sum += s.size;
          const double x = interface->nodes[s.node].reference[0] +
                           interface->displacement(s.node, interface_displacement)[0];
          x_min = std::min(x_min, x);
          x_max = std::max(x_max, x);
        }
    result.set("slave_nodes", n_slave)
      .set("hanging_slave_vertices", n_hanging)
      .set("active_slave_nodes", n_active)
      .set("contact_half_width", n_active > 0 ? 0.5 * (x_max - x_min) : 0.)
      .set("max_contact_pressure", p_max)
      .set("min_active_contact_pressure", n_active > 0 ? p_min : 0.)
      .set("max_gap_over_h_on_active_nodes", gap_max)
      .set("total_contact_force", contact_state().contact_force().norm())
      .set("slave_element_size", n_active > 0 ? size_sum / n_active : 0.);
    contact->add_results(*interface, result);
    result.set("largest_unexplained_penetration_over_h", search->last_penetration_excess());
    Json slave_split = Json::array(), master_split = Json::array();
    for (const unsigned int n : interface->slave_faces_per_rank)
      slave_split.push(n);
    for (const unsigned int n : interface->master_faces_per_rank)
      master_split.push(n);
    result.set("slave_faces_per_rank", slave_split).set("master_faces_per_rank", master_split);
    return result;
  }

  template <int dim>
  std::vector<double>
  ContactProblem<dim>::interface_contact_force() const
  {
    if (!contact)
      return {};
    return contact->residuals(*interface, interface_displacement).contact_force;
  }

  template <int dim>
  Json
  ContactProblem<dim>::reaction_results() const
  {
    // Reactions are the residual K u - f at the Dirichlet DoFs, less the
    // contact force where such a DoF belongs to the interface (a fixed
    // component of a contact node): contact forces are internal.
    const std::vector<double>            contact_force = interface_contact_force();
    Tensor<1, dim>                       reaction;
    double                               absolute_sum = 0.;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    std::set<types::global_dof_index>    seen;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (owned_dofs.is_element(dofs[i]) &&
                (dirichlet_constraints.is_constrained(dofs[i]) ||
                 inclined_supports.holds(dofs[i])) &&
                seen.insert(dofs[i]).second)
              {
                const double r =
                  held_dof_reaction(residual, interface.get(), contact_force, dofs[i]);
                reaction[fe.system_to_component_index(i).first] += r;
                absolute_sum += std::abs(r);
              }
        }
    for (unsigned int d = 0; d < dim; ++d)
      reaction[d] = Utilities::MPI::sum(reaction[d], comm);
    absolute_sum = Utilities::MPI::sum(absolute_sum, comm);
    // Scale of the balance: the applied load, or for displacement-driven
    // scenes (no applied load, reactions that cancel) half the sum of the
    // reaction magnitudes. When even that is below 1e-10 E_min |u|_max
    // h^(dim-2), no force acts (bodies pulled apart, rigid motion): the
    // forces are round-off and there is no balance to check.
    const Tensor<1, dim> load       = applied_load(current_time);
    const double         youngs_min = materials.youngs_modulus_range().first;
    double               h_max      = 0.;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        h_max = std::max(h_max, cell->diameter());
    h_max                 = Utilities::MPI::max(h_max, comm);
    const double no_force = 1e-10 * youngs_min * solution.linfty_norm() * std::pow(h_max, dim - 2.);
    // Loads that balance each other (two bodies pressed together by
    // opposite forces) have a net of round-off: their scale is the largest
    // load on one body.
    double largest_body_load = 0.;
    for (const auto &[id, body_load] : diagnosis().body_loads(current_time))
      largest_body_load = std::max(largest_body_load, body_load.norm());
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

  template <int dim>
  RunView<dim>
  ContactProblem<dim>::run_view(const unsigned int         step,
                                const ContactState<dim>   *state,
                                const std::vector<double> &contact_force) const
  {
    return {{dof_handler, *mapping, ghosted_solution, materials, volumetric_projection.get(),
             state},
            {dof_handler, residual, dirichlet_constraints, boundary_conditions.displacements,
             boundary_conditions.points, interface.get(), contact.get(), contact_force,
             contact_parameters.pairs, boundary_conditions.rollers},
            probe_dofs,
            solution,
            scene.frame,
            output,
            analytical,
            comparison.get(),
            cycle,
            step,
            current_time,
            comm};
  }

  template <int dim>
  void
  ContactProblem<dim>::postprocess(
    const std::function<void(Postprocessor<dim> &, std::ostream &)> &hook)
  {
    for (const auto &postprocessor : postprocessors)
      {
        std::ostringstream text;
        hook(*postprocessor, text);
        pcout << text.str();
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::print_results(const Json &contact_json,
                                     const Json &reaction,
                                     const Json &hertz) const
  {
    pcout << "  Results at t = " << current_time << ":" << std::endl << std::setprecision(6);
    if (contact)
      {
        // Printed from contact_results(), which computed them.
        const auto n_slave = static_cast<unsigned int>(contact_json["slave_nodes"].number_value());
        const auto n_active =
          static_cast<unsigned int>(contact_json["active_slave_nodes"].number_value());
        const double p_max   = contact_json["max_contact_pressure"].number_value();
        const double p_min   = contact_json["min_active_contact_pressure"].number_value();
        const double gap_max = contact_json["max_gap_over_h_on_active_nodes"].number_value();
        pcout << "    slave nodes:                  " << n_slave << std::endl
              << "    active slave nodes:           " << n_active << std::endl;
        if (n_active > 0)
          pcout << "    max contact pressure:         " << p_max << std::endl
                << "    min active contact pressure:  " << p_min << std::endl
                << "    pressure spread (max-min)/max: "
                << value_or_ok((p_max - p_min) / p_max, 1e-8) << std::endl
                << "    max |gap|/h on active nodes:  " << value_or_ok(gap_max, 1e-10) << std::endl;
        // Round-off-free: at or below 1e-6 h the excess is not printed as a
        // number (an exactly resolved contact gives noise there).
        const double excess = contact_json["largest_unexplained_penetration_over_h"].number_value();
        pcout << "    penetration check:            every slave node "
              << (interface->hanging_slave_vertices.empty() ? "" : "and hanging slave vertex ")
              << "against the whole master surface, unexplained penetration "
              << (excess < 1e-6 ? std::string("< 1e-6") : scientific(excess, 1)) << " h (tolerance "
              << contact_parameters.penetration_tolerance << " h)" << std::endl;
        std::ostringstream own_checks;
        contact->print_results(*interface, interface_displacement, contact_json, reaction,
                               own_checks);
        pcout << own_checks.str();
      }
    // A plain "0" when nothing is loaded. The net of loads that balance
    // is round-off, or exactly 0 depending on the summation order (on the
    // partition): printed alike either way.
    const double applied = reaction["applied_load"].number_value();
    pcout << "    applied load:                 "
          << (reaction["largest_body_load"].number_value() == 0. ?
                std::string("0") :
                force_text(applied, reaction["force_scale"].number_value()))
          << std::endl
          << "    support reaction:             "
          << force_text(reaction["support_reaction"].number_value(),
                        reaction["force_scale"].number_value())
          << std::endl
          << "    relative imbalance:           "
          << value_or_ok(reaction["relative_imbalance"].number_value(), 1e-10) << std::endl;
    if (comparison && contact)
      {
        std::ostringstream text;
        comparison->print(hertz, text);
        pcout << text.str();
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::write_summary(const Json        &cycles,
                                     const double       wall_time,
                                     const std::string &status) const
  {
    const std::string path = output.directory + "/summary.json";
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      {
        check_written(path, true);
        return;
      }
    Json summary = Json::object();
    summary.set("scene", scene_name)
      .set("dim", dim)
      .set("mpi_processes", Utilities::MPI::n_mpi_processes(comm))
      .set("status", status)
      .set("degree", degree)
      .set("mapping_degree", mapping->get_degree())
      .set("wall_time", wall_time);
    // A mesh far from the origin is computed (and its VTU files written)
    // moved next to it: the point of the user's coordinates that is 0 there.
    if (scene.frame.shifted())
      {
        Json origin = Json::array();
        for (unsigned int d = 0; d < dim; ++d)
          origin.push(scene.frame.origin[d]);
        summary.set("coordinate_origin", origin);
      }
    if (!warnings.empty())
      summary.set("warnings", warnings.to_json());
    summary.set("cycles", cycles);
    std::ostringstream out;
    summary.write(out);
    out << '\n';
    throw_if_unwritten(path, write_file_atomically(path, out.str()), comm);
  }

  template <int dim>
  OutputDirectoryReport
  ContactProblem<dim>::open_output_directory()
  {
    const OutputDirectoryReport report = prepare_output_directory(output.directory, comm);
    const bool                  root   = Utilities::MPI::this_mpi_process(comm) == 0;
    if (root)
      log_file.open(output.directory + "/log.txt");
    check_written(output.directory + "/log.txt", !root || static_cast<bool>(log_file));
    if (root)
      console.attach(log_file);
    postprocessors = Postprocessor<dim>::create_wanted(
      {output, analytical, static_cast<bool>(contact),
       [this](const std::string &kind, const std::string &text, Json &record) {
         warn(kind, text, record);
       },
       *timer, comm});
    return report;
  }

  template <int dim>
  void
  ContactProblem<dim>::report_earlier_outputs(const OutputDirectoryReport &report)
  {
    if (report.removed == 0)
      return;
    std::ostringstream text;
    text << "Output directory '" << output.directory << "': removed " << report.removed
         << " file(s) of an earlier run";
    // A rerun of the same scene replaces its own results, as expected: the
    // log says so, the console (and test output) stays the same for every
    // rerun. Results of another scene are worth a word on the console.
    if (report.earlier_scene == scene_name)
      {
        console.flush();
        if (log_file.is_open())
          log_file << text.str() << " of this scene." << std::endl;
      }
    else
      pcout << text.str()
            << (report.earlier_scene.empty() ? std::string(" (its scene is unknown)") :
                                               " of scene '" + report.earlier_scene + "'")
            << "." << std::endl;
  }

  template <int dim>
  void
  ContactProblem<dim>::check_written(const std::string &path, const bool ok) const
  {
    // Collective, so that every rank stops if rank 0 could not write.
    throw_if_unwritten(path, ok ? "" : "the write failed: a full disk?", comm);
  }

  // The class is instantiated in contact_problem.cc; here only the members
  // defined in this file.
#define INSTANTIATE(dim)                                                                         \
  template Tensor<1, dim>      ContactProblem<dim>::applied_load(const double) const;            \
  template Json                ContactProblem<dim>::contact_results() const;                     \
  template Json                ContactProblem<dim>::reaction_results() const;                    \
  template std::vector<double> ContactProblem<dim>::interface_contact_force() const;             \
  template RunView<dim>        ContactProblem<dim>::run_view(const unsigned int,                 \
                                                             const ContactState<dim> *,          \
                                                             const std::vector<double> &) const; \
  template void                ContactProblem<dim>::postprocess(                                 \
                   const std::function<void(Postprocessor<dim> &, std::ostream &)> &);           \
  template void ContactProblem<dim>::print_results(const Json &, const Json &, const Json &)     \
    const;                                                                                       \
  template void                  ContactProblem<dim>::write_summary(const Json &, const double,  \
                                                                    const std::string &) const;  \
  template OutputDirectoryReport ContactProblem<dim>::open_output_directory();                   \
  template void ContactProblem<dim>::report_earlier_outputs(const OutputDirectoryReport &);      \
  template void ContactProblem<dim>::check_written(const std::string &, const bool) const;
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace contact_fem
