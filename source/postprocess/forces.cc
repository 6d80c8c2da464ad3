#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe.h>

#include <contact_fem/contact/friction/stick_slip_sets.h>
#include <contact_fem/core/format.h>
#include <contact_fem/postprocess/forces.h>
#include <contact_fem/postprocess/output_files.h>
#include <contact_fem/postprocess/owned_rows.h>
#include <contact_fem/postprocess/postprocessor.h>
#include <contact_fem/simulator/scene_parameters.h>

#include <algorithm>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

namespace contact_fem
{
  namespace
  {
    /// Components below 1e-6 of @p scale as 0: their digits are the
    /// round-off of the converged equilibrium.
    template <int dim>
    Tensor<1, dim>
    snapped(const Tensor<1, dim> &force, const double scale)
    {
      Tensor<1, dim> result = force;
      for (unsigned int d = 0; d < dim; ++d)
        if (std::abs(result[d]) < 1e-6 * scale)
          result[d] = 0.;
      return result;
    }

    template <int dim>
    std::string
    vector_text(const Tensor<1, dim> &force, const double scale)
    {
      const Tensor<1, dim> f    = snapped(force, scale);
      std::string          text = "(";
      for (unsigned int d = 0; d < dim; ++d)
        text += (d > 0 ? ", " : "") + significant(f[d], 6);
      return text + ")";
    }

    std::string
    pair_name(const ContactPair &pair)
    {
      return std::to_string(pair.slave) + ": " + std::to_string(pair.master);
    }
  } // namespace

  template <int dim>
  void
  ForceReport<dim>::print(std::ostream &out, const double time) const
  {
    if (supports.empty() && pairs.empty())
      return;
    out << "    forces at t = " << time
        << " (on the bodies: reactions of the supports; pairs, from the master on the slave):"
        << std::endl;
    for (const auto &s : supports)
      out << "      " << s.label << ": " << vector_text(s.force, scale) << std::endl;
    for (const auto &p : pairs)
      out << "      pair " << pair_name(p.pair) << ": normal " << vector_text(p.normal, scale)
          << ", tangential " << vector_text(p.tangential, scale) << ", contact "
          << (dim == 2 ? "length " : "area ") << significant(p.area, 6) << std::endl;
  }

  template <int dim>
  Json
  ForceReport<dim>::to_json() const
  {
    Json support_list = Json::array(), pair_list = Json::array();
    for (const auto &s : supports)
      {
        Json entry = Json::object();
        entry.set("support", s.label).set("force", json_array(s.force, dim));
        support_list.push(entry);
      }
    for (const auto &p : pairs)
      {
        Json entry = Json::object();
        entry.set("slave", static_cast<unsigned int>(p.pair.slave))
          .set("master", static_cast<unsigned int>(p.pair.master))
          .set("normal_force", json_array(p.normal, dim))
          .set("tangential_force", json_array(p.tangential, dim))
          .set(dim == 2 ? "contact_length" : "contact_area", p.area);
        if (p.n_stick >= 0)
          entry.set("stick_nodes", p.n_stick).set("slip_nodes", p.n_slip);
        pair_list.push(entry);
      }
    Json result = Json::object();
    result.set("reactions", support_list).set("pairs", pair_list);
    return result;
  }

  template <int dim>
  std::string
  ForceReport<dim>::csv_header() const
  {
    const char *axes = "xyz";
    std::string header;
    for (const auto &s : supports)
      for (unsigned int d = 0; d < dim; ++d)
        header += "," + s.column + "_" + axes[d];
    for (const auto &p : pairs)
      {
        const std::string name =
          "pair_" + std::to_string(p.pair.slave) + "_" + std::to_string(p.pair.master);
        for (const std::string part : {"normal", "tangential"})
          for (unsigned int d = 0; d < dim; ++d)
            header += "," + name + "_" + part + "_" + axes[d];
        header += "," + name + (dim == 2 ? "_length" : "_area");
      }
    return header;
  }

  template <int dim>
  std::string
  ForceReport<dim>::csv_row() const
  {
    std::ostringstream row;
    row << std::setprecision(10);
    for (const auto &s : supports)
      for (unsigned int d = 0; d < dim; ++d)
        row << ',' << s.force[d];
    for (const auto &p : pairs)
      {
        for (const auto *part : {&p.normal, &p.tangential})
          for (unsigned int d = 0; d < dim; ++d)
            row << ',' << (*part)[d];
        row << ',' << p.area;
      }
    return row.str();
  }

  template <int dim>
  double
  held_dof_reaction(const TrilinosWrappers::MPI::Vector &residual,
                    const ContactInterface<dim>         *interface,
                    const std::vector<double>           &contact_force,
                    const types::global_dof_index        dof)
  {
    double r = residual(dof);
    if (interface && std::binary_search(interface->dofs().begin(), interface->dofs().end(), dof))
      r -= contact_force[interface->position(dof)];
    return r;
  }

  template <int dim>
  ForceReport<dim>
  compute_forces(const ForceInputs<dim> &in)
  {
    const auto                       &fe    = in.dof_handler.get_fe();
    const IndexSet                   &owned = in.dof_handler.locally_owned_dofs();
    const MPI_Comm                    comm  = in.dof_handler.get_communicator();
    ForceReport<dim>                  report;
    std::set<types::global_dof_index> seen;
    const auto                        reaction_at = [&](const types::global_dof_index dof) {
      return held_dof_reaction(in.residual, in.interface, in.contact_force, dof);
    };
    // Boundaries in the order of the input; each held component of a DoF
    // counts once, for the first boundary that holds it.
    std::vector<types::boundary_id>                 ids;
    std::map<types::boundary_id, std::vector<bool>> held;
    for (const auto &condition : in.displacements)
      {
        if (!held.count(condition.boundary_id))
          {
            ids.push_back(condition.boundary_id);
            held[condition.boundary_id] = std::vector<bool>(dim, false);
          }
        held[condition.boundary_id][condition.component] = true;
      }
    for (const types::boundary_id id : in.rollers)
      if (!held.count(id))
        {
          ids.push_back(id);
          held[id] = std::vector<bool>(dim, true);
        }
    const auto is_roller = [&](const types::boundary_id id) {
      return std::find(in.rollers.begin(), in.rollers.end(), id) != in.rollers.end();
    };
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const types::boundary_id id : ids)
      {
        Tensor<1, dim> force;
        // Ghost cells too: the cells that hold an owned DoF need not have a
        // face on the boundary (a cell touching it at an edge or a vertex),
        // while a ghost cell beside them does.
        for (const auto &cell : in.dof_handler.active_cell_iterators())
          if (!cell->is_artificial())
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == id)
                {
                  cell->get_dof_indices(dofs);
                  for (unsigned int i = 0; i < dofs.size(); ++i)
                    {
                      const unsigned int c = fe.system_to_component_index(i).first;
                      if (fe.has_support_on_face(i, f) && held[id][c] &&
                          owned.is_element(dofs[i]) &&
                          (in.dirichlet.is_constrained(dofs[i]) || is_roller(id)) &&
                          seen.insert(dofs[i]).second)
                        force[c] += reaction_at(dofs[i]);
                    }
                }
        report.supports.push_back({"boundary " + std::to_string(id),
                                   "boundary_" + std::to_string(id),
                                   Utilities::MPI::sum(force, comm)});
      }
    // What else is held: the fixed points, by body.
    std::set<types::material_id> point_bodies;
    for (const auto &condition : in.points)
      point_bodies.insert(condition.point.material_id);
    for (const types::material_id body : point_bodies)
      {
        Tensor<1, dim> force;
        for (const auto &cell : in.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() && cell->material_id() == body)
            {
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < dofs.size(); ++i)
                if (owned.is_element(dofs[i]) && in.dirichlet.is_constrained(dofs[i]) &&
                    seen.insert(dofs[i]).second)
                  force[fe.system_to_component_index(i).first] += reaction_at(dofs[i]);
            }
        report.supports.push_back({"fixed points of body " + std::to_string(body),
                                   "fixed_points_" + std::to_string(body),
                                   Utilities::MPI::sum(force, comm)});
      }
    // Each rank the slave nodes whose rows it owns: the counts summed, the
    // forces and areas summed in node order (the same on every rank).
    if (in.interface && in.contact)
      {
        report.pairs.resize(in.pairs.size());
        // Stick and slip by the formulation's set codes (1 stick, 2 and 3
        // slip), as the VTU's contact_state, over the nodes that carry
        // friction: a node a support holds tangentially (on the axis of a
        // symmetric model) neither sticks nor slips, as in the contact
        // summary (n_stick(), n_slip()).
        const std::vector<int> sets     = in.contact->contact_sets();
        const bool             friction = in.contact->transmits_shear();
        for (unsigned int p = 0; p < in.pairs.size(); ++p)
          {
            report.pairs[p].pair = in.pairs[p];
            if (friction)
              report.pairs[p].n_stick = report.pairs[p].n_slip = 0;
          }
        const ContactInterface<dim> &interface = *in.interface;
        for (const auto &s : interface.slave_nodes)
          if (friction && s.node < sets.size() && interface.owns_row(s) &&
              carries_friction(interface, s))
            {
              report.pairs[s.pair].n_stick += sets[s.node] == 1;
              report.pairs[s.pair].n_slip += sets[s.node] >= 2;
            }
        if (friction)
          for (auto &pair : report.pairs)
            {
              pair.n_stick = Utilities::MPI::sum(pair.n_stick, comm);
              pair.n_slip  = Utilities::MPI::sum(pair.n_slip, comm);
            }
        std::vector<std::vector<std::pair<unsigned int, Tensor<1, dim>>>> normals(in.pairs.size()),
          totals(in.pairs.size());
        std::vector<std::vector<std::pair<unsigned int, double>>> areas(in.pairs.size());
        for (unsigned int k = 0; k < interface.slave_nodes.size(); ++k)
          if (const auto &s = interface.slave_nodes[k];
              s.paired && interface.owns_row(s) && in.contact->is_active(s.node))
            {
              const Tensor<1, dim> lambda = in.contact->traction(s);
              const Tensor<1, dim> n      = in.contact->frame_normal(s);
              normals[s.pair].emplace_back(k, s.D * (lambda * n) * n);
              totals[s.pair].emplace_back(k, s.D * lambda);
              areas[s.pair].emplace_back(k, s.D);
            }
        for (unsigned int p = 0; p < in.pairs.size(); ++p)
          {
            auto &pair      = report.pairs[p];
            pair.normal     = sum_in_node_order(interface, normals[p]);
            pair.area       = interface.sum_in_node_order(areas[p]);
            pair.tangential = sum_in_node_order(interface, totals[p]) - pair.normal;
          }
      }
    for (const auto &s : report.supports)
      report.scale = std::max(report.scale, s.force.norm());
    for (const auto &p : report.pairs)
      report.scale = std::max(report.scale, (p.normal + p.tangential).norm());
    return report;
  }

  namespace
  {
    /// The reactions and pair forces of every converged load step: printed,
    /// recorded in the step's record and written as a row of forces.csv,
    /// followed by the probes' displacements (a force-displacement curve is
    /// two columns of one file).
    template <int dim>
    class ForceHistory : public Postprocessor<dim>
    {
    public:
      static std::unique_ptr<Postprocessor<dim>>
      create(const PostprocessorContext<dim> &)
      {
        return std::make_unique<ForceHistory<dim>>();
      }

      void
      after_load_step(const RunView<dim> &view, Json &step_record, std::ostream &out) override
      {
        const ForceReport<dim> forces = compute_forces<dim>(view.forces);
        forces.print(out, view.time);
        step_record.set("forces", forces.to_json());
        const std::vector<double> probes = view.probe_displacements();
        if (rows.empty())
          {
            header = "cycle,step,t" + forces.csv_header();
            for (unsigned int k = 0; k < probes.size(); ++k)
              header +=
                ",probe_" + std::to_string(k / dim + 1) + "_u" + std::string(1, "xyz"[k % dim]);
          }
        std::ostringstream row;
        row << view.cycle << ',' << view.step << ',' << std::setprecision(10) << view.time
            << forces.csv_row();
        for (const double u : probes)
          row << ',' << u;
        rows.push_back(row.str());
        const std::string path = view.output.directory + "/forces.csv";
        std::string       problem;
        if (Utilities::MPI::this_mpi_process(view.comm) == 0)
          {
            std::string csv = header + "\n";
            for (const auto &line : rows)
              csv += line + "\n";
            problem = write_file_atomically(path, csv);
          }
        throw_if_unwritten(path, problem, view.comm);
      }

    private:
      /// forces.csv: its header and the rows of the run so far.
      std::string              header;
      std::vector<std::string> rows;
    };
  } // namespace

  CONTACT_FEM_REGISTER_POSTPROCESSOR(ForceHistory, "forces", 10)

  template struct ForceReport<2>;
  template struct ForceReport<3>;
  template double
  held_dof_reaction(const TrilinosWrappers::MPI::Vector &,
                    const ContactInterface<2> *,
                    const std::vector<double> &,
                    const types::global_dof_index);
  template double
  held_dof_reaction(const TrilinosWrappers::MPI::Vector &,
                    const ContactInterface<3> *,
                    const std::vector<double> &,
                    const types::global_dof_index);
  template ForceReport<2>
  compute_forces(const ForceInputs<2> &);
  template ForceReport<3>
  compute_forces(const ForceInputs<3> &);
} // namespace contact_fem
