#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <contact_fem/contact/formulations/penalty_frictional.h>
#include <contact_fem/core/format.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace contact_fem
{
  namespace
  {
    /// Contact/Adaptive penalty must be off: the adapted normal penalty
    /// would enter the slip bound and the tangential penalty node by node.
    ParameterHandler &
    refuse_adaptive_penalty(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      const bool adaptive = prm.get_bool("Adaptive penalty");
      prm.leave_subsection();
      AssertThrow(!adaptive,
                  ExcMessage("Contact/Adaptive penalty = true is not supported by "
                             "Contact/Formulation = penalty frictional (the adapted normal "
                             "penalty would change the slip bound and the tangential penalty "
                             "node by node): set Contact/Adaptive penalty = false, or use "
                             "penalty frictionless."));
      return prm;
    }

    /// a x b in 3D; unused in 2D (the spin about the normal is 3D only).
    template <int dim>
    Tensor<1, dim>
    cross(const Tensor<1, dim> &a, const Tensor<1, dim> &b)
    {
      if constexpr (dim == 3)
        return cross_product_3d(a, b);
      else
        return Tensor<1, dim>();
    }
  } // namespace

  template <int dim>
  void
  PenaltyFrictional<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry("Tangential penalty", "auto", Patterns::Anything(),
                      "'penalty frictional' only: the tangential penalty eps_t of the "
                      "return mapping (trial traction t - eps_t * slip increment; a "
                      "sticking node slips elastically by t / eps_t). 'auto' = the "
                      "normal penalty of the pair (Contact/Penalty, or 1e4 * stiffness "
                      "factor * min(E/h)). Units: stress / length.");
    prm.leave_subsection();
  }

  template <int dim>
  PenaltyFrictional<dim>::PenaltyFrictional(ParameterHandler         &prm,
                                            const FrictionParameters &friction)
    : Base(friction, refuse_adaptive_penalty(prm))
  {
    AssertThrow(!laws.empty(),
                ExcMessage("Contact/Friction: 'penalty frictional' needs a frictional law, "
                           "e.g. 'coulomb 0.2' or 'tresca 0.01' (or per pair '3: coulomb "
                           "0.2'); for frictionless contact use Contact/Formulation = "
                           "penalty frictionless."));
    prm.enter_subsection("Contact");
    tangential_penalty =
      parse_auto_or_positive(prm.get("Tangential penalty"), "Contact/Tangential penalty");
    prm.leave_subsection();
  }

  template <int dim>
  void
  PenaltyFrictional<dim>::initialize(const ContactInterface<dim> &interface)
  {
    Base::initialize(interface);
    accepted_tangential.assign(interface.nodes.size(), TangentialVector<dim>());
    accepted_traction.assign(interface.nodes.size(), Tensor<1, dim>());
    accepted_normal.assign(interface.nodes.size(), Tensor<1, dim>());
    accepted_chords.assign(interface.nodes.size(), {});
    slave_faces_of_node.assign(interface.nodes.size(), {});
    for (unsigned int f = 0; f < interface.faces.size(); ++f)
      if (interface.faces[f].slave)
        for (const unsigned int n : interface.faces[f].nodes)
          slave_faces_of_node[n].push_back(f);
    cone_factor.assign(interface.nodes.size(), 0.);
    released_with_friction.assign(interface.nodes.size(), 0.);
    entering.assign(interface.nodes.size(), 0.);
  }

  template <int dim>
  TangentialVector<dim>
  PenaltyFrictional<dim>::slip_increment(const ContactInterface<dim> &interface,
                                         const SlaveNode             &s,
                                         const std::vector<double>   &u) const
  {
    if (this->current)
      return this->objective_slip(interface, s, u, nullptr);
    return to_frame(weighted_relative_displacement(interface, s, converged_displacement, u),
                    frame_normal(s));
  }

  template <int dim>
  void
  PenaltyFrictional<dim>::slip_gradient(const ContactInterface<dim> &,
                                        const SlaveNode     &s,
                                        const unsigned int   k,
                                        std::vector<double> &gradient) const
  {
    const Tensor<1, dim> tau = tangent_frame(frame_normal(s))[k];
    gradient.clear();
    for (unsigned int d = 0; d < dim; ++d)
      gradient.push_back(tau[d]);
    for (const auto &[m, value] : s.M)
      for (unsigned int d = 0; d < dim; ++d)
        gradient.push_back(-value / s.D * tau[d]);
  }

  template <int dim>
  TangentialVector<dim>
  PenaltyFrictional<dim>::trial_traction(const ContactInterface<dim> &interface,
                                         const SlaveNode             &s,
                                         const TangentialVector<dim> &xi) const
  {
    // A node a support holds along one tangent (3D symmetry plane): the
    // support carries the other, friction only the free one.
    return free_part(history(interface, s) - tangent_penalty[s.pair] * xi, frame_normal(s),
                     sets.held_component[s.node]);
  }

  template <int dim>
  std::vector<Tensor<1, dim>>
  PenaltyFrictional<dim>::face_chords(const ContactInterface<dim> &interface,
                                      const unsigned int           node) const
  {
    const std::vector<double> &u = interface.search_configuration();
    const Tensor<1, dim> x = interface.nodes[node].reference + interface.displacement(node, u);
    std::vector<Tensor<1, dim>> chords;
    for (const unsigned int f : slave_faces_of_node[node])
      {
        const auto    &nodes = interface.faces[f].nodes;
        Tensor<1, dim> centroid;
        for (const unsigned int m : nodes)
          centroid += interface.nodes[m].reference + interface.displacement(m, u);
        chords.push_back(centroid / double(nodes.size()) - x);
      }
    return chords;
  }

  template <int dim>
  typename PenaltyFrictional<dim>::Spin
  PenaltyFrictional<dim>::spin_about_normal(const ContactInterface<dim> &interface,
                                            const SlaveNode             &s) const
  {
    Spin                  spin;
    const auto           &before = accepted_chords[s.node];
    const Tensor<1, dim> &old    = accepted_normal[s.node];
    spin.now                     = face_chords(interface, s.node);
    const Tensor<1, dim> n_f     = frame_normal(s);
    if (dim == 2 || before.size() != spin.now.size())
      return spin;
    spin.X = 0.;
    for (unsigned int f = 0; f < before.size(); ++f)
      {
        // b_f = S A_f (A_f normal to n^n, as t_n in history()).
        const double beta = (n_f * before[f]) / (1. + old * n_f);
        spin.before.push_back(before[f] - beta * (old + n_f));
        spin.X += spin.before[f] * spin.now[f];
        spin.Y += n_f * cross<dim>(spin.before[f], spin.now[f]);
      }
    if (spin.X * spin.X + spin.Y * spin.Y == 0.)
      spin.X = 1.;
    return spin;
  }

  template <int dim>
  TangentialVector<dim>
  PenaltyFrictional<dim>::history(const ContactInterface<dim> &interface, const SlaveNode &s) const
  {
    if (!this->current)
      return accepted_tangential[s.node];
    // The smallest rotation taking n^n to n, applied to t_n (normal to
    // n^n): h = t_n - beta (n^n + n), beta = (n . t_n) / (1 + n^n . n).
    const Tensor<1, dim>  n_f  = frame_normal(s);
    const Tensor<1, dim> &t    = accepted_traction[s.node];
    const Tensor<1, dim> &old  = accepted_normal[s.node];
    const double          beta = (n_f * t) / (1. + old * n_f);
    const Tensor<1, dim>  h    = t - beta * (old + n_f);
    if (dim == 2 || t.norm_square() == 0.)
      return to_frame(h, n_f);
    // 3D: then the spin about n, cos phi h + sin phi n x h.
    const Spin   spin = spin_about_normal(interface, s);
    const double r    = std::hypot(spin.X, spin.Y);
    return to_frame(spin.X / r * h + spin.Y / r * cross<dim>(n_f, h), n_f);
  }

  template <int dim>
  void
  PenaltyFrictional<dim>::add_history_derivative(const ContactInterface<dim> &interface,
                                                 const SlaveNode             &s,
                                                 std::array<Row, dim - 1>    &rows) const
  {
    // d h_k = tau_k . dh (dtau_k . h = 0: h is normal to n and the frame
    // is held in the tangent plane), dh = -d beta (n^n + n) - beta dn,
    // d beta = (dn . t_n - beta n^n . dn) / (1 + n^n . n).
    const Tensor<1, dim>  n_f         = frame_normal(s);
    const auto           &dn_f        = this->frame_normal_derivative(interface, s);
    const Tensor<1, dim> &t           = accepted_traction[s.node];
    const Tensor<1, dim> &old         = accepted_normal[s.node];
    const double          denominator = 1. + old * n_f;
    const double          beta        = (n_f * t) / denominator;
    const auto            frame       = tangent_frame(n_f);
    const auto           &linearised  = interface.linearised_nodes.at(s.node);
    const Tensor<1, dim>  h           = t - beta * (old + n_f);
    if (dim == 2 || t.norm_square() == 0.)
      {
        for (unsigned int i = 0; i < linearised.dofs.size(); ++i)
          {
            Tensor<1, dim> dn;
            for (unsigned int d = 0; d < dim; ++d)
              dn[d] = dn_f[d][i];
            const double d_beta = (dn * t - beta * (old * dn)) / denominator;
            for (unsigned int k = 0; k < dim - 1; ++k)
              rows[k][linearised.dofs[i]] += -d_beta * (frame[k] * old) - beta * (frame[k] * dn);
          }
        return;
      }
    // 3D: h_spun = C h + S n x h, C = X / r, S = Y / r (spin_about_normal());
    // d h_spun = C dh + S (dn x h + n x dh) + d phi (-S h + C n x h), d phi
    // = (X dY - Y dX) / r^2, with dX, dY from dn (through b_f = S A_f) and
    // from the chords a_f (the positions of the slave faces' nodes).
    const Spin           spin = spin_about_normal(interface, s);
    const double         r2   = spin.X * spin.X + spin.Y * spin.Y;
    const double         C = spin.X / std::sqrt(r2), S = spin.Y / std::sqrt(r2);
    const Tensor<1, dim> n_h = cross<dim>(n_f, h);
    const auto           add = [&](const types::global_dof_index dof, const Tensor<1, dim> &dn,
                         const Tensor<1, dim> &dh, const double dX, const double dY) {
      const double         d_phi = (spin.X * dY - spin.Y * dX) / r2;
      const Tensor<1, dim> d_spun =
        C * dh + S * (cross<dim>(dn, h) + cross<dim>(n_f, dh)) + d_phi * (-S * h + C * n_h);
      for (unsigned int k = 0; k < dim - 1; ++k)
        rows[k][dof] += frame[k] * d_spun;
    };
    // The normal's part.
    const auto &before = accepted_chords[s.node];
    for (unsigned int i = 0; i < linearised.dofs.size(); ++i)
      {
        Tensor<1, dim> dn;
        for (unsigned int d = 0; d < dim; ++d)
          dn[d] = dn_f[d][i];
        const double         d_beta = (dn * t - beta * (old * dn)) / denominator;
        const Tensor<1, dim> dh     = -d_beta * (old + n_f) - beta * dn;
        double               dX = 0., dY = 0.;
        for (unsigned int f = 0; f < spin.before.size(); ++f)
          {
            const double         beta_f   = (n_f * before[f]) / denominator;
            const double         d_beta_f = (dn * before[f] - beta_f * (old * dn)) / denominator;
            const Tensor<1, dim> db       = -d_beta_f * (old + n_f) - beta_f * dn;
            dX += db * spin.now[f];
            dY += dn * cross<dim>(spin.before[f], spin.now[f]) + n_f * cross<dim>(db, spin.now[f]);
          }
        add(linearised.dofs[i], dn, dh, dX, dY);
      }
    // The chords' part: a_f = (sum of the face's node positions) / N_f - x_j.
    if (spin.before.empty())
      return;
    // Per node: the gradients of X and Y by its position (dX = b_f . da_f,
    // dY = n . (b_f x da_f) = da_f . (n x b_f)).
    std::map<unsigned int, std::pair<Tensor<1, dim>, Tensor<1, dim>>> by_node;
    for (unsigned int f = 0; f < spin.before.size(); ++f)
      {
        const Tensor<1, dim> gX    = spin.before[f];
        const Tensor<1, dim> gY    = cross<dim>(n_f, spin.before[f]);
        const auto          &nodes = interface.faces[slave_faces_of_node[s.node][f]].nodes;
        for (const unsigned int m : nodes)
          {
            // A hanging vertex moves with its parents (its DoFs are
            // constrained to theirs; the patch holds the parents).
            const auto &parents = interface.nodes[m].parents;
            if (parents.empty())
              {
                by_node[m].first += gX / double(nodes.size());
                by_node[m].second += gY / double(nodes.size());
              }
            for (const auto &[parent, weight] : parents)
              {
                by_node[parent].first += weight * gX / double(nodes.size());
                by_node[parent].second += weight * gY / double(nodes.size());
              }
          }
        by_node[s.node].first -= gX;
        by_node[s.node].second -= gY;
      }
    for (const auto &[m, g] : by_node)
      for (unsigned int d = 0; d < dim; ++d)
        add(interface.nodes[m].dofs[d], Tensor<1, dim>(), Tensor<1, dim>(), g.first[d],
            g.second[d]);
  }

  template <int dim>
  TangentialVector<dim>
  PenaltyFrictional<dim>::stick_or_slip(const ContactInterface<dim> &interface,
                                        const SlaveNode             &s,
                                        const double                 p,
                                        const TangentialVector<dim> &xi) const
  {
    const TangentialVector<dim> trial     = trial_traction(interface, s, xi);
    const double                size      = magnitude<dim>(trial);
    const TangentialVector<dim> direction = unit_direction<dim>(trial, size);
    if (pure_slip || frictionless_law(s))
      return direction;
    // A node with neither traction nor slip (it just touched) sticks.
    return size <= slip_bound(s, std::max(p, 0.)) ? TangentialVector<dim>() : direction;
  }

  template <int dim>
  TangentialVector<dim>
  PenaltyFrictional<dim>::tangential_traction(const ContactInterface<dim> &interface,
                                              const SlaveNode             &s,
                                              const TangentialVector<dim> &direction,
                                              const double                 p,
                                              const TangentialVector<dim> &xi) const
  {
    if (direction.norm_square() == 0.)
      return trial_traction(interface, s, xi);
    return slip_bound(s, std::max(p, 0.)) * direction;
  }

  template <int dim>
  double
  PenaltyFrictional<dim>::slip_cone_factor(const ContactInterface<dim> &interface,
                                           const SlaveNode             &s,
                                           const TangentialVector<dim> &direction,
                                           const double                 p,
                                           const TangentialVector<dim> &xi) const
  {
    // T / |t*|: the derivative of the slip direction t* / |t*| across it
    // (3D; in 2D the direction is a sign).
    // 0 too where a support holds one tangent: the direction is the other.
    if (dim == 2 || direction.norm_square() == 0. || frictionless_law(s) ||
        sets.held_component[s.node] < dim)
      return 0.;
    const double size = magnitude<dim>(trial_traction(interface, s, xi));
    return size > 0. ? slip_bound(s, std::max(p, 0.)) / size : 0.;
  }

  template <int dim>
  void
  PenaltyFrictional<dim>::start_load_step(const ContactInterface<dim> &interface,
                                          const std::vector<double>   &u,
                                          const StepStart              start)
  {
    // Each rank decides the nodes whose rows it owns, normal and
    // tangential, and shares them in one exchange (share_tangential()).
    this->decide_step_start(interface, u, start);
    updates_in_step = 0;
    std::fill(grazing.begin(), grazing.end(), 0.);
    std::fill(released_with_friction.begin(), released_with_friction.end(), 0.);
    std::fill(entering.begin(), entering.end(), 0.);
    if (this->current)
      this->keep_operators_of_new_pairs(interface);
    tangent_penalty.resize(this->penalty.size());
    for (unsigned int p = 0; p < tangent_penalty.size(); ++p)
      tangent_penalty[p] = tangential_penalty > 0. ? tangential_penalty : this->penalty[p];
    for (const auto &s : interface.slave_nodes)
      {
        if (!interface.owns_row(s))
          continue;
        if (!this->active[s.node])
          {
            tangential[s.node]     = TangentialVector<dim>();
            sets.direction[s.node] = TangentialVector<dim>();
            continue;
          }
        cone_factor[s.node] = 0.;
        if (!carries_friction(interface, s))
          {
            tangential[s.node]     = TangentialVector<dim>();
            sets.direction[s.node] = TangentialVector<dim>();
            continue;
          }
        // The elastic predictor: every node starts the step sticking (a node
        // that slipped has its trial traction on the bound, where round-off
        // would decide); the first solve tells which slip, and which way.
        // A law without friction, or Pure slip, slips at once.
        sets.direction[s.node] = TangentialVector<dim>();
        if (pure_slip || frictionless_law(s))
          {
            const double                p  = this->penalty[s.pair] * (-interface.gap(s, u));
            const TangentialVector<dim> xi = slip_increment(interface, s, u);
            sets.direction[s.node]         = stick_or_slip(interface, s, p, xi);
            cone_factor[s.node] = slip_cone_factor(interface, s, sets.direction[s.node], p, xi);
          }
      }
    share_tangential(interface);
    this->deactivate_master_nodes(interface);
    // The nodes outside the slave nodes' rows (master nodes, hanging
    // vertices) on every rank.
    for (unsigned int n = 0; n < interface.nodes.size(); ++n)
      if (!this->active[n])
        {
          tangential[n]     = TangentialVector<dim>();
          sets.direction[n] = TangentialVector<dim>();
        }
    this->reduce_counts(interface, {});
  }

  template <int dim>
  std::vector<int>
  PenaltyFrictional<dim>::contact_sets() const
  {
    std::vector<int> codes = Base::contact_sets();
    for (unsigned int n = 0; n < codes.size(); ++n)
      codes[n] += (released_with_friction[n] != 0. ? 4 : 0) + (entering[n] != 0. ? 16 : 0);
    return codes;
  }

  template <int dim>
  void
  PenaltyFrictional<dim>::share_tangential(const ContactInterface<dim> &interface)
  {
    // cone_factor is read only at active slip nodes; a key field all the
    // same, so that every value is the serial one.
    this->share_frictional_states(interface, {&tangential, &sets.direction},
                                  {&cone_factor, &grazing, &released_with_friction, &entering},
                                  [&](const std::vector<std::vector<double> *> &fields) {
                                    this->share_decisions(interface, fields);
                                  });
  }

  template <int dim>
  std::vector<unsigned int>
  PenaltyFrictional<dim>::count_owned_rows(const ContactInterface<dim> &interface) const
  {
    std::vector<unsigned int> counts = Base::count_owned_rows(interface);
    unsigned int              n      = 0;
    for (const auto &s : interface.slave_nodes)
      n += s.paired && interface.owns_row(s) && this->active[s.node] && frame_normal(s) != s.normal;
    counts.push_back(n);
    return counts;
  }

  template <int dim>
  void
  PenaltyFrictional<dim>::take_counts(std::vector<unsigned int>::const_iterator &next)
  {
    Base::take_counts(next);
    frame_turned = *next++ > 0;
  }

  template <int dim>
  void
  PenaltyFrictional<dim>::add_sparsity(const ContactInterface<dim>     &interface,
                                       const AffineConstraints<double> &constraints,
                                       const IndexSet                  &owned,
                                       DynamicSparsityPattern          &pattern) const
  {
    const bool any_friction = std::any_of(laws.begin(), laws.end(), [](const auto &law) {
      return !law->frictionless();
    });
    if (!any_friction)
      {
        PenaltyFrictionless<dim>::add_sparsity(interface, constraints, owned, pattern);
        return;
      }
    if (this->current)
      {
        // The linearised patch of every paired node and the masters of its
        // last accepted step, closed over the hanging nodes.
        for (const auto &[node, linearised] : interface.linearised_nodes)
          if (owned.is_element(interface.nodes[node].dofs[0]))
            constraints.add_entries_local_to_global(this->objective_slip_patch(interface, node),
                                                    pattern, true);
        return;
      }
    std::vector<types::global_dof_index> dofs;
    std::vector<double>                  gradient;
    for (const auto &s : interface.slave_nodes)
      if (s.paired && owned.is_element(interface.nodes[s.node].dofs[0]))
        {
          // The DoFs of gap_gradient() are every component of the slave
          // node and its masters, whatever the normal.
          this->gap_gradient(interface, s, dofs, gradient);
          constraints.add_entries_local_to_global(dofs, pattern, true);
        }
  }

  template <int dim>
  void
  PenaltyFrictional<dim>::assemble(const ContactInterface<dim>     &interface,
                                   const AffineConstraints<double> &constraints,
                                   const AffineConstraints<double> &,
                                   const IndexSet                 &owned,
                                   TrilinosWrappers::SparseMatrix &matrix,
                                   TrilinosWrappers::MPI::Vector  &rhs) const
  {
    PenaltyFrictionless<dim>::assemble(interface, constraints, constraints, owned, matrix, rhs);
    if (this->current)
      {
        const std::vector<double> &u = interface.search_configuration();
        for (const auto &s : interface.slave_nodes)
          if (s.paired && this->active[s.node] && carries_friction(interface, s) &&
              owned.is_element(interface.nodes[s.node].dofs[0]) &&
              !(sets.direction[s.node].norm_square() != 0. && frictionless_law(s)))
            assemble_current(interface, s, u, constraints, matrix, rhs);
        return;
      }
    // The tangential force D_j t_j grad xi_j with t_j linear in u:
    // stick: t = t_n - eps_t grad xi . (u - u_n);
    // slip:  t = sigma (T(p_k) + T'(p_k) (p(u) - p_k)), p(u) = -eps_n (g(0) +
    // grad g . u) (exact for Coulomb and Tresca).
    const std::vector<double>                zero(interface.dofs().size(), 0.);
    std::vector<types::global_dof_index>     dofs;
    std::vector<double>                      g_gradient;
    std::array<std::vector<double>, dim - 1> xi_gradient;
    for (const auto &s : interface.slave_nodes)
      {
        if (!this->active[s.node] || !carries_friction(interface, s) ||
            !owned.is_element(interface.nodes[s.node].dofs[0]))
          continue;
        const TangentialVector<dim> &direction = sets.direction[s.node];
        const bool                   slips     = direction.norm_square() != 0.;
        if (slips && frictionless_law(s))
          continue; // T = 0: the frictionless system
        this->gap_gradient(interface, s, dofs, g_gradient);
        for (unsigned int k = 0; k < dim - 1; ++k)
          slip_gradient(interface, s, k, xi_gradient[k]);
        const unsigned int n = dofs.size();
        FullMatrix<double> local_matrix(n, n);
        Vector<double>     local_rhs(n);
        // grad xi . u_n: the slip reference.
        const TangentialVector<dim> xi_reference = -slip_increment(interface, s, zero);
        const double                eps_t        = tangent_penalty[s.pair];
        if (!slips)
          {
            // t = Q (t_n - eps_t grad xi . (u - u_n)), Q the projection
            // of trial_traction() (the identity unless a support holds one
            // tangent).
            const unsigned int          held = sets.held_component[s.node];
            const TangentialVector<dim> free =
              held < dim ? to_frame(free_tangent(frame_normal(s), held), frame_normal(s)) :
                           TangentialVector<dim>();
            const auto Q = [&](const unsigned int k, const unsigned int l) {
              return held < dim ? free[k] * free[l] : (k == l ? 1. : 0.);
            };
            const TangentialVector<dim> history =
              trial_traction(interface, s, -xi_reference); // Q (t_n + eps_t grad xi . u_n)
            for (unsigned int k = 0; k < dim - 1; ++k)
              {
                const double load = s.D * history[k];
                for (unsigned int a = 0; a < n; ++a)
                  {
                    for (unsigned int l = 0; l < dim - 1; ++l)
                      if (Q(k, l) != 0.)
                        for (unsigned int b = 0; b < n; ++b)
                          local_matrix(a, b) +=
                            eps_t * s.D * Q(k, l) * xi_gradient[k][a] * xi_gradient[l][b];
                    local_rhs(a) += load * xi_gradient[k][a];
                  }
              }
          }
        else
          {
            const double eps_n = this->penalty[s.pair];
            const double p     = bound_pressure(s);
            const double T     = slip_bound(s, p);
            const double dT    = slip_bound_derivative(s, p);
            const double g0    = interface.gap(s, zero);
            // 3D: T d(t*) linearised across d, (T / |t*|) P t*(u), P = I - d d^T.
            const double                a = cone_factor[s.node];
            const TangentialVector<dim> history =
              accepted_tangential[s.node] + eps_t * xi_reference;
            const TangentialVector<dim> cone_trial = history - (direction * history) * direction;
            for (unsigned int k = 0; k < dim - 1; ++k)
              {
                const double load =
                  s.D * direction[k] * (T - dT * p - dT * eps_n * g0) + s.D * a * cone_trial[k];
                const double factor = s.D * direction[k] * dT * eps_n;
                for (unsigned int a_ = 0; a_ < n; ++a_)
                  {
                    for (unsigned int b = 0; b < n; ++b)
                      {
                        local_matrix(a_, b) += factor * xi_gradient[k][a_] * g_gradient[b];
                        for (unsigned int l = 0; l < dim - 1 && a != 0.; ++l)
                          local_matrix(a_, b) +=
                            s.D * a * eps_t * ((k == l ? 1. : 0.) - direction[k] * direction[l]) *
                            xi_gradient[k][a_] * xi_gradient[l][b];
                      }
                    local_rhs(a_) += load * xi_gradient[k][a_];
                  }
              }
          }
        this->eliminate_fixed(interface, dofs, local_matrix, local_rhs);
        constraints.distribute_local_to_global(local_matrix, local_rhs, dofs, matrix, rhs);
      }
  }

  template <int dim>
  unsigned int
  PenaltyFrictional<dim>::update_active_set(const ContactInterface<dim> &interface,
                                            const std::vector<double>   &u)
  {
    const std::vector<bool> was_active = this->active;
    const std::vector<double> was_pressure = this->pressure;
    // Active set and p_j = eps_n (-g_j) of the new iterate, on the rows
    // this rank owns (shared with the tangential state: share_tangential()).
    unsigned int changes    = this->decide_active_set(interface, u);
    last_stick_slip_changes = 0;
    const bool hold_stick   = this->current && ++updates_in_step == 1;
    for (const auto &s : interface.slave_nodes)
      {
        if (!s.paired || !interface.owns_row(s))
          continue;
        // A Tresca node released while it carried friction (its bound
        // pulled it off), which penetrates again without it, grazes
        // (doc/design.md, "Tresca at lift-off"): only one that comes back
        // to the surface (comes_back_grazing()), not one driven into it.
        // (An active node carried friction in the solve even where
        // tangential[] is not yet set: the step's stick predictor; but
        // one neither pressed nor loaded tangentially before that solve,
        // as every node at the first step of a scene that starts
        // touching, was not pulled off by a bound it held: the chain in
        // 20 steps let all of them graze at once and diverged.)
        if (was_active[s.node] && !this->active[s.node] && carries_friction(interface, s) &&
            this->bound_without_pressure(s) &&
            (was_pressure[s.node] > 0. || magnitude<dim>(tangential[s.node]) > 0.))
          released_with_friction[s.node] = 1.;
        if (!was_active[s.node] && this->active[s.node] && released_with_friction[s.node] != 0. &&
            this->comes_back_grazing(s, -interface.gap(s, u)))
          grazing[s.node] = 1.;
        entering[s.node] = grazing[s.node] != 0. && !was_active[s.node] && this->active[s.node];
        if (!this->active[s.node] || !carries_friction(interface, s))
          {
            tangential[s.node]     = TangentialVector<dim>();
            sets.direction[s.node] = TangentialVector<dim>();
            continue;
          }
        const double                 p         = bound_pressure(s);
        const TangentialVector<dim>  xi        = slip_increment(interface, s, u);
        TangentialVector<dim>        direction = stick_or_slip(interface, s, p, xi);
        const TangentialVector<dim> &old       = sets.direction[s.node];
        // A slipping node reverses (3D: turns by more than 90 degrees)
        // through stick: its slip solve overshoots (with eps_t ~ 1e4 E/h a
        // node that should stick swings from one bound to the other, period
        // 2, if the direction may flip directly).
        if (was_active[s.node] && old.norm_square() != 0. && direction * old < 0. && !pure_slip &&
            !frictionless_law(s))
          direction = TangentialVector<dim>();
        // Current kinematics: the step's first iterate is the stick
        // problem's linear predictor, too far off to decide who slips.
        if (hold_stick && old.norm_square() == 0. && !pure_slip && !frictionless_law(s))
          direction = TangentialVector<dim>();
        // Under a law without friction the direction changes nothing.
        if (was_active[s.node] && stick_slip_changed<dim>(old, direction) && !frictionless_law(s))
          {
            ++changes;
            ++last_stick_slip_changes;
          }
        sets.direction[s.node] = direction;
        tangential[s.node]     = tangential_traction(interface, s, direction, p, xi);
        cone_factor[s.node]    = slip_cone_factor(interface, s, direction, p, xi);
      }
    share_tangential(interface);
    const auto sums         = this->reduce_counts(interface, {changes, last_stick_slip_changes});
    last_stick_slip_changes = sums[1];
    return sums[0];
  }

  template <int dim>
  void
  PenaltyFrictional<dim>::add_force_terms(
    const ContactInterface<dim>                            &interface,
    const bool                                              all,
    std::vector<typename ContactInterface<dim>::ForceTerm> &terms) const
  {
    // The normal forces of the base class, then D_j t_j tau on the slave
    // and -M_jl t_j tau on the masters, keyed after every normal term.
    PenaltyFrictionless<dim>::add_force_terms(interface, all, terms);
    const auto n_nodes = static_cast<double>(interface.slave_nodes.size());
    for (unsigned int j = 0; j < interface.slave_nodes.size(); ++j)
      {
        const auto &s = interface.slave_nodes[j];
        if (!all && !interface.owns_row(s))
          continue;
        const TangentialVector<dim> &t = tangential[s.node];
        if (!s.paired || !this->active[s.node] || t.norm_square() == 0.)
          continue;
        const auto   frame = tangent_frame(frame_normal(s));
        const double key   = n_nodes + j;
        for (unsigned int k = 0; k < dim - 1; ++k)
          {
            for (unsigned int d = 0; d < dim; ++d)
              terms.push_back({key, interface.position(interface.nodes[s.node].dofs[d]),
                               s.D * t[k] * frame[k][d]});
            for (const auto &[m, value] : s.M)
              for (unsigned int d = 0; d < dim; ++d)
                terms.push_back({key, interface.position(interface.nodes[m].dofs[d]),
                                 -(value * t[k] * frame[k][d])});
          }
      }
  }

  template <int dim>
  void
  PenaltyFrictional<dim>::accept_load_step(const ContactInterface<dim> &interface,
                                           const std::vector<double>   &u)
  {
    this->accept_slip(interface, [&](const SlaveNode &s) {
      return slip_increment(interface, s, u);
    });
    converged_displacement = u;
    // The history of the trial traction: read only by the owner of the row.
    for (const auto &s : interface.slave_nodes)
      if (interface.owns_row(s))
        accepted_tangential[s.node] = tangential[s.node];
    if (this->current)
      {
        this->keep_operators(interface);
        for (const auto &s : interface.slave_nodes)
          {
            if (!interface.owns_row(s))
              continue;
            accepted_traction[s.node] = to_global(tangential[s.node], frame_normal(s));
            accepted_normal[s.node]   = frame_normal(s);
            if (dim == 3)
              {
                // In the plane of the normal, as the traction.
                accepted_chords[s.node] = face_chords(interface, s.node);
                for (auto &chord : accepted_chords[s.node])
                  chord -= (chord * frame_normal(s)) * frame_normal(s);
              }
          }
      }
  }

  template <int dim>
  void
  PenaltyFrictional<dim>::assemble_current(const ContactInterface<dim>     &interface,
                                           const SlaveNode                 &s,
                                           const std::vector<double>       &u,
                                           const AffineConstraints<double> &constraints,
                                           TrilinosWrappers::SparseMatrix  &matrix,
                                           TrilinosWrappers::MPI::Vector   &rhs) const
  {
    const auto &linearised = interface.linearised_nodes.at(s.node);
    // The frame normal n_f (the interface normal where the law has
    // friction) and the force derivatives along it.
    const Tensor<1, dim> n_f           = frame_normal(s);
    const auto          &force_rows_of = this->frame_force(interface, s);
    const auto          &tangent_force = this->frame_tangent_force(interface, s);
    const auto           frame         = tangent_frame(n_f);
    const double         eps_t         = tangent_penalty[s.pair];
    // d t*_k = d h_k - eps_t d xi_k, xi_k with the change of D_j (-xi_k
    // dD_j / D_j: a stick node slips elastically, xi = (h - t) / eps_t).
    std::array<Row, dim - 1>    d_xi;
    const TangentialVector<dim> xi = this->objective_slip(interface, s, u, &d_xi);
    std::array<Row, dim - 1>    d_trial;
    for (unsigned int k = 0; k < dim - 1; ++k)
      {
        for (const auto &[dof, value] : d_xi[k])
          d_trial[k][dof] -= eps_t * value;
        for (unsigned int i = 0; i < linearised.dofs.size(); ++i)
          d_trial[k][linearised.dofs[i]] += eps_t * xi[k] * linearised.D[i] / s.D;
      }
    add_history_derivative(interface, s, d_trial);
    // A node a support holds along one tangent: t* = Q t*_raw, Q the
    // projection onto the free tangent (trial_traction()). Its turn with
    // the normal, dQ t*_raw, is left out: t*_raw has no part across the
    // free tangent while the node stays on its plane (no slip along the
    // fixed component, the history projected), so the term vanishes there.
    if (const unsigned int held = sets.held_component[s.node]; held < dim)
      {
        const TangentialVector<dim> free = to_frame(free_tangent(n_f, held), n_f);
        Row                         along;
        for (unsigned int k = 0; k < dim - 1; ++k)
          for (const auto &[dof, value] : d_trial[k])
            along[dof] += free[k] * value;
        for (unsigned int k = 0; k < dim - 1; ++k)
          {
            d_trial[k].clear();
            for (const auto &[dof, value] : along)
              d_trial[k][dof] = free[k] * value;
          }
      }

    // d t_k: stick d t*_k; slip T'(p) dp d_k + (T / |t*|) (P dt*)_k (3D),
    // dp = -(eps_n dG_j + p dD_j) / D_j.
    const TangentialVector<dim> &direction = sets.direction[s.node];
    std::array<Row, dim - 1>     d_t;
    if (direction.norm_square() == 0.)
      d_t = d_trial;
    else
      {
        const double p     = this->pressure[s.node];
        const double eps_n = this->penalty[s.pair];
        const double dT    = slip_bound_derivative(s, bound_pressure(s));
        const double a     = cone_factor[s.node];
        for (unsigned int k = 0; k < dim - 1; ++k)
          {
            for (unsigned int i = 0; i < linearised.dofs.size(); ++i)
              d_t[k][linearised.dofs[i]] +=
                -dT * direction[k] * (eps_n * linearised.gap[i] + p * linearised.D[i]) / s.D;
            if (a != 0.)
              for (unsigned int l = 0; l < dim - 1; ++l)
                for (const auto &[dof, value] : d_trial[l])
                  d_t[k][dof] += a * ((k == l ? 1. : 0.) - direction[k] * direction[l]) * value;
          }
      }

    // The columns: the free DoFs of the rows of d t and of the patch (u_k
    // holds the Dirichlet values: their columns drop out).
    std::map<types::global_dof_index, unsigned int> column_of;
    for (const auto dof : this->objective_slip_patch(interface, s.node))
      if (!interface.dof_fixed(interface.position(dof)))
        column_of.emplace(dof, 0);
    std::vector<types::global_dof_index> columns;
    for (auto &[dof, index] : column_of)
      {
        index = columns.size();
        columns.push_back(dof);
      }
    // The force t_j h_j: coefficient D_j (slave) or -M_jl (master l) times
    // component c of t = sum_k t_k tau_k.
    std::map<types::global_dof_index, std::pair<double, unsigned int>> coefficient;
    for (unsigned int d = 0; d < dim; ++d)
      coefficient[interface.nodes[s.node].dofs[d]] = {s.D, d};
    for (const auto &[m, value] : s.M)
      for (unsigned int d = 0; d < dim; ++d)
        coefficient[interface.nodes[m].dofs[d]] = {-value, d};
    const Tensor<1, dim> t = to_global(tangential[s.node], n_f);

    // Newton for the total u, as the normal part: K (u - u_k) = -r(u_k),
    // r = -F the contact's internal force, K = -dF; right-hand side F + K
    // u_k.
    std::vector<types::global_dof_index> rows;
    FullMatrix<double>                   stiffness;
    std::vector<unsigned int>            force_rows;
    for (unsigned int r = 0; r < force_rows_of.size(); ++r)
      if (!interface.dof_fixed(interface.position(force_rows_of[r].first)))
        {
          rows.push_back(force_rows_of[r].first);
          force_rows.push_back(r);
        }
    stiffness.reinit(rows.size(), columns.size());
    Vector<double> stiffness_rhs(rows.size());
    for (unsigned int r = 0; r < rows.size(); ++r)
      {
        const auto it = coefficient.find(rows[r]);
        if (it != coefficient.end())
          {
            const auto [c, d] = it->second;
            stiffness_rhs(r)  = c * t[d];
            for (unsigned int k = 0; k < dim - 1; ++k)
              for (const auto &[dof, value] : d_t[k])
                {
                  const auto column = column_of.find(dof);
                  if (column != column_of.end())
                    stiffness(r, column->second) -= c * frame[k][d] * value;
                }
          }
        for (unsigned int i = 0; i < linearised.dofs.size(); ++i)
          {
            const auto column = column_of.find(linearised.dofs[i]);
            if (column == column_of.end())
              continue;
            for (unsigned int c = 0; c < dim; ++c)
              stiffness(r, column->second) -= t[c] * tangent_force[c][force_rows[r]].second[i];
          }
        for (unsigned int b = 0; b < columns.size(); ++b)
          stiffness_rhs(r) += stiffness(r, b) * u[interface.position(columns[b])];
      }
    constraints.distribute_local_to_global(stiffness, rows, constraints, columns, matrix);
    constraints.distribute_local_to_global(stiffness_rhs, rows, rhs);
  }

  template <int dim>
  std::unique_ptr<typename PenaltyFrictional<dim>::State>
  PenaltyFrictional<dim>::save_state() const
  {
    auto state                    = std::make_unique<FrictionState>();
    state->normal                 = PenaltyFrictionless<dim>::save_state();
    state->tangential             = tangential;
    state->converged_displacement = converged_displacement;
    state->slip_history           = slip_history;
    state->accepted_tangential    = accepted_tangential;
    state->sets                   = sets;
    state->last_step_slip         = last_step_slip;
    state->accepted_traction      = accepted_traction;
    state->accepted_normal        = accepted_normal;
    state->accepted_chords        = accepted_chords;
    state->converged_operators    = converged_operators;
    state->stick_count            = this->stick_count;
    state->slip_count             = this->slip_count;
    state->frame_turned           = frame_turned;
    return state;
  }

  template <int dim>
  void
  PenaltyFrictional<dim>::restore_state(const State &state)
  {
    const auto &saved = dynamic_cast<const FrictionState &>(state);
    PenaltyFrictionless<dim>::restore_state(*saved.normal);
    tangential             = saved.tangential;
    converged_displacement = saved.converged_displacement;
    slip_history           = saved.slip_history;
    accepted_tangential    = saved.accepted_tangential;
    sets                   = saved.sets;
    last_step_slip         = saved.last_step_slip;
    accepted_traction      = saved.accepted_traction;
    accepted_normal        = saved.accepted_normal;
    accepted_chords        = saved.accepted_chords;
    converged_operators    = saved.converged_operators;
    this->stick_count      = saved.stick_count;
    this->slip_count       = saved.slip_count;
    frame_turned           = saved.frame_turned;
  }

  template <int dim>
  void
  PenaltyFrictional<dim>::add_results(const ContactInterface<dim> &interface, Json &contact) const
  {
    PenaltyFrictionless<dim>::add_results(interface, contact);
    contact.set("friction", this->law_names())
      .set("tangential_penalty", tangent_penalty.empty() ? 0. : tangent_penalty[0])
      .set("stick_nodes", n_stick())
      .set("slip_nodes", n_slip());
    add_friction_totals(interface, *this, last_step_slip, slip_history, contact);
  }

  template <int dim>
  void
  PenaltyFrictional<dim>::print_results(const ContactInterface<dim> &interface,
                                        const std::vector<double>   &u,
                                        const Json                  &contact,
                                        const Json                  &reaction,
                                        std::ostream                &out) const
  {
    PenaltyFrictionless<dim>::print_results(interface, u, contact, reaction, out);
    print_slip_checks(interface, out);
    print_friction_totals(contact, reaction, dim, out);
  }

  template <int dim>
  void
  PenaltyFrictional<dim>::print_slip_checks(const ContactInterface<dim> &interface,
                                            std::ostream                &out) const
  {
    // sum_j D_j t_j and sum_j D_j p_j over the active nodes; with a single
    // Coulomb law (T(0) = 0) and every active node slipping one way their
    // ratio is mu up to round-off. (3D: the length of the vector sum, and
    // "one way" = every slip direction within 1e-10 of the first.)
    double         tangential_force = 0., normal_force = 0.;
    Tensor<1, dim> tangential_vector, common_direction;
    bool           all_slip = true, one_way = true, first = true;
    for (const auto &s : interface.slave_nodes)
      if (s.paired && this->active[s.node])
        {
          tangential_force += s.D * tangential[s.node][0];
          tangential_vector += s.D * to_global(tangential[s.node], frame_normal(s));
          normal_force += s.D * this->pressure[s.node];
          // 2D: the sign, in the node's own frame.
          Tensor<1, dim> direction;
          if (dim == 2)
            direction[0] = sets.direction[s.node][0];
          else
            direction = to_global(sets.direction[s.node], frame_normal(s));
          if (sets.direction[s.node].norm_square() == 0. || !carries_friction(interface, s))
            all_slip = false;
          else if (first)
            {
              common_direction = direction;
              first            = false;
            }
          else if ((direction - common_direction).norm() > 1e-10)
            one_way = false;
        }
    if (dim == 3)
      tangential_force = tangential_vector.norm();
    // A stick node moves |t| / eps_t elastically: the tangential analogue
    // of the penetration, which a soft tangential penalty makes large
    // enough to hold a block that should slide (measured: Tangential
    // penalty = 10 on frictional_block_coulomb_01 gives Q / N = 0.105
    // instead of mu = 0.2).
    double elastic_slip = 0.;
    for (const auto &s : interface.slave_nodes)
      if (sets.sticks(s.node, this->active) && carries_friction(interface, s))
        elastic_slip = std::max(elastic_slip, magnitude<dim>(tangential[s.node]) /
                                                tangent_penalty[s.pair] / s.size);
    constexpr double allowed_elastic_slip = 1e-2;
    out << "    largest elastic slip / h:     " << value_or_ok(elastic_slip, 1e-6)
        << " (stick nodes, |t| / eps_t)" << std::endl;
    // Said in the first cycle that finds it, like the driver's warnings
    // (an adaptive study would repeat it every cycle).
    if (elastic_slip > allowed_elastic_slip && !elastic_slip_warned)
      out << "  Warning: stick nodes move up to " << scientific(elastic_slip, 2)
          << " h elastically under the tangential penalty (more than " << allowed_elastic_slip
          << " h): the regularisation decides what sticks and what slips. Raise "
             "Contact/Tangential penalty (auto: that of the normal penalty) or use "
             "alm frictional."
          << std::endl;
    elastic_slip_warned = elastic_slip_warned || elastic_slip > allowed_elastic_slip;
    // The forces themselves are printed by print_friction_totals().
    if (normal_force == 0.)
      return;
    const double ratio           = tangential_force / normal_force;
    const bool   one_coulomb_law = std::all_of(laws.begin(), laws.end(), [&](const auto &law) {
      return law->threshold(0.) == 0. &&
             law->threshold_derivative(1.) == laws[0]->threshold_derivative(1.);
    });
    if (one_coulomb_law && all_slip && one_way && !first)
      {
        // Relative to mu (absolute for mu = 0).
        const double mu = laws[0]->threshold_derivative(1.);
        out << "    |ratio| - mu (all slip):      "
            << value_or_ok((std::abs(ratio) - mu) / (mu > 0. ? mu : 1.), 1e-8) << std::endl;
      }
  }

  template class PenaltyFrictional<2>;
  template class PenaltyFrictional<3>;

  CONTACT_FEM_REGISTER_FORMULATION(PenaltyFrictional, "penalty frictional", true, true, true)
} // namespace contact_fem
