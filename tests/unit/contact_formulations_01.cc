// The frictionless formulations through the ContactFormulation interface,
// on a hand-made interface without a scene: two unit squares (one cell each,
// Q1), the upper one 0.1 above the lower one, matching faces, so that every
// mortar quantity is known by hand: two slave nodes with D_j = 1/2,
// M_jl = delta_jl / 2, normal (0, -1), gap g_j = 0.1 + u_sy - u_my.
// 'alm frictionless': active-set rule lambda - eps g > 0, the constraint
// u_sy = u_my - 0.1 of an active node, multiplier recovery
// lambda = -r / (D n_y) from the bulk residual, release of a node in
// tension with its multiplier in the residual (lambda / k), traction
// -lambda n, save / restore of the state. 'penalty frictionless': pressure
// eps * penetration, no constraints, zero residual.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>

#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/material/material.h>

#include "unit_test_materials.h"
#include <contact_fem/core/parameters.h>

#include <iomanip>
#include <iostream>

using namespace dealii;
using namespace contact_fem;

namespace
{
  constexpr double gap0 = 0.1;

  void
  make_blocks(Triangulation<2> &tria)
  {
    Triangulation<2> lower, upper;
    GridGenerator::hyper_rectangle(lower, Point<2>(0., 0.), Point<2>(1., 1.));
    GridGenerator::hyper_rectangle(upper, Point<2>(0., 1. + gap0), Point<2>(1., 2. + gap0));
    GridGenerator::merge_triangulations(lower, upper, tria);
    for (const auto &cell : tria.active_cell_iterators())
      {
        const bool is_upper = cell->center()[1] > 1.;
        cell->set_material_id(is_upper ? 1 : 2);
        for (const auto f : cell->face_indices())
          {
            const double y = cell->face(f)->center()[1];
            if (is_upper && std::abs(y - (1. + gap0)) < 1e-12)
              cell->face(f)->set_boundary_id(3);
            else if (!is_upper && std::abs(y - 1.) < 1e-12)
              cell->face(f)->set_boundary_id(4);
            else
              cell->face(f)->set_boundary_id(0);
          }
      }
  }

  /// The interface displacement: slave nodes moved by @p slave_y, masters
  /// fixed.
  std::vector<double>
  displacement(const ContactInterface<2> &interface, const std::vector<double> &slave_y)
  {
    std::vector<double> u(interface.dofs().size(), 0.);
    unsigned int        k = 0;
    for (const auto &s : interface.slave_nodes)
      u[interface.position(interface.nodes[s.node].dofs[1])] = slave_y[k++];
    return u;
  }

  std::unique_ptr<ContactFormulation<2>>
  make_formulation(const std::string &name, const std::string &penalty)
  {
    ParameterHandler prm;
    ContactParameters::declare_parameters(prm);
    ContactFormulation<2>::declare_parameters(prm);
    prm.enter_subsection("Contact");
    prm.set("Formulation", name);
    prm.set("Penalty", penalty);
    prm.set("Scale factor", "10");
    prm.leave_subsection();
    return ContactFormulation<2>::create(prm);
  }

  void
  print_state(const ContactInterface<2> &interface, const ContactFormulation<2> &contact)
  {
    for (const auto &s : interface.slave_nodes)
      std::cout << "    node x = " << interface.nodes[s.node].reference[0] << ": active "
                << contact.is_active(s.node) << ", pressure " << contact.normal_pressure(s.node)
                << ", traction_y " << contact.traction(s)[1] << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(6);

  Triangulation<2> tria;
  make_blocks(tria);
  const FESystem<2> fe(FE_Q<2>(1), 2);
  DoFHandler<2>     dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const MappingQ<2> mapping(1);

  const Materials<2> materials = make_materials<2>("1, 2", "100, 200", "0, 0");

  AffineConstraints<double> no_dirichlet;
  no_dirichlet.close();
  ContactInterface<2> interface;
  interface.initialize(mapping, dof_handler, {ContactPair{3, 4}}, no_dirichlet, no_dirichlet,
                       materials, MPI_COMM_WORLD);
  interface.update(std::vector<double>(interface.dofs().size(), 0.), 3.);
  std::cout << "mortar: " << interface.slave_nodes.size() << " slave nodes" << std::endl;
  for (const auto &s : interface.slave_nodes)
    std::cout << "  x = " << interface.nodes[s.node].reference[0] << ": D = " << s.D << ", normal "
              << s.normal << ", gap "
              << interface.gap(s, std::vector<double>(interface.dofs().size(), 0.)) << std::endl;

  // --- alm frictionless, eps = 100 ------------------------------------------
  auto alm = make_formulation("alm frictionless", "100");
  alm->initialize(interface);
  // Both slave nodes 0.02 inside the master: lambda - eps g = 2 > 0.
  const std::vector<double> penetrating = displacement(interface, {-0.12, -0.12});
  alm->start_load_step(interface, penetrating, StepStart::continued);
  std::cout << "alm, both nodes 0.02 inside: " << alm->n_active() << " active" << std::endl;

  AffineConstraints<double> constraints;
  alm->add_constraints(interface, std::vector<double>(interface.dofs().size(), 0.), constraints,
                       false);
  constraints.close();
  for (const auto &s : interface.slave_nodes)
    {
      const auto dof = interface.nodes[s.node].dofs[1];
      std::cout << "  constraint of slave y DoF: inhomogeneity "
                << constraints.get_inhomogeneity(dof) << ", entries";
      for (const auto &[master_dof, coefficient] : *constraints.get_constraint_entries(dof))
        for (const auto &node : interface.nodes)
          for (unsigned int d = 0; d < 2; ++d)
            if (node.dofs[d] == master_dof)
              std::cout << " (u"
                        << "xy"[d] << " of the master node at x = " << node.reference[0] << ": "
                        << coefficient << ")";
      std::cout << std::endl;
    }

  // The bulk residual at the eliminated DoFs: r = -lambda D n_y with
  // lambda = 1.5 at the first node and -0.2 (tension) at the second.
  std::vector<double> residual(interface.dofs().size(), 0.);
  const double        lambdas[2] = {1.5, -0.2};
  for (unsigned int k = 0; k < 2; ++k)
    {
      const auto &s = interface.slave_nodes[k];
      residual[interface.position(interface.nodes[s.node].dofs[1])] =
        -lambdas[k] * s.D * s.normal[1];
    }
  alm->recover_multipliers(interface, residual);
  std::cout << "alm, recovered multipliers:" << std::endl;
  print_state(interface, *alm);
  const auto saved = alm->save_state();

  // At the converged gap 0 the node in tension is released.
  const std::vector<double> touching  = displacement(interface, {-0.1, -0.1});
  const unsigned int        changes   = alm->update_active_set(interface, touching);
  const auto                residuals = alm->residuals(interface, touching);
  std::cout << "alm, active-set update at zero gap: " << changes << " change(s), "
            << alm->n_active() << " active, multiplier residual " << residuals.multiplier
            << " (expected 0.2 / k = 0.02)" << std::endl;
  print_state(interface, *alm);
  double force_sum = 0., force_size = 0.;
  for (const double f : residuals.contact_force)
    {
      force_sum += f;
      force_size += std::abs(f);
    }
  std::cout << "  contact forces on slave and master cancel: "
            << (std::abs(force_sum) < 1e-12 * force_size ? "yes" : "no") << std::endl;

  alm->restore_state(*saved);
  std::cout << "alm, after restore_state:" << std::endl;
  print_state(interface, *alm);

  // --- penalty frictionless, eps = 1000 ---------------------------------------
  auto penalty = make_formulation("penalty frictionless", "1000");
  penalty->initialize(interface);
  penalty->start_load_step(interface, penetrating, StepStart::continued);
  AffineConstraints<double> none;
  penalty->add_constraints(interface, std::vector<double>(interface.dofs().size(), 0.), none,
                           false);
  const unsigned int penalty_changes = penalty->update_active_set(interface, penetrating);
  std::cout << "penalty, both nodes 0.02 inside: " << penalty_changes << " change(s), "
            << penalty->n_active() << " active, " << none.n_constraints()
            << " constraints, multiplier residual "
            << penalty->residuals(interface, penetrating).multiplier
            << " (pressure eps * 0.02 = 20)" << std::endl;
  print_state(interface, *penalty);
}
