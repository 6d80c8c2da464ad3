// Shared by the tangent tests of 'penalty frictional' on the stacked
// blocks: the formulation, a line of its sets, and the check of its matrix
// against central differences of its contact force.
#ifndef contact_fem_unit_test_penalty_frictional_h
#define contact_fem_unit_test_penalty_frictional_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/contact_parameters.h>
#include <contact_fem/contact/formulations/contact_formulation.h>

#include "unit_test_random.h"
#include "unit_test_stacked_interface.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <utility>

namespace unit_test_penalty_frictional
{
  /// Pairs 3: 4, eps_n = eps_t = 1e4, Coulomb 0.3, with @p kinematics.
  inline std::unique_ptr<contact_fem::ContactFormulation<3>>
  make_formulation(const std::string &kinematics)
  {
    dealii::ParameterHandler prm;
    contact_fem::ContactParameters::declare_parameters(prm);
    contact_fem::ContactFormulation<3>::declare_parameters(prm);
    prm.enter_subsection("Contact");
    prm.set("Pairs", "3: 4");
    prm.set("Formulation", "penalty frictional");
    prm.set("Kinematics", kinematics);
    prm.set("Penalty", "1e4");
    prm.set("Tangential penalty", "1e4");
    prm.set("Friction", "coulomb 0.3");
    prm.leave_subsection();
    return contact_fem::ContactFormulation<3>::create(prm);
  }

  /// "N active slave nodes, stick S, slip L" from the set codes.
  inline std::string
  sets_text(const contact_fem::ContactFormulation<3> &contact)
  {
    const auto codes = contact.contact_sets();
    return std::to_string(contact.n_active()) + " active slave nodes, stick " +
           std::to_string(std::count(codes.begin(), codes.end(), 1)) + ", slip " +
           std::to_string(std::count_if(codes.begin(), codes.end(), [](const int c) {
             return c >= 2;
           }));
  }

  /// The matrix of assemble() at @p u (K, the derivative of -F) against
  /// (F(u + h v) - F(u - h v)) / 2h for a random v (F from residuals()
  /// after update_active_set(), @p follow run on each perturbed iterate
  /// first), at h = 1e-6 and 1e-7 with the bounds 1e-6 and 1e-7 of |K v|
  /// (the truncation error at the first, the round-off at the second);
  /// then whether every perturbed iterate kept the current stick/slip
  /// sets. SHOW_ERROR=1 prints the errors.
  template <typename Follow>
  void
  check_tangent(contact_fem::ContactFormulation<3> &contact,
                contact_fem::ContactInterface<3>   &interface,
                const unsigned int                  n_dofs,
                const std::vector<double>          &u,
                Random                             &random,
                const Follow                       &follow)
  {
    using namespace dealii;
    const unsigned int        n     = interface.dofs().size();
    const std::vector<int>    sets  = contact.contact_sets();
    const IndexSet            owned = complete_index_set(n_dofs);
    AffineConstraints<double> none;
    none.close();
    DynamicSparsityPattern pattern(n_dofs);
    contact.add_sparsity(interface, none, owned, pattern);
    TrilinosWrappers::SparseMatrix matrix;
    matrix.reinit(owned, owned, pattern, MPI_COMM_WORLD);
    TrilinosWrappers::MPI::Vector rhs(owned, MPI_COMM_WORLD);
    contact.assemble(interface, none, none, owned, matrix, rhs);
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

    const auto state = contact.save_state();
    bool       same  = true;
    const auto force = [&](const double h) {
      std::vector<double> w = u;
      for (unsigned int i = 0; i < n; ++i)
        w[i] += h * v[i];
      follow(w);
      contact.update_active_set(interface, w);
      same         = same && contact.contact_sets() == sets;
      const auto F = contact.residuals(interface, w).contact_force;
      contact.restore_state(*state);
      return F;
    };
    for (const auto &[h, bound] : {std::pair(1e-6, 1e-6), std::pair(1e-7, 1e-7)})
      {
        const auto plus = force(h), minus = force(-h);
        double     error = 0.;
        for (unsigned int i = 0; i < n; ++i)
          error = std::max(error, std::abs((plus[i] - minus[i]) / (2. * h) +
                                           product(interface.dofs()[i])));
        std::cout << "h = " << h << ": tangent against central differences, error below " << bound
                  << " of |K v|: " << (error < bound * scale ? "yes" : "no") << std::endl;
        if (std::getenv("SHOW_ERROR") || error >= bound * scale)
          std::cout << "  error " << error / scale << " of |K v|" << std::endl;
      }
    std::cout << "the same stick/slip sets at every perturbed iterate: " << (same ? "yes" : "no")
              << std::endl;
  }

  /// The two load steps of the current-kinematics tangent tests on the
  /// stacked blocks (penalty_frictional_linearisation_01 and _03), then
  /// check_tangent() at the second step's iterate. The slave top is bent
  /// down and the master base up by @p sag r^2 (r from the centre of the
  /// unit square; 0 keeps them flat). Step 1 lowers the master by @p drop
  /// and slides the slave nodes by up to 1e-3 (they stick: the history
  /// traction is not zero); step 2 slides them by up to 0.006 per component
  /// and moves every interface DoF by up to 2e-3, so that some stick and
  /// some slip. The operators and their linearisation follow every iterate,
  /// as the driver's search does.
  inline void
  check_current_two_steps(const double sag, const double drop)
  {
    using namespace contact_fem;
    StackedBlocksInterface blocks(1);
    auto                  &interface = blocks.interface;
    const unsigned int     n         = interface.dofs().size();
    Random                 random(29);
    std::vector<double>    u_1(n, 0.), u_2(n, 0.);
    for (const auto &node : interface.nodes)
      for (unsigned int d = 0; d < 3; ++d)
        {
          const unsigned int i = interface.position(node.dofs[d]);
          const double       bend =
            sag * (std::pow(node.reference[0] - 0.5, 2) + std::pow(node.reference[1] - 0.5, 2));
          if (node.slave)
            {
              u_1[i] = d < 2 ? 1e-3 * random.next() : -bend;
              u_2[i] = u_1[i] + (d < 2 ? 0.006 * random.next() : 0.);
            }
          else
            u_1[i] = u_2[i] = d == 2 ? -drop + bend : 0.;
          u_2[i] += 2e-3 * random.next();
        }

    const auto follow = [&](const std::vector<double> &u) {
      interface.update(u, 3.);
      interface.linearise(true);
    };
    auto contact = make_formulation("current");
    follow(std::vector<double>(n, 0.));
    contact->initialize(interface);
    contact->start_load_step(interface, std::vector<double>(n, 0.), StepStart::continued);
    follow(u_1);
    contact->update_active_set(interface, u_1);
    std::cout << "step 1: " << sets_text(*contact) << std::endl;
    contact->accept_load_step(interface, u_1);
    contact->start_load_step(interface, u_1, StepStart::continued);
    follow(u_2);
    // The step's first update keeps the stick nodes sticking (current
    // kinematics: it sees the predictor); the second decides.
    contact->update_active_set(interface, u_2);
    contact->update_active_set(interface, u_2);
    std::cout << "step 2: " << sets_text(*contact) << std::endl;
    check_tangent(*contact, interface, blocks.dof_handler.n_dofs(), u_2, random, follow);
  }
} // namespace unit_test_penalty_frictional

#endif
