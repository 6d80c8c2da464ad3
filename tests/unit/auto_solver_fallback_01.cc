// Linear solver/Type = auto: when the iterative solver it picked (a large
// mesh inside the multigrid's measured limits) does not reach its target,
// the direct solver takes over for the mesh, solves the same system and
// says so once in a note; the description then names the direct solver
// and why. The system: the 5-point Laplacian on a 50 x 50 grid with a unit
// load, and the iterative solver held to 2 iterations, far fewer than its
// multigrid needs for the residual 1e-12 |b| it then aims at, so it fails.
// The answer is checked by its residual.

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_fem/solvers/linear_solver.h>

#include <iostream>

using namespace dealii;
using namespace contact_fem;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               m = 50, n = m * m;
  IndexSet                         owned(n);
  owned.add_range(0, n);
  TrilinosWrappers::SparseMatrix matrix(owned, owned, MPI_COMM_WORLD, 5);
  for (unsigned int i = 0; i < m; ++i)
    for (unsigned int j = 0; j < m; ++j)
      {
        const unsigned int k = i * m + j;
        matrix.set(k, k, 4.);
        if (i > 0)
          matrix.set(k, k - m, -1.);
        if (i + 1 < m)
          matrix.set(k, k + m, -1.);
        if (j > 0)
          matrix.set(k, k - 1, -1.);
        if (j + 1 < m)
          matrix.set(k, k + 1, -1.);
      }
  matrix.compress(VectorOperation::insert);
  TrilinosWrappers::MPI::Vector rhs(owned, MPI_COMM_WORLD), x(owned, MPI_COMM_WORLD);
  rhs = 1.;

  ParameterHandler prm;
  LinearSolver::declare_parameters(prm);
  prm.parse_input_from_string("subsection Linear solver\n  set Type = auto\n"
                              "  set Maximum iterations = 2\nend\n");
  const auto    solver = LinearSolver::create(prm);
  ProblemTraits traits; // 2D, inside every limit
  solver->set_problem(traits);
  if (solver->select(2000000)) // a mesh above the crossover: iterative
    solver->set_near_null_space({std::vector<double>(n, 1.)});
  std::cout << "before: " << (solver->iterative() ? "iterative" : "direct") << std::endl;

  LinearSystemRequest request;
  request.newton_residual_target = 0.; // the exact answer
  solver->solve(matrix, x, rhs, request);
  const std::string             note = solver->take_note();
  TrilinosWrappers::MPI::Vector residual(owned, MPI_COMM_WORLD);
  matrix.vmult(residual, x);
  residual -= rhs;
  std::cout << "after: " << (solver->iterative() ? "iterative" : "direct") << std::endl
            << "relative residual below 1e-12: " << (residual.l2_norm() < 1e-12 * rhs.l2_norm())
            << std::endl
            << "note names the failure and the direct solver: "
            << (note.find("did not reach its target") != std::string::npos &&
                note.find("The direct solver takes over") != std::string::npos)
            << std::endl
            << "note again (said once): '" << solver->take_note() << "'" << std::endl
            << "description: " << solver->description() << std::endl;
}
