#include <deal.II/base/mpi.h>

#include <contact_fem/core/format.h>
#include <contact_fem/simulator/search_control.h>

#include <algorithm>
#include <array>
#include <map>
#include <sstream>

namespace contact_fem
{
  template <int dim>
  SearchControl<dim>::SearchControl(ContactInterface<dim>    &interface,
                                    ContactFormulation<dim>  &contact,
                                    const ContactParameters  &parameters,
                                    TimerOutput              &timer,
                                    const ConditionalOStream &pcout)
    : interface(interface)
    , contact(contact)
    , parameters(parameters)
    , timer(timer)
    , pcout(pcout)
  {}

  template <int dim>
  void
  SearchControl<dim>::start_step(const std::vector<double> &displacement,
                                 const double               prescribed,
                                 const double               step_size,
                                 const StepStart            start)
  {
    TimerOutput::Scope t(timer, "Contact: search");
    step_start_displacement = displacement;
    searches_after_check    = 0;
    // The configuration the operators are built on: zero with small
    // kinematics, the step's start with updated.
    const std::vector<double> search_configuration =
      parameters.updated_kinematics ? displacement : std::vector<double>(displacement.size(), 0.);
    // The step moves the surfaces at least as far as the prescribed
    // displacements change, and about as far as the last step did per unit
    // of load; with small kinematics the operators must also reach as far as
    // the surfaces have moved from the reference configuration.
    const std::vector<double> moved = interface.relative_motion(search_configuration, displacement);
    motion_allowance.assign(interface.pairs.size(), 0.);
    for (unsigned int p = 0; p < motion_allowance.size(); ++p)
      {
        double predicted = prescribed;
        if (p < last_step_motion.size() && last_step_size > 0.)
          predicted = std::max(predicted, last_step_motion[p] * step_size / last_step_size);
        motion_allowance[p] = search_growth * (moved[p] + predicted);
      }
    search(search_configuration);
    contact.start_load_step(interface, displacement, start);
  }

  template <int dim>
  void
  SearchControl<dim>::search(const std::vector<double> &configuration)
  {
    interface.update(configuration, parameters.search_factor, motion_allowance);
    if (parameters.current_kinematics)
      interface.linearise(contact.transmits_shear());
  }

  template <int dim>
  bool
  SearchControl<dim>::follow(const std::vector<double> &displacement)
  {
    TimerOutput::Scope t(timer, "Contact: search");
    // The couplings of the sparsity pattern: the face pairs and the
    // paired nodes, of the rows this rank owns (each row has one owner, so
    // some rank sees any change; the list does not depend on which other
    // slave nodes a rank holds).
    const auto paired_nodes = [this] {
      std::vector<unsigned int> result;
      for (const auto &s : interface.slave_nodes)
        if (s.paired && interface.owns_row(s))
          result.push_back(s.node);
      return result;
    };
    // The face pairs of this rank's slave faces (the couplings are in
    // slave face order, so the whole list changed if one rank's did).
    const auto own_coupled_faces = [this] {
      std::vector<std::pair<unsigned int, unsigned int>> result;
      for (const auto &faces : interface.coupled_faces)
        if (faces.first >= interface.own_faces.first && faces.first < interface.own_faces.second)
          result.push_back(faces);
      return result;
    };
    const auto coupled = own_coupled_faces();
    const auto paired  = paired_nodes();
    search(displacement);
    const bool changed = own_coupled_faces() != coupled || paired_nodes() != paired;
    return Utilities::MPI::max(changed ? 1 : 0, interface.communicator()) > 0;
  }

  template <int dim>
  bool
  SearchControl<dim>::extend_if_outrun(const std::vector<double> &displacement)
  {
    const std::vector<double> motion = interface.motion_since_search(displacement);
    bool                      outrun = false;
    for (unsigned int p = 0; p < motion.size(); ++p)
      if (motion[p] > interface.search_reach()[p])
        {
          motion_allowance[p] = std::max(motion_allowance[p], search_growth * motion[p]);
          outrun              = true;
        }
    if (outrun)
      {
        pcout << "    the surfaces moved beyond the search reach: ";
        search_again(displacement);
      }
    return outrun;
  }

  template <int dim>
  bool
  SearchControl<dim>::accept(const std::vector<double> &displacement,
                             const unsigned int         step,
                             const double               time,
                             const double               step_size)
  {
    // The promise behind "converged": no slave node inside the master
    // beyond what its gap accounts for. A node no master face is paired
    // with gets a few wider searches.
    const PenetrationCheck check = check_penetration(displacement);
    if (check.excess > parameters.penetration_tolerance)
      {
        if (check.node.paired || searches_after_check == max_searches_after_check)
          throw penetration_failure(check, step, time);
        ++searches_after_check;
        widen(displacement, check.node.pair, check.penetration);
        return false;
      }
    penetration_excess = check.excess;
    last_step_motion   = interface.relative_motion(step_start_displacement, displacement);
    last_step_size     = step_size;
    return true;
  }

  template <int dim>
  void
  SearchControl<dim>::widen(const std::vector<double> &displacement,
                            const unsigned int         pair,
                            const double               depth)
  {
    const double motion    = interface.motion_since_search(displacement)[pair];
    motion_allowance[pair] = std::max(2. * motion_allowance[pair], search_growth * motion) + depth;
    pcout << "    a slave node penetrates the master where no master face is paired with "
             "it: ";
    search_again(displacement);
  }

  template <int dim>
  void
  SearchControl<dim>::search_again(const std::vector<double> &displacement)
  {
    pcout << "searching again with room for "
          << scientific(*std::max_element(motion_allowance.begin(), motion_allowance.end()), 2)
          << std::endl;
    TimerOutput::Scope t(timer, "Contact: search");
    // The same configuration as the step's search (a copy: update()
    // replaces the interface's own).
    const std::vector<double> configuration = interface.search_configuration();
    search(configuration);
    contact.start_load_step(interface, displacement, StepStart::continued);
  }

  template <int dim>
  double
  SearchControl<dim>::allowed_penetration(const typename ContactInterface<dim>::SlaveNode &s,
                                          const std::vector<double> &displacement) const
  {
    return s.paired ? std::max(0., -interface.nodal_gap(s, displacement)) +
                        max_sliding_angle * interface.slip_since_search(s, displacement) :
                      0.;
  }

  template <int dim>
  std::map<types::global_dof_index, double>
  SearchControl<dim>::allowed_depths(const std::vector<double> &displacement) const
  {
    std::map<types::global_dof_index, double> result;
    for (const auto &s : interface.slave_nodes)
      result[interface.nodes[s.node].dofs[0]] =
        allowed_penetration(s, displacement) + parameters.penetration_tolerance * s.size;
    return result;
  }

  template <int dim>
  typename SearchControl<dim>::PenetrationCheck
  SearchControl<dim>::check_penetration(const std::vector<double> &displacement) const
  {
    TimerOutput::Scope t(timer, "Contact: check");
    // What a node's own mortar gap says (with a penalty, or at the nodal
    // value of a curved face's weighted gap, a node may lie inside), and
    // the error of a gap linearised in the motion: a slip s along a surface
    // whose normal turns by theta on the way moves the node off the
    // linearised surface by about s theta, which small sliding bounds by
    // theta < max_sliding_angle.
    const auto allowed_at = [&](const typename ContactInterface<dim>::SlaveNode &s) {
      return allowed_penetration(s, displacement);
    };
    // Each rank checks the slave nodes and hanging slave vertices it owns
    // (ContactInterface::owns_node()). Only a node whose excess is positive
    // can become the worst (the scan below starts from zero), so those are
    // exchanged, and every rank scans them in the order of a serial run
    // (slave nodes, then hanging vertices): the tie rule makes the scan
    // depend on that order. Per candidate: its place in that order, the
    // excess, penetration and allowed penetration.
    using SlaveNode          = typename ContactInterface<dim>::SlaveNode;
    const auto &slave_nodes  = interface.slave_nodes;
    const auto &hanging      = interface.hanging_slave_vertices;
    const auto  own_excesses = [&](const std::vector<SlaveNode> &points,
                                  const unsigned int first_place, const auto &allowed_of,
                                  std::vector<double> &candidates) {
      std::vector<unsigned int> own;
      for (unsigned int i = 0; i < points.size(); ++i)
        if (interface.owns_node(points[i].node))
          own.push_back(i);
      const std::vector<double> distance = interface.surface_distances(points, own, displacement);
      for (unsigned int k = 0; k < own.size(); ++k)
        {
          const SlaveNode &s           = points[own[k]];
          const double     penetration = std::max(0., -distance[k]);
          const double     allowed     = allowed_of(s);
          const double     excess      = (penetration - allowed) / s.size;
          if (excess > 0.)
            candidates.insert(candidates.end(), {static_cast<double>(first_place + own[k]), excess,
                                                 penetration, allowed});
        }
    };
    std::vector<double> candidates;
    own_excesses(slave_nodes, 0, allowed_at, candidates);
    // A hanging vertex moves with its parents: it may lie inside by what
    // their gaps allow, in proportion to its weights.
    std::map<unsigned int, unsigned int> slave_node_at;
    if (!hanging.empty())
      for (unsigned int i = 0; i < slave_nodes.size(); ++i)
        slave_node_at[slave_nodes[i].node] = i;
    const auto allowed_of_hanging = [&](const SlaveNode &s) {
      double allowed = 0.;
      for (const auto &[parent, weight] : interface.nodes[s.node].parents)
        allowed += std::abs(weight) * allowed_at(slave_nodes[slave_node_at.at(parent)]);
      return allowed;
    };
    own_excesses(hanging, slave_nodes.size(), allowed_of_hanging, candidates);

    std::vector<std::array<double, 4>> all;
    for (const auto &chunk : Utilities::MPI::all_gather(interface.communicator(), candidates))
      for (unsigned int i = 0; i + 4 <= chunk.size(); i += 4)
        all.push_back({{chunk[i], chunk[i + 1], chunk[i + 2], chunk[i + 3]}});
    std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) {
      return a[0] < b[0];
    });

    PenetrationCheck check;
    for (const auto &[place_value, excess, penetration, allowed] : all)
      {
        const unsigned int place      = static_cast<unsigned int>(place_value);
        const bool         is_hanging = place >= slave_nodes.size();
        const SlaveNode &s = is_hanging ? hanging[place - slave_nodes.size()] : slave_nodes[place];
        // Symmetric nodes penetrate alike: the tie goes to the smaller
        // reference coordinates, not to the last bit of the excess.
        const bool tie =
          check.excess > 0. && std::abs(excess - check.excess) <= 1e-9 * check.excess;
        const auto precedes = [](const Point<dim> &a, const Point<dim> &b) {
          for (unsigned int d = 0; d < dim; ++d)
            if (a[d] != b[d])
              return a[d] < b[d];
          return false;
        };
        if (tie ? precedes(interface.nodes[s.node].reference,
                           interface.nodes[check.node.node].reference) :
                  excess > check.excess)
          {
            check.excess      = excess;
            check.node        = s;
            check.hanging     = is_hanging;
            check.penetration = penetration;
            check.allowed     = allowed;
          }
      }
    return check;
  }

  template <int dim>
  NewtonFailure
  SearchControl<dim>::penetration_failure(const PenetrationCheck &check,
                                          const unsigned int      step,
                                          const double            time) const
  {
    const auto        &s             = check.node;
    const std::string  configuration = parameters.updated_kinematics ?
                                         "configuration of the step's start" :
                                         "reference configuration";
    std::ostringstream message;
    message << "load step " << step + 1 << " (t = " << time
            << "): the converged solution is not a contact solution. The "
            << (check.hanging ? "hanging slave vertex" : "slave node") << " at ("
            << interface.nodes[s.node].reference << ") penetrates the master surface by "
            << scientific(check.penetration, 3) << " (h = " << scientific(s.size, 3) << "), ";
    if (s.paired)
      message << (check.hanging ?
                    "of which its parents' mortar gaps and their linearisation allow " :
                    "of which its mortar gap and its linearisation allow ")
              << scientific(check.allowed, 3)
              << ": the surfaces slid or turned farther than the operators built on the "
              << configuration << " can follow";
    else
      message << "and no master face is paired with it, also after a wider search (its "
                 "normal does not meet the master surface in the "
              << configuration << ")";
    message << " (Contact/Penetration tolerance = " << parameters.penetration_tolerance << " h).";
    if (!parameters.updated_kinematics)
      message << " This motion is beyond small sliding, so smaller load steps cannot help: "
                 "use Contact/Kinematics = updated with enough load steps, or current "
                 "(linearised on the deformed surfaces) where supported.";
    return NewtonFailure(message.str(), parameters.updated_kinematics);
  }

  template class SearchControl<2>;
  template class SearchControl<3>;
} // namespace contact_fem
