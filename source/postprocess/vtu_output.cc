#include <deal.II/base/data_out_base.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/contact/mesh_tying.h>
#include <contact_fem/postprocess/output_files.h>
#include <contact_fem/postprocess/owned_rows.h>
#include <contact_fem/postprocess/postprocessor.h>
#include <contact_fem/simulator/scene_parameters.h>
#include <contact_fem/postprocess/vtu_output.h>

#include <cmath>
#include <functional>
#include <iomanip>
#include <map>
#include <memory>
#include <sstream>
#include <type_traits>
#include <unordered_map>

namespace contact_fem
{
  namespace
  {
    /// The Cauchy stress tensor of the FE displacement (cell by cell
    /// material; with B-bar from the projected volumetric strain) and its
    /// von Mises stress sqrt(3/2 s:s), s the deviator (in 2D of the plane
    /// strain state, with sigma_zz). Finite-strain bodies (Materials/Models):
    /// the law's Cauchy stress at F = I + grad u, at the reference points.
    template <int dim>
    class StressFields : public DataPostprocessor<dim>
    {
    public:
      StressFields(const SolutionView<dim> &view)
        : materials(view.materials)
        , mapping(view.mapping)
        , solution(view.solution)
        , b_bar(view.volumetric_projection != nullptr)
      {}

      std::vector<std::string>
      get_names() const override
      {
        std::vector<std::string> names(dim * dim, "stress");
        names.push_back("von_Mises");
        return names;
      }

      std::vector<DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        std::vector<DataComponentInterpretation::DataComponentInterpretation> kinds(
          dim * dim, DataComponentInterpretation::component_is_part_of_tensor);
        kinds.push_back(DataComponentInterpretation::component_is_scalar);
        return kinds;
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_gradients | update_quadrature_points;
      }

      void
      evaluate_vector_field(const DataPostprocessorInputs::Vector<dim> &inputs,
                            std::vector<Vector<double>>                &computed) const override
      {
        const typename DoFHandler<dim>::active_cell_iterator cell = inputs.template get_cell<dim>();
        const auto                                           id   = cell->material_id();
        // Patches are built on several threads: each call has its own
        // projection (output only, so its set-up cost does not matter).
        std::unique_ptr<VolumetricProjection<dim>> projection;
        Vector<double>                             local_values;
        if (b_bar && materials.constants(id).model == ElasticModel::linear)
          {
            projection = std::make_unique<VolumetricProjection<dim>>(mapping, cell->get_fe());
            projection->reinit(cell);
            local_values.reinit(cell->get_fe().n_dofs_per_cell());
            cell->get_dof_values(solution, local_values);
          }
        const bool finite_strain = materials.constants(id).model != ElasticModel::linear;
        for (unsigned int q = 0; q < computed.size(); ++q)
          {
            if (finite_strain)
              {
                // The law's Cauchy stress at F = I + grad u (of F, not of
                // F-bar, with Volumetric strain = B-bar).
                Tensor<2, dim> grad_u;
                for (unsigned int i = 0; i < dim; ++i)
                  grad_u[i] = inputs.solution_gradients[q][i];
                const SymmetricTensor<2, 3> sigma = materials.finite_strain_stress(id, grad_u);
                for (unsigned int i = 0; i < dim; ++i)
                  for (unsigned int j = 0; j < dim; ++j)
                    computed[q](i * dim + j) = sigma[i][j];
                computed[q](dim * dim) = std::sqrt(1.5) * deviator(sigma).norm();
                continue;
              }
            SymmetricTensor<2, dim> strain;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j <= i; ++j)
                strain[i][j] =
                  0.5 * (inputs.solution_gradients[q][i][j] + inputs.solution_gradients[q][j][i]);
            const SymmetricTensor<2, dim> stress =
              b_bar ? materials.stress(id, strain,
                                       projection->value(local_values,
                                                         mapping.transform_real_to_unit_cell(
                                                           cell, inputs.evaluation_points[q]))) :
                      materials.stress(id, strain);
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                computed[q](i * dim + j) = stress[i][j];
            computed[q](dim * dim) = materials.von_mises(id, stress);
          }
      }

    private:
      const Materials<dim>                &materials;
      const Mapping<dim>                  &mapping;
      const TrilinosWrappers::MPI::Vector &solution;
      const bool                           b_bar;
    };

    /// zlib's fastest level: deal.II's default (best compression) took 60 %
    /// of the VTU time of prm/hertz.prm for 6 % smaller files
    /// (doc/performance.md).
    DataOutBase::VtkFlags
    fast_vtk_flags()
    {
      DataOutBase::VtkFlags flags;
      flags.compression_level = DataOutBase::VtkFlags::best_speed;
      return flags;
    }

    /// Calls @p at(n, scalar_dof) for every locally owned DoF of the scalar
    /// Q_p space @p scalar_dofs at a node n of @p interface (@p dof_handler:
    /// the displacement's, on the same mesh).
    template <int dim>
    void
    for_each_interface_dof(const DoFHandler<dim>       &dof_handler,
                           const DoFHandler<dim>       &scalar_dofs,
                           const ContactInterface<dim> &interface,
                           const std::function<void(unsigned int, types::global_dof_index)> &at)
    {
      std::unordered_map<types::global_dof_index, unsigned int> node_of_dof;
      for (unsigned int n = 0; n < interface.nodes.size(); ++n)
        node_of_dof[interface.nodes[n].dofs[0]] = n;
      const IndexSet                       scalar_owned = scalar_dofs.locally_owned_dofs();
      const FiniteElement<dim>            &fe           = dof_handler.get_fe();
      std::vector<types::global_dof_index> vector_dofs(fe.n_dofs_per_cell()),
        scalar_dofs_of_cell(scalar_dofs.get_fe().n_dofs_per_cell());
      auto scalar_cell = scalar_dofs.begin_active();
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(vector_dofs);
              scalar_cell->get_dof_indices(scalar_dofs_of_cell);
              for (unsigned int i = 0; i < vector_dofs.size(); ++i)
                {
                  const auto ci = fe.system_to_component_index(i);
                  const auto it = node_of_dof.find(vector_dofs[i]);
                  if (ci.first != 0 || it == node_of_dof.end())
                    continue;
                  const auto scalar_dof = scalar_dofs_of_cell[ci.second];
                  if (scalar_owned.is_element(scalar_dof))
                    at(it->second, scalar_dof);
                }
            }
          ++scalar_cell;
        }
    }

    /// @p fields (owned entries of @p dofs' vectors, set by insertion)
    /// compressed and with the ghost entries DataOut reads.
    template <int dim>
    std::vector<TrilinosWrappers::MPI::Vector>
    ghosted_fields(std::vector<TrilinosWrappers::MPI::Vector> &fields, const DoFHandler<dim> &dofs)
    {
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(dofs, relevant);
      std::vector<TrilinosWrappers::MPI::Vector> ghosted(fields.size());
      for (unsigned int k = 0; k < fields.size(); ++k)
        {
          fields[k].compress(VectorOperation::insert);
          ghosted[k].reinit(dofs.locally_owned_dofs(), relevant, dofs.get_communicator());
          ghosted[k] = fields[k];
        }
      return ghosted;
    }

    /// The nodal contact fields of @p contact on a scalar Q_p space
    /// @p scalar_dofs of the same mesh: the contact pressure, weighted gap,
    /// active, slave and master flags, then the formulation's own fields
    /// (friction: tangential traction, slip, stick); their names in
    /// @p names. Hanging vertices show the interpolation of their parents.
    template <int dim>
    std::vector<TrilinosWrappers::MPI::Vector>
    contact_fields(const SolutionView<dim>  &view,
                   const DoFHandler<dim>    &scalar_dofs,
                   std::vector<std::string> &names)
    {
      const ContactInterface<dim>   &interface = view.contact->interface;
      const ContactFormulation<dim> &contact   = view.contact->contact;
      const MPI_Comm                 comm      = view.dof_handler.get_communicator();

      names                 = {"contact_pressure", "weighted_gap", "active", "slave", "master"};
      const auto own_fields = contact.nodal_fields(interface);
      for (const auto &field : own_fields)
        names.push_back(field.name);
      std::vector<TrilinosWrappers::MPI::Vector> fields(names.size());
      for (auto &f : fields)
        f.reinit(scalar_dofs.locally_owned_dofs(), comm);

      std::vector<double> gap(interface.nodes.size(), 0.);
      for (const auto &s : interface.slave_nodes)
        if (s.paired)
          gap[s.node] = interface.gap(s, view.contact->displacement);

      for_each_interface_dof<dim>(
        view.dof_handler, scalar_dofs, interface,
        [&](const unsigned int n, const types::global_dof_index scalar_dof) {
          // A hanging vertex has no multiplier of its own: it shows the
          // interpolation of its parents, as its displacement.
          const std::vector<std::pair<unsigned int, double>> itself   = {{n, 1.}};
          const auto                                        &parents  = interface.nodes[n].parents;
          double                                             pressure = 0., interpolated_gap = 0.;
          bool                                               active = true;
          for (const auto &[source, weight] : parents.empty() ? itself : parents)
            {
              pressure += weight * contact.normal_pressure(source);
              interpolated_gap += weight * gap[source];
              active = active && contact.is_active(source);
            }
          fields[0](scalar_dof) = pressure;
          fields[1](scalar_dof) = interpolated_gap;
          fields[2](scalar_dof) = active ? 1. : 0.;
          fields[3](scalar_dof) = interface.nodes[n].slave ? 1. : 0.;
          fields[4](scalar_dof) = interface.nodes[n].master ? 1. : 0.;
          for (unsigned int k = 0; k < own_fields.size(); ++k)
            fields[5 + k](scalar_dof) = own_fields[k].values[n];
        });
      return ghosted_fields(fields, scalar_dofs);
    }

    /// The VTK cell type and the VTK order of the nodes of a slave face
    /// (deal.II's face node order: Mortar::LineFace, Mortar::QuadFace).
    template <int dim>
    std::pair<unsigned int, std::vector<unsigned int>>
    vtk_cell(const std::vector<unsigned int> &nodes)
    {
      if (dim == 2)
        return nodes.size() == 3 ?
                 std::make_pair(21u, std::vector<unsigned int>{nodes[0], nodes[1], nodes[2]}) :
                 std::make_pair(3u, std::vector<unsigned int>{nodes[0], nodes[1]});
      // Corners counter-clockwise, then the edge midpoints in the same
      // order (edges 2, 1, 3, 0 of deal.II's face), then the centre.
      if (nodes.size() == 9)
        return {28u,
                {nodes[0], nodes[1], nodes[3], nodes[2], nodes[6], nodes[5], nodes[7], nodes[4],
                 nodes[8]}};
      return {9u, {nodes[0], nodes[1], nodes[3], nodes[2]}};
    }

    /// The value of the nodal @p field (numbers or vectors, per interface
    /// node) at node @p n: a hanging vertex shows the interpolation of its
    /// parents.
    template <int dim, typename Field>
    auto
    interpolated(const ContactInterface<dim> &interface, const Field &field, const unsigned int n)
    {
      if (interface.nodes[n].parents.empty())
        return field[n];
      std::decay_t<decltype(field[n])> v{};
      for (const auto &[source, weight] : interface.nodes[n].parents)
        v += weight * field[source];
      return v;
    }

    /// @p field (per interface node, kept by reference) as a function of
    /// the node, interpolated at hanging vertices.
    template <int dim, typename Field>
    auto
    nodal_field(const ContactInterface<dim> &interface, const Field &field)
    {
      return [&interface, &field](const unsigned int n) {
        return interpolated(interface, field, n);
      };
    }

    /// The tying tractions of @p tying per node of its interface: the
    /// vector on the slave at its tied (or held) slave nodes, zero
    /// elsewhere, and its normal component (positive in tension).
    template <int dim>
    std::pair<std::vector<Tensor<1, dim>>, std::vector<double>>
    nodal_tying_tractions(const MeshTying<dim> &tying)
    {
      const ContactInterface<dim> &interface = tying.interface();
      std::vector<Tensor<1, dim>>  traction(interface.nodes.size());
      std::vector<double>          normal(interface.nodes.size(), 0.);
      for (unsigned int k = 0; k < interface.slave_nodes.size(); ++k)
        {
          const auto &s = interface.slave_nodes[k];
          if (!s.paired)
            continue;
          traction[s.node] = tying.tractions()[k];
          normal[s.node]   = traction[s.node] * s.normal;
        }
      return {traction, normal};
    }

    /// The tying traction of @p tying in the volume: the vector on the
    /// displacement's DoFs and its normal component on the scalar Q_p space
    /// @p scalar_dofs, as nodal_tying_tractions() (hanging vertices: the
    /// interpolation of their parents).
    template <int dim>
    std::pair<TrilinosWrappers::MPI::Vector, TrilinosWrappers::MPI::Vector>
    tying_fields(const DoFHandler<dim> &dof_handler,
                 const DoFHandler<dim> &scalar_dofs,
                 const MeshTying<dim>  &tying)
    {
      const ContactInterface<dim>               &interface = tying.interface();
      const auto                                 nodal     = nodal_tying_tractions(tying);
      const IndexSet                             owned     = dof_handler.locally_owned_dofs();
      std::vector<TrilinosWrappers::MPI::Vector> vector(1), scalar(1);
      vector[0].reinit(owned, dof_handler.get_communicator());
      scalar[0].reinit(scalar_dofs.locally_owned_dofs(), dof_handler.get_communicator());
      for (unsigned int n = 0; n < interface.nodes.size(); ++n)
        {
          const Tensor<1, dim> t = interpolated(interface, nodal.first, n);
          for (unsigned int d = 0; d < dim; ++d)
            if (owned.is_element(interface.nodes[n].dofs[d]))
              vector[0](interface.nodes[n].dofs[d]) = t[d];
        }
      for_each_interface_dof<dim>(dof_handler, scalar_dofs, interface,
                                  [&](const unsigned int n, const types::global_dof_index dof) {
                                    scalar[0](dof) = interpolated(interface, nodal.second, n);
                                  });
      return {ghosted_fields(vector, dof_handler)[0], ghosted_fields(scalar, scalar_dofs)[0]};
    }

    /// The nodal fields of a surface VTU: numbers and vectors per point.
    template <int dim>
    struct SurfaceFields
    {
      std::vector<std::pair<std::string, std::function<double(unsigned int)>>>         scalars;
      std::vector<std::pair<std::string, std::function<Tensor<1, dim>(unsigned int)>>> vectors;
    };

    /// The slave faces of @p interface as an ASCII VTU at the positions
    /// @p position of its nodes (degree-1 faces on a curved geometry as
    /// their straight cells), with the nodal @p fields. Each rank gives its
    /// own slave faces and the values at their nodes (held there: a hanging
    /// vertex reads its parents); rank 0 gathers them, the faces in face
    /// order (the ranks' own faces are consecutive runs of it), and writes
    /// the file; the other ranks return an empty text. Collective.
    template <int dim>
    std::string
    surface_vtu(const ContactInterface<dim>                     &interface,
                const std::function<Point<dim>(unsigned int)> &position,
                const SurfaceFields<dim>                        &fields)
    {
      // Rows: (0, VTK type, nodes in VTK order) per own slave face, then
      // (1, node, position, scalars, vectors) per node of those faces.
      std::vector<std::vector<double>> rows;
      std::vector<unsigned int>        own_nodes;
      std::vector<bool>                listed(interface.nodes.size(), false);
      for (unsigned int f = interface.own_faces.first; f < interface.own_faces.second; ++f)
        if (const auto &face = interface.faces[f]; face.slave)
          {
            const auto [type, nodes] = vtk_cell<dim>(face.nodes);
            rows.push_back({0., double(type)});
            for (const unsigned int n : nodes)
              {
                rows.back().push_back(n);
                if (!listed[n])
                  own_nodes.push_back(n);
                listed[n] = true;
              }
          }
      for (const unsigned int n : own_nodes)
        {
          std::vector<double> row = {1., double(n)};
          const Point<dim>    x   = position(n);
          row.insert(row.end(), x.begin_raw(), x.end_raw());
          for (const auto &[name, at] : fields.scalars)
            row.push_back(at(n));
          for (const auto &[name, at] : fields.vectors)
            {
              const Tensor<1, dim> v = at(n);
              row.insert(row.end(), v.begin_raw(), v.end_raw());
            }
          rows.push_back(row);
        }
      rows = gather_rows(interface.communicator(), rows, false);
      if (Utilities::MPI::this_mpi_process(interface.communicator()) != 0)
        return {};

      // A node's values from the first rank that gives them (every rank
      // holding a node has the same values).
      std::map<unsigned int, const std::vector<double> *> values;
      std::vector<int>          point_of_node(interface.nodes.size(), -1);
      std::vector<unsigned int> points, connectivity, offsets, types;
      for (const auto &row : rows)
        if (row[0] == 1.)
          values.emplace(static_cast<unsigned int>(row[1]), &row);
        else
          {
            for (unsigned int i = 2; i < row.size(); ++i)
              {
                const auto n = static_cast<unsigned int>(row[i]);
                if (point_of_node[n] < 0)
                  {
                    point_of_node[n] = points.size();
                    points.push_back(n);
                  }
                connectivity.push_back(point_of_node[n]);
              }
            offsets.push_back(connectivity.size());
            types.push_back(static_cast<unsigned int>(row[1]));
          }
      // The value at node n from position @p at of its row.
      const auto value = [&values](const unsigned int n, const unsigned int at) {
        return (*values.at(n))[2 + at];
      };
      const auto vector_at = [&value](const unsigned int n, const unsigned int at) {
        Tensor<1, dim> v;
        for (unsigned int d = 0; d < dim; ++d)
          v[d] = value(n, at + d);
        return v;
      };

      std::ostringstream out;
      out << std::setprecision(10);
      auto vector_values = [&](const unsigned int at) {
        for (const unsigned int n : points)
          {
            const Tensor<1, dim> v = vector_at(n, at);
            for (unsigned int d = 0; d < 3; ++d)
              out << (d < dim ? v[d] : 0.) << (d < 2 ? ' ' : '\n');
          }
      };
      out << "<?xml version=\"1.0\"?>\n"
          << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
          << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << points.size()
          << "\" NumberOfCells=\"" << types.size() << "\">\n"
          << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
      vector_values(0);
      out << "</DataArray>\n</Points>\n<Cells>\n"
          << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
      for (const unsigned int c : connectivity)
        out << c << '\n';
      out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
      for (const unsigned int o : offsets)
        out << o << '\n';
      out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
      for (const unsigned int t : types)
        out << t << '\n';
      out << "</DataArray>\n</Cells>\n<PointData>\n";
      unsigned int at = dim;
      for (const auto &field : fields.scalars)
        {
          out << "<DataArray type=\"Float64\" Name=\"" << field.first << "\" format=\"ascii\">\n";
          for (const unsigned int n : points)
            out << value(n, at) << '\n';
          out << "</DataArray>\n";
          ++at;
        }
      for (const auto &field : fields.vectors)
        {
          out << "<DataArray type=\"Float64\" Name=\"" << field.first
              << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
          vector_values(at);
          out << "</DataArray>\n";
          at += dim;
        }
      out << "</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
      return out.str();
    }

    /// The slave surfaces of @p state as an ASCII VTU: per node the contact
    /// pressure, the weighted gap, the active flag, the pair, the
    /// formulation's own fields, the traction vector on the slave and the
    /// displacement. A hanging vertex shows the interpolation of its parents.
    /// Whole on rank 0 (surface_vtu()). Collective.
    template <int dim>
    std::string
    contact_surface_vtu(const ContactState<dim> &state)
    {
      const ContactInterface<dim>   &interface = state.interface;
      const ContactFormulation<dim> &contact   = state.contact;
      const unsigned int             n_nodes   = interface.nodes.size();
      std::vector<double> pressure(n_nodes, 0.), gap(n_nodes, 0.), active(n_nodes, 0.),
        pair(n_nodes, -1.);
      std::vector<Tensor<1, dim>> traction(n_nodes);
      for (const auto &s : interface.slave_nodes)
        {
          pair[s.node] = s.pair;
          if (!s.paired)
            continue;
          pressure[s.node] = contact.normal_pressure(s.node);
          gap[s.node]      = interface.gap(s, state.displacement);
          active[s.node]   = contact.is_active(s.node) ? 1. : 0.;
          if (contact.is_active(s.node))
            traction[s.node] = contact.traction(s);
        }
      const auto own_fields = contact.nodal_fields(interface);
      SurfaceFields<dim> fields;
      fields.scalars = {{"contact_pressure", nodal_field(interface, pressure)},
                        {"weighted_gap", nodal_field(interface, gap)},
                        {"active", nodal_field(interface, active)},
                        {"pair", nodal_field(interface, pair)}};
      for (const auto &field : own_fields)
        fields.scalars.emplace_back(field.name, nodal_field(interface, field.values));
      // The points less the displacement are the reference positions.
      fields.vectors = {{"traction", nodal_field(interface, traction)},
                        {"displacement", [&](const unsigned int n) {
                           return interface.displacement(n, state.displacement);
                         }}};
      return surface_vtu<dim>(
        interface, [&state](const unsigned int n) { return state.position(n); }, fields);
    }

    /// The tied slave surfaces of @p tying as an ASCII VTU, as the contact
    /// surfaces: per node the tying traction on the slave (the master's
    /// traction on it, sigma n for the slave's outward normal n), its
    /// normal component (positive in tension), the tied flag (0 once
    /// released in tension), the pair and
    /// the displacement @p u (on every rank, ContactInterface::gather()).
    /// Whole on rank 0 (surface_vtu()). Collective.
    template <int dim>
    std::string
    tied_surface_vtu(const MeshTying<dim> &tying, const std::vector<double> &u)
    {
      const ContactInterface<dim> &interface = tying.interface();
      const unsigned int           n_nodes   = interface.nodes.size();
      std::vector<double>          tied(n_nodes, 0.), pair(n_nodes, -1.);
      const auto [traction, normal] = nodal_tying_tractions(tying);
      for (unsigned int k = 0; k < interface.slave_nodes.size(); ++k)
        {
          const auto &s = interface.slave_nodes[k];
          pair[s.node]  = s.pair;
          if (s.paired)
            tied[s.node] = tying.bond_of(k) == MeshTying<dim>::Bond::tied ? 1. : 0.;
        }
      SurfaceFields<dim> fields;
      fields.scalars = {{"normal_traction", nodal_field(interface, normal)},
                        {"tied", nodal_field(interface, tied)},
                        {"pair", nodal_field(interface, pair)}};
      fields.vectors = {{"traction", nodal_field(interface, traction)}, {"displacement", [&](const unsigned int n) {
                           return interface.displacement(n, u);
                         }}};
      return surface_vtu<dim>(
        interface,
        [&](const unsigned int n) {
          return interface.nodes[n].reference + interface.displacement(n, u);
        },
        fields);
    }

    template <int dim>
    void
    add_displacement(DataOut<dim> &data_out, const SolutionView<dim> &view)
    {
      const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector_field(
        dim, DataComponentInterpretation::component_is_part_of_vector);
      data_out.add_data_vector(view.dof_handler, view.solution,
                               std::vector<std::string>(dim, "displacement"), vector_field);
    }
  } // namespace

  template <int dim>
  VtuOutput<dim>::VtuOutput(const std::string &directory, const MPI_Comm comm)
    : directory(directory)
    , comm(comm)
  {}

  template <int dim>
  void
  VtuOutput<dim>::write_solution(const SolutionView<dim> &view,
                                 const unsigned int       cycle,
                                 const double             time,
                                 const MeshTying<dim>    *tying)
  {
    const auto        &triangulation = view.dof_handler.get_triangulation();
    const unsigned int degree        = view.dof_handler.get_fe().degree;
    // Nodal contact fields live on a scalar Q_p space on the same mesh.
    const FE_Q<dim> scalar_fe(degree);
    DoFHandler<dim> scalar_dofs(triangulation);
    scalar_dofs.distribute_dofs(scalar_fe);
    std::vector<std::string>                   names;
    std::vector<TrilinosWrappers::MPI::Vector> fields;
    if (view.contact)
      fields = contact_fields(view, scalar_dofs, names);
    // Only with tied pairs: the VTU of a scene without them is unchanged.
    std::pair<TrilinosWrappers::MPI::Vector, TrilinosWrappers::MPI::Vector> tying_traction;
    if (tying)
      tying_traction = tying_fields(view.dof_handler, scalar_dofs, *tying);

    DataOut<dim> data_out;
    data_out.attach_triangulation(triangulation);
    add_displacement(data_out, view);
    const StressFields<dim> stress(view);
    data_out.add_data_vector(view.dof_handler, view.solution, stress);
    for (unsigned int k = 0; k < fields.size(); ++k)
      data_out.add_data_vector(scalar_dofs, fields[k], names[k]);
    if (tying)
      {
        data_out.add_data_vector(
          view.dof_handler, tying_traction.first, std::vector<std::string>(dim, "tying_traction"),
          std::vector<DataComponentInterpretation::DataComponentInterpretation>(
            dim, DataComponentInterpretation::component_is_part_of_vector));
        data_out.add_data_vector(scalar_dofs, tying_traction.second, "tying_normal_traction");
      }
    Vector<float> material(triangulation.n_active_cells()),
      subdomain(triangulation.n_active_cells());
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          material(cell->active_cell_index())  = cell->material_id();
          subdomain(cell->active_cell_index()) = triangulation.locally_owned_subdomain();
        }
    data_out.add_data_vector(material, "material_id");
    data_out.add_data_vector(subdomain, "subdomain");
    data_out.build_patches(view.mapping, degree);
    data_out.set_flags(fast_vtk_flags());
    const std::string name =
      write_vtu_pieces<dim>(data_out, directory + "/", "solution", ++n_solutions, 3, comm);
    if (cycle != records_cycle)
      {
        cycle_records.clear();
        surface_records.clear();
        tied_records.clear();
      }
    records_cycle = cycle;
    cycle_records.emplace_back(time, name);
    write_collection("solution_cycle_" + std::to_string(cycle) + ".pvd", cycle_records);
    write_collection("solution.pvd", cycle_records);
    // Each rank gives its own faces, rank 0 writes the surfaces whole.
    if (view.contact)
      {
        const std::string text = contact_surface_vtu(*view.contact); // collective
        write_surface("contact_surface", [&] { return text; }, cycle, time, surface_records);
      }
    if (tying)
      {
        const std::vector<double> u = tying->interface().gather(view.solution); // collective
        const std::string text = tied_surface_vtu(*tying, u);                 // collective
        write_surface("tied_surface", [&] { return text; }, cycle, time, tied_records);
      }
  }

  template <int dim>
  void
  VtuOutput<dim>::write_surface(const std::string                           &prefix,
                                const std::function<std::string()>          &content,
                                const unsigned int                           cycle,
                                const double                                 time,
                                std::vector<std::pair<double, std::string>> &records)
  {
    const std::string surface = prefix + "_" + Utilities::int_to_string(n_solutions, 3) + ".vtu";
    const std::string path    = directory + "/" + surface;
    throw_if_unwritten(path,
                       Utilities::MPI::this_mpi_process(comm) != 0 ?
                         std::string() :
                         write_file_atomically(path, content()),
                       comm);
    records.emplace_back(time, surface);
    write_collection(prefix + "_cycle_" + std::to_string(cycle) + ".pvd", records);
    write_collection(prefix + ".pvd", records);
  }

  template <int dim>
  void
  VtuOutput<dim>::write_error_indicators(const SolutionView<dim> &view,
                                         const Vector<float>     &indicators,
                                         const unsigned int       cycle)
  {
    DataOut<dim> data_out;
    data_out.attach_dof_handler(view.dof_handler);
    add_displacement(data_out, view);
    data_out.add_data_vector(indicators, "error_indicator", DataOut<dim>::type_cell_data);
    data_out.build_patches(view.mapping, view.dof_handler.get_fe().degree);
    data_out.set_flags(fast_vtk_flags());
    const std::string name =
      write_vtu_pieces<dim>(data_out, directory + "/", "error_indicators", cycle, 2, comm);
    indicator_records.emplace_back(cycle, name);
    write_collection("error_indicators.pvd", indicator_records);
  }

  template <int dim>
  void
  VtuOutput<dim>::write_collection(const std::string                                 &name,
                                   const std::vector<std::pair<double, std::string>> &records) const
  {
    std::ostringstream pvd;
    DataOutBase::write_pvd_record(pvd, records);
    const std::string path = directory + "/" + name;
    throw_if_unwritten(path,
                       Utilities::MPI::this_mpi_process(comm) != 0 ?
                         std::string() :
                         write_file_atomically(path, pvd.str()),
                       comm);
  }

  namespace
  {
    /// The VTU/PVD files of every converged load step and of every cycle's
    /// error indicators (Output/Write VTU).
    template <int dim>
    class VtuFiles : public Postprocessor<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Write VTU", "true", Patterns::Bool(),
                          "Write the fields of every load step as VTU/PVTU.");
      }

      static std::unique_ptr<Postprocessor<dim>>
      create(const PostprocessorContext<dim> &context)
      {
        context.prm.enter_subsection("Output");
        const bool wanted = context.prm.get_bool("Write VTU");
        context.prm.leave_subsection();
        if (!wanted)
          return nullptr;
        return std::make_unique<VtuFiles<dim>>(context);
      }

      explicit VtuFiles(const PostprocessorContext<dim> &context)
        : files(context.output.directory, context.comm)
        , timer(context.timer)
      {}

      void
      after_load_step(const RunView<dim> &view, Json &, std::ostream &) override
      {
        TimerOutput::Scope t(timer, "Output: VTU");
        files.write_solution(view.solution, view.cycle, view.time, view.tying);
      }

      void
      after_estimate(const RunView<dim> &view, const Vector<float> &indicators) override
      {
        SolutionView<dim> without_contact = view.solution;
        without_contact.contact           = nullptr;
        files.write_error_indicators(without_contact, indicators, view.cycle);
      }

    private:
      VtuOutput<dim> files;
      TimerOutput   &timer;
    };
  } // namespace

  CONTACT_FEM_REGISTER_POSTPROCESSOR(VtuFiles, "vtu", 20)

  template class VtuOutput<2>;
  template class VtuOutput<3>;
} // namespace contact_fem
