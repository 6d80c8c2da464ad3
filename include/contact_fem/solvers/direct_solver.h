// Sparse direct solution of the condensed Newton system.
#ifndef contact_fem_direct_solver_h
#define contact_fem_direct_solver_h

#include <contact_fem/solvers/linear_solver.h>

#include <memory>
#include <stdexcept>
#include <string>

class Amesos_BaseSolver;
class Epetra_CrsMatrix;
class Epetra_LinearProblem;

namespace contact_fem
{
  using namespace dealii;

  class RankZeroMumps;


  /**
   * A Trilinos Amesos direct solver (KLU or MUMPS) for one sparsity pattern.
   * The symbolic factorisation (fill-reducing ordering) depends only on the
   * pattern, which stays the same over the Newton iterations and load steps
   * of one mesh, so it is computed once per mesh; each solve() only
   * refactorises the values. MUMPS orders with METIS (nested dissection),
   * a good ordering for 2D and 3D finite-element graphs, and detects zero
   * pivots (n_null_pivots()).
   *
   * solve() also applies up to three steps of iterative refinement with the
   * same factors: large stiffness contrasts (1e8 and more between the
   * bodies) cost the factorisation most of its digits, and refinement
   * recovers them as long as the system is not singular.
   *
   * A MUMPS factorisation that runs out of its workspace (INFOG(1) = -8,
   * -9, -17, -20: numerical pivoting delayed more pivots than the analysis
   * foresaw) is retried once with a larger workspace (ICNTL(14)); other
   * failures throw LinearSolverFailure with the MUMPS error code and its
   * meaning.
   *
   * Implemented in source/direct_solver.cc.
   */
  class DirectSolver : public LinearSolver
  {
  public:
    /// @p amesos_name: "Amesos_Klu" or "Amesos_Mumps".
    explicit DirectSolver(const std::string &amesos_name);
    ~DirectSolver();

    /// Forgets the factorisation. Must be called before the matrix is
    /// re-created (new sparsity pattern): the solver refers to it.
    void
    clear() override;

    std::string
    description() const override;

    /// Solves matrix x = rhs to the accuracy of the factorisation (the
    /// request's target is not needed); returns the l2 norm of the final
    /// residual.
    double
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          TrilinosWrappers::MPI::Vector        &x,
          const TrilinosWrappers::MPI::Vector  &rhs,
          const LinearSystemRequest            &request) override;

    bool
    can_solve_again() const override
    {
      return has_factorisation();
    }

    void
    solve_again(TrilinosWrappers::MPI::Vector &x, const TrilinosWrappers::MPI::Vector &rhs) override
    {
      solve_with_last_factors(x, rhs);
    }

    /// Solves with the factors of the last solve() (back substitution only,
    /// no refinement): the response of the same system to another load.
    /// Requires a factorisation (has_factorisation()).
    void
    solve_with_last_factors(TrilinosWrappers::MPI::Vector       &x,
                            const TrilinosWrappers::MPI::Vector &rhs);

    bool
    has_factorisation() const;

    bool
    detects_null_pivots() const override
    {
      return amesos_name == "Amesos_Mumps";
    }

    /// Zero pivots of the last factorisation (MUMPS; always 0 for KLU): the
    /// number of rigid-body modes the matrix leaves free.
    unsigned int
    n_null_pivots() const override
    {
      return null_pivots;
    }

    /// What the solver had to do beyond the plain factorisation since the
    /// last call (e.g. a retry with a larger workspace), for the log; empty
    /// if nothing. Clears it.
    std::string
    take_note() override;

  private:
    std::string amesos_name;
    std::string note;
    /// MUMPS ICNTL(14) once a factorisation ran out of workspace; 0: the
    /// default.
    int                                   workspace_percent = 0;
    std::unique_ptr<Epetra_LinearProblem> problem;
    /// KLU (Amesos).
    std::unique_ptr<Amesos_BaseSolver> solver;
    /// MUMPS, on process 0 (rank_zero_mumps.h: deterministic under MPI).
    std::unique_ptr<RankZeroMumps> mumps;
    /// The matrix whose pattern the symbolic factorisation belongs to.
    const Epetra_CrsMatrix *factorised_matrix   = nullptr;
    std::size_t             factorised_nonzeros = 0;
    unsigned int            null_pivots         = 0;

    void
    factorise(const TrilinosWrappers::SparseMatrix &matrix);
    /// The symbolic factorisation of a new pattern.
    void
    analyse(const TrilinosWrappers::SparseMatrix &matrix);
    /// MUMPS: retries a numeric factorisation that ran out of workspace
    /// once with a larger one; throws LinearSolverFailure if it still fails
    /// or failed for another reason.
    void
    handle_mumps_failure(const TrilinosWrappers::SparseMatrix &matrix);
  };
} // namespace contact_fem

#endif
