#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <contact_fem/contact/formulations/alm_frictionless.h>
#include <contact_fem/contact/formulations/constraint_line.h>

#include <algorithm>
#include <cmath>

namespace contact_fem
{

  template <int dim>
  AlmFrictionless<dim>::AlmFrictionless(ParameterHandler &prm)
    : AlmFrictionless(
        FrictionlessFormulation<dim>::Parameters::parse_for_exact_gap(prm, "alm frictionless"),
        current_kinematics(prm))
  {}

  template <int dim>
  AlmFrictionless<dim>::AlmFrictionless(const Parameters &parameters, const bool current_kinematics)
    : FrictionlessFormulation<dim>(parameters)
    , current(current_kinematics)
  {}

  template <int dim>
  bool
  AlmFrictionless<dim>::decides_active(const typename ContactInterface<dim>::SlaveNode &s,
                                       const double                                     g,
                                       const bool      at_step_start,
                                       const StepStart start) const
  {
    return this->augmented_rule(s, g, at_step_start, start);
  }

  template <int dim>
  void
  AlmFrictionless<dim>::initialize(const ContactInterface<dim> &interface)
  {
    FrictionlessFormulation<dim>::initialize(interface);
    released_pressure.assign(interface.nodes.size(), 0.);
  }

  template <int dim>
  void
  AlmFrictionless<dim>::start_load_step(const ContactInterface<dim> &interface,
                                        const std::vector<double>   &u,
                                        const StepStart              start)
  {
    this->set_pair_scaling(interface, 1.);
    std::fill(released_pressure.begin(), released_pressure.end(), 0.);
    auto &pressure = this->pressure;
    auto &active   = this->active;
    // Each rank decides the nodes whose rows it owns (share_states()).
    for (const auto &s : interface.slave_nodes)
      {
        if (!interface.owns_row(s))
          continue;
        if (!s.paired)
          {
            active[s.node]   = false;
            pressure[s.node] = 0.;
            continue;
          }
        const double g = interface.gap(s, u);
        active[s.node] =
          decides_active(s, g, true, start) && this->eliminated_component(interface, s) < dim;
        if (!active[s.node])
          {
            released_pressure[s.node] = pressure[s.node];
            pressure[s.node]          = 0.;
          }
      }
    this->share_states(interface, {&released_pressure});
    this->deactivate_master_nodes(interface);
    this->reduce_counts(interface, {});
  }

  template <int dim>
  void
  AlmFrictionless<dim>::add_constraints(const ContactInterface<dim> &interface,
                                        const std::vector<double>   &fixed_values,
                                        AffineConstraints<double>   &constraints,
                                        const bool                   all_candidates) const
  {
    // Current kinematics: the candidates' lines only shape the sparsity
    // pattern (the test space's couplings); the trial space is free.
    if (!current)
      this->add_gap_constraints(interface, fixed_values, constraints, !all_candidates);
    else if (!all_candidates)
      this->dirichlet_values = fixed_values;
    else
      for (const auto &s : interface.slave_nodes)
        {
          // Every component of the node and its masters: the normals turn
          // during Newton, so a coupling at round-off now may not stay so.
          if (!s.paired || !may_store_line_of<dim>(interface.nodes[s.node], constraints))
            continue;
          const unsigned int c = this->eliminated_component(interface, s);
          if (c == dim)
            continue;
          const auto    &slave = interface.nodes[s.node];
          ConstraintLine line;
          for (unsigned int d = 0; d < dim; ++d)
            {
              if (d != c)
                line.add(slave, d, 1., interface, fixed_values);
              for (const auto &[m, value] : s.M)
                line.add(interface.nodes[m], d, 1., interface, fixed_values);
            }
          if (constraints.can_store_line(slave.dofs[c]) &&
              !constraints.is_constrained(slave.dofs[c]))
            line.store(slave.dofs[c], constraints);
        }
  }

  template <int dim>
  void
  AlmFrictionless<dim>::add_test_constraints(const ContactInterface<dim> &interface,
                                             const std::vector<double>   &fixed_values,
                                             AffineConstraints<double>   &constraints) const
  {
    // The test functions v with f_j . v = 0: the homogeneous part of the
    // gap line of the current D, M and n.
    this->add_gap_constraints(interface, fixed_values, constraints, true);
  }

  template <int dim>
  void
  AlmFrictionless<dim>::recover_multipliers(const ContactInterface<dim> &interface,
                                            const std::vector<double>   &bulk_residual)
  {
    this->recover_through_chains(
      interface, bulk_residual, [&](const std::vector<double> &residual) {
        for (const auto &s : interface.slave_nodes)
          {
            if (!interface.owns_row(s))
              continue;
            if (!s.paired || !this->active[s.node])
              {
                this->pressure[s.node] = 0.;
                continue;
              }
            const unsigned int c   = this->eliminated_component(interface, s);
            const double       r   = residual[interface.position(interface.nodes[s.node].dofs[c])];
            this->pressure[s.node] = -r / (s.D * s.normal[c]);
          }
        this->share_states(interface, {&released_pressure});
      });
  }

  template <int dim>
  unsigned int
  AlmFrictionless<dim>::update_active_set(const ContactInterface<dim> &interface,
                                          const std::vector<double>   &u)
  {
    unsigned int changes = 0;
    std::fill(released_pressure.begin(), released_pressure.end(), 0.);
    auto &pressure = this->pressure;
    auto &active   = this->active;
    for (const auto &s : interface.slave_nodes)
      {
        if (!interface.owns_row(s))
          continue;
        if (!s.paired)
          {
            // Current kinematics: a node may leave its masters during Newton.
            if (active[s.node])
              ++changes;
            active[s.node]   = false;
            pressure[s.node] = 0.;
            continue;
          }
        const bool now_active =
          decides_active(s, interface.gap(s, u), false, StepStart::continued) &&
          this->eliminated_component(interface, s) < dim;
        if (now_active != active[s.node])
          ++changes;
        if (!now_active)
          {
            released_pressure[s.node] = pressure[s.node];
            pressure[s.node]          = 0.;
          }
        active[s.node] = now_active;
      }
    this->share_states(interface, {&released_pressure});
    return this->reduce_counts(interface, {changes})[0];
  }

  template <int dim>
  typename AlmFrictionless<dim>::Residuals
  AlmFrictionless<dim>::residuals(const ContactInterface<dim> &interface,
                                  const std::vector<double>   &u) const
  {
    Residuals result;
    // Each rank the terms of the rows it owns, summed in node order.
    std::vector<std::pair<unsigned int, double>> terms;
    for (unsigned int k = 0; k < interface.slave_nodes.size(); ++k)
      {
        const auto &s = interface.slave_nodes[k];
        if (!s.paired || !interface.owns_row(s))
          continue;
        // g = 0 on the active set, lambda = 0 elsewhere (the multiplier of
        // a node released in this update still counts).
        const double r = this->active[s.node] ? interface.gap(s, u) :
                                                released_pressure[s.node] / this->scale[s.pair];
        terms.emplace_back(k, r * r);
      }
    result.multiplier    = std::sqrt(interface.sum_in_node_order(terms));
    result.contact_force = this->contact_forces(interface);
    return result;
  }

  // Contact/Kinematics = current: the Newton system of the contact on the
  // configuration of the iterate u_k. An active node j eliminates one DoF
  // from the test space (the direction of its contact force f_j = -D_j n_j,
  // +M_jl n_j, so that its pressure drops out), and that DoF's row holds
  // the linearised gap G_j(u_k) + dG_j/du (u - u_k) = 0 (all patch DoFs:
  // slave, neighbouring slave nodes through the normals, masters). The
  // geometric stiffness -lambda_j df_j/du of the pressure of the last
  // iterate makes the tangent consistent. The derivatives:
  // ContactInterface::linearise().

  template <int dim>
  void
  AlmFrictionless<dim>::add_sparsity(const ContactInterface<dim>     &interface,
                                     const AffineConstraints<double> &constraints,
                                     const IndexSet                  &owned,
                                     DynamicSparsityPattern          &pattern) const
  {
    if (!current)
      return;
    // Closed over the candidate constraints: assemble() distributes the
    // rows and columns through the constraints of the iterate, and a DoF
    // of the patch may hang (3D adaptive: finite_strain_spr_adaptive_3d_01
    // assembled outside the pattern in its third cycle, a Trilinos error).
    for (const auto &[node, linearised] : interface.linearised_nodes)
      if (owned.is_element(interface.nodes[node].dofs[0]))
        this->add_closed_couplings(linearised.dofs, constraints, pattern);
  }

  template <int dim>
  void
  AlmFrictionless<dim>::assemble(const ContactInterface<dim>     &interface,
                                 const AffineConstraints<double> &constraints,
                                 const AffineConstraints<double> &test_constraints,
                                 const IndexSet                  &owned,
                                 TrilinosWrappers::SparseMatrix  &matrix,
                                 TrilinosWrappers::MPI::Vector   &rhs) const
  {
    if (!current)
      return;
    // The operators were built on the iterate: its displacement is the
    // search configuration.
    const std::vector<double> &u = interface.search_configuration();
    for (const auto &s : interface.slave_nodes)
      if (s.paired && this->active[s.node] && owned.is_element(interface.nodes[s.node].dofs[0]))
        assemble_current(interface, s, u, constraints, test_constraints, matrix, rhs);
  }

  template <int dim>
  void
  AlmFrictionless<dim>::assemble_current(const ContactInterface<dim>                     &interface,
                                         const typename ContactInterface<dim>::SlaveNode &s,
                                         const std::vector<double>                       &u,
                                         const AffineConstraints<double> &constraints,
                                         const AffineConstraints<double> &test_constraints,
                                         TrilinosWrappers::SparseMatrix  &matrix,
                                         TrilinosWrappers::MPI::Vector   &rhs) const
  {
    const auto                          &linearised = interface.linearised_nodes.at(s.node);
    std::vector<types::global_dof_index> columns;
    std::vector<unsigned int>            kept;
    this->free_patch_dofs(interface, linearised, kept, columns);
    const auto u_at = [&](const unsigned int i) {
      return u[interface.position(linearised.dofs[i])];
    };

    // The gap row, scaled by k (stress / length) to the bulk's size.
    const double       k = this->scale[s.pair];
    FullMatrix<double> gap_row(1, kept.size());
    Vector<double>     gap_rhs(1);
    gap_rhs(0) = -k * s.D * interface.gap(s, u);
    for (unsigned int a = 0; a < kept.size(); ++a)
      {
        gap_row(0, a) = k * linearised.gap[kept[a]];
        gap_rhs(0) += gap_row(0, a) * u_at(kept[a]);
      }
    const std::vector<types::global_dof_index> row = {
      interface.nodes[s.node].dofs[this->eliminated_component(interface, s)]};
    AffineConstraints<double> free_rows;
    free_rows.close();
    free_rows.distribute_local_to_global(gap_row, row, constraints, columns, matrix);
    free_rows.distribute_local_to_global(gap_rhs, row, rhs);

    // The geometric stiffness -lambda_j df_j/du, in the test space; its
    // part at u_k moves to the right-hand side (Newton for the total u).
    const double lambda = this->pressure[s.node];
    if (lambda == 0.)
      return;
    std::vector<types::global_dof_index>     rows;
    std::vector<const std::vector<double> *> values;
    for (const auto &[dof, derivatives] : linearised.force)
      if (!interface.dof_fixed(interface.position(dof)))
        {
          rows.push_back(dof);
          values.push_back(&derivatives);
        }
    FullMatrix<double> stiffness(rows.size(), kept.size());
    Vector<double>     stiffness_rhs(rows.size());
    for (unsigned int r = 0; r < rows.size(); ++r)
      for (unsigned int a = 0; a < kept.size(); ++a)
        {
          stiffness(r, a) = -lambda * (*values[r])[kept[a]];
          stiffness_rhs(r) += stiffness(r, a) * u_at(kept[a]);
        }
    test_constraints.distribute_local_to_global(stiffness, rows, constraints, columns, matrix);
    test_constraints.distribute_local_to_global(stiffness_rhs, rows, rhs);
  }

  template class AlmFrictionless<2>;
  template class AlmFrictionless<3>;

  CONTACT_FEM_REGISTER_FORMULATION(AlmFrictionless, "alm frictionless", false, false, false)
} // namespace contact_fem
