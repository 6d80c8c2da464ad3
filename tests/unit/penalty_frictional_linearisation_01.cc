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

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // Flat blocks, the master 0.06 down: 0.01 into the slave.
  // The bound: the differences' truncation error (h^2) at h = 1e-6, their
  // round-off at 1e-7 (measured 5.5e-8 and 2.1e-9 of |K v|; without the
  // history traction's derivative (its turn with n and spin) the error is
  // 8.6e-4, without the D_j change of xi 2e-3, without the slip
  // direction's derivative 0.6).
  unit_test_penalty_frictional::check_current_two_steps(0., 0.06);
}
