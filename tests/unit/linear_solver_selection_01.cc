// Linear solver/Type = auto picks the iterative solver per mesh only from
// the measured crossover size on and only inside the measured limits of the
// multigrid (every body supported, a slave side at most 100 times stiffer
// than its master, Young's moduli within 1e6, lambda / mu at most 100, cell
// aspect ratios at most 30); direct and iterative are taken as asked. The
// selected solver says why in its description, which the log prints.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <contact_fem/solvers/linear_solver.h>

#include <iostream>

using namespace dealii;
using namespace contact_fem;

namespace
{
  void
  show(LinearSolver &solver, const ProblemTraits &traits, const types::global_dof_index n)
  {
    solver.set_problem(traits);
    const bool wants_modes = solver.select(n);
    std::cout << "  " << n << " DoFs, " << traits.dim << "D, slave/master E "
              << traits.slave_stiffness_ratio << ", E contrast " << traits.youngs_modulus_contrast
              << ", lambda/mu " << traits.largest_lambda_over_mu << ", aspect ratio "
              << traits.largest_aspect_ratio << ", unsupported bodies "
              << traits.unsupported_bodies.size() << ": "
              << (solver.iterative() ? "iterative" : "direct")
              << (wants_modes ? " (asks for the rigid-body modes)" : "") << std::endl
              << "    " << solver.description() << std::endl;
  }

  std::unique_ptr<LinearSolver>
  make(const std::string &type)
  {
    ParameterHandler prm;
    LinearSolver::declare_parameters(prm);
    prm.parse_input_from_string("subsection Linear solver\n  set Type = " + type + "\nend\n");
    return LinearSolver::create(prm);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ProblemTraits                    hertz;
  hertz.slave_stiffness_ratio           = 1e-4; // soft cylinder on a stiff plate
  hertz.youngs_modulus_contrast         = 1e4;
  hertz.largest_lambda_over_mu          = 1.5;
  hertz.largest_aspect_ratio            = 4.6;
  ProblemTraits stiff_slave             = hertz;
  stiff_slave.slave_stiffness_ratio     = 1e3;
  ProblemTraits incompressible          = hertz;
  incompressible.largest_lambda_over_mu = 499.;
  // Measured failures of the multigrid that auto must avoid (issue 26).
  ProblemTraits stiff_master           = hertz;
  stiff_master.youngs_modulus_contrast = 1e10;
  ProblemTraits flat_cells             = hertz;
  flat_cells.largest_aspect_ratio      = 1e4;
  ProblemTraits unsupported            = hertz;
  unsupported.unsupported_bodies       = {1, 2};
  ProblemTraits hertz_3d               = hertz;
  hertz_3d.dim                         = 3;

  std::cout << "auto:" << std::endl;
  auto automatic = make("auto");
  show(*automatic, hertz, 5000);
  show(*automatic, hertz, 2000000);
  show(*automatic, stiff_slave, 2000000);
  show(*automatic, incompressible, 2000000);
  show(*automatic, stiff_master, 2000000);
  show(*automatic, flat_cells, 2000000);
  show(*automatic, unsupported, 2000000);
  show(*automatic, hertz_3d, 20000);
  show(*automatic, hertz_3d, 2000000);
  // Back to a small mesh: the direct solver again.
  show(*automatic, hertz, 5000);

  std::cout << "direct:" << std::endl;
  show(*make("direct"), hertz, 2000000);
  std::cout << "iterative:" << std::endl;
  show(*make("iterative"), stiff_slave, 5000);
}
