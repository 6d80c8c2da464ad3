#include <deal.II/base/mpi.h>
#include <deal.II/numerics/vector_tools.h>

#include <contact_fem/core/format.h>
#include <contact_fem/simulator/dof_setup.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace contact_fem
{
  template <int dim>
  void
  distribute_dofs(DoFHandler<dim> &dof_handler, const FESystem<dim> &fe, const unsigned int seed)
  {
    dof_handler.distribute_dofs(fe);
    if (seed == 0)
      return;
    // Each rank shuffles its own range: deal.II 9.4's DoFRenumbering::random
    // has a fixed seed and shuffles all n_dofs numbers, which a distributed
    // DoFHandler on several ranks does not accept (it takes the new numbers
    // of the owned DoFs only). The set-up of a mesh and its refinement both
    // call this on one mesh and get the same order.
    const MPI_Comm                       comm  = dof_handler.get_communicator();
    const IndexSet                      &owned = dof_handler.locally_owned_dofs();
    std::vector<types::global_dof_index> new_numbers(owned.begin(), owned.end());
    std::mt19937 generator(seed + 7919 * Utilities::MPI::this_mpi_process(comm));
    std::shuffle(new_numbers.begin(), new_numbers.end(), generator);
    dof_handler.renumber_dofs(new_numbers);
  }

  template <int dim>
  std::vector<types::global_dof_index>
  vertex_dofs(const DoFHandler<dim> &dof_handler,
              const ModelFrame<dim> &frame,
              const BodyPoint       &point,
              const std::string     &key)
  {
    Point<dim> user;
    for (unsigned int d = 0; d < dim; ++d)
      user[d] = point.coordinates[d];
    const Point<dim> location = frame.to_model(user);
    // The nearest vertex of the body, in units of its cell's diameter: a
    // point typed with fewer digits than the mesh file holds (a rotated
    // mesh) still names its vertex, and a miss names the nearest one.
    std::vector<types::global_dof_index> dofs;
    std::pair<double, Point<dim>>        nearest(std::numeric_limits<double>::infinity(), {});
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (cell->is_artificial() || cell->material_id() != point.material_id)
          continue;
        for (const auto v : cell->vertex_indices())
          {
            const double distance = cell->vertex(v).distance(location) / cell->diameter();
            if (distance < nearest.first)
              {
                // Printed: coordinates of round-off size (on a symmetry
                // line) as 0, so that the message is the same everywhere.
                nearest = {distance, frame.to_user(cell->vertex(v))};
                for (unsigned int d = 0; d < dim; ++d)
                  if (std::abs(nearest.second[d]) < 1e-10 * cell->diameter())
                    nearest.second[d] = 0.;
              }
            if (distance < vertex_match_tolerance && dofs.empty())
              for (unsigned int d = 0; d < dim; ++d)
                dofs.push_back(cell->vertex_dof_index(v, d));
          }
        // The nearest vertex matters only where no rank finds the point.
        if (!dofs.empty())
          break;
      }
    const MPI_Comm     comm  = dof_handler.get_communicator();
    const unsigned int found = dofs.empty() ? 0 : 1;
    if (Utilities::MPI::sum(found, comm) == 0)
      {
        for (const auto &candidate : Utilities::MPI::all_gather(comm, nearest))
          if (candidate.first < nearest.first)
            nearest = candidate;
        const std::string text = to_string(point);
        AssertThrow(false,
                    ExcMessage(key + ": body " + std::to_string(point.material_id) +
                               " has no mesh vertex at (" + text.substr(text.find('@') + 2) + ")" +
                               (std::isfinite(nearest.first) ?
                                  "; its nearest vertex is " +
                                    coordinates_text(frame.to_model(nearest.second)) + ", " +
                                    significant(nearest.first, 2) +
                                    " of its cell's diameter away (a point names a vertex "
                                    "within " +
                                    significant(vertex_match_tolerance, 2) + ")" :
                                  "; the body has no cells") +
                               "."));
      }
    return dofs;
  }

  template <int dim>
  void
  make_dirichlet_constraints(const DirichletInputs<dim> &in,
                             const IndexSet             &relevant_dofs,
                             const double                time,
                             AffineConstraints<double>  &dirichlet)
  {
    dirichlet.clear();
    dirichlet.reinit(relevant_dofs);
    for (const auto &condition : in.boundary_conditions.displacements)
      {
        std::vector<std::string> expressions(dim, "0");
        expressions[condition.component] = condition.expression;
        UserFunction<dim> function(expressions, in.frame);
        function.set_time(time);
        ComponentMask mask(dim, false);
        mask.set(condition.component, true);
        VectorTools::interpolate_boundary_values(in.mapping, in.dof_handler, condition.boundary_id,
                                                 function, dirichlet, mask);
      }
    for (const auto dof : in.fixed_point_dofs)
      if (!dirichlet.is_constrained(dof))
        dirichlet.add_line(dof);
    in.inclined_supports.add_constraints(in.dof_handler, in.hanging_constraints, dirichlet);
    dirichlet.close();
  }

  void
  distribute_two_space(const FullMatrix<double>                   &K,
                       const Vector<double>                       &load,
                       const std::vector<types::global_dof_index> &dofs,
                       const AffineConstraints<double>            &constraints,
                       const AffineConstraints<double>            &test_constraints,
                       TrilinosWrappers::SparseMatrix             &matrix,
                       TrilinosWrappers::MPI::Vector              &rhs)
  {
    // P (K (C u~ + b) - f) = 0 with the trial constraints u = C u~ + b and
    // the test constraints P: the rows follow the test space, the columns
    // the trial space, and the inhomogeneity b moves to the right-hand side.
    const unsigned int n = dofs.size();
    Vector<double>     b(n), local_rhs(load);
    for (unsigned int i = 0; i < n; ++i)
      if (constraints.is_constrained(dofs[i]))
        b(i) = constraints.get_inhomogeneity(dofs[i]);
    b *= -1.;
    K.vmult_add(local_rhs, b);
    test_constraints.distribute_local_to_global(K, dofs, constraints, dofs, matrix);
    test_constraints.distribute_local_to_global(local_rhs, dofs, rhs);
    // The two-space form leaves the eliminated rows empty: a diagonal entry
    // of the bulk's scale keeps the matrix regular (the value is overwritten
    // by distribute()). Both spaces eliminate the same DoFs.
    for (unsigned int i = 0; i < n; ++i)
      if (constraints.is_constrained(dofs[i]))
        matrix.add(dofs[i], dofs[i], std::abs(K(i, i)));
  }

#define INSTANTIATE(dim)                                                                       \
  template void distribute_dofs(DoFHandler<dim> &, const FESystem<dim> &, const unsigned int); \
  template std::vector<types::global_dof_index> vertex_dofs(const DoFHandler<dim> &,           \
                                                            const ModelFrame<dim> &,           \
                                                            const BodyPoint &,                 \
                                                            const std::string &);              \
  template void make_dirichlet_constraints(const DirichletInputs<dim> &, const IndexSet &,     \
                                           const double, AffineConstraints<double> &);
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace contact_fem
