// The rigid-body modes of a displacement field: the near-null space of
// linear elasticity, for algebraic multigrid.
#ifndef contact_fem_rigid_body_modes_h
#define contact_fem_rigid_body_modes_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /// The dim translations and dim (dim - 1) / 2 rotations of the
  /// vector-valued (one component per direction) @p dof_handler, each with
  /// one entry per locally owned DoF in the order of its IndexSet. The
  /// rotations are about the centre of the locally owned support points,
  /// which keeps their entries of the size of the mesh, not of its
  /// coordinates.
  template <int dim>
  std::vector<std::vector<double>>
  rigid_body_modes(const Mapping<dim> &mapping, const DoFHandler<dim> &dof_handler);
} // namespace contact_fem

#endif
