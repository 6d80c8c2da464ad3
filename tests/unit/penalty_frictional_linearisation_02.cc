// The tangent of 'penalty frictional' with small kinematics (the operators
// of one search, held) against central differences of its contact force,
// in 3D, where the frame is the shared interface normal (issue 29): the
// normal force -p n_int along it with p = eps_n (-g) from the slave-normal
// gap (an unsymmetric normal stiffness), the slip and the tangential
// traction in the tangent plane of n_int. Two stacked blocks (the lower
// one's top the slave, 3 x 3 faces, E = 100; the upper one's base the
// master, 2 x 2, overhanging, E = 200), eps_n = eps_t = 1e4, Coulomb 0.3.
// The search runs once, on a configuration with every interface DoF
// moved randomly by up to 0.03 (the slave and master normals turn apart:
// the interface normal leaves the slave normal by more than 0.05). Step 1
// presses the master 0.01 into the slave and slides the slave nodes by up
// to 1e-3 (most stick: the history traction is not zero); step 2 slides
// them by up to 0.006 more per component, so that some stick and some
// slip, and moves every interface DoF by up to 2e-3. There the matrix of
// assemble() (K, the derivative of -F) is compared with (F(u + h v) - F(u
// - h v)) / 2h for random v (F from residuals() after update_active_set()),
// h = 1e-6 and 1e-7: the error must be below 1e-6 and 1e-7 of |K v| and
// the stick/slip sets the same at every perturbed iterate. (Measured:
// 1.4e-4, 1.4e-6, 1.4e-8 of |K v| at h = 1e-4, 1e-5, 1e-6, second order,
// 1.3e-9 at 1e-7; with the slave normal in the rows of the normal
// penalty, the old frame's matrix, 0.036 at every h.) SHOW_ERROR=1 prints
// the errors.

#include <deal.II/base/mpi.h>

#include "unit_test_penalty_frictional.h"
#include "unit_test_random.h"
#include "unit_test_stacked_interface.h"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <vector>

using namespace dealii;
using namespace contact_fem;
using namespace unit_test_penalty_frictional;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  StackedBlocksInterface blocks(1);
  auto                  &interface = blocks.interface;
  const unsigned int     n         = interface.dofs().size();

  // The search configuration: every interface DoF moved randomly, the
  // master 0.05 down (touching). Step 1: the master 0.01 into the slave, the slave
  // nodes slid a little. Step 2: larger random slides and a random
  // perturbation.
  Random              random(29);
  std::vector<double> u_search(n, 0.), u_1(n, 0.), u_2(n, 0.);
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
        u_search[i] = (node.slave ? 0. : (d == 2 ? -0.05 : 0.)) + 0.03 * random.next();
      }
  interface.update(u_search, 3.);
  double largest_turn = 0.;
  for (const auto &s : interface.slave_nodes)
    if (s.paired)
      largest_turn = std::max(largest_turn, (s.interface_normal - s.normal).norm());
  std::cout << "interface normal off the slave normal by more than 0.05: "
            << (largest_turn > 0.05 ? "yes" : "no") << std::endl;
  if (std::getenv("SHOW_ERROR"))
    std::cout << "  largest |n_int - n|: " << largest_turn << std::endl;

  auto contact = make_formulation("small");
  contact->initialize(interface);
  contact->start_load_step(interface, std::vector<double>(n, 0.), StepStart::continued);
  contact->update_active_set(interface, u_1);
  std::cout << "step 1: " << sets_text(*contact) << std::endl;
  contact->accept_load_step(interface, u_1);
  contact->start_load_step(interface, u_1, StepStart::continued);
  contact->update_active_set(interface, u_2);
  std::cout << "step 2: " << sets_text(*contact) << std::endl;
  std::cout << "matrix symmetric: " << (contact->matrix_symmetric() ? "yes" : "no") << std::endl;

  // The bound: the differences' truncation error (h^2, the 3D slip
  // direction; the rest is linear in u) at h = 1e-6, their round-off at
  // 1e-7.
  check_tangent(*contact, interface, blocks.dof_handler.n_dofs(), u_2, random,
                [](const std::vector<double> &) {});
}
