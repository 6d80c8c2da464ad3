// Frictionless mortar contact: the augmented-Lagrangian formulation with
// exact active constraints (semi-smooth Newton), or its penalty
// regularisation, optionally with adaptive nodal penalties.
#ifndef contact_fem_frictionless_contact_h
#define contact_fem_frictionless_contact_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_fem/contact_interface.h>
#include <contact_fem/parameters.h>

#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /**
   * The normal contact conditions of every paired slave node j,
   *   lambda_j >= 0,  g_j >= 0,  lambda_j g_j = 0,
   * written as the nonlinear complementarity function
   *   C_j = lambda_j - max(0, lambda_j - eps g_j) = 0,
   * where lambda_j is the contact pressure (positive in compression), g_j the
   * normalised weighted gap and eps the penalty. Its semi-smooth Newton
   * linearisation is: on the active set A = {lambda_j - eps g_j > 0} the gap
   * vanishes, elsewhere lambda_j = 0.
   *
   * Because the dual basis makes D diagonal, the condition g_j = 0 of an
   * active node fixes one displacement component of that node in terms of the
   * master DoFs, so it is imposed as an affine constraint (exact static
   * condensation of the multipliers), and lambda_j is recovered afterwards
   * from the residual of that eliminated DoF: lambda_j = -r_c / (D_j n_j,c).
   *
   * With Formulation = penalty frictionless (parameters.regularised()) the
   * same weighted gaps are penalised instead: an active node (g_j < 0)
   * carries lambda_j = eps_j (-g_j), from the energy sum_j 1/2 eps_j D_j g_j^2,
   * whose stiffness and load assemble_penalty() adds to the system; no
   * constraints. With Adaptive penalty, eps_j is updated in every iteration
   * from the penetrations of this and the previous iteration (the rule of
   * Bussetta, Marceau and Ponthot) until each is below the allowed one.
   *
   * Implemented in source/frictionless_contact.cc.
   */
  template <int dim>
  class FrictionlessContact
  {
  public:
    explicit FrictionlessContact(const ContactParameters &parameters);

    /// Resets the state for a new mesh of @p interface.
    void
    initialize(const ContactInterface<dim> &interface);

    /**
     * After a search: sets the penalty and scale factor of every pair and
     * the active set at the start of a load step, from the last converged
     * multipliers and the gaps at @p u. On the first step of a mesh, nodes
     * with a gap below "Active check factor" * h also start active.
     */
    void
    start_load_step(const ContactInterface<dim> &interface,
                    const std::vector<double>   &u,
                    const bool                   first_step);

    /**
     * Adds the constraint g_j(u) = 0 of every active node (all paired nodes
     * with @p all_candidates, for the sparsity pattern). @p fixed_values are
     * the Dirichlet values at the interface DoFs.
     */
    void
    add_constraints(const ContactInterface<dim> &interface,
                    const std::vector<double>   &fixed_values,
                    AffineConstraints<double>   &constraints,
                    const bool                   all_candidates = false) const;

    /**
     * Penalty formulation: adds, for every active slave node whose first DoF
     * is in @p owned (so that each node is added once), eps_j D_j grad g_j
     * grad g_j^T to @p matrix and -eps_j D_j g_j(0) grad g_j to @p rhs,
     * through @p constraints. The caller compresses.
     */
    void
    assemble_penalty(const ContactInterface<dim>    &interface,
                     const AffineConstraints<double> &constraints,
                     const IndexSet                  &owned,
                     TrilinosWrappers::SparseMatrix  &matrix,
                     TrilinosWrappers::MPI::Vector   &rhs) const;

    /// Penalty formulation: the couplings assemble_penalty() may create, for
    /// every paired slave node whose first DoF is in @p owned.
    void
    add_penalty_sparsity(const ContactInterface<dim>    &interface,
                         const AffineConstraints<double> &constraints,
                         const IndexSet                  &owned,
                         DynamicSparsityPattern          &pattern) const;

    /// lambda_j from the bulk residual r = C_h^T (K u - f) at the interface DoFs
    /// (ALM; the penalty formulation computes lambda_j from the gap instead).
    void
    recover_multipliers(const ContactInterface<dim> &interface,
                        const std::vector<double>   &residual);

    /// Recomputes the active set from lambda - eps g; returns the number of
    /// nodes that changed state. Released nodes get lambda = 0.
    unsigned int
    update_active_set(const ContactInterface<dim> &interface,
                      const std::vector<double>   &u);

    /// Residuals of the current iterate for the active set just computed.
    struct Residuals
    {
      double multiplier = 0.;            ///< |(g_A, lambda_I / k)|, a length
      std::vector<double> contact_force; ///< at the interface DoFs
    };
    Residuals
    residuals(const ContactInterface<dim> &interface,
              const std::vector<double>   &u) const;

    /// Number of active slave nodes.
    unsigned int
    n_active() const;

    std::vector<double>       pressure; ///< lambda per interface node
    std::vector<bool>         active;   ///< per interface node
    std::vector<double>       penalty;  ///< eps per pair
    std::vector<double>       scale;    ///< k per pair
    /// Penalty formulation: eps_j per interface node (adapted or the pair's).
    std::vector<double> node_penalty;

  private:
    ContactParameters parameters;
    /// The component eliminated for an active node, or dim if none can be.
    unsigned int
    eliminated_component(const ContactInterface<dim>                    &interface,
                         const typename ContactInterface<dim>::SlaveNode &s) const;
    /// Multipliers of released nodes before the reset (for the residual).
    std::vector<double> released_pressure;
    /// The DoFs of slave node @p s and its masters, with grad g_j there.
    void
    gap_gradient(const ContactInterface<dim>                     &interface,
                 const typename ContactInterface<dim>::SlaveNode &s,
                 std::vector<types::global_dof_index>            &dofs,
                 std::vector<double>                             &gradient) const;
    /// Penalty formulation: the gap of the previous iteration, per node.
    std::vector<double> previous_gap;
    /// Bussetta-Marceau-Ponthot update of a nodal penalty @p eps from the
    /// penetrations (> 0 when overlapping) of this and the previous iteration.
    double
    adapted_penalty(const double eps,
                    const double penetration,
                    const double previous_penetration,
                    const double allowed) const;
  };
} // namespace contact_fem

#endif
