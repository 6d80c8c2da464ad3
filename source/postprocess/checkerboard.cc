// The checkerboard test of find_checkerboards(): per active slave node the
// deviation r_j = p_j - mean of p over its neighbours (the nodes of its
// slave faces). A smooth profile has r of one sign over whole regions
// (negative under a Hertz peak, positive toward a punch's edges, zero in a
// patch test); a checkerboard flips the sign from node to node.
#include <deal.II/base/mpi.h>

#include <contact_fem/core/format.h>
#include <contact_fem/postprocess/checkerboard.h>
#include <contact_fem/postprocess/postprocessor.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace contact_fem
{
  namespace
  {
    constexpr double       relative_threshold   = 0.01;
    constexpr double       alternating_fraction = 0.5;
    constexpr unsigned int least_alternating    = 3;
  } // namespace

  template <int dim>
  std::vector<CheckerboardFinding>
  find_checkerboards(const ContactInterface<dim> &interface, const ContactFormulation<dim> &contact)
  {
    // Each rank computes the deviations of the nodes whose rows it owns
    // (ContactInterface::owns_row()), from the pressures of their
    // neighbours (the nodes of the faces holding them, which it holds), and
    // counts the neighbour pairs whose lower node is one of them; the
    // deviations of the other nodes come from the owners of their rows
    // (gather(), point to point). Counts are summed and maxima taken over
    // the ranks, so the findings are those of one rank going over the whole
    // surface.
    const MPI_Comm                   comm = interface.communicator();
    std::vector<CheckerboardFinding> findings;
    const unsigned int               q1_face_nodes = dim == 2 ? 2 : 4;
    for (unsigned int p = 0; p < interface.pairs.size(); ++p)
      {
        std::map<unsigned int, double> pressure; // active slave nodes of the pair
        std::set<unsigned int>         own_rows; // those whose rows this rank owns
        double                         p_max = 0.;
        for (const auto &s : interface.slave_nodes)
          if (s.pair == p && s.paired && contact.is_active(s.node) &&
              interface.nodes[s.node].parents.empty())
            {
              pressure[s.node] = contact.normal_pressure(s.node);
              if (interface.owns_row(s))
                {
                  own_rows.insert(s.node);
                  p_max = std::max(p_max, pressure[s.node]);
                }
            }
        std::map<unsigned int, std::set<unsigned int>> neighbours;
        for (const auto &face : interface.faces)
          if (face.slave && face.pair == p)
            for (const unsigned int a : face.nodes)
              for (const unsigned int b : face.nodes)
                if (a != b)
                  neighbours[a].insert(b);
        bool q1 = true;
        for (unsigned int f = interface.own_faces.first; f < interface.own_faces.second; ++f)
          if (interface.faces[f].slave && interface.faces[f].pair == p)
            q1 = q1 && interface.faces[f].nodes.size() == q1_face_nodes;
        q1                  = Utilities::MPI::min(q1 ? 1u : 0u, comm) == 1u;
        const auto n_active = static_cast<unsigned int>(own_rows.size());
        if (!q1 || Utilities::MPI::sum(n_active, comm) < 3)
          continue;
        p_max = Utilities::MPI::max(p_max, comm);
        // The deviation of an interior active node (one whose neighbours
        // are all active) whose row this rank owns, keyed by its x DoF.
        std::map<types::global_dof_index, double> own_deviations;
        for (const unsigned int node : own_rows)
          {
            double sum      = 0.;
            bool   interior = !neighbours[node].empty();
            for (const unsigned int k : neighbours[node])
              {
                interior = interior && pressure.count(k);
                sum += interior ? pressure.at(k) : 0.;
              }
            if (interior)
              own_deviations[interface.nodes[node].dofs[0]] =
                pressure.at(node) - sum / neighbours[node].size();
          }
        // Every node's from the owner of its row (NaN: none).
        const std::vector<double> at_dofs =
          interface.gather([&own_deviations](const types::global_dof_index dof) {
            const auto r = own_deviations.find(dof);
            return r != own_deviations.end() ? r->second : std::numeric_limits<double>::quiet_NaN();
          });
        const auto deviation = [&](const unsigned int node) -> std::optional<double> {
          const double r = at_dofs[interface.position(interface.nodes[node].dofs[0])];
          return std::isnan(r) ? std::nullopt : std::optional<double>(r);
        };
        CheckerboardFinding finding;
        finding.pair = p;
        for (const unsigned int node : own_rows)
          {
            if (!deviation(node))
              continue;
            const double r = *deviation(node);
            for (const unsigned int k : neighbours[node])
              if (k > node && deviation(k))
                {
                  ++finding.neighbour_pairs;
                  const double other = *deviation(k);
                  if (r * other < 0. &&
                      std::min(std::abs(r), std::abs(other)) > relative_threshold * p_max)
                    {
                      ++finding.alternating;
                      finding.amplitude =
                        std::max(finding.amplitude, std::max(std::abs(r), std::abs(other)) / p_max);
                    }
                }
          }
        finding.neighbour_pairs = Utilities::MPI::sum(finding.neighbour_pairs, comm);
        finding.alternating     = Utilities::MPI::sum(finding.alternating, comm);
        finding.amplitude       = Utilities::MPI::max(finding.amplitude, comm);
        if (finding.alternating >= least_alternating &&
            finding.alternating >= alternating_fraction * finding.neighbour_pairs)
          findings.push_back(finding);
      }
    return findings;
  }

  template <int dim>
  std::vector<std::string>
  checkerboard_warnings(const ContactInterface<dim>   &interface,
                        const ContactFormulation<dim> &contact)
  {
    std::vector<std::string> warnings;
    for (const auto &finding : find_checkerboards(interface, contact))
      {
        const auto       &pair  = interface.pairs[finding.pair];
        const auto       &stats = interface.statistics[finding.pair];
        const std::string name  = std::to_string(static_cast<unsigned int>(pair.slave)) + ": " +
                                 std::to_string(static_cast<unsigned int>(pair.master));
        std::ostringstream message;
        message << "contact pair " << name << ": the contact pressure alternates from slave "
                << "node to slave node (a checkerboard: " << finding.alternating << " of "
                << finding.neighbour_pairs << " neighbouring active node pairs, up to "
                << significant(100. * finding.amplitude, 2)
                << " % of the largest pressure), so nodal pressures and p_max are not "
                   "reliable; ";
        const std::string swapped =
          "Contact/Pairs = " + std::to_string(static_cast<unsigned int>(pair.master)) + ": " +
          std::to_string(static_cast<unsigned int>(pair.slave));
        if (stats.mean_slave_size > 1.5 * stats.mean_master_size)
          message << "the slave surface is the coarser one (mean element sizes "
                  << significant(stats.mean_slave_size, 3) << " slave, "
                  << significant(stats.mean_master_size, 3)
                  << " master): make the finer surface the slave (" << swapped
                  << "), or use Q2 (Finite element/Degree)";
        else
          message << "the master (mean element size " << significant(stats.mean_master_size, 3)
                  << ", slave " << significant(stats.mean_slave_size, 3)
                  << ") cannot follow the slave's multipliers: refine the master surface to "
                     "the slave's resolution at the contact (Geometry/Local refinements), "
                     "make the coarser surface the slave ("
                  << swapped << "), or use Q2 (Finite element/Degree)";
        warnings.push_back(message.str());
      }
    return warnings;
  }

  namespace
  {
    /// The checkerboard warnings of each cycle's contact pressure (with
    /// contact pairs).
    template <int dim>
    class CheckerboardCheck : public Postprocessor<dim>
    {
    public:
      static std::unique_ptr<Postprocessor<dim>>
      create(const PostprocessorContext<dim> &context)
      {
        if (!context.has_contact)
          return nullptr;
        return std::make_unique<CheckerboardCheck<dim>>(context.warn);
      }

      explicit CheckerboardCheck(
        const std::function<void(const std::string &, const std::string &, Json &)> &warn)
        : warn(warn)
      {}

      void
      after_cycle(const RunView<dim> &view, Json &cycle_record, std::ostream &) override
      {
        const ContactState<dim> &state = *view.solution.contact;
        for (const std::string &text : checkerboard_warnings(state.interface, state.contact))
          warn("checkerboard_warning", text, cycle_record);
      }

    private:
      const std::function<void(const std::string &, const std::string &, Json &)> warn;
    };
  } // namespace

  CONTACT_FEM_REGISTER_POSTPROCESSOR(CheckerboardCheck, "checkerboard check", 10)

  template std::vector<CheckerboardFinding>
  find_checkerboards(const ContactInterface<2> &, const ContactFormulation<2> &);
  template std::vector<CheckerboardFinding>
  find_checkerboards(const ContactInterface<3> &, const ContactFormulation<3> &);
  template std::vector<std::string>
  checkerboard_warnings(const ContactInterface<2> &, const ContactFormulation<2> &);
  template std::vector<std::string>
  checkerboard_warnings(const ContactInterface<3> &, const ContactFormulation<3> &);
} // namespace contact_fem
