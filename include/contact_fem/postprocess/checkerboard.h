// Detection of the Q1 pressure checkerboard: contact pressures that
// alternate from slave node to slave node instead of following a smooth
// profile (the dual multipliers of a slave surface that the master side
// cannot follow, issue 30).
#ifndef contact_fem_checkerboard_h
#define contact_fem_checkerboard_h

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/core/json.h>

#include <string>
#include <vector>

namespace contact_fem
{
  /// What the check found on one contact pair.
  struct CheckerboardFinding
  {
    unsigned int pair = 0;
    /// Pairs of neighbouring interior active slave nodes (all of whose
    /// neighbours are active) and those of them whose pressures deviate
    /// from their neighbours' mean in opposite directions, each by more
    /// than the threshold.
    unsigned int neighbour_pairs = 0, alternating = 0;
    /// The largest such deviation over the pair's largest pressure.
    double amplitude = 0.;
  };

  /**
   * Finds checkerboards on the Q1 slave surfaces of @p interface (degree-2
   * faces are not checked): a pair is flagged when at least 3 and at least
   * half of its neighbouring interior active node pairs alternate by more
   * than 1 % of the pair's largest pressure. A smooth profile (Hertz,
   * flat punch, patch test) deviates in one direction over whole regions;
   * the irregular nodal weights of an unstructured (split tetrahedral)
   * surface alternate at about a third of the pairs and are not flagged.
   * Collective: each rank counts the neighbour pairs whose lower node it
   * owns (ContactInterface::owns_node()), the counts are summed and the
   * largest values taken over the ranks; the result is the same on every
   * rank and on any number of ranks.
   */
  template <int dim>
  std::vector<CheckerboardFinding>
  find_checkerboards(const ContactInterface<dim>   &interface,
                     const ContactFormulation<dim> &contact);

  /// The warnings naming each flagged pair, how strong the alternation is
  /// and what to change (the driver prints them once per run).
  template <int dim>
  std::vector<std::string>
  checkerboard_warnings(const ContactInterface<dim>   &interface,
                        const ContactFormulation<dim> &contact);
} // namespace contact_fem

#endif
