#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <contact_fem/contact/formulations/alm_frictional.h>
#include <contact_fem/contact/formulations/constraint_line.h>
#include <contact_fem/core/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace contact_fem
{
  template <int dim>
  AlmFrictional<dim>::AlmFrictional(ParameterHandler &prm, const FrictionParameters &friction)
    : AlmFrictional(friction,
                    FrictionlessFormulation<dim>::Parameters::parse_for_exact_gap(prm,
                                                                                  "alm frictional"),
                    "alm",
                    current_kinematics(prm))
  {}

  template <int dim>
  AlmFrictional<dim>::AlmFrictional(const FrictionParameters &friction,
                                    const Parameters         &parameters,
                                    const std::string        &name,
                                    const bool                current_kinematics)
    : Base(friction, parameters)
    , current(current_kinematics)
  {
    AssertThrow(!laws.empty(),
                ExcMessage("Contact/Friction: '" + name +
                           " frictional' needs a frictional law, e.g. "
                           "'coulomb 0.2' or 'tresca 0.01' (or per pair '3: coulomb 0.2'); "
                           "for frictionless contact use Contact/Formulation = " +
                           name + " frictionless."));
  }

  template <int dim>
  void
  AlmFrictional<dim>::initialize(const ContactInterface<dim> &interface)
  {
    Base::initialize(interface);
    const unsigned int n = interface.nodes.size();
    released_pressure.assign(n, 0.);
    released_tangential.assign(n, TangentialVector<dim>());
    released_in_tension.assign(n, false);
    cone_stiffness.assign(n, 0.);
  }

  template <int dim>
  TangentialVector<dim>
  AlmFrictional<dim>::slip_increment(const ContactInterface<dim> &interface,
                                     const SlaveNode             &s,
                                     const std::vector<double>   &u) const
  {
    if (current)
      return objective_slip(interface, s, u, nullptr);
    return to_frame(weighted_relative_displacement(interface, s, converged_displacement, u),
                    frame_normal(s));
  }

  template <int dim>
  TangentialVector<dim>
  AlmFrictional<dim>::stick_or_slip(const SlaveNode             &s,
                                    const double                 p_bound,
                                    const TangentialVector<dim> &xi) const
  {
    return decide_on_trial(s, p_bound, tangential[s.node] - this->penalty[s.pair] * xi);
  }

  template <int dim>
  TangentialVector<dim>
  AlmFrictional<dim>::decide_on_trial(const SlaveNode             &s,
                                      const double                 p_bound,
                                      const TangentialVector<dim> &trial_traction) const
  {
    const TangentialVector<dim> trial = free_part(s, trial_traction);
    const double                size  = magnitude<dim>(trial);
    // For zero only a law without friction slips: its direction changes
    // nothing.
    const TangentialVector<dim> direction = unit_direction<dim>(trial, size);
    if (pure_slip)
      return direction;
    const double bound = slip_bound(s, std::max(p_bound, 0.));
    // A node with neither traction nor slip (it just touched) sticks: its
    // slip direction is undefined, and any guess would push it sideways.
    if (size == 0. && !frictionless_law(s))
      return TangentialVector<dim>();
    // A node on the bound (every slip node at the start of a step) keeps
    // slipping: without the margin round-off would decide, differently on
    // another partition.
    constexpr double on_bound = 1e-10;
    if (size < bound * (1. - on_bound))
      return TangentialVector<dim>();
    // A slip node whose trial points back against its slip passes through
    // stick: after a load reversal the first iterate lets the old slip
    // nodes slide back freely, c xi carries their trial far past the
    // opposite bound, and jumping there at once makes the set cycle (the
    // exact answer keeps most of them stuck).
    if (sets.direction[s.node] * direction < 0. && !frictionless_law(s))
      return TangentialVector<dim>();
    return direction;
  }

  template <int dim>
  TangentialVector<dim>
  AlmFrictional<dim>::free_part(const SlaveNode &s, const TangentialVector<dim> &t) const
  {
    return contact_fem::free_part(t, frame_normal(s), sets.held_component[s.node]);
  }

  template <int dim>
  double
  AlmFrictional<dim>::slip_cone_stiffness(const SlaveNode &s, const TangentialVector<dim> &xi) const
  {
    if (dim == 2 || !sets.slips(s.node, this->active) || frictionless_law(s))
      return 0.;
    // beta = c a / (1 - a), a = T(p) / |t*|: the derivative of the slip
    // direction t* / |t*| across it. a reaches 1 at zero slip (infinitely
    // stiff); the cap keeps beta below 1e4 times the E / h of the stiffer
    // side (c is that of the softer one), the stiffness of a default
    // tangential penalty there, and changes only the rate, not the
    // solution. Capped at the softer side, the slip of a node against a
    // much stiffer slave converged only linearly (bench/stability,
    // patch-base-1e6).
    const double largest_a = 1. - 1e-4 / stiffness_ratio[s.pair];
    const double c         = this->penalty[s.pair];
    const double trial     = magnitude<dim>(tangential[s.node] - c * xi);
    const double bound     = slip_bound(s, std::max(this->pressure[s.node], 0.));
    const double a         = trial > 0. ? std::min(bound / trial, largest_a) : largest_a;
    return c * a / (1. - a);
  }

  template <int dim>
  void
  AlmFrictional<dim>::set_direction(const ContactInterface<dim> &interface,
                                    const SlaveNode             &s,
                                    const double                 p_bound,
                                    const std::vector<double>   &u)
  {
    if (!carries_friction(interface, s))
      {
        sets.direction[s.node] = TangentialVector<dim>();
        cone_stiffness[s.node] = 0.;
        return;
      }
    // Along one tangent only where a support holds the other: no cone term
    // across the slip direction (the support carries that direction).
    const TangentialVector<dim> xi = free_part(s, slip_increment(interface, s, u));
    sets.direction[s.node]         = stick_or_slip(s, p_bound, xi);
    cone_stiffness[s.node] = sets.held_component[s.node] < dim ? 0. : slip_cone_stiffness(s, xi);
  }

  template <int dim>
  Tensor<1, dim>
  AlmFrictional<dim>::slip_direction(const SlaveNode &s) const
  {
    const double         p = this->pressure[s.node];
    const Tensor<1, dim> n = frame_normal(s);
    if constexpr (dim == 2)
      return ContactFormulation<dim>::tangent(n) +
             sets.direction[s.node][0] * slip_bound_derivative(s, p) * n;
    else
      return to_global(sets.direction[s.node], n) + slip_bound_derivative(s, p) * n;
  }

  template <int dim>
  Tensor<1, dim>
  AlmFrictional<dim>::test_normal(const SlaveNode &s) const
  {
    if constexpr (dim == 2)
      {
        const Tensor<1, dim> w = slip_direction(s);
        Tensor<1, dim>       result;
        result[0] = w[1];
        result[1] = -w[0];
        return result;
      }
    else
      {
        // Normal to w = d + T' n and to e = n x d: n - T' d.
        const Tensor<1, dim> n = frame_normal(s);
        return n - slip_bound_derivative(s, this->pressure[s.node]) *
                     to_global(sets.direction[s.node], n);
      }
  }

  template <int dim>
  unsigned int
  AlmFrictional<dim>::slip_eliminated_component(const SlaveNode &s) const
  {
    // Component c carries the gap (needs n_c) and the test line divides by
    // component c of the test normal m (2D: w turned, 3D: n - T' d). |m|^2
    // = 1 + T'^2, so one choice always has min(|n_c|, |m_c|) of order one.
    // With T' = 0 this is the largest |n_c|, the frictionless choice.
    const Tensor<1, dim> m          = test_normal(s);
    unsigned int         best       = dim;
    double               best_value = 0.1;
    for (unsigned int c = 0; c < dim; ++c)
      {
        if (c == sets.held_component[s.node])
          continue;
        const double value = std::min(std::abs(s.normal[c]), std::abs(m[c]));
        if (value > best_value)
          {
            best       = c;
            best_value = value;
          }
      }
    return best;
  }

  template <int dim>
  bool
  AlmFrictional<dim>::slips_dependent_on_pressure(const ContactInterface<dim> &interface,
                                                  const SlaveNode             &s) const
  {
    // Only mu = 0 (w = tau, frame = slave normal) may use the symmetric
    // assembly: its test space is the trial space. Under Tresca the trial
    // space is normal to the slave normal, the slip condition to the frame
    // (interface) normal; tested with the trial space it would impose
    // t = T + p tan(angle between them) on curved pairs, which the residual
    // never accepts (2D Tresca on prm/hertz_frictional.prm stalled). In 3D
    // the test plane also carries the cone term (assemble()).
    return sets.slips(s.node, this->active) && carries_friction(interface, s) &&
           (slip_bound_derivative(s, this->pressure[s.node]) != 0. ||
            (!frictionless_law(s)));
  }

  template <int dim>
  std::vector<unsigned int>
  AlmFrictional<dim>::count_owned_rows(const ContactInterface<dim> &interface) const
  {
    std::vector<unsigned int> counts = Base::count_owned_rows(interface);
    unsigned int              n      = 0;
    for (const auto &s : interface.slave_nodes)
      n += interface.owns_row(s) && slips_dependent_on_pressure(interface, s);
    counts.push_back(n);
    return counts;
  }

  template <int dim>
  void
  AlmFrictional<dim>::take_counts(std::vector<unsigned int>::const_iterator &next)
  {
    Base::take_counts(next);
    pressure_dependent_slip = *next++ > 0;
  }

  template <int dim>
  void
  AlmFrictional<dim>::start_load_step(const ContactInterface<dim> &interface,
                                      const std::vector<double>   &u,
                                      const StepStart              start)
  {
    this->set_pair_scaling(interface, 1.);
    stiffness_ratio.assign(interface.pairs.size(), 1.);
    for (unsigned int p = 0; p < interface.pairs.size(); ++p)
      {
        const auto &stat = interface.statistics[p];
        if (stat.mean_slave_size > 0.)
          {
            const double slave  = stat.slave_modulus / stat.mean_slave_size;
            const double master = stat.master_modulus / stat.mean_master_size;
            stiffness_ratio[p]  = std::max(slave, master) / std::min(slave, master);
          }
      }
    std::fill(grazing.begin(), grazing.end(), 0.);
    std::fill(released_in_tension.begin(), released_in_tension.end(), false);
    std::fill(released_pressure.begin(), released_pressure.end(), 0.);
    std::fill(released_tangential.begin(), released_tangential.end(), TangentialVector<dim>());
    // Current kinematics: a node paired for the first time measures its
    // slip from the operators of this step's start.
    if (current)
      this->keep_operators_of_new_pairs(interface);
    auto &pressure = this->pressure;
    auto &active   = this->active;
    // Each rank decides the nodes whose rows it owns (share_decisions()).
    for (const auto &s : interface.slave_nodes)
      {
        if (!interface.owns_row(s))
          continue;
        const double g = s.paired ? interface.gap(s, u) : 0.;
        active[s.node] = s.paired && decides_active(s, g, true, start) &&
                         this->eliminated_component(interface, s) < dim;
        if (!active[s.node])
          {
            released_pressure[s.node]   = pressure[s.node];
            released_tangential[s.node] = tangential[s.node];
            pressure[s.node]            = 0.;
            tangential[s.node]          = TangentialVector<dim>();
            sets.direction[s.node]      = TangentialVector<dim>();
            continue;
          }
        set_direction(interface, s, bound_pressure(s, g), u);
      }
    share_decisions(interface);
    this->deactivate_master_nodes(interface);
    for (unsigned int n = 0; n < interface.nodes.size(); ++n)
      if (!interface.nodes[n].slave)
        sets.direction[n] = TangentialVector<dim>();
    this->reduce_counts(interface, {});
  }

  template <int dim>
  void
  AlmFrictional<dim>::add_stick_constraint(const ContactInterface<dim> &interface,
                                           const SlaveNode             &s,
                                           const std::vector<double>   &fixed_values,
                                           AffineConstraints<double>   &constraints) const
  {
    const auto        &slave = interface.nodes[s.node];
    const unsigned int held  = sets.held_component[s.node];
    for (unsigned int d = 0; d < dim; ++d)
      if (d != held &&
          (!constraints.can_store_line(slave.dofs[d]) || constraints.is_constrained(slave.dofs[d])))
        return;
    // u_j = sum_l M_jl / D_j u_l + n (gap offset) + tau (slip offset): the
    // normal part closes the gap, the tangential part keeps the relative
    // position of the last accepted step.
    // The offset z solves n . z = gap offset (slave normal, as the gap) and
    // tau . z = tau . (old relative displacement) (frame tangent); the two
    // directions differ by the small angle between the slave and the
    // interface normal, so the 2x2 system is well conditioned.
    double normal_offset = s.curvature_gap / s.D - s.normal * slave.reference;
    for (const auto &[m, value] : s.M)
      normal_offset += value * (s.normal * interface.nodes[m].reference) / s.D;
    Tensor<1, dim> old_relative = interface.displacement(s.node, converged_displacement);
    for (const auto &[m, value] : s.M)
      old_relative -= (value / s.D) * interface.displacement(m, converged_displacement);
    if constexpr (dim == 3)
      if (held < dim)
        {
          add_partly_held_stick(interface, s, normal_offset, old_relative, fixed_values,
                                constraints);
          return;
        }
    const auto     frame = tangent_frame(frame_normal(s));
    Tensor<1, dim> offset;
    if constexpr (dim == 2)
      {
        const Tensor<1, dim> &tau               = frame[0];
        const double          tangential_offset = old_relative * tau;
        const double          det               = s.normal[0] * tau[1] - s.normal[1] * tau[0];
        offset[0] = (normal_offset * tau[1] - s.normal[1] * tangential_offset) / det;
        offset[1] = (s.normal[0] * tangential_offset - tau[0] * normal_offset) / det;
      }
    else
      {
        // Rows n, tau_1, tau_2: the same system in 3D.
        Tensor<2, dim> rows;
        Tensor<1, dim> values;
        rows[0]   = s.normal;
        values[0] = normal_offset;
        for (unsigned int k = 0; k < dim - 1; ++k)
          {
            rows[k + 1]   = frame[k];
            values[k + 1] = old_relative * frame[k];
          }
        offset = invert(rows) * values;
      }
    for (unsigned int d = 0; d < dim; ++d)
      {
        ConstraintLine line;
        line.inhomogeneity = offset[d];
        for (const auto &[m, value] : s.M)
          line.add(interface.nodes[m], d, value / s.D, interface, fixed_values);
        line.store(slave.dofs[d], constraints);
      }
  }

  template <int dim>
  void
  AlmFrictional<dim>::add_partly_held_stick(const ContactInterface<dim> &interface,
                                            const SlaveNode             &s,
                                            const double                 normal_offset,
                                            const Tensor<1, dim>        &old_relative,
                                            const std::vector<double>   &fixed_values,
                                            AffineConstraints<double>   &constraints) const
  {
    // A support fixes component f: the gap (n . z = normal offset) and the
    // free tangent (a . z = a . old relative displacement) on the free
    // components g_0, g_1, with u_j,f its Dirichlet value. The 2x2 system
    // has determinant (n x a)_f = sqrt(1 - n_f^2) for n along the frame
    // normal, of order one on an active node (a free |n_c| > 0.1).
    const auto          &slave     = interface.nodes[s.node];
    const unsigned int   f         = sets.held_component[s.node];
    const unsigned int   g[2]      = {(f + 1) % dim, (f + 2) % dim};
    const Tensor<1, dim> rows[2]   = {s.normal, free_tangent(frame_normal(s), f)};
    const double         values[2] = {normal_offset, old_relative * rows[1]};
    const double         det       = rows[0][g[0]] * rows[1][g[1]] - rows[0][g[1]] * rows[1][g[0]];
    const double         inverse[2][2] = {{rows[1][g[1]] / det, -rows[0][g[1]] / det},
                                          {-rows[1][g[0]] / det, rows[0][g[0]] / det}};
    for (unsigned int i = 0; i < 2; ++i)
      {
        // u_j,g_i = sum_r inverse_ir (rows_r . (sum_l M_jl / D_j u_l) +
        // values_r - rows_r,f u_j,f).
        Tensor<1, dim> coefficient;
        ConstraintLine line;
        for (unsigned int r = 0; r < 2; ++r)
          {
            coefficient += inverse[i][r] * rows[r];
            line.inhomogeneity += inverse[i][r] * values[r];
          }
        for (const auto &[m, value] : s.M)
          for (unsigned int d = 0; d < dim; ++d)
            line.add(interface.nodes[m], d, coefficient[d] * value / s.D, interface, fixed_values);
        line.add(slave, f, -coefficient[f], interface, fixed_values);
        line.store(slave.dofs[g[i]], constraints);
      }
  }

  template <int dim>
  void
  AlmFrictional<dim>::add_slip_constraint(const ContactInterface<dim> &interface,
                                          const SlaveNode             &s,
                                          const std::vector<double>   &fixed_values,
                                          AffineConstraints<double>   &constraints,
                                          const bool                   test) const
  {
    const unsigned int c = slip_eliminated_component(s);
    if (c == dim)
      return;
    // Trial space: g_j(u) = 0 solved for u_j,c, as in the frictionless
    // formulation, only with the component chosen for the slip line.
    if (!test)
      {
        this->add_gap_line(interface, s, c, fixed_values, constraints);
        return;
      }
    const auto &slave = interface.nodes[s.node];
    if (!constraints.can_store_line(slave.dofs[c]) || constraints.is_constrained(slave.dofs[c]))
      return;
    // Test space: v_j = sum_l M_jl / D_j v_l + z with z normal to the test
    // normal m (2D: z = alpha w; 3D: z in the plane of w and e = n x d): the
    // slave's own equations are those along w (and e), and the masters take
    // the whole traction. m . z = 0 solved for z_c.
    const Tensor<1, dim> m = test_normal(s);
    Tensor<1, dim>       ratio;
    for (unsigned int d = 0; d < dim; ++d)
      if (d != c)
        ratio[d] = -m[d] / m[c];
    ConstraintLine line;
    for (unsigned int d = 0; d < dim; ++d)
      if (d != c)
        line.add(slave, d, ratio[d], interface, fixed_values, true);
    for (const auto &[master, value] : s.M)
      {
        line.add(interface.nodes[master], c, value / s.D, interface, fixed_values, true);
        for (unsigned int d = 0; d < dim; ++d)
          if (d != c)
            line.add(interface.nodes[master], d, -ratio[d] * value / s.D, interface, fixed_values,
                     true);
      }
    line.store(slave.dofs[c], constraints);
  }

  template <int dim>
  void
  AlmFrictional<dim>::add_constraints(const ContactInterface<dim> &interface,
                                      const std::vector<double>   &fixed_values,
                                      AffineConstraints<double>   &constraints,
                                      const bool                   all_candidates) const
  {
    if (!all_candidates)
      this->dirichlet_values = fixed_values;
    // Current kinematics: no trial constraints (assemble_current()).
    if (current && !all_candidates)
      return;
    // For the sparsity: the stick lines couple a slave node with every
    // component of its masters (the gap line drops the components normal
    // to n), a superset of the slip lines' couplings.
    if (all_candidates)
      {
        for (const auto &s : interface.slave_nodes)
          if (carries_friction(interface, s))
            add_stick_constraint(interface, s, fixed_values, constraints);
        this->add_gap_constraints(interface, fixed_values, constraints, false,
                                  [&](const SlaveNode &s) {
                                    return carries_friction(interface, s);
                                  });
        return;
      }
    for (const auto &s : interface.slave_nodes)
      if (s.paired && this->active[s.node])
        {
          if (!carries_friction(interface, s))
            continue;
          if (!sets.slips(s.node, this->active))
            add_stick_constraint(interface, s, fixed_values, constraints);
          else
            add_slip_constraint(interface, s, fixed_values, constraints, false);
        }
    // The active nodes held by a support: frictionless gap lines.
    this->add_gap_constraints(interface, fixed_values, constraints, true, [&](const SlaveNode &s) {
      return carries_friction(interface, s);
    });
  }

  template <int dim>
  void
  AlmFrictional<dim>::add_test_constraints(const ContactInterface<dim> &interface,
                                           const std::vector<double>   &fixed_values,
                                           AffineConstraints<double>   &constraints) const
  {
    for (const auto &s : interface.slave_nodes)
      if (s.paired && this->active[s.node] && carries_friction(interface, s))
        {
          if (!sets.slips(s.node, this->active))
            add_stick_constraint(interface, s, fixed_values, constraints);
          else
            add_slip_constraint(interface, s, fixed_values, constraints, true);
        }
    this->add_gap_constraints(interface, fixed_values, constraints, true, [&](const SlaveNode &s) {
      return carries_friction(interface, s);
    });
  }

  template <int dim>
  bool
  AlmFrictional<dim>::symmetric() const
  {
    return !current && !pressure_dependent_slip;
  }

  template <int dim>
  void
  AlmFrictional<dim>::add_sparsity(const ContactInterface<dim>     &interface,
                                   const AffineConstraints<double> &constraints,
                                   const IndexSet                  &owned,
                                   DynamicSparsityPattern          &pattern) const
  {
    if (!current)
      return;
    // Closed over the candidate constraints, as AlmFrictionless::add_sparsity().
    for (const auto &[node, linearised] : interface.linearised_nodes)
      if (owned.is_element(interface.nodes[node].dofs[0]))
        this->add_closed_couplings(this->objective_slip_patch(interface, node), constraints,
                                   pattern);
  }

  template <int dim>
  void
  AlmFrictional<dim>::assemble(const ContactInterface<dim>     &interface,
                               const AffineConstraints<double> &constraints,
                               const AffineConstraints<double> &test_constraints,
                               const IndexSet                  &owned,
                               TrilinosWrappers::SparseMatrix  &matrix,
                               TrilinosWrappers::MPI::Vector   &rhs) const
  {
    // K u = f + B^T lambda: the known part h d of a slip node's traction,
    // h = T(p) - T'(p) p along its slip direction d, is a load (D_j on the
    // slave, -M_jl on the masters); the rest is carried by the constraints
    // (and in 3D by the cone term).
    if (current)
      {
        const std::vector<double> &u = interface.search_configuration();
        for (const auto &s : interface.slave_nodes)
          if (s.paired && this->active[s.node] && owned.is_element(interface.nodes[s.node].dofs[0]))
            assemble_current(interface, s, u, constraints, test_constraints, matrix, rhs);
      }
    std::vector<types::global_dof_index> dofs;
    Vector<double>                       values;
    for (const auto &s : interface.slave_nodes)
      {
        if (!s.paired || !sets.slips(s.node, this->active) || !carries_friction(interface, s) ||
            !owned.is_element(interface.nodes[s.node].dofs[0]))
          continue;
        if (cone_stiffness[s.node] > 0.)
          assemble_cone_term(interface, s, constraints, test_constraints, matrix, rhs);
        const double p = this->pressure[s.node];
        const double h = slip_bound(s, p) - slip_bound_derivative(s, p) * p;
        if (h == 0.)
          continue;
        const Tensor<1, dim> direction = to_global(sets.direction[s.node], frame_normal(s));
        dofs.clear();
        std::vector<double> force;
        for (unsigned int d = 0; d < dim; ++d)
          {
            dofs.push_back(interface.nodes[s.node].dofs[d]);
            force.push_back(s.D * h * direction[d]);
          }
        for (const auto &[m, value] : s.M)
          for (unsigned int d = 0; d < dim; ++d)
            {
              dofs.push_back(interface.nodes[m].dofs[d]);
              force.push_back(-value * h * direction[d]);
            }
        values.reinit(force.size());
        for (unsigned int i = 0; i < force.size(); ++i)
          values(i) = force[i];
        test_constraints.distribute_local_to_global(values, dofs, rhs);
      }
  }

  template <int dim>
  void
  AlmFrictional<dim>::assemble_cone_term(const ContactInterface<dim>     &interface,
                                         const SlaveNode                 &s,
                                         const AffineConstraints<double> &constraints,
                                         const AffineConstraints<double> &test_constraints,
                                         TrilinosWrappers::SparseMatrix  &matrix,
                                         TrilinosWrappers::MPI::Vector   &rhs) const
  {
    // The slip condition across the slip direction, linearised: e . t +
    // beta e . xi = 0 (e = n x d), tested with the e part of the test
    // function: D_j beta (e . dv)(e . (du - du_n)), du = u_j - sum_l M_jl /
    // D_j u_l. Rows in the test space, columns in the trial space, whose
    // inhomogeneities move to the right-hand side.
    const Tensor<1, dim> n = frame_normal(s);
    Tensor<1, dim>       e;
    if constexpr (dim == 3)
      e = cross_product_3d(n, to_global(sets.direction[s.node], n));
    std::vector<types::global_dof_index> dofs;
    std::vector<double>                  gradient;
    for (unsigned int d = 0; d < dim; ++d)
      {
        dofs.push_back(interface.nodes[s.node].dofs[d]);
        gradient.push_back(e[d]);
      }
    // Masters at round-off of M drop out, and Dirichlet components move
    // their value to the right-hand side, as in the constraint lines
    // (ConstraintLine), whose couplings the sparsity pattern holds (on
    // another rank's part of the master the constraints do not know them).
    constexpr double negligible = 1e-14;
    double           fixed_slip = 0.;
    for (const auto &[m, value] : s.M)
      if (std::abs(value / s.D) >= negligible)
        for (unsigned int d = 0; d < dim; ++d)
          {
            const auto &master = interface.nodes[m];
            if (master.fixed[d])
              {
                fixed_slip -=
                  value / s.D * e[d] * this->dirichlet_values[interface.position(master.dofs[d])];
                continue;
              }
            dofs.push_back(master.dofs[d]);
            gradient.push_back(-value / s.D * e[d]);
          }
    // The columns: the gradient of e . xi and its offset z, e . xi = gradient
    // . u - z; of the objective slip at the search configuration u_k for
    // current kinematics (z = gradient . u_k - e . xi(u_k)).
    std::vector<types::global_dof_index> columns = dofs;
    std::vector<double>                  entries = gradient;
    double                               z       = 0.;
    if (current)
      {
        columns.clear();
        entries.clear();
        const std::vector<double>  &u = interface.search_configuration();
        std::array<Row, dim - 1>    slip_rows;
        const TangentialVector<dim> xi     = objective_slip(interface, s, u, &slip_rows);
        const TangentialVector<dim> e_part = to_frame(e, n);
        z                                  = -(e_part * xi);
        Row column;
        for (unsigned int k = 0; k < dim - 1; ++k)
          for (const auto &[dof, entry] : slip_rows[k])
            column[dof] += e_part[k] * entry;
        for (const auto &[dof, entry] : column)
          if (!interface.dof_fixed(interface.position(dof)))
            {
              columns.push_back(dof);
              entries.push_back(entry);
              z += entry * u[interface.position(dof)];
            }
      }
    else
      {
        const std::vector<double> zero(interface.dofs().size(), 0.);
        z = e * weighted_relative_displacement(interface, s, zero, converged_displacement) -
            fixed_slip;
      }
    const double       factor = s.D * cone_stiffness[s.node];
    FullMatrix<double> local_matrix(dofs.size(), columns.size());
    Vector<double>     local_rhs(dofs.size()), inhomogeneity(columns.size());
    for (unsigned int a = 0; a < dofs.size(); ++a)
      {
        for (unsigned int b = 0; b < columns.size(); ++b)
          local_matrix(a, b) = factor * gradient[a] * entries[b];
        local_rhs(a) = factor * z * gradient[a];
      }
    for (unsigned int b = 0; b < columns.size(); ++b)
      if (constraints.is_constrained(columns[b]))
        inhomogeneity(b) = -constraints.get_inhomogeneity(columns[b]);
    local_matrix.vmult_add(local_rhs, inhomogeneity);
    test_constraints.distribute_local_to_global(local_matrix, dofs, constraints, columns, matrix);
    test_constraints.distribute_local_to_global(local_rhs, dofs, rhs);
  }

  template <int dim>
  void
  AlmFrictional<dim>::assemble_current(const ContactInterface<dim>     &interface,
                                       const SlaveNode                 &s,
                                       const std::vector<double>       &u,
                                       const AffineConstraints<double> &constraints,
                                       const AffineConstraints<double> &test_constraints,
                                       TrilinosWrappers::SparseMatrix  &matrix,
                                       TrilinosWrappers::MPI::Vector   &rhs) const
  {
    // The rows of the DoFs the test space eliminates: k (value + row . (u -
    // u_k)) = 0, k the pair's scale; Dirichlet columns drop out (u_k holds
    // their values).
    const double              k = this->scale[s.pair];
    AffineConstraints<double> free_rows;
    free_rows.close();
    const auto add_row = [&](const unsigned int component, const Row &row, const double value) {
      std::vector<types::global_dof_index> columns;
      std::vector<double>                  entries;
      double                               right = -k * value;
      for (const auto &[dof, entry] : row)
        if (!interface.dof_fixed(interface.position(dof)))
          {
            columns.push_back(dof);
            entries.push_back(k * entry);
            right += k * entry * u[interface.position(dof)];
          }
      FullMatrix<double> local(1, columns.size());
      for (unsigned int a = 0; a < columns.size(); ++a)
        local(0, a) = entries[a];
      Vector<double>                             local_rhs(1);
      const std::vector<types::global_dof_index> row_dof = {
        interface.nodes[s.node].dofs[component]};
      local_rhs(0) = right;
      free_rows.distribute_local_to_global(local, row_dof, constraints, columns, matrix);
      free_rows.distribute_local_to_global(local_rhs, row_dof, rhs);
    };
    const auto        &linearised = interface.linearised_nodes.at(s.node);
    const bool         friction   = carries_friction(interface, s);
    const bool         sticks     = friction && !sets.slips(s.node, this->active);
    const unsigned int gap_component =
      friction && !sticks ? slip_eliminated_component(s) : this->eliminated_component(interface, s);
    if (gap_component == dim)
      return;
    Row gap_row;
    for (unsigned int i = 0; i < linearised.dofs.size(); ++i)
      gap_row[linearised.dofs[i]] = linearised.gap[i];
    add_row(gap_component, gap_row, s.D * interface.gap(s, u));
    if (sticks)
      {
        // xi_j = 0, one frame component in each of the other rows.
        std::array<Row, dim - 1>    slip_rows;
        const TangentialVector<dim> xi   = objective_slip(interface, s, u, &slip_rows);
        const unsigned int          held = sets.held_component[s.node];
        if (held < dim)
          {
            // A support fixes component held: the free tangent's slip in
            // the remaining free component.
            const Tensor<1, dim>        n_f  = frame_normal(s);
            const TangentialVector<dim> free = to_frame(free_tangent(n_f, held), n_f);
            Row                         row;
            for (unsigned int k = 0; k < dim - 1; ++k)
              for (const auto &[dof, entry] : slip_rows[k])
                row[dof] += free[k] * entry;
            add_row(3 - gap_component - held, row, xi * free);
          }
        else
          for (unsigned int k = 0, component = 0; k < dim - 1; ++k, ++component)
            {
              component += component == gap_component;
              add_row(component, slip_rows[k], xi[k]);
            }
      }

    // The geometric stiffness -p df/du - t_c dh^c/du in the test space
    // (t the tangential traction), its part at u_k on the right-hand side
    // (Newton for the total u).
    const double         p   = this->pressure[s.node];
    const Tensor<1, dim> n_f = frame_normal(s);
    const Tensor<1, dim> t =
      sticks   ? to_global(tangential[s.node], n_f) :
      friction ? slip_bound(s, p) * to_global(sets.direction[s.node], n_f) :
                 Tensor<1, dim>();
    if (p == 0. && t.norm_square() == 0.)
      return;
    // Along the frame normal n_f: where it is the interface normal, the
    // derivatives of the force along it and of the traction held in its
    // tangent plane (as the penalty's).
    const auto                          &force         = this->frame_force(interface, s);
    const auto                          &tangent_force = this->frame_tangent_force(interface, s);
    std::vector<types::global_dof_index> columns, rows;
    std::vector<unsigned int>            kept, kept_rows;
    for (unsigned int i = 0; i < linearised.dofs.size(); ++i)
      if (!interface.dof_fixed(interface.position(linearised.dofs[i])))
        {
          kept.push_back(i);
          columns.push_back(linearised.dofs[i]);
        }
    for (unsigned int r = 0; r < force.size(); ++r)
      if (!interface.dof_fixed(interface.position(force[r].first)))
        {
          kept_rows.push_back(r);
          rows.push_back(force[r].first);
        }
    FullMatrix<double> stiffness(rows.size(), kept.size());
    Vector<double>     stiffness_rhs(rows.size());
    for (unsigned int r = 0; r < rows.size(); ++r)
      for (unsigned int a = 0; a < kept.size(); ++a)
        {
          const unsigned int row = kept_rows[r];
          stiffness(r, a)        = -p * force[row].second[kept[a]];
          if (friction)
            for (unsigned int c = 0; c < dim; ++c)
              stiffness(r, a) -= t[c] * tangent_force[c][row].second[kept[a]];
          stiffness_rhs(r) += stiffness(r, a) * u[interface.position(columns[a])];
        }
    test_constraints.distribute_local_to_global(stiffness, rows, constraints, columns, matrix);
    test_constraints.distribute_local_to_global(stiffness_rhs, rows, rhs);
  }

  template <int dim>
  void
  AlmFrictional<dim>::recover_multipliers(const ContactInterface<dim> &interface,
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
                tangential[s.node]     = TangentialVector<dim>();
                continue;
              }
            const auto &slave = interface.nodes[s.node];
            if (!carries_friction(interface, s))
              {
                // A support carries the tangential force: the pressure from the
                // eliminated component, as frictionless.
                const unsigned int c = this->eliminated_component(interface, s);
                this->pressure[s.node] =
                  -residual[interface.position(slave.dofs[c])] / (s.D * s.normal[c]);
                tangential[s.node] = TangentialVector<dim>();
                continue;
              }
            if constexpr (dim == 3)
              if (sets.held_component[s.node] < dim)
                {
                  recover_partly_held(interface, s, residual);
                  continue;
                }
            Tensor<1, dim> lambda;
            for (unsigned int d = 0; d < dim; ++d)
              lambda[d] = residual[interface.position(slave.dofs[d])] / s.D;
            const Tensor<1, dim> n = frame_normal(s);
            this->pressure[s.node] = -(lambda * n);
            tangential[s.node]     = to_frame(lambda, n);
            // Current kinematics (2D): a slip node's traction is the one its
            // slip condition imposed, T(p) d. From the residual it also carries
            // the change of D_j and n_j over the iteration, which at a node
            // leaving the master (D_j -> 0 under a large normal force) reversed
            // it, and the node cycled between stick and slip. (In 3D the
            // linearised condition leaves a component across d.)
            if (dim == 2 && current && sets.slips(s.node, this->active))
              tangential[s.node] = slip_bound(s, std::max(this->pressure[s.node], 0.)) *
                                   sets.direction[s.node];
          }
        // Only the multipliers changed.
        this->share_frictional_states(interface, {&tangential}, {},
                                      [&](const std::vector<std::vector<double> *> &fields) {
                                        this->share_states(interface, fields);
                                      });
      });
  }

  template <int dim>
  void
  AlmFrictional<dim>::recover_partly_held(const ContactInterface<dim> &interface,
                                          const SlaveNode             &s,
                                          const std::vector<double>   &residual)
  {
    // The residual of the fixed component holds the support's reaction:
    // lambda = alpha b + beta a from the free components g_0, g_1, b the
    // other direction of the node's conditions (stick: the gap's slave
    // normal; slip: the frame normal of the slip condition's test space),
    // a the free tangent. The tangential traction keeps the part along
    // n x a of a stick node's lambda (its slave normal's tilt off the frame
    // normal), so that the masters' force is traction(): that part is the
    // support's, and the cone sees only the one along a (free_part()).
    const auto          &slave = interface.nodes[s.node];
    const unsigned int   f     = sets.held_component[s.node];
    const unsigned int   g[2]  = {(f + 1) % dim, (f + 2) % dim};
    const Tensor<1, dim> n     = frame_normal(s);
    const Tensor<1, dim> a     = free_tangent(n, f);
    const Tensor<1, dim> b     = sets.slips(s.node, this->active) ? n : s.normal;
    double               r[2];
    for (unsigned int i = 0; i < 2; ++i)
      r[i] = residual[interface.position(slave.dofs[g[i]])] / s.D;
    const double         det    = b[g[0]] * a[g[1]] - b[g[1]] * a[g[0]];
    const double         alpha  = (r[0] * a[g[1]] - r[1] * a[g[0]]) / det;
    const double         beta   = (b[g[0]] * r[1] - b[g[1]] * r[0]) / det;
    const Tensor<1, dim> lambda = alpha * b + beta * a;
    this->pressure[s.node]      = -(lambda * n);
    tangential[s.node]          = to_frame(lambda, n);
  }

  template <int dim>
  unsigned int
  AlmFrictional<dim>::update_active_set(const ContactInterface<dim> &interface,
                                        const std::vector<double>   &u)
  {
    unsigned int changes    = 0;
    last_stick_slip_changes = 0;
    std::fill(released_pressure.begin(), released_pressure.end(), 0.);
    std::fill(released_tangential.begin(), released_tangential.end(), TangentialVector<dim>());
    auto &pressure = this->pressure;
    auto &active   = this->active;
    for (const auto &s : interface.slave_nodes)
      {
        if (!s.paired || !interface.owns_row(s))
          continue;
        const double g          = interface.gap(s, u);
        const bool   now_active = decides_active(s, g, false, StepStart::continued) &&
                                this->eliminated_component(interface, s) < dim;
        if (now_active != active[s.node])
          ++changes;
        // A Tresca node released in tension while it carried friction, which
        // penetrates again without it, grazes (doc/design.md, "Tresca at
        // lift-off"): its bound is then slip_bound(). Only a node that comes
        // back to the surface (comes_back_grazing(): it stands at the edge
        // of the lift-off), not one driven into it.
        if (!now_active && active[s.node] && pressure[s.node] < 0. &&
            magnitude<dim>(tangential[s.node]) > 0. && this->bound_without_pressure(s))
          released_in_tension[s.node] = true;
        if (now_active && !active[s.node] && released_in_tension[s.node] &&
            this->comes_back_grazing(s, -g))
          grazing[s.node] = 1.;
        if (!now_active)
          {
            released_pressure[s.node]   = pressure[s.node];
            released_tangential[s.node] = tangential[s.node];
            pressure[s.node]            = 0.;
            tangential[s.node]          = TangentialVector<dim>();
            sets.direction[s.node]      = TangentialVector<dim>();
            active[s.node]              = false;
            continue;
          }
        const bool                  was_active = active[s.node];
        const TangentialVector<dim> old        = sets.direction[s.node];
        active[s.node]                         = true;
        set_direction(interface, s, bound_pressure(s, g), u);
        // Under a law without friction the direction changes nothing.
        if (was_active && stick_slip_changed<dim>(old, sets.direction[s.node]) &&
            !frictionless_law(s))
          {
            ++changes;
            ++last_stick_slip_changes;
          }
      }
    share_decisions(interface);
    const auto sums         = this->reduce_counts(interface, {changes, last_stick_slip_changes});
    last_stick_slip_changes = sums[1];
    return sums[0];
  }

  template <int dim>
  std::vector<int>
  AlmFrictional<dim>::contact_sets() const
  {
    std::vector<int> codes = Base::contact_sets();
    for (unsigned int n = 0; n < codes.size(); ++n)
      codes[n] += released_in_tension[n] ? 4 : 0;
    return codes;
  }

  template <int dim>
  void
  AlmFrictional<dim>::share_decisions(const ContactInterface<dim> &interface)
  {
    this->share_frictional_states(interface, {&tangential, &released_tangential, &sets.direction},
                                  {&released_pressure, &cone_stiffness, &grazing},
                                  [&](const std::vector<std::vector<double> *> &fields) {
                                    this->share_states(interface, fields);
                                  });
  }

  template <int dim>
  typename AlmFrictional<dim>::Residuals
  AlmFrictional<dim>::residuals(const ContactInterface<dim> &interface,
                                const std::vector<double>   &u) const
  {
    Residuals result;
    // Each rank the terms of the rows it owns, summed in node order; the
    // contact force on every rank from the shared multipliers.
    std::vector<std::pair<unsigned int, double>> terms;
    for (unsigned int i = 0; i < interface.slave_nodes.size(); ++i)
      {
        const auto &s = interface.slave_nodes[i];
        if (!s.paired || !interface.owns_row(s))
          continue;
        const double k = this->scale[s.pair];
        if (!this->active[s.node])
          {
            const double rn = released_pressure[s.node] / k;
            const double rt = magnitude<dim>(released_tangential[s.node]) / k;
            terms.emplace_back(i, rn * rn + rt * rt);
            continue;
          }
        const double g = interface.gap(s, u);
        terms.emplace_back(i, g * g);
        if (carries_friction(interface, s))
          {
            const double p  = this->pressure[s.node];
            const double rt = !sets.slips(s.node, this->active) ?
                                magnitude<dim>(free_part(s, slip_increment(interface, s, u))) :
                                magnitude<dim>(tangential[s.node] - slip_bound(s, p) *
                                                                      sets.direction[s.node]) /
                                  k;
            terms.emplace_back(i, rt * rt);
          }
      }
    result.multiplier    = std::sqrt(interface.sum_in_node_order(terms));
    result.contact_force = this->contact_forces(interface);
    return result;
  }

  template <int dim>
  void
  AlmFrictional<dim>::add_force_terms(
    const ContactInterface<dim>                            &interface,
    const bool                                              all,
    std::vector<typename ContactInterface<dim>::ForceTerm> &terms) const
  {
    for (unsigned int k = 0; k < interface.slave_nodes.size(); ++k)
      {
        const auto &s = interface.slave_nodes[k];
        if (!s.paired || (!all && !interface.owns_row(s)) || !this->active[s.node])
          continue;
        // D_j lambda_j on the slave, -M_jl lambda_j on the masters.
        const Tensor<1, dim> lambda = traction(s);
        for (unsigned int d = 0; d < dim; ++d)
          terms.push_back({static_cast<double>(k),
                           interface.position(interface.nodes[s.node].dofs[d]), s.D * lambda[d]});
        for (const auto &[m, value] : s.M)
          for (unsigned int d = 0; d < dim; ++d)
            terms.push_back({static_cast<double>(k), interface.position(interface.nodes[m].dofs[d]),
                             -(value * lambda[d])});
      }
  }

  template <int dim>
  void
  AlmFrictional<dim>::accept_load_step(const ContactInterface<dim> &interface,
                                       const std::vector<double>   &u)
  {
    this->accept_slip(interface, [&](const SlaveNode &s) {
      return slip_increment(interface, s, u);
    });
    // On every rank: the stick lines of the ghosts read it.
    converged_displacement = u;
    if (current)
      this->keep_operators(interface);
  }

  template <int dim>
  void
  AlmFrictional<dim>::print_results(const ContactInterface<dim> &interface,
                                    const std::vector<double> &,
                                    const Json   &contact,
                                    const Json   &reaction,
                                    std::ostream &out) const
  {
    print_cone_check(interface, out);
    print_friction_totals(contact, reaction, dim, out);
  }

  template <int dim>
  void
  AlmFrictional<dim>::print_cone_check(const ContactInterface<dim> &interface,
                                       std::ostream                &out) const
  {
    double largest_bound = 0., largest_pressure = 0., off_bound = 0., outside = 0.;
    for (const auto &s : interface.slave_nodes)
      if (s.paired && this->active[s.node] && carries_friction(interface, s))
        {
          const double                 bound = slip_bound(s, this->pressure[s.node]);
          const TangentialVector<dim> &t     = tangential[s.node];
          largest_bound                      = std::max(largest_bound, bound);
          largest_pressure = std::max(largest_pressure, this->pressure[s.node]);
          if (sets.slips(s.node, this->active))
            off_bound = std::max(off_bound, magnitude<dim>(t - bound * sets.direction[s.node]));
          else
            outside = std::max(outside, magnitude<dim>(free_part(s, t)) - bound);
        }
    if (largest_bound == 0.)
      {
        out << "    friction cone:                no friction at the active nodes" << std::endl;
        return;
      }
    // The tractions carry the round-off of the pressures (about 1e-16 of
    // them), so bounds far below the pressures cannot be met more closely:
    // below 1e-6 of the largest pressure the conditions are measured
    // against that (a Tresca bound of 1e-12 on p ~ 1 read "2.2e-4 of the
    // largest slip bound" and asked for tighter tolerances; doc/metamorphic.md).
    const double resolution = 1e-6 * largest_pressure;
    const double unit       = std::max(largest_bound, resolution);
    if (largest_bound < resolution)
      out << "    slip bounds below 1e-6 of the largest pressure: measured against 1e-6 max p"
          << std::endl;
    out << "    slip nodes off the slip bound: " << value_or_ok(off_bound / unit, 1e-8)
        << (dim == 2 ? " (|t - sigma T(p)| / max T)" : " (|t - T(p) d| / max T)") << std::endl
        << "    stick nodes outside the cone:  "
        << value_or_ok(std::max(outside, 0.) / unit, 1e-8) << " ((|t| - T(p)) / max T)"
        << std::endl;
    // Newton stops at its tolerances (the multipliers' by default 1e-4 of
    // the scale), which may leave the friction conditions met to less than
    // the check's 1e-8: said once, with the setting that meets them.
    const double worst = std::max(off_bound, outside) / unit;
    if (worst > 1e-8 && !cone_check_warned)
      out << "  Warning: the friction conditions hold to " << scientific(worst, 2)
          << " of the largest slip bound, not to 1e-8: Newton's tolerances stopped it there. "
             "Smaller Newton/Multiplier relative tolerance and Multiplier absolute tolerance "
             "(e.g. 1e-12 and 1e-16) meet them at the cost of a few iterations."
          << std::endl;
    cone_check_warned = cone_check_warned || worst > 1e-8;
  }

  template <int dim>
  std::unique_ptr<typename AlmFrictional<dim>::State>
  AlmFrictional<dim>::save_state() const
  {
    auto state                     = std::make_unique<FrictionState>();
    state->normal                  = FrictionlessFormulation<dim>::save_state();
    state->tangential              = tangential;
    state->converged_displacement  = converged_displacement;
    state->slip_history            = slip_history;
    state->last_step_slip          = last_step_slip;
    state->sets                    = sets;
    state->converged_operators     = converged_operators;
    state->stick_count             = this->stick_count;
    state->slip_count              = this->slip_count;
    state->pressure_dependent_slip = pressure_dependent_slip;
    return state;
  }

  template <int dim>
  void
  AlmFrictional<dim>::restore_state(const State &state)
  {
    const auto &saved = dynamic_cast<const FrictionState &>(state);
    FrictionlessFormulation<dim>::restore_state(*saved.normal);
    tangential              = saved.tangential;
    converged_displacement  = saved.converged_displacement;
    slip_history            = saved.slip_history;
    last_step_slip          = saved.last_step_slip;
    sets                    = saved.sets;
    converged_operators     = saved.converged_operators;
    this->stick_count       = saved.stick_count;
    this->slip_count        = saved.slip_count;
    pressure_dependent_slip = saved.pressure_dependent_slip;
  }

  template <int dim>
  void
  AlmFrictional<dim>::add_results(const ContactInterface<dim> &interface, Json &contact) const
  {
    FrictionlessFormulation<dim>::add_results(interface, contact);
    contact.set("friction", this->law_names())
      .set("stick_nodes", n_stick())
      .set("slip_nodes", n_slip());
    add_friction_totals(interface, *this, last_step_slip, slip_history, contact);
  }

  template class AlmFrictional<2>;
  template class AlmFrictional<3>;

  CONTACT_FEM_REGISTER_FORMULATION(AlmFrictional, "alm frictional", true, false, false)
} // namespace contact_fem
