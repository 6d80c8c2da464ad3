// The tangent of 'penalty frictional' on the current configuration
// (Contact/Kinematics = current) against central differences of its
// contact force, in 3D (issue 29). Two stacked blocks (the lower one's top
// the slave, 3 x 3 faces; the upper one's base the master, 2 x 2,
// overhanging: no coincident rims), eps_n = eps_t = 1e4, Coulomb 0.3. Step
// 1 presses the master 0.01 into the slave and slides the slave nodes by
// up to 1e-3 (they stick: the history traction t^n is not zero); step 2
// moves every slave node by a random tangential slide of up to 0.006 per component, so
// that some stick and some slip, and every interface DoF by up to 2e-3 (the
// normals turn). At that iterate the matrix of assemble() (K, the
// derivative of -F) is compared with (F(u + h v) - F(u - h v)) / 2h for
// random v (F from residuals() after update_active_set(), the operators
// rebuilt at u +- h v), h = 1e-6 and 1e-7: the error must be below 1e-6
// and 1e-7 of |K v| (truncation and round-off) and the stick/slip sets the
// same at every perturbed iterate. SHOW_ERROR=1 prints the errors.

#include <deal.II/base/mpi.h>

#include "unit_test_penalty_frictional.h"
#include "unit_test_random.h"
#include "unit_test_stacked_interface.h"

#include <iostream>
#include <vector>

using namespace dealii;
using namespace contact_fem;
using namespace unit_test_penalty_frictional;

namespace
{
  /// The operators and their linearisation at @p u, as the driver's
  /// search on every iterate.
  void
  follow(ContactInterface<3> &interface, const std::vector<double> &u)
  {
    interface.update(u, 3.);
    interface.linearise(true);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  StackedBlocksInterface blocks(1);
  auto                  &interface = blocks.interface;
  const unsigned int     n         = interface.dofs().size();

  // Step 1: the master 0.06 down (0.01 into the slave), the slave nodes slid
  // a little. Step 2: larger random slides and a random perturbation.
  Random              random(29);
  std::vector<double> u_1(n, 0.), u_2(n, 0.);
  for (const auto &node : interface.nodes)
    for (unsigned int d = 0; d < 3; ++d)
      {
        const unsigned int i = interface.position(node.dofs[d]);
        if (node.slave)
          {
            u_1[i] = d < 2 ? 1e-3 * random.next() : 0.;
            u_2[i] = u_1[i] + (d < 2 ? 0.006 * random.next() : 0.);
          }
        else
          u_1[i] = u_2[i] = d == 2 ? -0.06 : 0.;
        u_2[i] += 2e-3 * random.next();
      }

  auto contact = make_formulation("current");
  follow(interface, std::vector<double>(n, 0.));
  contact->initialize(interface);
  contact->start_load_step(interface, std::vector<double>(n, 0.), StepStart::continued);
  follow(interface, u_1);
  contact->update_active_set(interface, u_1);
  std::cout << "step 1: " << sets_text(*contact) << std::endl;
  contact->accept_load_step(interface, u_1);
  contact->start_load_step(interface, u_1, StepStart::continued);
  follow(interface, u_2);
  // The step's first update keeps the stick nodes sticking (current
  // kinematics: it sees the predictor); the second decides.
  contact->update_active_set(interface, u_2);
  contact->update_active_set(interface, u_2);
  std::cout << "step 2: " << sets_text(*contact) << std::endl;

  // The bound: the differences' truncation error (h^2) at h = 1e-6, their
  // round-off at 1e-7 (measured 5.5e-8 and 2.1e-9 of |K v|; without the
  // history traction's derivative (its turn with n and spin) the error is
  // 8.6e-4, without the D_j change of xi 2e-3, without the slip
  // direction's derivative 0.6).
  check_tangent(*contact, interface, blocks.dof_handler.n_dofs(), u_2, random,
                [&](const std::vector<double> &w) {
                  follow(interface, w);
                });
}
