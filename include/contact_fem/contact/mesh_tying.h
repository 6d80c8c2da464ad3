// Mortar mesh tying: tied pairs glued by the dual-mortar coupling
// u_s = D^-1 M u_m, imposed as affine constraints.
#ifndef contact_fem_mesh_tying_h
#define contact_fem_mesh_tying_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/core/json.h>

#include <optional>
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
   *
   * With a release threshold (Contact/Tied release in tension), a tied
   * slave node whose normal tying traction pulls by more than the threshold
   * times the pair's traction scale is released for good (debonded) and
   * becomes a frictionless contact node of the pair: open (no line) while
   * its normal relative displacement n . (u_s - D^-1 M u_m) opens, held by
   * the normal line n . u_s = n . D^-1 M u_m when it would penetrate, and
   * open again when that line pulls. update_bonds() decides it per Newton
   * iteration, as an active set.
   */
  template <int dim>
  class MeshTying
  {
  public:
    /// The state of a tied slave node: tied, or released and then open or
    /// held by the normal contact line.
    enum class Bond : unsigned char
    {
      tied,
      open,
      held
    };

    /// What update_bonds() changed.
    struct BondUpdate
    {
      unsigned int changes = 0; ///< nodes released, opened or held
      std::string  cycling;     ///< not empty: the bonds came back (why)
    };

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
               const std::optional<double>     &release_threshold,
               const MPI_Comm                   comm);

    /// Sorted DoF indices of all nodes of the tied surfaces.
    const std::vector<types::global_dof_index> &
    dofs() const
    {
      return surfaces.dofs();
    }

    /// Throws, naming both pairs and the node, if a node of a tied surface
    /// is also on a contact surface of @p contact (an edge or corner they
    /// share), unless it is a master of both: its tying line and a contact
    /// line would conflict (a slave of both) or chain into a cycle.
    void
    check_apart_from(const ContactInterface<dim> &contact) const;

    /// Takes the Dirichlet values at dofs() of the present load step (from
    /// their owners, collective).
    void
    set_fixed_values(const std::function<double(types::global_dof_index)> &value_on_owner);

    /// Adds the tying lines of every tied slave node's free components and
    /// the normal lines of the held ones to @p constraints (lines already
    /// there are kept); for the @p test space without the prescribed values
    /// of fixed masters. @p all_candidates: every paired node as tied (the
    /// sparsity of any bond state).
    void
    add_constraints(AffineConstraints<double> &constraints,
                    const bool                 test           = false,
                    const bool                 all_candidates = false) const;

    /// Whether tied nodes are released in tension (a threshold was given).
    bool
    releases() const
    {
      return release_threshold.has_value();
    }

    /**
     * Releases the tied nodes whose normal traction (from the latest
     * condense_residual()) pulls beyond the threshold, holds the released
     * ones that penetrate by @p solution and opens the held ones that pull.
     * Iteration @p iteration of the load step (1 clears the record of the
     * step's bond states, used to tell a cycle). Collective.
     */
    BondUpdate
    update_bonds(const TrilinosWrappers::MPI::Vector &solution, const unsigned int iteration);

    /// Keeps the bonds of a converged load step.
    void
    accept_load_step()
    {
      accepted_bond = bond;
    }

    /// Back to the bonds of the last converged load step.
    void
    restore_load_step()
    {
      bond = accepted_bond;
    }

    /// The number of released slave nodes (open or held). Collective.
    unsigned int
    n_released() const;

    /// Per entry of interface().slave_nodes: the bond state.
    Bond
    bond_of(const unsigned int k) const
    {
      return bond[k];
    }

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
    /// Collective.
    unsigned int
    n_tied_nodes() const;

    /// The number of nodes of the tied slave surfaces: those beyond their
    /// master (not paired) stay free. Collective.
    unsigned int
    n_slave_surface_nodes() const;

    /// Per pair: the force of the master on the slave (the sum of r_j),
    /// the traction range and the nodes; printed to @p out as well.
    /// Collective.
    Json
    results(std::ostream &out) const;

    /// Distance of the mortar image of a tied slave node to the node, over
    /// its element size, above which the surfaces count as apart.
    static constexpr double max_distance_over_h = 0.25;

    /// A released node penetrates when its opening is below minus this
    /// fraction of its element size (not decided by round-off).
    static constexpr double penetration_over_h = 1e-8;

  private:
    /// Throws if a pair's surfaces do not touch (initialize()).
    void
    check_surfaces_touch() const;

    /// The normal line of held slave node @p s (n . u_s = n . D^-1 M u_m).
    void
    add_normal_line(const typename ContactInterface<dim>::SlaveNode &s,
                    AffineConstraints<double>                       &constraints,
                    const bool                                       test) const;

    /// The release in tension of pair @p p (@p largest its largest
    /// traction): the released and held nodes, the largest normal traction
    /// of a tied node and the openings of the open ones, set in @p record
    /// and printed to @p out.
    void
    release_results(const unsigned int p,
                    const double       largest,
                    Json              &record,
                    std::ostream      &out) const;

    /// The number of paired slave nodes of pair @p p. Collective.
    unsigned int
    n_paired(const unsigned int p) const;

    /// Per pair: the traction scale the release threshold is relative to.
    /// Collective.
    std::vector<double>
    traction_scales() const;

    /// Condenses the residual of slave node @p k into @p correction (by
    /// its bond) and sets its force and traction from @p r.
    void
    condense_node(const unsigned int         k,
                  const std::vector<double> &r,
                  std::vector<double>       &correction);

    /// Sets roller_rows and roller_projector from the lines of @p dirichlet
    /// (each owner its nodes, summed over @p comm).
    void
    find_roller_projectors(const DoFHandler<dim>           &dof_handler,
                           const AffineConstraints<double> &dirichlet,
                           const MPI_Comm                   comm);

    ContactInterface<dim> surfaces;
    std::vector<double>   fixed_values; ///< at dofs()
    /// Per entry of surfaces.slave_nodes: the projector onto the plane that
    /// its rollers leave free (I - sum n n^T over the normals of the
    /// Boundary conditions/Rollers lines of the node; the identity without
    /// one). The node is tied by u_s = P D^-1 M u_m, which holds n . u_s = 0
    /// itself: tying a component of an axis alone would replace the roller's
    /// line (the tying line comes first) by one the exact state does not
    /// meet, so the answer depended on how the model is turned.
    std::vector<Tensor<2, dim>> roller_projector;
    /// Per entry of surfaces.nodes: row p is the direction h the roller's
    /// line of component p holds (h_p = 1; zero rows for components without
    /// such a line).
    std::vector<Tensor<2, dim>> roller_rows;
    /// Per entry of surfaces.slave_nodes: the tying traction (on the slave).
    std::vector<Tensor<1, dim>> traction;
    /// Per entry of surfaces.slave_nodes: the residual r_j it came from.
    std::vector<Tensor<1, dim>> slave_force;

    std::optional<double> release_threshold;
    /// Per entry of surfaces.slave_nodes: the bond now and at the last
    /// converged load step, and the normal opening of the last update.
    std::vector<Bond>              bond, accepted_bond;
    std::vector<double>            opening;
    std::vector<std::vector<Bond>> bonds_of_iteration; ///< of this load step
  };
} // namespace contact_fem

#endif
