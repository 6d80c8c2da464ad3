// Rollers (Boundary conditions/Rollers): zero displacement normal to a flat
// boundary of any orientation, as affine constraints among the components
// of each node.
#ifndef contact_fem_inclined_supports_h
#define contact_fem_inclined_supports_h

#include <deal.II/base/tensor.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_fem/contact/contact_parameters.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  template <int dim>
  class InclinedSupports
  {
  public:
    /// Takes the normals of the boundaries @p ids from the coarse mesh
    /// @p coarse (every coarse cell is known on every rank). Throws, naming
    /// the key and the boundary, if one is not flat (its face normals differ
    /// by more than 1e-6 rad, or a curved manifold is attached), or if it
    /// shares a vertex with a contact surface of @p pairs.
    void
    initialize(const Triangulation<dim>              &coarse,
               const std::vector<types::boundary_id> &ids,
               const std::vector<ContactPair>        &pairs);

    bool
    empty() const
    {
      return normals.empty();
    }

    /// Adds to @p dirichlet (whose Fixed, prescribed and fixed-point lines
    /// are already there, not yet closed) per node of the roller boundaries
    /// n . u = 0 for each of its boundaries: the components with the largest
    /// coefficients are expressed by the others. Hanging nodes are left to
    /// their hanging constraints.
    void
    add_constraints(const DoFHandler<dim>           &dof_handler,
                    const AffineConstraints<double> &hanging,
                    AffineConstraints<double>       &dirichlet);

    /// Whether @p dof belongs to an owned node that a roller holds: its
    /// residual is partly a reaction.
    bool
    holds(const types::global_dof_index dof) const
    {
      return held.count(dof) > 0;
    }

    /// Sum over the owned held nodes of the squared residual in the
    /// directions left free by the rollers and fixed components there.
    double
    free_residual_squared(const TrilinosWrappers::MPI::Vector &residual) const;

  private:
    /// The nodes of the roller faces on this rank (owned and ghost cells),
    /// keyed by their x DoF: their DoFs by component and their boundaries.
    std::map<types::global_dof_index,
             std::pair<std::vector<types::global_dof_index>, std::set<types::boundary_id>>>
    roller_nodes(const DoFHandler<dim> &dof_handler) const;

    /// Adds the lines n . u = 0 of the @p rows at the node with @p dofs,
    /// whose @p fixed components are held already.
    void
    constrain_node(const std::vector<types::global_dof_index> &dofs,
                   std::vector<Tensor<1, dim>>                 rows,
                   const std::vector<bool>                    &fixed,
                   AffineConstraints<double>                  &dirichlet) const;

    std::map<types::boundary_id, Tensor<1, dim>> normals;
    struct Node
    {
      std::vector<types::global_dof_index> dofs;
      std::vector<Tensor<1, dim>>          held_directions; ///< orthonormal
    };
    std::vector<Node>                               owned_nodes;
    std::map<types::global_dof_index, unsigned int> held;
  };
} // namespace contact_fem

#endif
