// The tangent of 'penalty frictional' on the current configuration
// (Contact/Kinematics = current) against central differences of its
// contact force on a curved pair, where its frame, the interface normal
// (the modulus-weighted mean of the slave normal and the reversed master
// normal), differs from the slave normal: the blocks of
// penalty_frictional_linearisation_01 (E = 100 below, the slave; 200
// above), the slave top bent down and the master base bent up to
// paraboloids (sag 0.015 at the corners of the unit square, the interface
// normal up to 0.03 rad off the slave normal), eps_n = eps_t = 1e4,
// Coulomb 0.3. Step 1 presses the master 0.02 into the slave at the centre
// and slides the slave nodes by up to 1e-3 (they stick, the history
// traction t^n is not zero); step 2 slides them by up to 0.006 per
// component and moves every interface DoF by up to 2e-3, so that some stick
// and some slip. At that iterate the matrix of assemble() is compared with
// (F(u + h v) - F(u - h v)) / 2h (check_tangent(): h = 1e-6 and 1e-7,
// bounds 1e-6 and 1e-7 of |K v|), which takes the derivative of the frame
// (d n_int/du through the master nodal normals and M) in the normal force
// -p n_int, the slip, the history's transport and the tangential force
// (SHOW_ERROR=1 prints the errors). Tried: with the slave normal's force
// derivative (LinearisedNode::force) in the normal force's place the error
// is 0.038 of |K v|, with the held traction turning with the slave normal
// (tangent_force) 0.012.

#include <deal.II/base/mpi.h>

#include "unit_test_penalty_frictional.h"
#include "unit_test_random.h"
#include "unit_test_stacked_interface.h"

#include <cmath>
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

  // Step 1: the master 0.07 down (0.02 into the slave at the centre), the slave nodes slid
  // a little. Step 2: larger random slides and a random perturbation.
  Random              random(29);
  std::vector<double> u_1(n, 0.), u_2(n, 0.);
  for (const auto &node : interface.nodes)
    for (unsigned int d = 0; d < 3; ++d)
      {
        const unsigned int i = interface.position(node.dofs[d]);
        // The sag r^2 / 2R, 0.015 at the corners (x, y in [0, 1]).
        const double r2 =
          std::pow(node.reference[0] - 0.5, 2) + std::pow(node.reference[1] - 0.5, 2);
        const double sag = 0.03 * r2;
        if (node.slave)
          {
            u_1[i] = d < 2 ? 1e-3 * random.next() : -sag;
            u_2[i] = u_1[i] + (d < 2 ? 0.006 * random.next() : 0.);
          }
        else
          u_1[i] = u_2[i] = d == 2 ? -0.07 + sag : 0.;
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

  check_tangent(*contact, interface, blocks.dof_handler.n_dofs(), u_2, random,
                [&](const std::vector<double> &w) {
                  follow(interface, w);
                });
}
