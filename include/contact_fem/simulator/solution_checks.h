// Checks of a converged solution against the model's range: displacements,
// strains and rotations beyond small-strain theory, and rigid rotations that
// only the discretisation holds.
#ifndef contact_fem_solution_checks_h
#define contact_fem_solution_checks_h

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_fem/core/json.h>
#include <contact_fem/solvers/rigid_body_modes.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  class LinearSolver;

  /**
   * Reads a converged solution and says where it leaves what the model
   * describes. Each check returns the text of its warning (empty if none);
   * the driver prints and records it.
   */
  template <int dim>
  class SolutionChecks
  {
  public:
    /// What the checks read of the run; all of it outlives the checks.
    struct ConvergedSystem
    {
      const DoFHandler<dim> &dof_handler;
      const Mapping<dim>    &mapping;
      /// All constraints of the last Newton system, and the supports among
      /// them (Fixed, Fixed points, prescribed displacements).
      const AffineConstraints<double>     &constraints;
      const AffineConstraints<double>     &dirichlet_constraints;
      const IndexSet                      &owned_dofs;
      const IndexSet                      &relevant_dofs;
      const TrilinosWrappers::MPI::Vector &solution;         ///< owned
      const TrilinosWrappers::MPI::Vector &ghosted_solution; ///< locally relevant
    };

    explicit SolutionChecks(const ConvergedSystem &system);

    /// Why |u|_max, beyond half the model size, leaves linear elasticity,
    /// or "". The cells of @p finite_strain_bodies count only @p
    /// with_contact (a contact gap linear in u), as in large_strain().
    std::string
    large_displacement(const std::set<types::material_id> &finite_strain_bodies = {},
                       const bool                          with_contact         = true) const;

    /// Records the largest principal strain and rotation in @p record;
    /// why they leave the small-strain range, or "". The cells of
    /// @p finite_strain_bodies (Materials/Models) follow their law at any
    /// strain: only their rotation is checked, and only @p with_contact
    /// (a contact gap linear in u: Contact/Kinematics small or updated).
    std::string
    large_strain(Json                               &record,
                 const std::set<types::material_id> &finite_strain_bodies = {},
                 const bool                          with_contact         = true) const;

    /// The probe for a weakly held rotation.
    struct HeldRotation
    {
      /// Per probed body: which axes its supports hold, which were probed
      /// (with theta G V), which not after a warning.
      Json check = Json::array();
      /// One per body that turns too easily.
      std::vector<std::string> warnings;
      std::string              skipped; ///< why the probe could not run, or ""
    };

    /// Loads every body with a face in @p contact_surfaces with a unit
    /// couple about each axis its supports do not hold, and solves with the
    /// kept factors of the converged system (@p solver): a rotation beyond
    /// what elasticity of the softest shear modulus @p softest_shear_modulus
    /// allows is held only by the discretisation. @p bodies: the material
    /// ids, sorted. Collective.
    HeldRotation
    weakly_held_rotation(const std::vector<types::material_id> &bodies,
                         const double                           softest_shear_modulus,
                         const std::set<types::boundary_id>    &contact_surfaces,
                         LinearSolver                          &solver) const;

  private:
    /// Volume, centroid and central second moments of a body.
    struct BodyMoments
    {
      double         volume = 0.;
      Point<dim>     centre;
      Tensor<1, dim> central; ///< int (x_i - c_i)^2
      /// The root mean square distance of the body from its centroid.
      double
      radius_of_gyration() const;
    };
    /// The moments of body @p body (material id). Collective.
    BodyMoments
    body_moments(const types::material_id body) const;
    /// Which DoFs @p dofs of @p cell hold the body as supports: fixed ones
    /// (lines of dirichlet_constraints without entries); in 3D only those
    /// on a boundary face whose DoFs of that component are all fixed.
    std::vector<bool>
    supporting_dofs(const typename DoFHandler<dim>::active_cell_iterator &cell,
                    const std::vector<types::global_dof_index>           &dofs) const;
    /// This rank's supporting DoFs of each body, each once, at their
    /// support points.
    std::map<types::material_id, std::vector<FixedDof<dim>>>
    fixed_dofs_by_body() const;
    /// The probe of one body with the supporting DoFs @p fixed: its
    /// entry of HeldRotation::check, and a warning if it turns too easily.
    /// Throws LinearSolverFailure if a probe's solve fails.
    void
    probe_body(const types::material_id          body,
               const std::vector<FixedDof<dim>> &fixed,
               const double                      softest_shear_modulus,
               LinearSolver                     &solver,
               HeldRotation                     &result) const;
    /// The mean rotation about @p axis (3D; the plane's in 2D) of @p body
    /// under a unit couple (body force omega x (x - centre) / polar),
    /// solved with the kept factors of @p solver.
    double
    rotation_under_couple(const types::material_id body,
                          const BodyMoments       &moments,
                          const unsigned int       axis,
                          LinearSolver            &solver) const;

    ConvergedSystem system;
    MPI_Comm        comm;
  };
} // namespace contact_fem

#endif
