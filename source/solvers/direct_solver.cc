#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <contact_fem/solvers/direct_solver.h>
#include <contact_fem/solvers/rank_zero_mumps.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <sstream>

namespace contact_fem
{
  namespace
  {
    /// Amesos (KLU) prints its error codes on std::cerr, without
    /// context and on whichever rank; the solver reports them with their
    /// meaning instead. Captures std::cerr while alive.
    class QuietCerr
    {
    public:
      QuietCerr()
        : saved(std::cerr.rdbuf(captured.rdbuf()))
      {}
      ~QuietCerr()
      {
        std::cerr.rdbuf(saved);
      }

    private:
      std::ostringstream captured;
      std::streambuf    *saved;
    };

    /// The extra workspace of a retried factorisation, in percent of the
    /// analysis' estimate (ICNTL(14); Amesos sets 20). On prm/hertz.prm with
    /// nu = 0.4999999999999 and B-bar, 20 % fails with INFOG(1) = -9 and
    /// 200 % succeeds.
    constexpr int retry_workspace_percent = 200;

    /// MUMPS errors that ask for a larger ICNTL(14) (MUMPS 5 users' guide,
    /// "Error diagnostics").
    bool
    is_workspace_error(const int code)
    {
      return code == -8 || code == -9 || code == -17 || code == -20;
    }

    /// The meaning of MUMPS' INFOG(1) < 0 (same source).
    std::string
    mumps_error_meaning(const int code)
    {
      switch (code)
        {
          case -5:
          case -7:
            return "allocating the workspace of the analysis failed: out of memory";
          case -6:
            return "the matrix is singular in structure";
          case -8:
            return "the integer workspace of the factorisation is too small";
          case -9:
            return "the real workspace of the factorisation is too small";
          case -10:
            return "the matrix is numerically singular";
          case -13:
            return "allocating the workspace of the factorisation failed: out of memory";
          case -17:
            return "the internal send buffer is too small";
          case -20:
            return "the internal receive buffer is too small";
          default:
            return "see \"Error diagnostics\" in the MUMPS users' guide";
        }
    }

    /// INFOG(2) of an error, as MUMPS defines it for that error.
    std::string
    mumps_error_detail(const int code, const int detail)
    {
      // A negative amount counts millions.
      const std::string amount =
        detail >= 0 ? std::to_string(detail) : std::to_string(-detail) + " million";
      switch (code)
        {
          case -6:
            return " (structural rank " + amount + ")";
          case -8:
          case -9:
            return " (" + amount + " entries missing)";
          case -13:
            return " (" + amount + " entries)";
          default:
            return " (INFOG(2) = " + std::to_string(detail) + ")";
        }
    }
  } // namespace

  DirectSolver::DirectSolver(const std::string &amesos_name)
    : amesos_name(amesos_name)
  {}

  DirectSolver::~DirectSolver() = default;

  void
  DirectSolver::clear()
  {
    solver.reset();
    mumps.reset();
    problem.reset();
    factorised_matrix   = nullptr;
    factorised_nonzeros = 0;
    null_pivots         = 0;
  }

  bool
  DirectSolver::has_factorisation() const
  {
    return (solver != nullptr || mumps != nullptr) && factorised_matrix != nullptr;
  }

  void
  DirectSolver::analyse(const TrilinosWrappers::SparseMatrix &matrix)
  {
    clear();
    if (amesos_name == "Amesos_Mumps")
      {
        mumps = std::make_unique<RankZeroMumps>();
        mumps->set_icntl(7, 5); // METIS ordering
        // Null-pivot detection: a pivot below 1e-12 of the largest entry
        // is a free rigid-body mode. MUMPS then holds the mode at one
        // DoF instead of returning an arbitrary component of it. On the
        // Hertz scene with and without its fixed points the counts are
        // the same for thresholds from 1e-14 to 1e-10.
        mumps->set_icntl(24, 1);
        mumps->set_cntl(3, 1e-12);
        // Once a factorisation needed more workspace, the next meshes and
        // load steps of the same model will too.
        if (workspace_percent > 0)
          mumps->set_icntl(14, workspace_percent);
        if (mumps->analyse(matrix.trilinos_matrix()) < 0)
          throw LinearSolverFailure("the symbolic factorisation of MUMPS failed: INFOG(1) = " +
                                      std::to_string(mumps->info()[0]) + ", " +
                                      mumps_error_meaning(mumps->info()[0]),
                                    false);
      }
    else
      {
        problem = std::make_unique<Epetra_LinearProblem>();
        problem->SetOperator(const_cast<Epetra_CrsMatrix *>(&matrix.trilinos_matrix()));
        Amesos factory;
        solver.reset(factory.Create(amesos_name.c_str(), *problem));
        AssertThrow(solver != nullptr, ExcMessage("the direct solver " + amesos_name +
                                                  " is not available in this Trilinos build"));
        QuietCerr quiet;
        if (solver->SymbolicFactorization() != 0)
          throw LinearSolverFailure("the symbolic factorisation of " + amesos_name + " failed",
                                    false);
      }
    factorised_matrix   = &matrix.trilinos_matrix();
    factorised_nonzeros = matrix.n_nonzero_elements();
  }

  void
  DirectSolver::factorise(const TrilinosWrappers::SparseMatrix &matrix)
  {
    // A re-created matrix is a new Epetra object; the entry count guards
    // against a new object at the old address.
    if (factorised_matrix != &matrix.trilinos_matrix() ||
        factorised_nonzeros != matrix.n_nonzero_elements())
      analyse(matrix);
    if (mumps)
      {
        if (mumps->factorise(matrix.trilinos_matrix()) < 0)
          handle_mumps_failure(matrix);
        null_pivots = std::max(mumps->info()[2], 0);
        return;
      }
    int failed = 0;
    {
      QuietCerr quiet;
      failed = solver->NumericFactorization();
    }
    if (failed != 0)
      throw LinearSolverFailure("the numeric factorisation of " + amesos_name +
                                  " failed (singular matrix?)",
                                true);
    null_pivots = 0;
  }

  void
  DirectSolver::handle_mumps_failure(const TrilinosWrappers::SparseMatrix &matrix)
  {
    std::array<int, 3> info  = mumps->info();
    const bool         retry = is_workspace_error(info[0]) && workspace_percent == 0;
    if (retry)
      {
        // The analysis sizes the workspace for the pivot order it chose;
        // numerical pivoting that delays many pivots (a badly conditioned
        // matrix) needs more. ICNTL(14) is read by the analysis: redo it.
        workspace_percent = retry_workspace_percent;
        mumps->set_icntl(14, workspace_percent);
        if (mumps->analyse(matrix.trilinos_matrix()) >= 0 &&
            mumps->factorise(matrix.trilinos_matrix()) >= 0)
          {
            // INFOG(2) (the entries missing) is left out: it depends on the
            // MUMPS version, and the note reaches test output.
            note = "MUMPS INFOG(1) = " + std::to_string(info[0]) + ": " +
                   mumps_error_meaning(info[0]) + "; factorised again with " +
                   std::to_string(workspace_percent) +
                   " % extra workspace (ICNTL(14)), which this run keeps";
            return;
          }
        info = mumps->info();
      }
    std::string text = "MUMPS failed: INFOG(1) = " + std::to_string(info[0]) + ", " +
                       mumps_error_meaning(info[0]) + mumps_error_detail(info[0], info[1]);
    if (is_workspace_error(info[0]))
      text += ", also with " + std::to_string(workspace_percent) +
              " % extra workspace (ICNTL(14)); numerical pivoting delayed more pivots "
              "than the analysis foresaw, the sign of a badly conditioned matrix "
              "(stiffness ratios or nearly incompressible bodies beyond double "
              "precision)";
    else if (retry)
      text += ", after a retry with " + std::to_string(workspace_percent) +
              " % extra workspace (ICNTL(14)) for a workspace error";
    throw LinearSolverFailure(text, info[0] == -6 || info[0] == -10);
  }

  std::string
  DirectSolver::take_note()
  {
    std::string text;
    std::swap(text, note);
    return text;
  }

  void
  DirectSolver::solve_with_last_factors(TrilinosWrappers::MPI::Vector       &x,
                                        const TrilinosWrappers::MPI::Vector &rhs)
  {
    AssertThrow(has_factorisation(), ExcMessage("the direct solver has no factorisation"));
    if (mumps)
      {
        AssertThrow(mumps->solve(x.trilinos_vector(), rhs.trilinos_vector()) >= 0,
                    ExcMessage("the direct solve failed: MUMPS INFOG(1) = " +
                               std::to_string(mumps->info()[0])));
        return;
      }
    problem->SetLHS(&x.trilinos_vector());
    problem->SetRHS(const_cast<Epetra_MultiVector *>(
      static_cast<const Epetra_MultiVector *>(&rhs.trilinos_vector())));
    AssertThrow(solver->Solve() == 0, ExcMessage("the direct solve failed"));
  }

  std::string
  DirectSolver::description() const
  {
    return amesos_name == "Amesos_Mumps" ? "direct (MUMPS)" : "direct (KLU)";
  }

  double
  DirectSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                      TrilinosWrappers::MPI::Vector        &x,
                      const TrilinosWrappers::MPI::Vector  &rhs,
                      const LinearSystemRequest & /*request*/)
  {
    factorise(matrix);
    solve_with_last_factors(x, rhs);

    TrilinosWrappers::MPI::Vector check(rhs), correction(rhs);
    double                        residual = matrix.residual(check, x, rhs);
    const double                  target   = 1e-12 * rhs.l2_norm();
    for (unsigned int step = 0; step < 3 && std::isfinite(residual) && residual > target; ++step)
      {
        solve_with_last_factors(correction, check);
        TrilinosWrappers::MPI::Vector refined = x;
        refined += correction;
        TrilinosWrappers::MPI::Vector refined_check(rhs);
        const double refined_residual = matrix.residual(refined_check, refined, rhs);
        if (!(refined_residual < 0.5 * residual))
          break;
        x        = refined;
        check    = refined_check;
        residual = refined_residual;
      }
    return residual;
  }
} // namespace contact_fem
