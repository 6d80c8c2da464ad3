#include <deal.II/base/exceptions.h>

#include <contact_fem/direct_solver.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Amesos_Mumps.h>
#include <Epetra_LinearProblem.h>
#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <cmath>

namespace contact_fem
{
  DirectSolver::DirectSolver(const std::string &amesos_name)
    : amesos_name(amesos_name)
  {}

  DirectSolver::~DirectSolver() = default;

  void
  DirectSolver::clear()
  {
    solver.reset();
    problem.reset();
    factorised_matrix   = nullptr;
    factorised_nonzeros = 0;
    null_pivots         = 0;
  }

  void
  DirectSolver::factorise(const TrilinosWrappers::SparseMatrix &matrix)
  {
    // A re-created matrix is a new Epetra object; the entry count guards
    // against a new object at the old address.
    if (factorised_matrix != &matrix.trilinos_matrix() ||
        factorised_nonzeros != matrix.n_nonzero_elements())
      {
        clear();
        problem = std::make_unique<Epetra_LinearProblem>();
        problem->SetOperator(const_cast<Epetra_CrsMatrix *>(&matrix.trilinos_matrix()));
        Amesos factory;
        solver.reset(factory.Create(amesos_name.c_str(), *problem));
        AssertThrow(solver != nullptr,
                    ExcMessage("the direct solver " + amesos_name +
                               " is not available in this Trilinos build"));
        if (auto *mumps = dynamic_cast<Amesos_Mumps *>(solver.get()))
          {
            mumps->SetICNTL(7, 5); // METIS ordering
            // Null-pivot detection: a pivot below 1e-12 of the largest entry
            // is a free rigid-body mode. MUMPS then holds the mode at one
            // DoF instead of returning an arbitrary component of it. On the
            // Hertz scene with and without its fixed points the counts are
            // the same for thresholds from 1e-14 to 1e-10.
            mumps->SetICNTL(24, 1);
            mumps->SetCNTL(3, 1e-12);
          }
        AssertThrow(solver->SymbolicFactorization() == 0,
                    ExcMessage("the symbolic factorisation of " + amesos_name + " failed"));
        factorised_matrix   = &matrix.trilinos_matrix();
        factorised_nonzeros = matrix.n_nonzero_elements();
      }
    AssertThrow(solver->NumericFactorization() == 0,
                ExcMessage("the numeric factorisation of " + amesos_name +
                           " failed (singular matrix?)"));
    // INFOG(28): the number of null pivots found.
    auto *mumps = dynamic_cast<Amesos_Mumps *>(solver.get());
    null_pivots = mumps ? std::max(mumps->GetINFOG()[27], 0) : 0;
  }

  void
  DirectSolver::solve_with_last_factors(TrilinosWrappers::MPI::Vector       &x,
                                        const TrilinosWrappers::MPI::Vector &rhs)
  {
    AssertThrow(has_factorisation(), ExcMessage("the direct solver has no factorisation"));
    problem->SetLHS(&x.trilinos_vector());
    problem->SetRHS(const_cast<Epetra_MultiVector *>(
      static_cast<const Epetra_MultiVector *>(&rhs.trilinos_vector())));
    AssertThrow(solver->Solve() == 0, ExcMessage("the direct solve failed"));
  }

  double
  DirectSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                      TrilinosWrappers::MPI::Vector       &x,
                      const TrilinosWrappers::MPI::Vector &rhs)
  {
    factorise(matrix);
    solve_with_last_factors(x, rhs);

    TrilinosWrappers::MPI::Vector check(rhs), correction(rhs);
    double residual = matrix.residual(check, x, rhs);
    const double target = 1e-12 * rhs.l2_norm();
    for (unsigned int step = 0; step < 3 && std::isfinite(residual) && residual > target;
         ++step)
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
