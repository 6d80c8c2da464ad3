// MeshTying: the tied pairs' dual-mortar coupling as affine constraints,
// their tractions from the slave residual, and the check that the tied
// surfaces touch.
#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>

#include <contact_fem/contact/formulations/constraint_line.h>
#include <contact_fem/contact/mesh_tying.h>
#include <contact_fem/core/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace contact_fem
{
  namespace
  {
    std::string
    pair_text(const ContactPair &pair)
    {
      return std::to_string(static_cast<unsigned int>(pair.slave)) + ": " +
             std::to_string(static_cast<unsigned int>(pair.master));
    }

    /// @p value with 8 digits, or 0 below 1e-10 of @p scale (round-off).
    std::string
    value_text(const double value, const double scale)
    {
      return std::abs(value) < 1e-10 * scale ? std::string("0") : significant(value, 8);
    }

    template <int dim>
    std::string
    vector_text(const Tensor<1, dim> &v, const double scale)
    {
      std::string text = "(";
      for (unsigned int d = 0; d < dim; ++d)
        text += (d > 0 ? ", " : "") + value_text(v[d], scale);
      return text + ")";
    }

    /// The number of entries k of @p surfaces' slave_nodes for which
    /// @p counts(k) holds, over the ranks: each counts the rows it owns
    /// (ContactInterface::owns_row()), so no rank needs the others' nodes.
    /// Collective.
    template <int dim, typename Predicate>
    unsigned int
    count_over_rows(const ContactInterface<dim> &surfaces, const Predicate &counts)
    {
      unsigned int n = 0;
      for (unsigned int k = 0; k < surfaces.slave_nodes.size(); ++k)
        n += surfaces.owns_row(surfaces.slave_nodes[k]) && counts(k);
      return Utilities::MPI::sum(n, surfaces.communicator());
    }
  } // namespace

  template <int dim>
  void
  MeshTying<dim>::initialize(const MappingQ<dim>             &mapping,
                             const DoFHandler<dim>           &dof_handler,
                             const std::vector<ContactPair>  &pairs,
                             const AffineConstraints<double> &dirichlet,
                             const AffineConstraints<double> &hanging,
                             const Materials<dim>            &materials,
                             const double                     search_factor,
                             const std::optional<double>     &release_threshold,
                             const MPI_Comm                   comm)
  {
    surfaces.initialize(mapping, dof_handler, pairs, dirichlet, hanging, materials, comm);
    // Once, on the reference configuration: the search only needs to
    // bridge the discrete mismatch of surfaces that touch.
    surfaces.update(std::vector<double>(surfaces.dofs().size(), 0.), search_factor);
    check_surfaces_touch();
    find_roller_projectors(dof_handler, dirichlet, comm);
    fixed_values.assign(surfaces.dofs().size(), 0.);
    traction.assign(surfaces.slave_nodes.size(), Tensor<1, dim>());
    slave_force.assign(surfaces.slave_nodes.size(), Tensor<1, dim>());
    this->release_threshold = release_threshold;
    bond.assign(surfaces.slave_nodes.size(), Bond::tied);
    accepted_bond = bond;
    opening.assign(surfaces.slave_nodes.size(), 0.);
    bonds_of_iteration.clear();
  }

  template <int dim>
  void
  MeshTying<dim>::find_roller_projectors(const DoFHandler<dim>           &dof_handler,
                                         const AffineConstraints<double> &dirichlet,
                                         const MPI_Comm                   comm)
  {
    // A roller's line u_p = sum_d a_d u_d among the node's own components
    // (InclinedSupports) holds the direction h = e_p - sum_d a_d e_d, its
    // normal. A line without entries (Fixed, Prescribed displacement, a
    // roller along an axis) is a fixed component, tied by no line at all.
    // Known to the DoF's owner only: gathered for every rank.
    const unsigned int  n = surfaces.nodes.size();
    std::vector<double> rows(n * dim * dim, 0.);
    const IndexSet     &owned = dof_handler.locally_owned_dofs();
    for (unsigned int k = 0; k < n; ++k)
      {
        const auto &node = surfaces.nodes[k];
        for (unsigned int p = 0; p < dim; ++p)
          {
            const auto dof = node.dofs[p];
            if (!owned.is_element(dof) || !dirichlet.is_constrained(dof) ||
                dirichlet.get_inhomogeneity(dof) != 0.)
              continue;
            const auto *entries = dirichlet.get_constraint_entries(dof);
            if (entries == nullptr || entries->empty())
              continue;
            std::vector<double> row(dim, 0.);
            row[p]       = 1.;
            bool own_dof = true;
            for (const auto &[j, a] : *entries)
              {
                const auto at = std::find(node.dofs.begin(), node.dofs.end(), j);
                own_dof       = own_dof && at != node.dofs.end();
                if (at != node.dofs.end())
                  row[at - node.dofs.begin()] -= a;
              }
            if (own_dof)
              std::copy(row.begin(), row.end(), rows.begin() + (k * dim + p) * dim);
          }
      }
    Utilities::MPI::sum(rows, comm, rows);
    roller_rows.assign(n, Tensor<2, dim>());
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int p = 0; p < dim; ++p)
        for (unsigned int d = 0; d < dim; ++d)
          roller_rows[k][p][d] = rows[(k * dim + p) * dim + d];

    roller_projector.assign(surfaces.slave_nodes.size(),
                            Tensor<2, dim>(unit_symmetric_tensor<dim>()));
    for (unsigned int k = 0; k < surfaces.slave_nodes.size(); ++k)
      {
        // With a fixed component as well the per-component tying stays.
        const unsigned int node = surfaces.slave_nodes[k].node;
        const auto        &fixed = surfaces.nodes[node].fixed;
        if (std::any_of(fixed.begin(), fixed.end(), [](bool f) { return f; }))
          continue;
        std::vector<Tensor<1, dim>> basis; // orthonormal, of the held directions
        for (unsigned int p = 0; p < dim; ++p)
          {
            Tensor<1, dim> h = roller_rows[node][p];
            if (h.norm() == 0.)
              continue;
            const double length = h.norm();
            for (const auto &b : basis)
              h -= (h * b) * b;
            if (h.norm() > 1e-8 * length)
              basis.push_back(h / h.norm());
          }
        for (const auto &b : basis)
          roller_projector[k] -= outer_product(b, b);
      }
  }

  template <int dim>
  void
  MeshTying<dim>::check_surfaces_touch() const
  {
    // Each rank checks the rows it owns; the message names the first node
    // too far off in node order (the lowest node number, that of a serial
    // run), sent by its owner to every rank.
    const MPI_Comm comm = surfaces.communicator();
    for (unsigned int p = 0; p < surfaces.pairs.size(); ++p)
      {
        const std::string key = "Contact/Tied pairs: pair '" + pair_text(surfaces.pairs[p]) + "'";
        unsigned int      any = 0;
        unsigned int      first_apart = std::numeric_limits<unsigned int>::max();
        std::string       message;
        for (const auto &s : surfaces.slave_nodes)
          {
            if (s.pair != p || !s.paired || !surfaces.owns_row(s))
              continue;
            any           = 1;
            const auto &x = surfaces.nodes[s.node].reference;
            Point<dim>  image;
            for (const auto &[m, value] : s.M)
              image += (value / s.D) * (surfaces.nodes[m].reference - x);
            const double distance = image.norm();
            if (distance <= max_distance_over_h * s.size || s.node >= first_apart)
              continue;
            first_apart = s.node;
            message     = key + ": the slave node at " + coordinates_text(x) + " is " +
                      significant(distance, 3) + " from its mortar image on the master surface, " +
                      significant(distance / s.size, 3) +
                      " times its element size; tied surfaces must touch (within " +
                      significant(max_distance_over_h, 2) +
                      " element sizes). Check the pair, or mesh the two surfaces on one "
                      "geometric surface.";
          }
        if (const unsigned int first = Utilities::MPI::min(first_apart, comm);
            first != std::numeric_limits<unsigned int>::max())
          {
            const unsigned int owner =
              Utilities::MPI::min(first_apart == first ? Utilities::MPI::this_mpi_process(comm) :
                                                         Utilities::MPI::n_mpi_processes(comm),
                                  comm);
            AssertThrow(false, ExcMessage(Utilities::MPI::broadcast(comm, message, owner)));
          }
        AssertThrow(Utilities::MPI::max(any, comm) > 0,
                    ExcMessage(key + ": no slave node faces the master surface (the "
                                     "surfaces are apart, or their normals do not "
                                     "oppose); tied surfaces must touch."));
      }
  }

  template <int dim>
  void
  MeshTying<dim>::check_apart_from(const ContactInterface<dim> &contact) const
  {
    // A node by its first DoF (the same in both interfaces), from the faces
    // (the search has not run on the contact surfaces yet): its contact
    // pair and side.
    std::map<types::global_dof_index, std::pair<unsigned int, bool>> on_contact;
    for (const auto &face : contact.faces)
      for (const unsigned int n : face.nodes)
        {
          auto &entry = on_contact[contact.nodes[n].dofs[0]];
          if (face.slave || entry.first == 0)
            entry = {face.pair + 1, face.slave};
        }
    const auto side = [](const bool slave) {
      return std::string(slave ? "slave" : "master");
    };
    for (const auto &face : surfaces.faces)
      for (const unsigned int n : face.nodes)
        {
          const auto &node  = surfaces.nodes[n];
          const auto  other = on_contact.find(node.dofs[0]);
          // Only a master of both carries no line of either.
          if (other == on_contact.end() || (!face.slave && !other->second.second))
            continue;
          AssertThrow(false,
                      ExcMessage("Contact/Tied pairs: the node at " +
                                 coordinates_text(node.reference) + " is on the " +
                                 side(face.slave) + " side of the tied pair '" +
                                 pair_text(surfaces.pairs[face.pair]) + "' and on the " +
                                 side(other->second.second) + " side of the contact pair '" +
                                 pair_text(contact.pairs[other->second.first - 1]) +
                                 "' of Contact/Pairs (the surfaces share an edge or corner). "
                                 "Its tying and contact constraints would conflict or form a "
                                 "cycle; let the tied and the contact surfaces share no node "
                                 "(end one an element before the other)."));
        }
  }

  template <int dim>
  void
  MeshTying<dim>::set_fixed_values(
    const std::function<double(types::global_dof_index)> &value_on_owner)
  {
    fixed_values = surfaces.gather(value_on_owner);
  }

  template <int dim>
  void
  MeshTying<dim>::add_constraints(AffineConstraints<double> &constraints,
                                  const bool                 test,
                                  const bool                 all_candidates) const
  {
    for (unsigned int k = 0; k < surfaces.slave_nodes.size(); ++k)
      {
        const auto &s = surfaces.slave_nodes[k];
        if (!s.paired)
          continue;
        if (bond[k] == Bond::held && !all_candidates)
          add_normal_line(s, constraints, test);
        if (bond[k] != Bond::tied && !all_candidates)
          continue;
        const auto &slave = surfaces.nodes[s.node];
        const auto &P     = roller_projector[k];
        for (unsigned int d = 0; d < dim; ++d)
          {
            if (slave.fixed[d] || !constraints.can_store_line(slave.dofs[d]) ||
                constraints.is_constrained(slave.dofs[d]))
              continue;
            ConstraintLine line;
            for (const auto &[m, value] : s.M)
              for (unsigned int c = 0; c < dim; ++c)
                {
                  // A master component on a roller by the roller's line in
                  // place: a rank need not hold that line to close the chain.
                  const Tensor<1, dim> &row         = roller_rows[m][c];
                  const double          coefficient = P[d][c] * value / s.D;
                  if (row[c] == 0.)
                    line.add(surfaces.nodes[m], c, coefficient, surfaces, fixed_values, test);
                  else
                    for (unsigned int e = 0; e < dim; ++e)
                      if (e != c)
                        line.add(surfaces.nodes[m], e, -row[e] * coefficient, surfaces,
                                 fixed_values, test);
                }
            line.store(slave.dofs[d], constraints);
          }
      }
  }

  template <int dim>
  void
  MeshTying<dim>::add_normal_line(const typename ContactInterface<dim>::SlaveNode &s,
                                  AffineConstraints<double>                       &constraints,
                                  const bool                                       test) const
  {
    const unsigned int c     = normal_line_component(surfaces, s);
    const auto        &slave = surfaces.nodes[s.node];
    if (c == dim || !constraints.can_store_line(slave.dofs[c]) ||
        constraints.is_constrained(slave.dofs[c]))
      return;
    // n . u_s = n . sum_l (M_jl / D_j) u_l, solved for u_s,c: the tied
    // reference (opening 0), not the geometric gap.
    ConstraintLine line;
    for (const auto &[m, value] : s.M)
      for (unsigned int d = 0; d < dim; ++d)
        line.add(surfaces.nodes[m], d, value * s.normal[d] / (s.D * s.normal[c]), surfaces,
                 fixed_values, test);
    for (unsigned int d = 0; d < dim; ++d)
      if (d != c)
        line.add(slave, d, -s.normal[d] / s.normal[c], surfaces, fixed_values, test);
    line.store(slave.dofs[c], constraints);
  }

  template <int dim>
  void
  MeshTying<dim>::condense_residual(TrilinosWrappers::MPI::Vector &residual, const IndexSet &owned)
  {
    const std::vector<double> r = surfaces.gather(residual);
    std::vector<double>       correction(r.size(), 0.);
    for (unsigned int k = 0; k < surfaces.slave_nodes.size(); ++k)
      condense_node(k, r, correction);
    for (unsigned int i = 0; i < correction.size(); ++i)
      if (correction[i] != 0. && owned.is_element(surfaces.dofs()[i]))
        residual(surfaces.dofs()[i]) += correction[i];
    residual.compress(VectorOperation::add);
  }

  template <int dim>
  void
  MeshTying<dim>::condense_node(const unsigned int         k,
                                const std::vector<double> &r,
                                std::vector<double>       &correction)
  {
    // C^T r of the node's lines: the eliminated rows go to the line's
    // entries (fixed masters too: their reactions carry the slave's force).
    const auto &s = surfaces.slave_nodes[k];
    traction[k] = slave_force[k] = Tensor<1, dim>();
    if (!s.paired || bond[k] == Bond::open)
      return;
    const auto &slave = surfaces.nodes[s.node];
    const auto  at    = [&](const unsigned int node, const unsigned int d) -> double  &{
      return correction[surfaces.position(surfaces.nodes[node].dofs[d])];
    };
    if (bond[k] == Bond::held)
      {
        const unsigned int c = normal_line_component(surfaces, s);
        if (c == dim)
          return;
        const double r_c = r[surfaces.position(slave.dofs[c])];
        slave_force[k]   = r_c / s.normal[c] * s.normal;
        for (unsigned int d = 0; d < dim; ++d)
          {
            at(s.node, d) -= s.normal[d] / s.normal[c] * r_c;
            for (const auto &[m, value] : s.M)
              at(m, d) += value / s.D * s.normal[d] / s.normal[c] * r_c;
          }
      }
    else
      {
        // The lines u_s = P D^-1 M u_m: their part P r of the residual goes
        // to the masters, the rest (n . r) n stays as the roller's reaction.
        Tensor<1, dim> r_s;
        for (unsigned int d = 0; d < dim; ++d)
          if (!slave.fixed[d])
            r_s[d] = r[surfaces.position(slave.dofs[d])];
        slave_force[k] = roller_projector[k] * r_s;
        for (unsigned int d = 0; d < dim; ++d)
          {
            if (slave.fixed[d])
              continue;
            at(s.node, d) -= slave_force[k][d];
            for (const auto &[m, value] : s.M)
              at(m, d) += value / s.D * slave_force[k][d];
          }
      }
    traction[k] = slave_force[k] / s.D;
  }

  template <int dim>
  std::vector<double>
  MeshTying<dim>::traction_scales() const
  {
    // The largest traction a node of the pair carries, and at least 1e-12
    // of the pair's modulus: at no load, round-off decides nothing.
    std::vector<double> scale(surfaces.pairs.size(), 0.);
    for (unsigned int p = 0; p < scale.size(); ++p)
      scale[p] = 1e-12 * std::min(surfaces.statistics[p].slave_modulus,
                                  surfaces.statistics[p].master_modulus);
    for (unsigned int k = 0; k < surfaces.slave_nodes.size(); ++k)
      if (const auto &s = surfaces.slave_nodes[k]; s.paired && surfaces.owns_row(s))
        scale[s.pair] = std::max(scale[s.pair], traction[k].norm());
    Utilities::MPI::max(scale, surfaces.communicator(), scale);
    return scale;
  }

  template <int dim>
  typename MeshTying<dim>::BondUpdate
  MeshTying<dim>::update_bonds(const TrilinosWrappers::MPI::Vector &solution,
                               const unsigned int                   iteration)
  {
    BondUpdate update;
    if (!release_threshold)
      return update;
    if (iteration <= 1)
      bonds_of_iteration.assign(1, bond);
    const std::vector<double> u     = surfaces.gather(solution);
    const std::vector<double> scale = traction_scales();
    for (unsigned int k = 0; k < surfaces.slave_nodes.size(); ++k)
      {
        const auto &s = surfaces.slave_nodes[k];
        if (!s.paired)
          continue;
        // The opening: positive where the slave moves off its mortar image
        // against its outward normal (away from the master).
        Tensor<1, dim> relative = surfaces.displacement(s.node, u);
        for (const auto &[m, value] : s.M)
          relative -= value / s.D * surfaces.displacement(m, u);
        opening[k]        = -(relative * s.normal);
        const bool pulls  = traction[k] * s.normal > *release_threshold * scale[s.pair];
        const Bond before = bond[k];
        if (bond[k] != Bond::open && pulls)
          bond[k] = Bond::open;
        else if (bond[k] == Bond::open && opening[k] < -penetration_over_h * s.size &&
                 normal_line_component(surfaces, s) < dim)
          bond[k] = Bond::held;
        // Counted by the owner of the row.
        update.changes += bond[k] != before && surfaces.owns_row(s);
      }
    const MPI_Comm comm = surfaces.communicator();
    update.changes      = Utilities::MPI::sum(update.changes, comm);
    if (update.changes > 0)
      {
        // Whether the bonds of each earlier iteration come back: compared
        // on the rows each rank owns.
        std::vector<int> same(bonds_of_iteration.size(), 1);
        for (unsigned int i = 0; i < bonds_of_iteration.size(); ++i)
          for (unsigned int k = 0; k < surfaces.slave_nodes.size() && same[i]; ++k)
            same[i] =
              !surfaces.owns_row(surfaces.slave_nodes[k]) || bonds_of_iteration[i][k] == bond[k];
        Utilities::MPI::min(same, comm, same);
        for (unsigned int i = 0; i < bonds_of_iteration.size(); ++i)
          if (same[i])
            update.cycling = "the released tied nodes cycle between open and held: iteration " +
                             std::to_string(iteration) + " brings back the bonds of iteration " +
                             std::to_string(i) +
                             ", so the release in tension cannot settle (smaller load steps "
                             "usually break the cycle; the step is split)";
        bonds_of_iteration.push_back(bond);
      }
    return update;
  }

  template <int dim>
  unsigned int
  MeshTying<dim>::n_released() const
  {
    return count_over_rows(surfaces, [this](const unsigned int k) {
      return bond[k] != Bond::tied;
    });
  }

  template <int dim>
  unsigned int
  MeshTying<dim>::n_tied_nodes() const
  {
    return count_over_rows(surfaces, [this](const unsigned int k) {
      return surfaces.slave_nodes[k].paired;
    });
  }

  template <int dim>
  unsigned int
  MeshTying<dim>::n_slave_surface_nodes() const
  {
    return count_over_rows(surfaces, [](const unsigned int) {
      return true;
    });
  }

  template <int dim>
  unsigned int
  MeshTying<dim>::n_paired(const unsigned int p) const
  {
    return count_over_rows(surfaces, [this, p](const unsigned int k) {
      return surfaces.slave_nodes[k].paired && surfaces.slave_nodes[k].pair == p;
    });
  }

  template <int dim>
  Json
  MeshTying<dim>::results(std::ostream &out) const
  {
    Json result = Json::array();
    for (unsigned int p = 0; p < surfaces.pairs.size(); ++p)
      {
        // Over the rows each rank owns: the counts summed, the extremes
        // reduced, the area and the force added in node order
        // (sum_in_node_order()), so every rank has the serial values.
        const auto in_pair = [&](const unsigned int k) {
          const auto &s = surfaces.slave_nodes[k];
          return s.pair == p && s.paired && surfaces.owns_row(s);
        };
        unsigned int n              = 0;
        double       largest        = 0.;
        double       normal_min     = std::numeric_limits<double>::max();
        double       normal_max     = std::numeric_limits<double>::lowest();
        double       tangential_max = 0.;
        std::vector<std::vector<std::pair<unsigned int, double>>> terms(dim + 1); // D, force
        for (unsigned int k = 0; k < surfaces.slave_nodes.size(); ++k)
          if (in_pair(k))
            {
              const auto &s = surfaces.slave_nodes[k];
              n += bond[k] == Bond::tied;
              terms[0].emplace_back(k, s.D);
              for (unsigned int d = 0; d < dim; ++d)
                terms[1 + d].emplace_back(k, slave_force[k][d]);
              largest             = std::max(largest, traction[k].norm());
              const double normal = traction[k] * s.normal;
              normal_min          = std::min(normal_min, normal);
              normal_max          = std::max(normal_max, normal);
              tangential_max = std::max(tangential_max, (traction[k] - normal * s.normal).norm());
            }
        const MPI_Comm comm = surfaces.communicator();
        n                   = Utilities::MPI::sum(n, comm);
        largest             = Utilities::MPI::max(largest, comm);
        normal_min          = Utilities::MPI::min(normal_min, comm);
        normal_max          = Utilities::MPI::max(normal_max, comm);
        tangential_max      = Utilities::MPI::max(tangential_max, comm);
        const double   area = surfaces.sum_in_node_order(terms[0]);
        Tensor<1, dim> force;
        for (unsigned int d = 0; d < dim; ++d)
          force[d] = surfaces.sum_in_node_order(terms[1 + d]);
        // The traction's spread about its mean (force over area), over the
        // largest traction: 0 for a uniform stress.
        const Tensor<1, dim> mean   = area > 0. ? force / area : Tensor<1, dim>();
        double               spread = 0.;
        for (unsigned int k = 0; k < surfaces.slave_nodes.size(); ++k)
          if (in_pair(k) && largest > 0.)
            spread = std::max(spread, (traction[k] - mean).norm() / largest);
        spread                   = Utilities::MPI::max(spread, comm);
        const std::string name   = pair_text(surfaces.pairs[p]);
        Json              record = Json::object();
        record.set("pair", name)
          .set("tied_slave_nodes", n)
          .set("area", area)
          .set("force", json_array(force, dim))
          .set("mean_traction", json_array(mean, dim))
          .set("traction_spread", spread)
          .set("min_normal_traction", normal_min)
          .set("max_normal_traction", normal_max)
          .set("max_tangential_traction", tangential_max);
        out << "    tied pair " << name << ": " << n << " tied slave nodes, force on the slave "
            << vector_text(force, largest * area) << ", mean traction "
            << vector_text(mean, largest) << std::endl
            << "      normal traction (+ tension): " << value_text(normal_min, largest) << " ... "
            << value_text(normal_max, largest) << ", largest tangential "
            << value_text(tangential_max, largest) << std::endl
            << "      traction spread max|t - mean|/max|t|: " << value_or_ok(spread, 1e-10)
            << std::endl;
        if (releases())
          release_results(p, largest, record, out);
        result.push(record);
      }
    return result;
  }

  template <int dim>
  void
  MeshTying<dim>::release_results(const unsigned int p,
                                  const double       largest,
                                  Json              &record,
                                  std::ostream      &out) const
  {
    unsigned int released = 0, held = 0;
    double       tied_normal_max = std::numeric_limits<double>::lowest();
    double       open_min = std::numeric_limits<double>::max(), open_max = 0.;
    for (unsigned int k = 0; k < surfaces.slave_nodes.size(); ++k)
      if (const auto &s = surfaces.slave_nodes[k]; s.pair == p && s.paired && surfaces.owns_row(s))
        {
          released += bond[k] != Bond::tied;
          held += bond[k] == Bond::held;
          if (bond[k] == Bond::tied)
            tied_normal_max = std::max(tied_normal_max, traction[k] * s.normal);
          if (bond[k] == Bond::open)
            {
              open_min = std::min(open_min, opening[k]);
              open_max = std::max(open_max, opening[k]);
            }
        }
    // Summed and reduced over the rows each rank owns.
    const MPI_Comm comm = surfaces.communicator();
    released            = Utilities::MPI::sum(released, comm);
    held                = Utilities::MPI::sum(held, comm);
    tied_normal_max     = Utilities::MPI::max(tied_normal_max, comm);
    open_min            = Utilities::MPI::min(open_min, comm);
    open_max            = Utilities::MPI::max(open_max, comm);
    if (released == held)
      open_min = 0.;
    record.set("released_nodes", released)
      .set("held_released_nodes", held)
      .set("max_tied_normal_traction", tied_normal_max)
      .set("min_opening", open_min)
      .set("max_opening", open_max);
    const double h = surfaces.statistics[p].mean_slave_size;
    out << "      released in tension: " << released << " slave nodes (" << held
        << " of them held in contact)";
    if (released > held)
      out << ", the open ones open by " << value_text(open_min, h) << " ... "
          << value_text(open_max, h);
    if (released < n_paired(p))
      out << "; largest normal traction of a tied node " << value_text(tied_normal_max, largest);
    out << std::endl;
  }

  template class MeshTying<2>;
  template class MeshTying<3>;
} // namespace contact_fem
