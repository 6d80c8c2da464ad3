// The linear solver of the condensed Newton system, behind one interface.
#ifndef contact_fem_linear_solver_h
#define contact_fem_linear_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /// Thrown when the linear solver cannot solve the system. The message
  /// names the solver's error and its meaning; singular tells a singular
  /// matrix (a body that nothing holds) from the solver's own limits
  /// (workspace, memory, iterations), so that the caller does not blame the
  /// supports for a workspace shortage.
  struct LinearSolverFailure : public std::runtime_error
  {
    LinearSolverFailure(const std::string &what, const bool singular)
      : std::runtime_error(what)
      , singular(singular)
    {}
    bool singular;
  };

  /// What the caller knows about one system: whether it is symmetric, and
  /// the residual at which the Newton iteration accepts its result.
  struct LinearSystemRequest
  {
    bool symmetric = true;
    /// Newton's acceptance threshold for the equilibrium residual (force
    /// units); an iterative solver stops a fixed factor below it. 0: as
    /// accurate as the solver can.
    double newton_residual_target = 0.;
  };

  /// The properties of a scene that decide which solver can serve it.
  struct ProblemTraits
  {
    unsigned int dim = 2;
    /// Largest Young's modulus of a contact pair's slave side over that of
    /// its master side: the slave rows are condensed onto the master DoFs,
    /// and a stiff slave on a soft master puts stiffnesses of both sizes
    /// into the same aggregates.
    double slave_stiffness_ratio = 0.;
    /// Largest lambda / mu of the bodies (nu -> 0.5: lambda / mu -> inf).
    double largest_lambda_over_mu = 1.;
    /// Largest Young's modulus of the bodies over the smallest, whichever
    /// side of a pair the stiff one is.
    double youngs_modulus_contrast = 1.;
    /// Largest ratio of the longest to the shortest edge of a cell.
    double largest_aspect_ratio = 1.;
    /// Material ids of the bodies that no Dirichlet condition holds (no
    /// fixed or prescribed boundary, no fixed point): held only through
    /// contact, or not at all.
    std::vector<unsigned int> unsupported_bodies;
  };

  /// Why the multigrid of the iterative solver is known (measured,
  /// doc/stability.md) to converge slowly or not at all on a scene with
  /// @p traits; empty if no measured limit applies. Type = auto takes the
  /// direct solver where this is not empty, and a Krylov failure names it.
  std::string
  multigrid_limit_exceeded(const ProblemTraits &traits);

  /**
   * Solves the condensed Newton systems of one sparsity pattern. The driver
   * and the checks that probe the converged system (a weakly held rotation)
   * see the solver only through this class. Implementations: DirectSolver
   * (MUMPS or KLU), IterativeSolver (CG or GMRES with algebraic multigrid)
   * and AutomaticSolver, which picks one of the two per mesh.
   */
  class LinearSolver
  {
  public:
    virtual ~LinearSolver() = default;

    /// Subsection "Linear solver".
    static void
    declare_parameters(ParameterHandler &prm);

    /// The solver the "Linear solver" subsection of @p prm asks for.
    static std::unique_ptr<LinearSolver>
    create(ParameterHandler &prm);

    /// The scene, once its materials are known (AutomaticSolver decides
    /// with it).
    virtual void
    set_problem(const ProblemTraits &)
    {}

    /// A new mesh with @p n_dofs unknowns, before its first solve. Returns
    /// whether the solver wants the near-null space (the rigid-body modes)
    /// of this mesh through set_near_null_space().
    virtual bool
    select(const types::global_dof_index n_dofs)
    {
      (void)n_dofs;
      return false;
    }

    /// The rigid-body modes, each with one entry per locally owned DoF.
    virtual void
    set_near_null_space(std::vector<std::vector<double>> &&modes)
    {
      (void)modes;
    }

    /// One line for the log: which solver serves the current mesh.
    virtual std::string
    description() const = 0;

    /// Whether solve() iterates (then its iteration counts are reported).
    virtual bool
    iterative() const
    {
      return false;
    }

    /// Forgets everything tied to the matrix. Must be called before the
    /// matrix is re-created (new sparsity pattern).
    virtual void
    clear() = 0;

    /// Solves matrix x = rhs, starting from @p x if the solver iterates;
    /// returns the l2 norm of the final residual.
    virtual double
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          TrilinosWrappers::MPI::Vector        &x,
          const TrilinosWrappers::MPI::Vector  &rhs,
          const LinearSystemRequest            &request) = 0;

    /// Krylov iterations of the last solve(); 0 for a direct solver.
    virtual unsigned int
    last_iterations() const
    {
      return 0;
    }

    /// Wall seconds spent building preconditioners since the last call;
    /// clears them.
    virtual double
    take_setup_seconds()
    {
      return 0.;
    }

    /// Whether solve_again() can answer for the matrix of the last solve()
    /// at a small cost (kept factors or preconditioner).
    virtual bool
    can_solve_again() const = 0;

    /// The response of the matrix of the last solve() to another @p rhs.
    virtual void
    solve_again(TrilinosWrappers::MPI::Vector &x, const TrilinosWrappers::MPI::Vector &rhs) = 0;

    /// Whether n_null_pivots() means anything: only a factorisation sees
    /// zero pivots.
    virtual bool
    detects_null_pivots() const
    {
      return false;
    }

    /// Zero pivots of the last solve (free rigid-body modes the matrix
    /// leaves), for a solver that detects them; 0 otherwise.
    virtual unsigned int
    n_null_pivots() const = 0;

    /// What the solver had to do beyond the ordinary since the last call
    /// (e.g. retry with more workspace), for the console; empty if nothing.
    /// Clears it.
    virtual std::string
    take_note()
    {
      return {};
    }
  };
} // namespace contact_fem

#endif
