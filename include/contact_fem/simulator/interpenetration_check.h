// The interpenetration check of a converged finite-deformation state: a
// boundary vertex inside a body where no contact pair accounts for it (a
// body folding onto itself, or passing through a body it is not paired with).
#ifndef contact_fem_interpenetration_check_h
#define contact_fem_interpenetration_check_h

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_fem/contact/contact_parameters.h>
#include <contact_fem/core/json.h>

#include <map>
#include <string>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /**
   * Every boundary vertex of the deformed mesh against every deformed cell
   * whose (enlarged) bounding box holds it, skipping the cells the vertex
   * belongs to: a vertex inside a cell (its displaced mapping inverted by
   * Newton) is inside that cell's body, as deep as its distance to that
   * body's deformed boundary (the boundary faces as chords through their
   * vertices). Flagged when deeper than @p tolerance times the vertex's
   * element size (the smallest edge of its boundary faces), except:
   * - a vertex of a slave surface inside the master body of its pair (or of
   *   a tied pair): flagged deeper than what the contact's penetration
   *   check allows it (its gap, e.g. a penalty's penetration, plus the
   *   tolerance times its nodal size), so also through faces of the
   *   master body outside the master surface;
   * - a vertex of a master surface inside the slave body of its pair: the
   *   mortar conditions hold at the slave nodes only, and a master corner
   *   enters between them by a part of an element; flagged only deeper than
   *   its element size.
   * Collective: the boundary faces and vertices of all ranks are gathered
   * (the surfaces are small), each rank tests them against the cells it
   * owns, and the deepest finding is the same on every rank.
   */
  template <int dim>
  class InterpenetrationCheck
  {
  public:
    struct Finding
    {
      bool         found = false;
      Point<dim>   reference, position;   ///< of the vertex
      double       depth = 0., size = 0.; ///< below the body's surface; h of the vertex
      unsigned int vertex_body = 0, cell_body = 0;
      std::vector<unsigned int> boundary_ids; ///< of the vertex's faces
      std::string               kind;         ///< "fold", "unpaired body", "paired body"
    };

    /// @p pairs: the contact and tied pairs; @p tolerance relative to the
    /// vertex's element size (Contact/Penetration tolerance).
    InterpenetrationCheck(const DoFHandler<dim>          &dof_handler,
                          const MappingQ<dim>            &mapping,
                          const std::vector<ContactPair> &pairs,
                          const double                    tolerance);

    /// Checks the configuration displaced by @p solution (owned), of which
    /// @p ghosted_solution is the locally relevant copy. @p
    /// allowed_by_contact: per paired slave vertex (its x DoF) the depth
    /// the contact's penetration check allows it in its master body (the
    /// same on every rank). Collective.
    Finding
    check(const TrilinosWrappers::MPI::Vector             &solution,
          const TrilinosWrappers::MPI::Vector             &ghosted_solution,
          const std::map<types::global_dof_index, double> &allowed_by_contact);

    /// Counts of the last check (summary.json).
    unsigned int n_vertices = 0, n_candidates = 0, n_inside = 0, n_found = 0;

    /// The text of a finding, for the failure of load step @p where.
    std::string
    message(const Finding &finding) const;

    Json
    record(const Finding &finding) const;

  private:
    const DoFHandler<dim>   &dof_handler;
    const MappingQ<dim>     &mapping;
    std::vector<ContactPair> pairs;
    double                   tolerance;
  };
} // namespace contact_fem

#endif
