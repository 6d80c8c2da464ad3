#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/grid/grid_tools.h>

#include <contact_fem/adaptivity/marking.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace contact_fem::Marking
{
  template <int dim>
  void
  flag_cells(parallel::distributed::Triangulation<dim> &triangulation,
             const Vector<float>                       &indicators,
             const RefinementParameters                &parameters)
  {
    if (parameters.estimator == "global")
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            cell->set_refine_flag();
      }
    else if (parameters.strategy == "fixed fraction")
      parallel::distributed::GridRefinement::refine_and_coarsen_fixed_fraction(
        triangulation, indicators, parameters.refine_fraction, parameters.coarsen_fraction);
    else if (parameters.strategy == "fixed number")
      parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
        triangulation, indicators, parameters.refine_fraction, parameters.coarsen_fraction);
    else
      {
        float local_max = 0.;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            local_max = std::max(local_max, indicators(cell->active_cell_index()));
        const double largest =
          Utilities::MPI::max(double(local_max), triangulation.get_communicator());
        const double threshold = parameters.refine_fraction * largest;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() && indicators(cell->active_cell_index()) > threshold)
            cell->set_refine_flag();
      }
  }

  template <int dim>
  void
  flag_layers_behind_faces(parallel::distributed::Triangulation<dim> &triangulation,
                           const std::set<types::boundary_id>        &contact_ids,
                           const unsigned int                         layers,
                           const bool                                 along_surface)
  {
    if (contact_ids.empty())
      return;

    // The front: the cells flagged in the last layer, each with the faces
    // it passes the refinement on through (a bit per face). Straight
    // behind (@p along_surface false): the face opposite its contact faces,
    // then the one opposite the face it was reached by, i.e. the column
    // behind a flagged contact cell. Along the surface: every face, so
    // each layer also takes the neighbours along the contact surface.
    // Each process pulls the front from the cells next to its cells,
    // ghosts included, so the result does not depend on the partition.
    const auto passed_on = [&](const unsigned int f) -> unsigned char {
      return along_surface ? 0xff : 1u << GeometryInfo<dim>::opposite_face[f];
    };
    std::vector<unsigned char> front(triangulation.n_active_cells(), 0);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->refine_flag_set())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && contact_ids.count(cell->face(f)->boundary_id()))
            front[cell->active_cell_index()] |= passed_on(f);

    using CellIterator = typename Triangulation<dim>::active_cell_iterator;
    for (unsigned int layer = 1; layer < layers; ++layer)
      {
        GridTools::exchange_cell_data_to_ghosts<unsigned char, Triangulation<dim>>(
          triangulation,
          [&](const CellIterator &cell) -> std_cxx17::optional<unsigned char> {
            return front[cell->active_cell_index()];
          },
          [&](const CellIterator &cell, const unsigned char &value) {
            front[cell->active_cell_index()] = value;
          });
        // A cell joins through its face f if a front cell of its level or
        // finer across f passes the refinement on through that face.
        const auto passes = [&](const CellIterator &neighbor, const unsigned int face) {
          return neighbor->is_active() && (front[neighbor->active_cell_index()] >> face) & 1u;
        };
        std::vector<unsigned char> next(front.size(), 0);
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() && !cell->refine_flag_set())
            for (const auto f : cell->face_indices())
              {
                if (cell->at_boundary(f))
                  continue;
                const auto neighbor = cell->neighbor(f);
                bool       joins    = false;
                if (!neighbor->has_children())
                  joins = neighbor->level() == cell->level() &&
                          passes(neighbor, cell->neighbor_of_neighbor(f));
                else
                  // The children of the neighbor on this face number it
                  // as their parent does.
                  for (unsigned int sf = 0; sf < cell->face(f)->n_children(); ++sf)
                    joins = joins || passes(cell->neighbor_child_on_subface(f, sf),
                                            cell->neighbor_of_neighbor(f));
                if (joins)
                  next[cell->active_cell_index()] |= passed_on(f);
              }
        for (const auto &cell : triangulation.active_cell_iterators())
          if (next[cell->active_cell_index()])
            cell->set_refine_flag();
        front = std::move(next);
      }
  }

  template <int dim>
  void
  flag_master_faces_opposite_flagged_slave_faces(DoFHandler<dim>             &dof_handler,
                                                 const ContactInterface<dim> &interface)
  {
    // An interface face is known by the DoFs of the first component of its
    // nodes. The faces of this rank's cells are the ones it contributed
    // (ContactInterface::own_faces).
    const FiniteElement<dim> &fe    = dof_handler.get_fe();
    const auto [first_own, end_own] = interface.own_faces;
    std::map<std::vector<types::global_dof_index>, unsigned int> face_of_dofs;
    for (unsigned int i = first_own; i < end_own; ++i)
      {
        std::vector<types::global_dof_index> key;
        for (const unsigned int n : interface.faces[i].nodes)
          key.push_back(interface.nodes[n].dofs[0]);
        std::sort(key.begin(), key.end());
        face_of_dofs[key] = i;
      }
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    const auto interface_face = [&](const auto &cell, const unsigned int f) {
      cell->face(f)->get_dof_indices(face_dofs);
      std::vector<types::global_dof_index> key;
      for (unsigned int i = 0; i < face_dofs.size(); ++i)
        if (fe.face_system_to_component_index(i, f).first == 0)
          key.push_back(face_dofs[i]);
      std::sort(key.begin(), key.end());
      const auto it = face_of_dofs.find(key);
      return it == face_of_dofs.end() ? numbers::invalid_unsigned_int : it->second;
    };

    // This rank's flagged slave faces.
    std::set<unsigned int> slave_flagged;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->refine_flag_set())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            if (const unsigned int i = interface_face(cell, f);
                i != numbers::invalid_unsigned_int && interface.faces[i].slave)
              slave_flagged.insert(i);

    // Refinement halves a face, so a master face is "comparable" to the
    // children of its slave face unless it is nearer (on the log scale)
    // to twice their length than to their length. Each rank decides for
    // the masters of its flagged slave faces (its own faces, and their
    // coupled master faces are within their reach); the master faces so
    // marked are sent to their owners (faces are numbered rank by rank:
    // the owner is the rank whose own_faces holds the number), so the owner
    // of a master face refines it whoever owns the slave.
    const MPI_Comm            comm          = dof_handler.get_communicator();
    const double              largest_ratio = std::sqrt(2.);
    const auto                owned_ranges  = Utilities::MPI::all_gather(comm, interface.own_faces);
    std::map<unsigned int, std::vector<unsigned int>> marked;
    for (const auto &[slave, master] : interface.coupled_faces)
      if (slave_flagged.count(slave) &&
          interface.face_lengths[master] > largest_ratio * 0.5 * interface.face_lengths[slave])
        {
          const auto owner = std::partition_point(owned_ranges.begin(), owned_ranges.end(),
                                                  [m = master](const auto &range) {
                                                    return range.second <= m;
                                                  });
          AssertThrow(owner != owned_ranges.end() && owner->first <= master, ExcInternalError());
          marked[owner - owned_ranges.begin()].push_back(master);
        }
    std::set<unsigned int> refine_master;
    for (const auto &[rank, faces] : Utilities::MPI::some_to_some(comm, marked))
      refine_master.insert(faces.begin(), faces.end());

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && !cell->refine_flag_set())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            if (const unsigned int i = interface_face(cell, f);
                i != numbers::invalid_unsigned_int && refine_master.count(i))
              {
                cell->clear_coarsen_flag();
                cell->set_refine_flag();
              }
  }

  template void
  flag_cells(parallel::distributed::Triangulation<2> &,
             const Vector<float> &,
             const RefinementParameters &);
  template void
  flag_cells(parallel::distributed::Triangulation<3> &,
             const Vector<float> &,
             const RefinementParameters &);
  template void
  flag_layers_behind_faces(parallel::distributed::Triangulation<2> &,
                           const std::set<types::boundary_id> &,
                           const unsigned int,
                           const bool);
  template void
  flag_layers_behind_faces(parallel::distributed::Triangulation<3> &,
                           const std::set<types::boundary_id> &,
                           const unsigned int,
                           const bool);
  template void
  flag_master_faces_opposite_flagged_slave_faces(DoFHandler<2> &, const ContactInterface<2> &);
  template void
  flag_master_faces_opposite_flagged_slave_faces(DoFHandler<3> &, const ContactInterface<3> &);
} // namespace contact_fem::Marking
