// The tangent of 'alm frictional' and 'mpc frictional' on the current
// configuration (Contact/Kinematics = current), whose frame is the slave
// normal n_j (AlmFrictional::frame_on_interface()), against central
// differences, on curved non-matching pairs where the interface normal n_int
// is well off the slave normal (so that a frame taken from n_int would
// show): the stacked blocks (2D: 3 slave cells under 2 master cells; 3D
// those of penalty_frictional_linearisation_01, E = 100 below, the slave;
// 200 above), the slave top bent down and the master base bent up to
// parabolas / paraboloids (sag 0.08 over the unit width; n_int up to 0.28
// rad (2D) and 0.21 rad (3D) off the slave normal), Coulomb 0.3.
// Step 1 presses the master into the slave and slides the slave nodes a
// little; the multipliers are set (recover_multipliers(): a pressure and a
// tangential traction inside the cone per node), the step accepted; step 2
// slides the slave nodes further and perturbs every interface DoF, and the
// sets decided there hold stick and slip nodes.
//
// The alm eliminates the multipliers by its test space V_0 (frozen at the
// iterate u: a stick node's test functions follow its masters, a slip
// node's lie in the line / plane that annihilates the unknown part of its
// multiplier), so its matrix is the derivative at u of
//   rows of V_0:         V_0^T (-F(w)) + the cone term (3D slip nodes),
//   the eliminated rows: k G_j(w) (the weighted gap) and, for a stick node,
//                        k tau_k . D_j(w) xi_j(w) / D_j(u) (per tangent),
// with F(w) the force of the multipliers held at their values: D_j lambda_j
// on the slave, -M_jl lambda_j on the masters, lambda_j = -p_j n_f(w) +
// P_f(w) t_j (t_j the stick traction or T(p_j) d_j of a slip node, held in
// the tangent plane of the frame normal n_f = frame_normal(), here n_j),
// the cone term beta D_j(w) (e . xi_j(w)) (e . v) with e = n_f x d at u,
// and xi_j the objective slip from the operators of step 1. (D_j(w) xi_j(w)
// / D_j(u): the alm holds D_j in d xi_j; the term it drops, -xi_j dD_j /
// D_j, vanishes with xi_j at a solution.)
// Differences at h = 2e-4 and 1e-4 (error ratio near 4: second order,
// unless below 1e-9 of |K v|) and at 1e-6 (below 1e-6 of |K v|), the face
// pairs the same at every perturbed configuration. SHOW_ERROR=1 prints the
// errors.

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
#include <deal.II/lac/vector.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/contact_parameters.h>
#include <contact_fem/contact/formulations/alm_frictional.h>
#include <contact_fem/contact/formulations/mpc_frictional.h>
#include <contact_fem/material/material.h>

#include "unit_test_blocks.h"
#include "unit_test_materials.h"
#include "unit_test_random.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <vector>

using namespace dealii;
using namespace contact_fem;

namespace
{
  /// The formulation with read access to the multipliers and sets the
  /// tangent holds.
  template <class Formulation, int dim>
  class Probe : public Formulation
  {
  public:
    using Formulation::Formulation;
    using SlaveNode = typename ContactInterface<dim>::SlaveNode;

    bool
    slips(const SlaveNode &s) const
    {
      return this->sets.slips(s.node, this->active);
    }

    double
    pressure_of(const SlaveNode &s) const
    {
      return this->pressure[s.node];
    }

    /// t_j of a stick node, T(p_j) d_j of a slip node (global).
    Tensor<1, dim>
    held_tangential(const SlaveNode &s) const
    {
      const Tensor<1, dim> n = this->frame_normal(s);
      if (slips(s))
        return this->laws[s.pair]->threshold(this->pressure[s.node]) *
               to_global(this->sets.direction[s.node], n);
      return to_global(this->tangential[s.node], n);
    }

    Tensor<1, dim>
    direction(const SlaveNode &s) const
    {
      return to_global(this->sets.direction[s.node], this->frame_normal(s));
    }

    double
    cone_stiffness(const SlaveNode &s, const TangentialVector<dim> &xi) const
    {
      return this->slip_cone_stiffness(s, xi);
    }

    double
    scale_of(const SlaveNode &s) const
    {
      return this->scale[s.pair];
    }

    unsigned int
    gap_component(const ContactInterface<dim> &interface, const SlaveNode &s) const
    {
      return this->eliminated_component(interface, s);
    }
  };

  template <int dim>
  struct Operators
  {
    double                                       D = 0.;
    std::vector<std::pair<unsigned int, double>> M;
  };

  void
  make_blocks(Triangulation<2> &tria)
  {
    Triangulation<2> lower, upper;
    GridGenerator::subdivided_hyper_rectangle(lower, {3, 1}, Point<2>(0., 0.), Point<2>(1., 1.));
    GridGenerator::subdivided_hyper_rectangle(upper, {2, 1}, Point<2>(-0.1, 1.05),
                                              Point<2>(1.1, 2.05));
    GridGenerator::merge_triangulations(lower, upper, tria);
  }

  void
  make_blocks(Triangulation<3> &tria)
  {
    make_stacked_blocks_3d(tria);
  }

  /// -P_f(w) (D_j - D_j^n) x_j - sum_l (M_jl - M_jl^n) x_l: D_j xi_j (global)
  /// at the interface's configuration @p w.
  template <int dim>
  Tensor<1, dim>
  weighted_slip(const ContactInterface<dim>                     &interface,
                const typename ContactInterface<dim>::SlaveNode &s,
                const Operators<dim>                            &old,
                const Tensor<1, dim>                            &n_f,
                const std::vector<double>                       &w)
  {
    std::map<unsigned int, double> coefficient;
    coefficient[s.node] += s.D - old.D;
    for (const auto &[m, value] : s.M)
      coefficient[m] -= value;
    for (const auto &[m, value] : old.M)
      coefficient[m] += value;
    Tensor<1, dim> sum;
    for (const auto &[node, c] : coefficient)
      sum += c * (interface.nodes[node].reference + interface.displacement(node, w));
    return -(sum - (sum * n_f) * n_f);
  }

  template <int dim, class Formulation>
  void
  run(const std::string &name)
  {
    Triangulation<dim> tria;
    make_blocks(tria);
    label_stacked_blocks(tria, 0.05);
    const FESystem<dim> fe(FE_Q<dim>(1), dim);
    DoFHandler<dim>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const MappingQ<dim>       mapping(1);
    const Materials<dim>      materials = make_materials<dim>("1, 2", "100, 200", "0.3, 0.3");
    AffineConstraints<double> none;
    none.close();
    ContactInterface<dim> interface;
    interface.initialize(mapping, dof_handler, {ContactPair{3, 4}}, none, none, materials,
                         MPI_COMM_WORLD);
    const unsigned int n = interface.dofs().size();

    ParameterHandler prm;
    ContactParameters::declare_parameters(prm);
    ContactFormulation<dim>::declare_parameters(prm);
    prm.enter_subsection("Contact");
    prm.set("Pairs", "3: 4");
    prm.set("Formulation", name);
    prm.set("Kinematics", "current");
    prm.set("Friction", "coulomb 0.3");
    prm.leave_subsection();
    FrictionParameters friction;
    friction.parse_parameters(prm);
    Probe<Formulation, dim> contact(prm, friction);
    const auto              follow = [&](const std::vector<double> &w) {
      interface.update(w, 3.);
      interface.linearise(true);
    };

    // Step 1: the master 0.23 down (every slave node in contact),
    // both faces bent, the slave nodes slid by up to 1e-3. Step 2: further
    // slides, larger on every second slave node, and a perturbation of every
    // DoF.
    Random              random(dim == 2 ? 7 : 29);
    std::vector<double> u_1(n, 0.), u_2(n, 0.);
    unsigned int        count = 0;
    for (const auto &node : interface.nodes)
      {
        double r2 = 0.;
        for (unsigned int d = 0; d + 1 < dim; ++d)
          r2 += std::pow(2. * node.reference[d] - 1., 2);
        const double sag   = 0.08 * r2 / (dim - 1);
        const double slide = node.slave && ++count % 2 == 0 ? 0.1 : 0.002;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const unsigned int i = interface.position(node.dofs[d]);
            if (d + 1 < dim)
              {
                u_1[i] = node.slave ? 1e-3 * random.next() : 0.;
                u_2[i] = u_1[i] + (node.slave ? slide * random.next() : 0.);
              }
            else
              u_1[i] = u_2[i] = node.slave ? -sag : -0.23 + sag;
            u_2[i] += 1e-3 * random.next();
          }
      }

    follow(std::vector<double>(n, 0.));
    contact.initialize(interface);
    contact.start_load_step(interface, std::vector<double>(n, 0.), StepStart::continued);
    follow(u_1);
    contact.update_active_set(interface, u_1);
    // Multipliers: p_j in [5, 15], t_j of up to @p share p_j per component.
    const auto set_multipliers = [&](const double share) {
      std::vector<double> residual(n, 0.);
      for (const auto &s : interface.slave_nodes)
        if (s.paired)
          {
            const Tensor<1, dim> n_f = contact.frame_normal(s);
            const double         p   = 10. + 5. * random.next();
            Tensor<1, dim>       t;
            for (unsigned int d = 0; d < dim; ++d)
              t[d] = share * p * random.next() / std::sqrt(dim - 1.);
            t -= (t * n_f) * n_f;
            const Tensor<1, dim> lambda = -p * n_f + t;
            for (unsigned int d = 0; d < dim; ++d)
              residual[interface.position(interface.nodes[s.node].dofs[d])] = s.D * lambda[d];
          }
      contact.recover_multipliers(interface, residual);
    };
    set_multipliers(0.2);
    contact.accept_load_step(interface, u_1);
    std::map<unsigned int, Operators<dim>> step_1;
    for (const auto &s : interface.slave_nodes)
      if (s.paired)
        step_1[s.node] = Operators<dim>{s.D, s.M};
    contact.start_load_step(interface, u_1, StepStart::continued);
    follow(u_2);
    set_multipliers(0.4);
    contact.update_active_set(interface, u_2);

    // What the tangent holds at u = u_2, per active node.
    struct Held
    {
      double                                               p = 0., D = 0., k = 0., beta = 0.;
      Tensor<1, dim>                                       t, e;
      bool                                                 slips = false;
      std::vector<types::global_dof_index>                 gradient_dofs;
      std::vector<double>                                  gradient;
      std::vector<std::pair<types::global_dof_index, int>> rows; ///< -1 gap, k tangent k
      std::array<Tensor<1, dim>, dim - 1>                  frame;
    };
    const std::vector<double> zero(n, 0.);
    AffineConstraints<double> constraints, test_constraints;
    contact.add_constraints(interface, zero, constraints, false);
    constraints.close();
    contact.add_test_constraints(interface, zero, test_constraints);
    test_constraints.close();
    std::map<unsigned int, Held> held;
    unsigned int                 n_stick = 0, n_slip = 0;
    double                       largest_angle   = 0.;
    bool                         on_slave_normal = true;
    for (const auto &s : interface.slave_nodes)
      if (s.paired && contact.n_active() > 0 && contact.contact_sets()[s.node] > 0)
        {
          Held          &h   = held[s.node];
          Tensor<1, dim> n_f = contact.frame_normal(s);
          largest_angle =
            std::max(largest_angle, std::acos(std::min(1., s.interface_normal * s.normal)));
          on_slave_normal = on_slave_normal && n_f == s.normal;
          h.p             = contact.pressure_of(s);
          h.D             = s.D;
          h.k             = contact.scale_of(s);
          h.t             = contact.held_tangential(s);
          h.slips         = contact.slips(s);
          h.frame         = tangent_frame(n_f);
          (h.slips ? n_slip : n_stick) += 1;
          const auto &dofs = interface.nodes[s.node].dofs;
          if (h.slips)
            {
              for (unsigned int d = 0; d < dim; ++d)
                if (test_constraints.is_constrained(dofs[d]))
                  h.rows.emplace_back(dofs[d], -1);
              if constexpr (dim == 3)
                {
                  h.e = cross_product_3d(n_f, contact.direction(s));
                  const Tensor<1, dim> xi =
                    weighted_slip(interface, s, step_1.at(s.node), n_f, u_2) / s.D;
                  h.beta = contact.cone_stiffness(s, to_frame(xi, n_f));
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      h.gradient_dofs.push_back(dofs[d]);
                      h.gradient.push_back(h.e[d]);
                    }
                  for (const auto &[m, value] : s.M)
                    if (std::abs(value / s.D) >= 1e-14)
                      for (unsigned int d = 0; d < dim; ++d)
                        {
                          h.gradient_dofs.push_back(interface.nodes[m].dofs[d]);
                          h.gradient.push_back(-value / s.D * h.e[d]);
                        }
                }
            }
          else
            {
              const unsigned int gap = contact.gap_component(interface, s);
              h.rows.emplace_back(dofs[gap], -1);
              for (unsigned int k = 0, c = 0; k < dim - 1; ++k, ++c)
                {
                  c += c == gap;
                  h.rows.emplace_back(dofs[c], k);
                }
            }
        }

    // The rows at the interface configuration w (follow() run before).
    const unsigned int n_dofs = dof_handler.n_dofs();
    const auto         rows   = [&](const std::vector<double> &w) {
      Vector<double> force(n_dofs), result(n_dofs);
      for (const auto &s : interface.slave_nodes)
        {
          const auto it = held.find(s.node);
          if (it == held.end())
            continue;
          const Held          &h      = it->second;
          const Tensor<1, dim> n_w    = contact.frame_normal(s);
          const Tensor<1, dim> lambda = -h.p * n_w + h.t - (h.t * n_w) * n_w;
          for (unsigned int d = 0; d < dim; ++d)
            {
              force(interface.nodes[s.node].dofs[d]) -= s.D * lambda[d];
              for (const auto &[m, value] : s.M)
                force(interface.nodes[m].dofs[d]) += value * lambda[d];
            }
          const Tensor<1, dim> Dxi = weighted_slip(interface, s, step_1.at(s.node), n_w, w);
          for (unsigned int a = 0; a < h.gradient.size(); ++a)
            force(h.gradient_dofs[a]) += h.beta * h.gradient[a] * (h.e * Dxi);
        }
      std::vector<types::global_dof_index> all(n_dofs);
      for (unsigned int i = 0; i < n_dofs; ++i)
        all[i] = i;
      test_constraints.distribute_local_to_global(force, all, result);
      for (const auto &s : interface.slave_nodes)
        {
          const auto it = held.find(s.node);
          if (it == held.end())
            continue;
          const Held          &h   = it->second;
          const Tensor<1, dim> n_w = contact.frame_normal(s);
          const Tensor<1, dim> Dxi = weighted_slip(interface, s, step_1.at(s.node), n_w, w);
          for (const auto &[dof, k] : h.rows)
            result(dof) = k < 0 ? h.k * s.D * interface.gap(s, w) : h.k * (h.frame[k] * Dxi) / h.D;
        }
      return result;
    };

    // The matrix (rows by the test space, the free rows of the eliminated
    // DoFs) on a full pattern of the small problem.
    const IndexSet         owned = complete_index_set(n_dofs);
    DynamicSparsityPattern pattern(n_dofs, n_dofs);
    for (unsigned int i = 0; i < n_dofs; ++i)
      for (unsigned int j = 0; j < n_dofs; ++j)
        pattern.add(i, j);
    TrilinosWrappers::SparseMatrix matrix;
    matrix.reinit(owned, owned, pattern, MPI_COMM_WORLD);
    TrilinosWrappers::MPI::Vector rhs(owned, MPI_COMM_WORLD);
    contact.assemble(interface, constraints, test_constraints, owned, matrix, rhs);
    matrix.compress(VectorOperation::add);

    std::vector<double> v(n);
    for (double &value : v)
      value = random.next();
    TrilinosWrappers::MPI::Vector direction(owned, MPI_COMM_WORLD), product(owned, MPI_COMM_WORLD);
    for (unsigned int i = 0; i < n; ++i)
      direction(interface.dofs()[i]) = v[i];
    matrix.vmult(product, direction);
    double scale = 0.;
    for (unsigned int i = 0; i < n_dofs; ++i)
      scale = std::max(scale, std::abs(product(i)));

    const auto coupled    = interface.coupled_faces;
    bool       same_pairs = true;
    const auto difference = [&](const double h) {
      std::vector<double> plus = u_2, minus = u_2;
      for (unsigned int i = 0; i < n; ++i)
        {
          plus[i] += h * v[i];
          minus[i] -= h * v[i];
        }
      follow(plus);
      same_pairs           = same_pairs && interface.coupled_faces == coupled;
      const auto rows_plus = rows(plus);
      follow(minus);
      same_pairs            = same_pairs && interface.coupled_faces == coupled;
      const auto rows_minus = rows(minus);
      double     error      = 0.;
      for (unsigned int i = 0; i < n_dofs; ++i)
        error = std::max(error, std::abs((rows_plus(i) - rows_minus(i)) / (2. * h) - product(i)));
      return error / scale;
    };
    const double coarse = difference(2e-4), fine = difference(1e-4), tight = difference(1e-6);
    follow(u_2);

    std::cout << dim << "D, " << name << ": " << held.size() << " active slave nodes, stick "
              << n_stick << ", slip " << n_slip << std::endl
              << "  largest angle between slave and interface normal above 0.05 rad: "
              << (largest_angle > 0.05 ? "yes" : "no") << std::endl
              << "  frame the slave normal at every active node: "
              << (on_slave_normal ? "yes" : "no") << std::endl
              << "  same face pairs at every perturbed configuration: "
              << (same_pairs ? "yes" : "no") << std::endl
              << "  tangent against central differences at h = 1e-6, error below 1e-6 of |K v|: "
              << (tight < 1e-6 ? "yes" : "no") << std::endl
              << "  error falling at second order (h = 2e-4, 1e-4; or below 1e-9): "
              << (coarse < 1e-9 || (coarse / fine > 3.5 && coarse / fine < 4.5) ? "yes" : "no")
              << std::endl;
    if (std::getenv("SHOW_ERROR") || tight >= 1e-6)
      std::cout << "  errors " << coarse << ", " << fine << ", " << tight << " of |K v|"
                << ", largest angle " << largest_angle << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run<2, AlmFrictional<2>>("alm frictional");
  run<3, AlmFrictional<3>>("alm frictional");
  run<2, MpcFrictional<2>>("mpc frictional");
  run<3, MpcFrictional<3>>("mpc frictional");
}
