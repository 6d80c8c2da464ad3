// The active-set rule of 'mpc frictionless' through the ContactFormulation
// interface, on a hand-made interface: two unit squares, the upper one
// (slave, base boundary 4) 0.1 above the lower one (master, top 3),
// matching faces: two slave nodes with D_j = 1/2, M_jl = delta_jl / 2,
// normal (0, -1), gap g_j = 0.1 + u_sy - u_my (masters fixed here).
// - Contact/Penalty given: refused (the formulation has none).
// - start of a step: the penetrating node starts active, the open one not;
//   one constraint, that of the active node (u_sy = u_my - 0.1).
// - the reaction of the active node pulls (lambda = -0.3): released,
//   whatever its gap; the other node penetrates (g = -0.03): activated.
//   Residual: |(released multiplier / k, gap of the active node)| =
//   |(0.3 / 10, 0.03)|.
// - an active node in compression stays active even where its gap is
//   open (g = +0.01: only the reaction releases it), where 'alm
//   frictionless' (eps = 1000: 1 - 1000 * 0.01 < 0) releases it; an
//   inactive node with an open gap stays inactive.
// - the first step of a mesh: a node about to touch (g below Active check
//   factor * h) starts active.

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

  /// The interface displacement: slave node k moved by @p slave_y[k] along
  /// y, masters fixed.
  std::vector<double>
  displacement(const ContactInterface<2> &interface, const std::vector<double> &slave_y)
  {
    std::vector<double> u(interface.dofs().size(), 0.);
    unsigned int        k = 0;
    for (const auto &s : interface.slave_nodes)
      u[interface.position(interface.nodes[s.node].dofs[1])] = slave_y[k++];
    return u;
  }

  /// The bulk residual of a state with multiplier @p lambdas[k] at slave
  /// node k: r = -lambda D n_y at its y DoF (the DoF an active node
  /// eliminates).
  std::vector<double>
  residual_of(const ContactInterface<2> &interface, const std::vector<double> &lambdas)
  {
    std::vector<double> residual(interface.dofs().size(), 0.);
    for (unsigned int k = 0; k < interface.slave_nodes.size(); ++k)
      {
        const auto &s = interface.slave_nodes[k];
        residual[interface.position(interface.nodes[s.node].dofs[1])] =
          -lambdas[k] * s.D * s.normal[1];
      }
    return residual;
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
    prm.leave_subsection();
    return ContactFormulation<2>::create(prm);
  }

  void
  print_state(const std::string           &what,
              const ContactInterface<2>   &interface,
              const ContactFormulation<2> &contact,
              const std::vector<double>   &u)
  {
    std::cout << what << ": " << contact.n_active() << " active" << std::endl;
    for (const auto &s : interface.slave_nodes)
      std::cout << "    node x = " << interface.nodes[s.node].reference[0] << ": gap "
                << (std::abs(interface.gap(s, u)) < 1e-12 ? 0. : interface.gap(s, u)) << ", active " << contact.is_active(s.node)
                << ", pressure " << contact.normal_pressure(s.node) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(6);

  Triangulation<2> tria;
  {
    Triangulation<2> lower, upper;
    GridGenerator::hyper_rectangle(lower, Point<2>(0., 0.), Point<2>(1., 1.));
    GridGenerator::hyper_rectangle(upper, Point<2>(0., 1. + gap0), Point<2>(1., 2. + gap0));
    GridGenerator::merge_triangulations(lower, upper, tria);
    label_stacked_blocks(tria, gap0);
  }
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
  std::cout << "mortar: " << interface.slave_nodes.size() << " slave nodes, D = "
            << interface.slave_nodes[0].D << ", normal " << interface.slave_nodes[0].normal
            << std::endl;

  try
    {
      make_formulation("mpc frictionless", "100");
      std::cout << "Contact/Penalty = 100 accepted (wrong)" << std::endl;
    }
  catch (const std::exception &e)
    {
      const std::string what = e.what();
      std::cout << "Contact/Penalty = 100 refused: "
                << what.substr(what.find("Contact/Penalty is set"),
                               what.find("\n\n") - what.find("Contact/Penalty is set"))
                << std::endl;
    }

  auto mpc = make_formulation("mpc frictionless", "auto");
  mpc->initialize(interface);
  const std::vector<double> zero(interface.dofs().size(), 0.);

  // Node 0 penetrates by 0.02, node 1 is open (gap 0.1).
  const auto start = displacement(interface, {-0.12, 0.});
  mpc->start_load_step(interface, start, false);
  print_state("start of a step", interface, *mpc, start);
  AffineConstraints<double> constraints;
  mpc->add_constraints(interface, zero, constraints, false);
  constraints.close();
  std::cout << "  constraints: " << constraints.n_constraints() << ", node 0's inhomogeneity "
            << constraints.get_inhomogeneity(
                 interface.nodes[interface.slave_nodes[0].node].dofs[1])
            << std::endl;

  // Node 0 held at gap 0 but pulling; node 1 penetrating by 0.03.
  const auto pulled = displacement(interface, {-0.1, -0.13});
  mpc->recover_multipliers(interface, residual_of(interface, {-0.3, 0.}));
  unsigned int changes = mpc->update_active_set(interface, pulled);
  std::cout << "update: " << changes << " change(s), multiplier residual "
            << mpc->residuals(interface, pulled).multiplier << " (expected |(0.3 / k, 0.03)| = 0.0424264: the\n    released multiplier over k, the active node's gap)"
            << std::endl;
  print_state("  after release on tension and activation on penetration", interface, *mpc,
              pulled);

  // Node 1 compressed (lambda = 1) at an open gap 0.01; node 0 open.
  const auto opened = displacement(interface, {-0.05, -0.09});
  mpc->recover_multipliers(interface, residual_of(interface, {0., 1.}));
  changes = mpc->update_active_set(interface, opened);
  std::cout << "update: " << changes << " change(s)" << std::endl;
  print_state("  mpc, compressed node at an open gap", interface, *mpc, opened);

  auto alm = make_formulation("alm frictionless", "1000");
  alm->initialize(interface);
  alm->start_load_step(interface, displacement(interface, {0., -0.13}), false);
  alm->recover_multipliers(interface, residual_of(interface, {0., 1.}));
  changes = alm->update_active_set(interface, opened);
  std::cout << "alm (eps = 1000), the same: " << changes << " change(s)" << std::endl;
  print_state("  alm, compressed node at an open gap", interface, *alm, opened);

  // A new mesh: node 0 at gap 0.005 (about to touch), node 1 at 0.05.
  mpc->initialize(interface);
  const auto near = displacement(interface, {-0.095, -0.05});
  mpc->start_load_step(interface, near, true);
  print_state("first step of a mesh (Active check factor 1e-2, h = " +
                std::to_string(interface.slave_nodes[0].size) + ")",
              interface, *mpc, near);
}
