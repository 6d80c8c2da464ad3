// The rigid-body modes of a displacement field: the near-null space of
// linear elasticity, for algebraic multigrid; and how far a body's supports
// hold its rigid rotations.
#ifndef contact_fem_rigid_body_modes_h
#define contact_fem_rigid_body_modes_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
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

  /// Component @p d of the displacement of a point at @p x from the centre
  /// under a unit rotation about axis @p r (0, 1, 2 in 3D; in 2D only 0, the
  /// plane's normal): (e_r x x)_d.
  template <int dim>
  inline double
  rotation_displacement(const unsigned int r, const unsigned int d, const Tensor<1, dim> &x)
  {
    const unsigned int axis = dim == 2 ? 2 : r;
    const unsigned int i1 = (axis + 1) % 3, i2 = (axis + 2) % 3;
    if (d == i1 && i2 < dim)
      return -x[i2];
    if (d == i2 && i1 < dim)
      return x[i1];
    return 0.;
  }

  /// A DoF that a support holds fixed: its support point and component.
  template <int dim>
  struct FixedDof
  {
    Point<dim>   point;
    unsigned int component;
  };

  /**
   * How firmly the fixed DoFs of one body hold each of its rigid rotations
   * (1 in 2D, 3 in 3D), as a lever arm over @p size: of the rigid motions
   * t + omega x (x - @p centre) with omega_r = 1, the one that moves the
   * fixed DoFs least (least squares) is taken, and its largest displacement
   * of a fixed DoF is the lever arm. Zero (to round-off) if a rigid motion
   * with a rotation about axis r moves no fixed DoF; small if the supports
   * that hold it lie close to a common axis (two fixed points close
   * together). The largest displacement, not the mean, so that the result
   * does not depend on how densely the supports are meshed.
   *
   * @p fixed holds this rank's share of the body's fixed DoFs, each DoF on
   * one rank only. Collective; every rank returns the same values.
   */
  template <int dim>
  std::vector<double>
  support_lever_arms(const std::vector<FixedDof<dim>> &fixed,
                     const Point<dim>                 &centre,
                     const double                      size,
                     const MPI_Comm                    comm);
} // namespace contact_fem

#endif
