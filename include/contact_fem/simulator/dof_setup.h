// The DoF-level pieces of a mesh's set-up: the numbering, the DoFs of the
// vertices that the input names, the prescribed displacements as
// constraints, and the assembly of a cell into a two-space (Petrov-Galerkin)
// system.
#ifndef contact_fem_dof_setup_h
#define contact_fem_dof_setup_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <contact_fem/core/parameters.h>
#include <contact_fem/geometry/model_frame.h>
#include <contact_fem/simulator/inclined_supports.h>
#include <contact_fem/simulator/scene_parameters.h>

#include <string>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /// Distributes the DoFs of @p fe, in a random order of each rank's own
  /// DoFs if @p seed is not 0 (Finite element/DoF renumbering seed): the
  /// same order for the same mesh, seed and number of ranks.
  template <int dim>
  void
  distribute_dofs(DoFHandler<dim> &dof_handler, const FESystem<dim> &fe, const unsigned int seed);

  /// A point names a vertex closer than this times the cell's diameter
  /// (far above the digits a user types, far below the distance of two
  /// vertices of a valid cell).
  constexpr double vertex_match_tolerance = 1e-3;

  /// The dim DoFs of the vertex @p point of its body (user coordinates,
  /// @p frame), if a non-artificial cell of this rank has it (else empty);
  /// throws naming @p key and the nearest vertex if no rank has it.
  /// Collective.
  template <int dim>
  std::vector<types::global_dof_index>
  vertex_dofs(const DoFHandler<dim> &dof_handler,
              const ModelFrame<dim> &frame,
              const BodyPoint       &point,
              const std::string     &key);

  /// What the prescribed displacements are made of.
  template <int dim>
  struct DirichletInputs
  {
    const Mapping<dim>       &mapping;
    const DoFHandler<dim>    &dof_handler;
    const ModelFrame<dim>    &frame;
    const BoundaryConditions &boundary_conditions;
    /// The DoFs of Boundary conditions/Fixed points (held at 0).
    const std::vector<types::global_dof_index> &fixed_point_dofs;
    const AffineConstraints<double>            &hanging_constraints;
    InclinedSupports<dim>                      &inclined_supports; ///< adds the rollers
  };

  /// Fills @p dirichlet (on @p relevant_dofs) with the prescribed
  /// displacements at @p time, the fixed points and the rollers, closed.
  template <int dim>
  void
  make_dirichlet_constraints(const DirichletInputs<dim> &in,
                             const IndexSet             &relevant_dofs,
                             const double                time,
                             AffineConstraints<double>  &dirichlet);

  /// Adds a cell's matrix @p K and @p load when the test space differs from
  /// the trial space: the rows by @p test_constraints, the columns by
  /// @p constraints (whose inhomogeneities move to the right-hand side).
  void
  distribute_two_space(const FullMatrix<double>                   &K,
                       const Vector<double>                       &load,
                       const std::vector<types::global_dof_index> &dofs,
                       const AffineConstraints<double>            &constraints,
                       const AffineConstraints<double>            &test_constraints,
                       TrilinosWrappers::SparseMatrix             &matrix,
                       TrilinosWrappers::MPI::Vector              &rhs);
} // namespace contact_fem

#endif
