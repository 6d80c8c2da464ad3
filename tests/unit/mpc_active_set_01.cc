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
// 'mpc frictional' (Coulomb mu = 0.5; tangent (1, 0), weighted slip
// xi_j = u_sx - u_mx since the last accepted step, masters fixed):
// - recovered (t, p) = (-0.3, 1) sticks (|t| < T = 0.5), (-0.6, 1) slips
//   along the traction (sign -1);
// - the slipping node moved by dx = +0.01 (its traction -T opposes the
//   slip) keeps slipping; moved by -0.01 (the slip turned back against the
//   traction) it sticks;
// - a node that comes into contact moving by dx = 0.02 slides in, its
//   traction opposing the slip (sign -1).

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
  /// y (and @p slave_x[k] along x, if given), masters fixed.
  std::vector<double>
  displacement(const ContactInterface<2> &interface,
               const std::vector<double> &slave_y,
               const std::vector<double> &slave_x = {0., 0.})
  {
    std::vector<double> u(interface.dofs().size(), 0.);
    for (unsigned int k = 0; k < interface.slave_nodes.size(); ++k)
      {
        const auto &dofs               = interface.nodes[interface.slave_nodes[k].node].dofs;
        u[interface.position(dofs[0])] = slave_x[k];
        u[interface.position(dofs[1])] = slave_y[k];
      }
    return u;
  }

  /// The bulk residual of a state with pressure @p lambdas[k] (and
  /// tangential traction @p tangential[k], if given) at slave node k:
  /// r = D (-lambda n + t tau), tau = (1, 0).
  std::vector<double>
  residual_of(const ContactInterface<2> &interface,
              const std::vector<double> &lambdas,
              const std::vector<double> &tangential = {0., 0.})
  {
    std::vector<double> residual(interface.dofs().size(), 0.);
    for (unsigned int k = 0; k < interface.slave_nodes.size(); ++k)
      {
        const auto &s                         = interface.slave_nodes[k];
        const auto &dofs                      = interface.nodes[s.node].dofs;
        residual[interface.position(dofs[0])] = s.D * tangential[k];
        residual[interface.position(dofs[1])] = -lambdas[k] * s.D * s.normal[1];
      }
    return residual;
  }

  std::unique_ptr<ContactFormulation<2>>
  make_formulation(const std::string &name,
                   const std::string &penalty,
                   const std::string &friction = "")
  {
    ParameterHandler prm;
    ContactParameters::declare_parameters(prm);
    ContactFormulation<2>::declare_parameters(prm);
    prm.enter_subsection("Contact");
    prm.set("Pairs", "4: 3");
    prm.set("Formulation", name);
    prm.set("Penalty", penalty);
    prm.set("Scale factor", "10");
    prm.set("Friction", friction);
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
                << (std::abs(interface.gap(s, u)) < 1e-12 ? 0. : interface.gap(s, u)) << ", active "
                << contact.is_active(s.node) << ", pressure " << contact.normal_pressure(s.node)
                << (contact.transmits_shear() ?
                      ", stick " + std::to_string(contact.held_tangentially(s.node)) +
                        ", traction_x " + std::to_string(contact.traction(s)[0]) :
                      std::string())
                << std::endl;
  }

  void
  mpc_frictional(const ContactInterface<2> &interface)
  {
    auto contact = make_formulation("mpc frictional", "auto", "coulomb 0.5");
    contact->initialize(interface);
    const auto touching = displacement(interface, {-0.1, -0.1});
    contact->start_load_step(interface, touching, StepStart::unloaded);
    contact->recover_multipliers(interface, residual_of(interface, {1., 1.}, {-0.3, -0.6}));
    unsigned int changes = contact->update_active_set(interface, touching);
    std::cout << "mpc frictional, (t, p) = (-0.3, 1) and (-0.6, 1): " << changes << " change(s)"
              << std::endl;
    print_state("  stick inside the bound, slip on it", interface, *contact, touching);
    const auto saved = contact->save_state();
    // Node 1 slips with traction -T = -0.5: recovered as such.
    const auto slip_residual = residual_of(interface, {1., 1.}, {-0.3, -0.5});
    for (const double dx : {0.01, -0.01})
      {
        contact->restore_state(*saved);
        contact->recover_multipliers(interface, slip_residual);
        const auto moved = displacement(interface, {-0.1, -0.1}, {0., dx});
        changes          = contact->update_active_set(interface, moved);
        std::cout << "mpc frictional, slip node moved by dx = " << dx << ": " << changes
                  << " change(s)" << std::endl;
        print_state("  state", interface, *contact, moved);
      }
    // A new step: node 0 open, node 1 not in contact; then node 0 comes in
    // moving by 0.02.
    contact->initialize(interface);
    const auto open = displacement(interface, {0., 0.});
    contact->start_load_step(interface, open, StepStart::continued);
    contact->accept_load_step(interface, open);
    const auto entering = displacement(interface, {-0.11, 0.}, {0.02, 0.});
    contact->recover_multipliers(interface, residual_of(interface, {0., 0.}));
    changes = contact->update_active_set(interface, entering);
    std::cout << "mpc frictional, node 0 comes into contact moving by 0.02: " << changes
              << " change(s), stick " << contact->held_tangentially(interface.slave_nodes[0].node)
              << ", slip direction from the contact sets "
              << contact->contact_sets()[interface.slave_nodes[0].node] << " (2 = +, 3 = -)"
              << std::endl;
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
  std::cout << "mortar: " << interface.slave_nodes.size()
            << " slave nodes, D = " << interface.slave_nodes[0].D << ", normal "
            << interface.slave_nodes[0].normal << std::endl;

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
  mpc->start_load_step(interface, start, StepStart::continued);
  print_state("start of a step", interface, *mpc, start);
  AffineConstraints<double> constraints;
  mpc->add_constraints(interface, zero, constraints, false);
  constraints.close();
  std::cout << "  constraints: " << constraints.n_constraints() << ", node 0's inhomogeneity "
            << constraints.get_inhomogeneity(interface.nodes[interface.slave_nodes[0].node].dofs[1])
            << std::endl;

  // Node 0 held at gap 0 but pulling; node 1 penetrating by 0.03.
  const auto pulled = displacement(interface, {-0.1, -0.13});
  mpc->recover_multipliers(interface, residual_of(interface, {-0.3, 0.}));
  unsigned int changes = mpc->update_active_set(interface, pulled);
  std::cout
    << "update: " << changes << " change(s), multiplier residual "
    << mpc->residuals(interface, pulled).multiplier
    << " (expected |(0.3 / k, 0.03)| = 0.0424264: the\n    released multiplier over k, the active node's gap)"
    << std::endl;
  print_state("  after release on tension and activation on penetration", interface, *mpc, pulled);

  // Node 1 compressed (lambda = 1) at an open gap 0.01; node 0 open.
  const auto opened = displacement(interface, {-0.05, -0.09});
  mpc->recover_multipliers(interface, residual_of(interface, {0., 1.}));
  changes = mpc->update_active_set(interface, opened);
  std::cout << "update: " << changes << " change(s)" << std::endl;
  print_state("  mpc, compressed node at an open gap", interface, *mpc, opened);

  auto alm = make_formulation("alm frictionless", "1000");
  alm->initialize(interface);
  alm->start_load_step(interface, displacement(interface, {0., -0.13}), StepStart::continued);
  alm->recover_multipliers(interface, residual_of(interface, {0., 1.}));
  changes = alm->update_active_set(interface, opened);
  std::cout << "alm (eps = 1000), the same: " << changes << " change(s)" << std::endl;
  print_state("  alm, compressed node at an open gap", interface, *alm, opened);

  // A new mesh: node 0 at gap 0.005 (about to touch), node 1 at 0.05.
  mpc->initialize(interface);
  const auto near = displacement(interface, {-0.095, -0.05});
  mpc->start_load_step(interface, near, StepStart::unloaded);
  print_state("first step of a mesh (Active check factor 1e-2, h = " +
                std::to_string(interface.slave_nodes[0].size) + ")",
              interface, *mpc, near);

  mpc_frictional(interface);
}
