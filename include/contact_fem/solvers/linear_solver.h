// The linear solver of the condensed Newton system, behind one interface.
#ifndef contact_fem_linear_solver_h
#define contact_fem_linear_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace contact_fem
{
  using namespace dealii;

  /// Thrown when the linear solver cannot solve the system. The message
  /// names the solver's error and its meaning; singular tells a singular
  /// matrix (a body that nothing holds) from the solver's own limits
  /// (workspace, memory), so that the caller does not blame the supports
  /// for a workspace shortage.
  struct LinearSolverFailure : public std::runtime_error
  {
    LinearSolverFailure(const std::string &what, const bool singular)
      : std::runtime_error(what)
      , singular(singular)
    {}
    bool singular;
  };

  /**
   * Solves the condensed Newton systems of one sparsity pattern. The driver
   * and the checks that probe the converged system (a weakly held rotation)
   * see the solver only through this class; today's implementation is the
   * sparse direct DirectSolver, and an iterative one is one more class here
   * and one more name in create().
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

    /// Forgets everything tied to the matrix. Must be called before the
    /// matrix is re-created (new sparsity pattern).
    virtual void
    clear() = 0;

    /// Solves matrix x = rhs; returns the l2 norm of the final residual.
    virtual double
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          TrilinosWrappers::MPI::Vector       &x,
          const TrilinosWrappers::MPI::Vector &rhs) = 0;

    /// Whether solve_again() can answer for the matrix of the last solve()
    /// at a small cost (kept factors or preconditioner).
    virtual bool
    can_solve_again() const = 0;

    /// The response of the matrix of the last solve() to another @p rhs.
    virtual void
    solve_again(TrilinosWrappers::MPI::Vector &x, const TrilinosWrappers::MPI::Vector &rhs) = 0;

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
