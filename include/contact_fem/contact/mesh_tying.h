// Mortar mesh tying: tied pairs glued by the dual-mortar coupling
// u_s = D^-1 M u_m, imposed as affine constraints.
#ifndef contact_fem_mesh_tying_h
#define contact_fem_mesh_tying_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/core/json.h>

#include <string>
#include <vector>

namespace contact_fem
{
  /**
   * The tied pairs of a scene (Contact/Tied pairs): non-matching surfaces
   * glued by the full vector dual-mortar coupling. Per paired slave node j
   * and free component c,
   *
   *     u_j,c = sum_l (M_jl / D_j) u_l,c ,
   *
   * with D and M of the contact machinery (ContactInterface: the same
   * search, segmentation, dual basis, rim and hanging-vertex treatment),
   * built once per mesh on the reference configuration. The coupling is of
   * displacements, so a small initial mismatch of the two discrete
   * surfaces (chords of a curved interface) is kept, not closed, and D^-1 M
   * reproduces every rigid translation because sum_l M_jl = D_j.
   *
   * The lines are exact eliminations of the multipliers (as the active gap
   * conditions of the contact formulations). The tying traction is the
   * multiplier lambda_j = r_j / D_j from the residual r = K u - f at the
   * slave node (the force the master exerts on the slave, over its dual
   * weight); the residual the Newton monitor and the reactions read is then
   * condensed, C_t^T r, so that the slave's force is carried by its masters.
   *
   * A slave component under a Dirichlet condition keeps it (is not tied);
   * a fixed master component enters the line as its prescribed value.
   */
  template <int dim>
  class MeshTying
  {
  public:
    /// Builds the tied surfaces of @p pairs (arguments as for
    /// ContactInterface::initialize()), integrates the operators on the
    /// reference configuration (slave boxes grown by @p search_factor
    /// times the face length, as in contact) and checks that the surfaces
    /// touch: throws
    /// naming Contact/Tied pairs if a pair has no slave node facing its
    /// master, or one whose mortar image is farther than
    /// max_distance_over_h of its element size.
    void
    initialize(const MappingQ<dim>             &mapping,
               const DoFHandler<dim>           &dof_handler,
               const std::vector<ContactPair>  &pairs,
               const AffineConstraints<double> &dirichlet,
               const AffineConstraints<double> &hanging,
               const Materials<dim>            &materials,
               const double                     search_factor,
               const MPI_Comm                   comm);

    /// Sorted DoF indices of all nodes of the tied surfaces.
    const std::vector<types::global_dof_index> &
    dofs() const
    {
      return surfaces.dofs();
    }

    /// Takes the Dirichlet values at dofs() of the present load step (from
    /// their owners, collective).
    void
    set_fixed_values(const std::function<double(types::global_dof_index)> &value_on_owner);

    /// Adds the tying lines of every paired slave node's free components to
    /// @p constraints (lines already there are kept); for the @p test space
    /// without the prescribed values of fixed masters.
    void
    add_constraints(AffineConstraints<double> &constraints, const bool test = false) const;

    /**
     * Recovers the tying tractions from @p residual (r = K u - f, hanging
     * rows condensed; ghosted on dofs()) and condenses it in place: the
     * slave rows of the tied components go to their masters with the
     * weights M_jl / D_j and are zeroed. Collective.
     */
    void
    condense_residual(TrilinosWrappers::MPI::Vector &residual, const IndexSet &owned);

    /// The tied surfaces (nodes, slave faces and mortar operators).
    const ContactInterface<dim> &
    interface() const
    {
      return surfaces;
    }

    /// Per entry of interface().slave_nodes: the tying traction on the
    /// slave from the latest condense_residual() (zero where not tied).
    const std::vector<Tensor<1, dim>> &
    tractions() const
    {
      return traction;
    }

    /// The number of tied slave nodes (paired, with a multiplier).
    unsigned int
    n_tied_nodes() const;

    /// Per pair: the force of the master on the slave (the sum of r_j),
    /// the traction range and the nodes; printed to @p out as well.
    Json
    results(std::ostream &out) const;

    /// Distance of the mortar image of a tied slave node to the node, over
    /// its element size, above which the surfaces count as apart.
    static constexpr double max_distance_over_h = 0.25;

  private:
    /// Throws if a pair's surfaces do not touch (initialize()).
    void
    check_surfaces_touch() const;

    ContactInterface<dim> surfaces;
    std::vector<double>   fixed_values; ///< at dofs()
    /// Per entry of surfaces.slave_nodes: the tying traction (on the slave).
    std::vector<Tensor<1, dim>> traction;
    /// Per entry of surfaces.slave_nodes: the residual r_j it came from.
    std::vector<Tensor<1, dim>> slave_force;
  };
} // namespace contact_fem

#endif
