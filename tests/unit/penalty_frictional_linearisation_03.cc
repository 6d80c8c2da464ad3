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

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // The sag r^2 / 2R, 0.015 at the corners; the master 0.07 down: 0.02
  // into the slave at the centre.
  unit_test_penalty_frictional::check_current_two_steps(0.03, 0.07);
}
