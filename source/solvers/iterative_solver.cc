#include <deal.II/base/timer.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <contact_fem/core/format.h>
#include <contact_fem/solvers/iterative_solver.h>

#include <ml_MultiLevelPreconditioner.h>

#include <algorithm>
#include <cmath>

namespace contact_fem
{
  IterativeSolver::IterativeSolver(const Parameters &parameters)
    : parameters(parameters)
  {}

  IterativeSolver::~IterativeSolver() = default;

  void
  IterativeSolver::set_near_null_space(std::vector<std::vector<double>> &&modes)
  {
    n_modes = modes.size();
    null_space.clear();
    for (const auto &mode : modes)
      null_space.insert(null_space.end(), mode.begin(), mode.end());
  }

  std::string
  IterativeSolver::description() const
  {
    return "iterative (CG, or GMRES while a Coulomb node slips; ML algebraic multigrid "
           "with the rigid-body modes)";
  }

  void
  IterativeSolver::clear()
  {
    preconditioner.reset();
    last_matrix = nullptr;
  }

  double
  IterativeSolver::take_setup_seconds()
  {
    const double seconds = setup_seconds;
    setup_seconds        = 0.;
    return seconds;
  }

  void
  IterativeSolver::build_preconditioner(const TrilinosWrappers::SparseMatrix &matrix)
  {
    Timer timer;
    AssertThrow(n_modes > 0 &&
                  null_space.size() == n_modes * static_cast<std::size_t>(matrix.local_size()),
                ExcMessage("the iterative solver has no near-null space for this mesh"));
    // Measured against other lists for the total solve time
    // (doc/performance.md, "Cheaper set-ups for every solve"): the set-up is
    // mostly ML's sparse products for the smoothed prolongator and the
    // Galerkin operators. Unsmoothed aggregation (damping factor 0) cuts it
    // to a third and paid in 3D Q1, but nearly tripled the CG iterations in
    // 2D Q2; a threshold of 1e-3 saved iterations in 3D serially only; more
    // sweeps, Gauss-Seidel, the power method, nodal aggregation and other
    // thresholds or coarse sizes cost more than they saved. No other list
    // was faster in 2D and 3D, serial and on 2 ranks.
    Teuchos::ParameterList list;
    ML_Epetra::SetDefaults("SA", list);
    list.set("ML output", 0);
    list.set("aggregation: type", "Uncoupled");
    list.set("aggregation: threshold", parameters.aggregation_threshold);
    list.set("smoother: type", "Chebyshev");
    list.set("smoother: sweeps", static_cast<int>(parameters.smoother_sweeps));
    list.set("smoother: pre or post", "both");
    list.set("coarse: type", "Amesos-KLU");
    list.set("coarse: max size", 2000);
    list.set("null space: type", "pre-computed");
    list.set("null space: dimension", static_cast<int>(n_modes));
    list.set("null space: vectors", null_space.data());
    preconditioner = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    preconditioner->initialize(matrix, list);
    setup_seconds += timer.wall_time();
  }

  unsigned int
  IterativeSolver::iterate(const TrilinosWrappers::SparseMatrix &matrix,
                           TrilinosWrappers::MPI::Vector        &x,
                           const TrilinosWrappers::MPI::Vector  &rhs,
                           const bool                            symmetric,
                           const double                          target)
  {
    SolverControl control(parameters.max_iterations, target, false, false);
    try
      {
        if (symmetric)
          {
            SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
            cg.solve(matrix, x, rhs, *preconditioner);
          }
        else
          {
            // Right preconditioning: the residual GMRES watches is the
            // residual of the system itself, which the target is about.
            SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
              control, SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(100, true));
            gmres.solve(matrix, x, rhs, *preconditioner);
          }
      }
    catch (const SolverControl::NoConvergence &e)
      {
        const std::string limit = multigrid_limit_exceeded(traits);
        throw LinearSolverFailure(
          std::string(symmetric ? "CG" : "GMRES") +
            " with algebraic multigrid did not reach its target residual " + scientific(target) +
            " in " + std::to_string(e.last_step) +
            " iterations (Linear solver/Maximum iterations; reached " +
            scientific(e.last_residual) + ").\n    " +
            (limit.empty() ? "None of the multigrid's measured limits (doc/stability.md) "
                             "applies to this scene" :
                             "The scene is beyond a measured limit of the multigrid: " + limit) +
            "; set Linear solver/Type = direct, or raise the iteration limit",
          false);
      }
    return control.last_step();
  }

  double
  IterativeSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                         TrilinosWrappers::MPI::Vector        &x,
                         const TrilinosWrappers::MPI::Vector  &rhs,
                         const LinearSystemRequest            &request)
  {
    // Rebuilt for every solve (doc/performance.md, "Keeping the multigrid
    // across Newton iterations"): keeping the multigrid of the step's first
    // iteration added 46 % of Krylov iterations (the contact rows change
    // with the active set), and ML's recomputation on the kept aggregates
    // saved a third of the set-up in 2D but added 15-36 % of Krylov
    // iterations; neither was reliably faster.
    build_preconditioner(matrix);
    last_matrix    = &matrix;
    last_symmetric = request.symmetric;
    // Without a target (a caller that wants the exact answer), and never
    // below it: the accuracy an iteration in double precision can reach.
    const double floor = 1e-12 * rhs.l2_norm();
    const double target =
      std::max(floor, parameters.tolerance_factor * request.newton_residual_target);
    iterations = iterate(matrix, x, rhs, request.symmetric, target);
    TrilinosWrappers::MPI::Vector check(rhs);
    return matrix.residual(check, x, rhs);
  }

  void
  IterativeSolver::solve_again(TrilinosWrappers::MPI::Vector       &x,
                               const TrilinosWrappers::MPI::Vector &rhs)
  {
    AssertThrow(can_solve_again(), ExcMessage("the iterative solver has no preconditioner"));
    x = 0.;
    iterate(*last_matrix, x, rhs, last_symmetric, again_tolerance * rhs.l2_norm());
  }
} // namespace contact_fem
