#include <contact_fem/solvers/direct_solver.h>
#include <contact_fem/solvers/linear_solver.h>

namespace contact_fem
{
  void
  LinearSolver::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Direct solver", "Amesos_Mumps",
                      Patterns::Selection("Amesos_Klu|Amesos_Mumps"),
                      "Trilinos Amesos direct solver of the condensed system: "
                      "MUMPS (METIS ordering, distributed under MPI) or KLU "
                      "(gathers the matrix on one process). MUMPS is the faster "
                      "from 5k DoFs on, 7x at 74k DoFs (doc/performance.md), and "
                      "the only one that detects zero pivots (free rigid-body "
                      "modes).");
    prm.leave_subsection();
  }

  std::unique_ptr<LinearSolver>
  LinearSolver::create(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    const std::string name = prm.get("Direct solver");
    prm.leave_subsection();
    // A direct solver: the stiffness contrast between bodies (up to 1e12)
    // defeats iterative solvers without a contact-aware preconditioner.
    return std::make_unique<DirectSolver>(name);
  }
} // namespace contact_fem
