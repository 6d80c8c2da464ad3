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

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/contact_parameters.h>
#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/material/material.h>

#include "unit_test_blocks.h"
#include "unit_test_materials.h"
#include "unit_test_random.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <utility>

using namespace dealii;
using namespace contact_fem;

namespace
{
  std::unique_ptr<ContactFormulation<3>>
  make_formulation()
  {
    ParameterHandler prm;
    ContactParameters::declare_parameters(prm);
    ContactFormulation<3>::declare_parameters(prm);
    prm.enter_subsection("Contact");
    prm.set("Pairs", "3: 4");
    prm.set("Formulation", "penalty frictional");
    prm.set("Penalty", "1e4");
    prm.set("Tangential penalty", "1e4");
    prm.set("Friction", "coulomb 0.3");
    prm.leave_subsection();
    return ContactFormulation<3>::create(prm);
  }

  /// "N active slave nodes, stick S, slip L" from the set codes.
  std::string
  sets_text(const ContactFormulation<3> &contact)
  {
    const auto codes = contact.contact_sets();
    return std::to_string(contact.n_active()) + " active slave nodes, stick " +
           std::to_string(std::count(codes.begin(), codes.end(), 1)) + ", slip " +
           std::to_string(std::count_if(codes.begin(), codes.end(), [](const int c) {
             return c >= 2;
           }));
  }

} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  Triangulation<3> tria;
  make_stacked_blocks_3d(tria);
  const FESystem<3> fe(FE_Q<3>(1), 3);
  DoFHandler<3>     dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const MappingQ<3>         mapping(1);
  const Materials<3>        materials = make_materials<3>("1, 2", "100, 200", "0.3, 0.3");
  AffineConstraints<double> none;
  none.close();
  ContactInterface<3> interface;
  interface.initialize(mapping, dof_handler, {ContactPair{3, 4}}, none, none, materials,
                       MPI_COMM_WORLD);
  const unsigned int n = interface.dofs().size();

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

  auto contact = make_formulation();
  contact->initialize(interface);
  contact->start_load_step(interface, std::vector<double>(n, 0.), StepStart::continued);
  contact->update_active_set(interface, u_1);
  std::cout << "step 1: " << sets_text(*contact) << std::endl;
  contact->accept_load_step(interface, u_1);
  contact->start_load_step(interface, u_1, StepStart::continued);
  contact->update_active_set(interface, u_2);
  const std::vector<int> sets = contact->contact_sets();
  std::cout << "step 2: " << sets_text(*contact) << std::endl;
  std::cout << "matrix symmetric: " << (contact->matrix_symmetric() ? "yes" : "no") << std::endl;

  // K and F at u_2.
  const IndexSet         owned = complete_index_set(dof_handler.n_dofs());
  DynamicSparsityPattern pattern(dof_handler.n_dofs());
  contact->add_sparsity(interface, none, owned, pattern);
  TrilinosWrappers::SparseMatrix matrix;
  matrix.reinit(owned, owned, pattern, MPI_COMM_WORLD);
  TrilinosWrappers::MPI::Vector rhs(owned, MPI_COMM_WORLD);
  contact->assemble(interface, none, none, owned, matrix, rhs);
  matrix.compress(VectorOperation::add);

  std::vector<double> v(n);
  for (double &value : v)
    value = random.next();
  TrilinosWrappers::MPI::Vector direction(owned, MPI_COMM_WORLD), product(owned, MPI_COMM_WORLD);
  for (unsigned int i = 0; i < n; ++i)
    direction(interface.dofs()[i]) = v[i];
  matrix.vmult(product, direction);
  double scale = 0.;
  for (unsigned int i = 0; i < n; ++i)
    scale = std::max(scale, std::abs(product(interface.dofs()[i])));

  const auto state = contact->save_state();
  bool       same  = true;
  const auto force = [&](const double h) {
    std::vector<double> u = u_2;
    for (unsigned int i = 0; i < n; ++i)
      u[i] += h * v[i];
    contact->update_active_set(interface, u);
    same         = same && contact->contact_sets() == sets;
    const auto F = contact->residuals(interface, u).contact_force;
    contact->restore_state(*state);
    return F;
  };
  // The bound: the differences' truncation error (h^2, the 3D slip
  // direction; the rest is linear in u) at h = 1e-6, their round-off at
  // 1e-7.
  for (const auto [h, bound] : {std::pair(1e-6, 1e-6), std::pair(1e-7, 1e-7)})
    {
      const auto plus = force(h), minus = force(-h);
      double     error = 0.;
      for (unsigned int i = 0; i < n; ++i)
        error =
          std::max(error, std::abs((plus[i] - minus[i]) / (2. * h) + product(interface.dofs()[i])));
      std::cout << "h = " << h << ": tangent against central differences, error below " << bound
                << " of |K v|: " << (error < bound * scale ? "yes" : "no") << std::endl;
      if (std::getenv("SHOW_ERROR") || error >= bound * scale)
        std::cout << "  error " << error / scale << " of |K v|" << std::endl;
    }
  std::cout << "the same stick/slip sets at every perturbed iterate: " << (same ? "yes" : "no")
            << std::endl;
}
