// The frictional formulations through the ContactFormulation interface, on
// a hand-made interface: two unit squares, the upper one (slave, its base
// boundary 4) 0.1 above the lower one (master, its top 3),
// matching faces: two slave nodes with D_j = 1/2, M_jl = delta_jl / 2,
// normal (0, -1), tangent (1, 0), gap g_j = 0.1 + u_sy - u_my, weighted slip
// xi_j = u_sx - u_mx since the last accepted step. Coulomb mu = 0.5, k = 10.
//
// 'penalty frictional' (eps_n = 100, eps_t = 50): both slave nodes 0.02
// inside (p = eps_n 0.02 = 2, slip bound T = mu p = 1) and moved by dx:
// trial traction -eps_t dx; dx = 0.01 sticks with t = -0.5, dx = 0.04 slips
// with t = -T = -1. The tangential force D t is on the slave, -M t on the
// master.
// 'alm frictional' (eps = 100): multipliers p = 1, t = -0.3 recovered from
// a hand-made residual r_j = D_j lambda_j; at gap 0 the trial traction
// t - eps dx against T(p) = 0.5: dx = 0.001 sticks (trial -0.4, residual
// the slip xi = 0.001 per node), dx = 0.005 slips (trial -0.8, residual
// (t - sigma T) / k = (-0.3 + 0.5) / 10 = 0.02 per node); the multiplier
// residual is sqrt(2) times that of one node.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/material/material.h>

#include "unit_test_blocks.h"
#include "unit_test_materials.h"

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
    label_stacked_blocks(tria, gap0);
  }

  /// The interface displacement: every slave node moved by (@p dx, @p dy),
  /// masters fixed.
  std::vector<double>
  displacement(const ContactInterface<2> &interface, const double dx, const double dy)
  {
    std::vector<double> u(interface.dofs().size(), 0.);
    for (const auto &s : interface.slave_nodes)
      {
        u[interface.position(interface.nodes[s.node].dofs[0])] = dx;
        u[interface.position(interface.nodes[s.node].dofs[1])] = dy;
      }
    return u;
  }

  std::unique_ptr<ContactFormulation<2>>
  make_formulation(const std::string &name, const std::string &penalty)
  {
    ParameterHandler prm;
    ContactParameters::declare_parameters(prm);
    ContactFormulation<2>::declare_parameters(prm);
    prm.enter_subsection("Contact");
    prm.set("Pairs", "4: 3");
    prm.set("Formulation", name);
    prm.set("Penalty", penalty);
    prm.set("Scale factor", "10");
    prm.set("Friction", "coulomb 0.5");
    if (name == "penalty frictional")
      prm.set("Tangential penalty", "50");
    prm.leave_subsection();
    return ContactFormulation<2>::create(prm);
  }

  /// Per slave node: active, held tangentially (stick), pressure and the
  /// traction (t, p) = -p n + t tau; then the Newton table cells.
  void
  print_state(const ContactInterface<2>   &interface,
              const ContactFormulation<2> &contact,
              const unsigned int           iteration)
  {
    for (const auto &s : interface.slave_nodes)
      std::cout << "    node x = " << interface.nodes[s.node].reference[0] << ": active "
                << contact.is_active(s.node) << ", stick " << contact.held_tangentially(s.node)
                << ", pressure " << contact.normal_pressure(s.node) << ", traction "
                << contact.traction(s) << std::endl;
    std::cout << "    table:" << contact.iteration_header() << std::endl
              << "          " << contact.iteration_cells(iteration) << std::endl;
  }

  /// The x contact force on the slave and on the master nodes.
  void
  print_tangential_forces(const ContactInterface<2>              &interface,
                          const ContactFormulation<2>::Residuals &residuals)
  {
    for (const auto &node : interface.nodes)
      std::cout << "    x force on the " << (node.slave ? "slave " : "master")
                << " node at x = " << node.reference[0] << ": "
                << residuals.contact_force[interface.position(node.dofs[0])] << std::endl;
  }

  void
  penalty_frictional(const ContactInterface<2> &interface)
  {
    for (const double dx : {0.01, 0.04})
      {
        auto contact = make_formulation("penalty frictional", "100");
        contact->initialize(interface);
        const auto u = displacement(interface, dx, -0.12);
        contact->start_load_step(interface, u, StepStart::continued);
        const unsigned int changes = contact->update_active_set(interface, u);
        std::cout << "penalty frictional, 0.02 inside, dx = " << dx << ": " << changes
                  << " change(s) (the step starts sticking)" << std::endl;
        print_state(interface, *contact, 1);
        print_tangential_forces(interface, contact->residuals(interface, u));
        Json results = Json::object();
        contact->add_results(interface, results);
        std::cout << "    results: stick " << results["stick_nodes"].number_value() << ", slip "
                  << results["slip_nodes"].number_value() << ", total tangential force "
                  << results["total_tangential_contact_force"].number_value()
                  << ", total normal force " << results["total_normal_contact_force"].number_value()
                  << std::endl;
      }
  }

  void
  alm_frictional(const ContactInterface<2> &interface)
  {
    for (const double dx : {0.001, 0.005})
      {
        auto contact = make_formulation("alm frictional", "100");
        contact->initialize(interface);
        // 0.02 inside: lambda - eps g = 2 > 0 (active), and with neither
        // traction nor slip the nodes start sticking.
        const auto start = displacement(interface, 0., -0.12);
        contact->start_load_step(interface, start, StepStart::continued);
        AffineConstraints<double> constraints;
        contact->add_constraints(interface, std::vector<double>(interface.dofs().size(), 0.),
                                 constraints, false);
        std::cout << "alm frictional, start: " << contact->n_active() << " active, "
                  << constraints.n_constraints() << " constrained DoFs (stick: both)" << std::endl;
        // r_j = D_j lambda_j with lambda_j = (t, p) = (-0.3, 1).
        std::vector<double> residual(interface.dofs().size(), 0.);
        for (const auto &s : interface.slave_nodes)
          {
            residual[interface.position(interface.nodes[s.node].dofs[0])] = s.D * -0.3;
            residual[interface.position(interface.nodes[s.node].dofs[1])] = s.D * 1.;
          }
        contact->recover_multipliers(interface, residual);
        const auto u       = displacement(interface, dx, -0.1);
        const auto changes = contact->update_active_set(interface, u);
        std::cout << "alm frictional, gap 0, dx = " << dx << ": " << changes
                  << " change(s), symmetric " << contact->symmetric() << ", multiplier residual "
                  << contact->residuals(interface, u).multiplier << std::endl;
        print_state(interface, *contact, 1);
      }
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
  const MappingQ<2>  mapping(1);
  const Materials<2> materials = make_materials<2>("1, 2", "100, 200", "0, 0");

  AffineConstraints<double> no_dirichlet;
  no_dirichlet.close();
  ContactInterface<2> interface;
  interface.initialize(mapping, dof_handler, {ContactPair{4, 3}}, no_dirichlet, no_dirichlet,
                       materials, MPI_COMM_WORLD);
  interface.update(std::vector<double>(interface.dofs().size(), 0.), 3.);
  for (const auto &s : interface.slave_nodes)
    std::cout << "slave x = " << interface.nodes[s.node].reference[0] << ": D = " << s.D
              << ", normal " << s.normal << ", interface normal " << s.interface_normal
              << std::endl;

  penalty_frictional(interface);
  alm_frictional(interface);
}
