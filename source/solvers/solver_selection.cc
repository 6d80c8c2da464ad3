// The choice of the linear solver: LinearSolver::create() makes the direct,
// the iterative or the automatic one (which picks one of the two per mesh,
// by measured crossovers and the multigrid's limits). This file knows the
// implementations; the interface (linear_solver.h) does not.
#include <contact_fem/core/format.h>
#include <contact_fem/solvers/direct_solver.h>
#include <contact_fem/solvers/iterative_solver.h>
#include <contact_fem/solvers/linear_solver.h>

namespace contact_fem
{
  namespace
  {
    /**
     * Picks the direct or the iterative solver for each mesh: the
     * iterative one from the measured crossover size on, and only for
     * scenes inside the limits where the multigrid was measured to
     * converge (doc/performance.md, doc/stability.md).
     */
    class AutomaticSolver : public LinearSolver
    {
    public:
      AutomaticSolver(std::unique_ptr<DirectSolver> direct, std::unique_ptr<IterativeSolver> krylov)
        : direct(std::move(direct))
        , krylov(std::move(krylov))
        , current(this->direct.get())
      {}

      void
      set_problem(const ProblemTraits &problem) override
      {
        traits = problem;
        krylov->set_problem(problem);
      }

      bool
      select(const types::global_dof_index n_dofs) override
      {
        LinearSolver *const before = current;
        selected_dofs              = n_dofs;
        reason                     = iterative_reason(n_dofs);
        current                    = reason.empty() ? static_cast<LinearSolver *>(direct.get()) :
                                                      static_cast<LinearSolver *>(krylov.get());
        if (current != before)
          before->clear();
        return current->select(n_dofs);
      }

      void
      set_near_null_space(std::vector<std::vector<double>> &&modes) override
      {
        current->set_near_null_space(std::move(modes));
      }

      std::string
      description() const override
      {
        return current->description() + " (auto: " + (reason.empty() ? why_direct : reason) + ")";
      }

      bool
      iterative() const override
      {
        return current->iterative();
      }

      void
      clear() override
      {
        current->clear();
      }

      double
      solve(const TrilinosWrappers::SparseMatrix &matrix,
            TrilinosWrappers::MPI::Vector        &x,
            const TrilinosWrappers::MPI::Vector  &rhs,
            const LinearSystemRequest            &request) override
      {
        if (current != krylov.get())
          return current->solve(matrix, x, rhs, request);
        try
          {
            return krylov->solve(matrix, x, rhs, request);
          }
        catch (const LinearSolverFailure &e)
          {
            // A system inside the multigrid's measured limits that it still
            // does not solve (measured: penalty friction in 3D, whose
            // tangential penalty of 1e4 E/h leaves GMRES far from its
            // target): the direct solver takes over for this mesh. A
            // singular system is not the multigrid's fault.
            if (e.singular)
              throw;
            krylov->clear();
            current    = direct.get();
            why_direct = "the iterative solver did not converge on this mesh";
            reason.clear();
            // Its first line: the second one advises what auto now does.
            const std::string what = e.what();
            fallback_note =
              what.substr(0, what.find('\n')) + " The direct solver takes over for this mesh";
            direct->select(selected_dofs);
            return direct->solve(matrix, x, rhs, request);
          }
      }

      unsigned int
      last_iterations() const override
      {
        return current->last_iterations();
      }

      double
      take_setup_seconds() override
      {
        return current->take_setup_seconds();
      }

      bool
      can_solve_again() const override
      {
        return current->can_solve_again();
      }

      void
      solve_again(TrilinosWrappers::MPI::Vector       &x,
                  const TrilinosWrappers::MPI::Vector &rhs) override
      {
        current->solve_again(x, rhs);
      }

      bool
      detects_null_pivots() const override
      {
        return current->detects_null_pivots();
      }

      unsigned int
      n_null_pivots() const override
      {
        return current->n_null_pivots();
      }

      std::string
      take_note() override
      {
        std::string note = current->take_note();
        if (!fallback_note.empty())
          note = fallback_note + (note.empty() ? "" : "; " + note);
        fallback_note.clear();
        return note;
      }

    private:
      std::unique_ptr<DirectSolver>    direct;
      std::unique_ptr<IterativeSolver> krylov;
      LinearSolver                    *current;
      ProblemTraits                    traits;
      /// The DoFs of the current mesh (select()).
      types::global_dof_index selected_dofs = 0;
      /// Said once by take_note() after the iterative solver gave way.
      std::string fallback_note;
      /// Why the iterative solver serves this mesh; empty: the direct one.
      std::string reason;
      std::string why_direct;

      /// Empty if the direct solver should serve @p n_dofs unknowns (and
      /// why_direct says why), else why the iterative one.
      std::string
      iterative_reason(const types::global_dof_index n_dofs)
      {
        const types::global_dof_index crossover = traits.dim == 2 ? crossover_2d : crossover_3d;
        if (n_dofs < crossover)
          {
            why_direct = std::to_string(n_dofs) + " DoFs, below the " + std::to_string(traits.dim) +
                         "D crossover " + std::to_string(crossover);
            return "";
          }
        why_direct = multigrid_limit_exceeded(traits);
        if (!why_direct.empty())
          return "";
        return std::to_string(n_dofs) + " DoFs, at or above the " + std::to_string(traits.dim) +
               "D crossover " + std::to_string(crossover);
      }

      // Measured on this machine (bench/solver_crossover.py,
      // doc/performance.md "Direct or iterative"), prm/hertz.prm serial:
      // per Newton iteration the direct solve is 8 % faster at 74k DoFs,
      // the iterative one 3 % faster at 292k and 29 % at 1.16M (with 36 %
      // less memory), and only the iterative one speeds up on 2 ranks.
      static constexpr types::global_dof_index crossover_2d = 200000;
      // 3D, measured the same way: on two stacked Q1 blocks (bulky bodies)
      // the direct solve is 8 % faster at 6.8k DoFs, the iterative one 2.9x
      // faster at 47k and 13x at 346k (4x less memory); on a Q2 slab of
      // one to two element layers (prm/two_cylinders_3d.prm, a factorisation
      // with 2D-like fill) the direct one is still 1.8x faster at 81k.
      // On the 3D Hertz sphere (bulky, Q1 and Q2) the two are equal at
      // 5k-8k DoFs and the iterative one is 3-7x faster at 55k
      // (doc/performance.md, "Direct or iterative in 3D"): the switch
      // sits between the bulky and the slab crossovers. Rechecked on the
      // sphere graded toward the contact (issue 32): 1.6x at 22k DoFs (Q1),
      // 1.1x at 45k (Q2); no bulky scene below 30k gains 3x.
      static constexpr types::global_dof_index crossover_3d = 30000;
    };

    // Measured on prm/hertz.prm with CG (doc/stability.md, group
    // "iterative"): a slave 1e2 / 1e3 / 1e4 times stiffer than its
    // master takes 55 / 153 / 316 iterations, 1e8 does not converge;
    // lambda / mu = 49 / 99 / 499 takes 72 / 96 / 164, B-bar at 4999 does
    // not converge.
    constexpr double slave_stiffness_limit = 100.;
    constexpr double lambda_over_mu_limit  = 100.;
    // A stiff master costs nothing (measured on prm/hertz.prm up to a
    // contrast of 1e12 and on the patch test at 1e10), so the contrast of
    // the moduli alone does not send a scene to the direct solver.
    // tests/scenes/contact_patch_01.prm, Global refinements = 3 (4.6k
    // DoFs), the blocks widened: cells of aspect ratio 1 / 10 / 30 / 100 /
    // 300 take 10 / 44 / 104 / 252 / 666 iterations, 1e3 does not converge
    // in 1000. The shipped scenes stay below 15 (prm/two_cylinders.prm).
    constexpr double aspect_ratio_limit = 30.;
  } // namespace

  std::string
  multigrid_limit_exceeded(const ProblemTraits &traits)
  {
    const auto beyond = [](const std::string &what, const double value, const double limit) {
      return what + " " + significant(value, 3) + ", above the multigrid's measured limit " +
             significant(limit, 3);
    };
    if (!traits.unsupported_bodies.empty())
      {
        std::string ids;
        for (const unsigned int id : traits.unsupported_bodies)
          ids += (ids.empty() ? "" : ", ") + std::to_string(id);
        return (traits.unsupported_bodies.size() == 1 ? "body " : "bodies ") + ids +
               " held by no support (no fixed or prescribed boundary, no fixed point): "
               "only contact, if anything, removes their rigid-body modes, which the "
               "multigrid then cannot resolve";
      }
    if (traits.slave_stiffness_ratio > slave_stiffness_limit)
      return beyond("a slave side stiffer than its master by a factor",
                    traits.slave_stiffness_ratio, slave_stiffness_limit);
    if (traits.largest_lambda_over_mu > lambda_over_mu_limit)
      return beyond("lambda/mu", traits.largest_lambda_over_mu, lambda_over_mu_limit);
    if (traits.largest_aspect_ratio > aspect_ratio_limit)
      return beyond("cells with an aspect ratio (longest over shortest edge) of",
                    traits.largest_aspect_ratio, aspect_ratio_limit);
    return "";
  }

  void
  LinearSolver::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Type", "auto", Patterns::Selection("auto|direct|iterative"),
                      "direct: a sparse factorisation (Direct solver). iterative: "
                      "CG (GMRES while a Coulomb node slips) preconditioned by "
                      "Trilinos ML algebraic multigrid with the rigid-body modes. "
                      "auto: the iterative solver from the measured crossover size "
                      "on (doc/performance.md), unless a body has no support (no "
                      "fixed or prescribed boundary, no fixed point), a contact "
                      "pair's slave side is more than 100 times stiffer than its "
                      "master, a body has "
                      "lambda/mu above 100 (nu > 0.495) or a cell an aspect ratio "
                      "above 30, where the multigrid was measured to converge slowly "
                      "or not at all (doc/stability.md).");
    prm.declare_entry("Direct solver", "Amesos_Mumps",
                      Patterns::Selection("Amesos_Klu|Amesos_Mumps"),
                      "Direct solver of the condensed system: MUMPS (METIS "
                      "ordering; under MPI on the first process, the matrix "
                      "gathered there: its parallel factorisation is not "
                      "deterministic, doc/stability.md) or Trilinos Amesos KLU "
                      "(gathers the matrix on one process). MUMPS is the faster "
                      "from 5k DoFs on, 7x at 74k DoFs (doc/performance.md), and "
                      "the only one that detects zero pivots (free rigid-body "
                      "modes).");
    prm.declare_entry("Maximum iterations", "1000", Patterns::Integer(1),
                      "Krylov iterations allowed per solve of the iterative "
                      "solver; a solve that needs more stops the run with a "
                      "diagnosis.");
    prm.declare_entry("Tolerance factor", "1e-2", Patterns::Double(0.),
                      "The iterative solver stops when the linear residual is "
                      "below this fraction of the residual at which Newton "
                      "accepts an iterate (Newton/Displacement tolerances), so "
                      "that no Newton iteration is added. In (0, 1).");
    prm.declare_entry("Aggregation threshold", "1e-4", Patterns::Double(0.),
                      "ML smoothed aggregation: couplings weaker than this "
                      "fraction of the diagonal do not join aggregates.");
    prm.declare_entry("Smoother sweeps", "2", Patterns::Integer(1, 20),
                      "Degree of the Chebyshev smoother on each multigrid level.");
    prm.leave_subsection();
  }

  std::unique_ptr<LinearSolver>
  LinearSolver::create(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    const std::string           type = prm.get("Type");
    const std::string           name = prm.get("Direct solver");
    IterativeSolver::Parameters parameters;
    parameters.max_iterations        = prm.get_integer("Maximum iterations");
    parameters.tolerance_factor      = prm.get_double("Tolerance factor");
    parameters.aggregation_threshold = prm.get_double("Aggregation threshold");
    parameters.smoother_sweeps       = prm.get_integer("Smoother sweeps");
    prm.leave_subsection();
    AssertThrow(parameters.tolerance_factor > 0. && parameters.tolerance_factor < 1.,
                ExcMessage("Linear solver/Tolerance factor: got " +
                           significant(parameters.tolerance_factor, 6) +
                           "; expected a value in (0, 1) (default 1e-2)."));
    AssertThrow(parameters.aggregation_threshold < 1.,
                ExcMessage("Linear solver/Aggregation threshold: got " +
                           significant(parameters.aggregation_threshold, 6) +
                           "; expected a value in [0, 1) (default 1e-4)."));
    if (type == "direct")
      return std::make_unique<DirectSolver>(name);
    if (type == "iterative")
      return std::make_unique<IterativeSolver>(parameters);
    return std::make_unique<AutomaticSolver>(std::make_unique<DirectSolver>(name),
                                             std::make_unique<IterativeSolver>(parameters));
  }
} // namespace contact_fem
