#include <deal.II/base/mpi.h>

#include <contact_fem/contact/formulations/frictional_formulation.h>
#include <contact_fem/contact/formulations/penalty_frictionless.h>

#include <algorithm>
#include <set>

namespace contact_fem
{
  template <int dim, class NormalPart>
  void
  FrictionalFormulation<dim, NormalPart>::initialize(const ContactInterface<dim> &interface)
  {
    NormalPart::initialize(interface);
    const unsigned int n = interface.nodes.size();
    tangential.assign(n, TangentialVector<dim>());
    grazing.assign(n, 0.);
    sets.initialize(interface);
    last_step_slip.assign(n, TangentialVector<dim>());
    slip_history.initialize(n);
    converged_displacement.assign(interface.dofs().size(), 0.);
    last_stick_slip_changes = 0;
    stick_count             = 0;
    slip_count              = 0;
    converged_operators.assign(n, Operators());
  }

  template <int dim, class NormalPart>
  bool
  FrictionalFormulation<dim, NormalPart>::slides_everywhere() const
  {
    const bool any_friction = std::any_of(laws.begin(), laws.end(), [](const auto &law) {
      return !law->frictionless();
    });
    return !pure_slip && any_friction && n_stick() == 0 && n_slip() > 0 &&
           n_slip() == this->n_active();
  }

  template <int dim, class NormalPart>
  std::string
  FrictionalFormulation<dim, NormalPart>::iteration_header() const
  {
    return friction_iteration_header();
  }

  template <int dim, class NormalPart>
  std::string
  FrictionalFormulation<dim, NormalPart>::iteration_cells(const unsigned int iteration) const
  {
    return friction_iteration_cells(iteration, n_stick(), n_slip(), last_stick_slip_changes);
  }

  template <int dim, class NormalPart>
  std::vector<typename ContactFormulation<dim>::NodalField>
  FrictionalFormulation<dim, NormalPart>::nodal_fields(const ContactInterface<dim> &interface) const
  {
    return friction_nodal_fields(interface, *this, last_step_slip, slip_history);
  }

  template <int dim, class NormalPart>
  std::vector<int>
  FrictionalFormulation<dim, NormalPart>::contact_sets() const
  {
    std::vector<int> codes = sets.codes(this->active);
    for (unsigned int n = 0; n < codes.size(); ++n)
      codes[n] += grazing[n] != 0. ? 8 : 0;
    return codes;
  }

  template <int dim, class NormalPart>
  std::vector<unsigned int>
  FrictionalFormulation<dim, NormalPart>::count_owned_rows(
    const ContactInterface<dim> &interface) const
  {
    std::vector<unsigned int> counts = NormalPart::count_owned_rows(interface);
    unsigned int              stick = 0, slip = 0;
    for (const auto &s : interface.slave_nodes)
      if (interface.owns_row(s))
        {
          stick += sets.sticks(s.node, this->active);
          slip += sets.slips(s.node, this->active);
        }
    counts.push_back(stick);
    counts.push_back(slip);
    return counts;
  }

  template <int dim, class NormalPart>
  void
  FrictionalFormulation<dim, NormalPart>::take_counts(
    std::vector<unsigned int>::const_iterator &next)
  {
    NormalPart::take_counts(next);
    stick_count = *next++;
    slip_count  = *next++;
  }

  template <int dim, class NormalPart>
  Json
  FrictionalFormulation<dim, NormalPart>::law_names() const
  {
    Json names = Json::array();
    for (const auto &law : laws)
      names.push(law->description());
    return names;
  }

  template <int dim, class NormalPart>
  TangentialVector<dim>
  FrictionalFormulation<dim, NormalPart>::objective_slip(
    const ContactInterface<dim> &interface,
    const SlaveNode             &s,
    const std::vector<double>   &u,
    std::array<Row, dim - 1>    *derivatives) const
  {
    // xi_j = -P w_j / D_j, P the projection onto the tangent plane (in the
    // frame tau_k of n_j), w_j = sum_a c_a x_a over the slave node (c = D_j
    // - D_j^n) and its masters now and at the last accepted step (c =
    // -(M_jl - M_jl^n)): the operators' change at the current positions,
    // per unit D_j, a length like the small path's slip (weighted by D_j,
    // c xi_j would fall with the face area, h^2 in 3D, and the stick/slip
    // decision would follow the pressure's change instead of the slip).
    const Operators               &old = converged_operators[s.node];
    std::map<unsigned int, double> coefficient;
    coefficient[s.node] += s.D - old.D;
    for (const auto &[m, value] : s.M)
      coefficient[m] -= value;
    for (const auto &[m, value] : old.M)
      coefficient[m] += value;
    // In the frame of frame_normal(s): the slave normal, or the interface
    // normal (penalty frictional).
    const Tensor<1, dim> n_f   = this->frame_normal(s);
    const auto           frame = tangent_frame(n_f);
    Tensor<1, dim>       w;
    for (const auto &[node, c] : coefficient)
      w += c * (interface.nodes[node].reference + interface.displacement(node, u));
    TangentialVector<dim> xi;
    for (unsigned int k = 0; k < dim - 1; ++k)
      xi[k] = -(frame[k] * w) / s.D;
    if (!derivatives)
      return xi;
    // d xi_k = (-tau_k . dw - d tau_k . w) / D_j, the frame held in the
    // tangent plane as n turns: d tau_k = -(tau_k . dn) n (in 2D the turn
    // of tau). dw: c_a dx_a, and the operators' derivatives at held x. D_j
    // is held: its part, -xi_k dD_j / D_j, vanishes where the derivative
    // matters for the alm (xi = 0 on a stick node, e . xi = 0 across a
    // slip direction); the penalty adds it.
    const auto  &linearised  = interface.linearised_nodes.at(s.node);
    const auto  &dn          = frame_normal_derivative(interface, s);
    const double normal_part = n_f * w;
    for (unsigned int k = 0; k < dim - 1; ++k)
      {
        Row &row = (*derivatives)[k];
        for (const auto &[node, c] : coefficient)
          for (unsigned int d = 0; d < dim; ++d)
            row[interface.nodes[node].dofs[d]] -= c * frame[k][d] / s.D;
        for (unsigned int i = 0; i < linearised.dofs.size(); ++i)
          {
            double tau_dn = 0., tau_dw = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              {
                tau_dn += frame[k][d] * dn[d][i];
                tau_dw += frame[k][d] * linearised.operators[d][i];
              }
            row[linearised.dofs[i]] += (tau_dn * normal_part - tau_dw) / s.D;
          }
      }
    return xi;
  }

  template <int dim, class NormalPart>
  void
  FrictionalFormulation<dim, NormalPart>::keep_operators_of_new_pairs(
    const ContactInterface<dim> &interface)
  {
    for (const auto &s : interface.slave_nodes)
      if (s.paired && interface.owns_row(s) && converged_operators[s.node].M.empty())
        converged_operators[s.node] = Operators{s.D, s.M};
  }

  template <int dim, class NormalPart>
  void
  FrictionalFormulation<dim, NormalPart>::keep_operators(const ContactInterface<dim> &interface)
  {
    for (const auto &s : interface.slave_nodes)
      if (interface.owns_row(s))
        converged_operators[s.node] = s.paired ? Operators{s.D, s.M} : Operators();
  }

  template <int dim, class NormalPart>
  void
  FrictionalFormulation<dim, NormalPart>::accept_slip(
    const ContactInterface<dim>                                   &interface,
    const std::function<TangentialVector<dim>(const SlaveNode &)> &slip)
  {
    std::fill(last_step_slip.begin(), last_step_slip.end(), TangentialVector<dim>());
    for (const auto &s : interface.slave_nodes)
      if (s.paired && interface.owns_row(s))
        last_step_slip[s.node] = slip(s);
    slip_history.add(interface, *this, last_step_slip);
    if (Utilities::MPI::n_mpi_processes(interface.communicator()) == 1)
      return;
    // The components as fields of doubles: the step's slip (dim - 1), the
    // path length, the accumulated displacement (dim).
    const unsigned int               n = interface.nodes.size();
    std::vector<std::vector<double>> values(2 * dim, std::vector<double>(n));
    for (unsigned int node = 0; node < n; ++node)
      {
        for (unsigned int k = 0; k < dim - 1; ++k)
          values[k][node] = last_step_slip[node][k];
        values[dim - 1][node] = slip_history.length[node];
        for (unsigned int d = 0; d < dim; ++d)
          values[dim + d][node] = slip_history.displacement[node][d];
      }
    std::vector<std::vector<double> *> fields;
    for (auto &field : values)
      fields.push_back(&field);
    interface.share_node_values(fields, fields.size());
    for (unsigned int node = 0; node < n; ++node)
      {
        for (unsigned int k = 0; k < dim - 1; ++k)
          last_step_slip[node][k] = values[k][node];
        slip_history.length[node] = values[dim - 1][node];
        for (unsigned int d = 0; d < dim; ++d)
          slip_history.displacement[node][d] = values[dim + d][node];
      }
  }

  template <int dim, class NormalPart>
  void
  FrictionalFormulation<dim, NormalPart>::share_frictional_states(
    const ContactInterface<dim>                                           &interface,
    const std::vector<std::vector<TangentialVector<dim>> *>               &tangential_fields,
    const std::vector<std::vector<double> *>                              &double_fields,
    const std::function<void(const std::vector<std::vector<double> *> &)> &share_normal) const
  {
    if (Utilities::MPI::n_mpi_processes(interface.communicator()) == 1)
      return;
    // The components of the tangential fields as fields of doubles.
    const unsigned int               n = interface.nodes.size();
    std::vector<std::vector<double>> components(tangential_fields.size() * (dim - 1),
                                                std::vector<double>(n));
    for (unsigned int f = 0; f < tangential_fields.size(); ++f)
      for (unsigned int node = 0; node < n; ++node)
        for (unsigned int k = 0; k < dim - 1; ++k)
          components[f * (dim - 1) + k][node] = (*tangential_fields[f])[node][k];
    std::vector<std::vector<double> *> fields = double_fields;
    for (auto &component : components)
      fields.push_back(&component);
    share_normal(fields);
    for (unsigned int f = 0; f < tangential_fields.size(); ++f)
      for (unsigned int node = 0; node < n; ++node)
        for (unsigned int k = 0; k < dim - 1; ++k)
          (*tangential_fields[f])[node][k] = components[f * (dim - 1) + k][node];
  }

  template <int dim, class NormalPart>
  std::vector<types::global_dof_index>
  FrictionalFormulation<dim, NormalPart>::objective_slip_patch(
    const ContactInterface<dim> &interface,
    const unsigned int           node) const
  {
    const auto                       &linearised = interface.linearised_nodes.at(node);
    std::set<types::global_dof_index> unique(linearised.dofs.begin(), linearised.dofs.end());
    for (const auto &[m, value] : converged_operators[node].M)
      for (unsigned int d = 0; d < dim; ++d)
        unique.insert(interface.nodes[m].dofs[d]);
    return std::vector<types::global_dof_index>(unique.begin(), unique.end());
  }

  template <int dim, class NormalPart>
  std::vector<types::global_dof_index>
  FrictionalFormulation<dim, NormalPart>::line_seeds(const ContactInterface<dim> &interface) const
  {
    std::vector<types::global_dof_index> dofs = NormalPart::line_seeds(interface);
    if (on_current_configuration())
      for (const auto &[node, linearised] : interface.linearised_nodes)
        for (const auto &[m, value] : converged_operators[node].M)
          dofs.insert(dofs.end(), interface.nodes[m].dofs.begin(), interface.nodes[m].dofs.end());
    std::sort(dofs.begin(), dofs.end());
    dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
    return dofs;
  }

  template class FrictionalFormulation<2, FrictionlessFormulation<2>>;
  template class FrictionalFormulation<3, FrictionlessFormulation<3>>;
  template class FrictionalFormulation<2, PenaltyFrictionless<2>>;
  template class FrictionalFormulation<3, PenaltyFrictionless<3>>;
} // namespace contact_fem
