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
  std::vector<double>
  ContactProblem<dim>::interface_contact_force() const
  {
    if (!contact)
      return {};
    return contact->residuals(*interface, interface_displacement).contact_force;
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
            tying.get(),
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
  ContactProblem<dim>::write_summary(const Json        &cycles,
                                     const double       wall_time,
                                     const std::string &status) const
  {
    const std::string path = output.directory + "/summary.json";
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      {
        throw_if_unwritten(path, "", comm);
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

  // The class is instantiated in contact_problem.cc; here only the members
  // defined in this file.
#define INSTANTIATE(dim)                                                                         \
  template std::vector<double> ContactProblem<dim>::interface_contact_force() const;             \
  template RunView<dim>        ContactProblem<dim>::run_view(const unsigned int,                 \
                                                             const ContactState<dim> *,          \
                                                             const std::vector<double> &) const; \
  template void                ContactProblem<dim>::postprocess(                                 \
                   const std::function<void(Postprocessor<dim> &, std::ostream &)> &);           \
  template void ContactProblem<dim>::write_summary(const Json &, const double,                   \
                                                   const std::string &) const;
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace contact_fem
