// Marking cells for refinement: by their indicators, and the cell layers
// behind flagged contact-surface cells.
#ifndef contact_fem_marking_h
#define contact_fem_marking_h

#include <deal.II/distributed/tria.h>
#include <deal.II/lac/vector.h>

#include <contact_fem/adaptivity/refinement.h>

#include <set>

namespace contact_fem
{
  using namespace dealii;

  namespace Marking
  {
    /// Sets the refine (and coarsen) flags of the locally owned cells: every
    /// cell for Estimator = global, else by @p indicators (one per active
    /// cell) with the strategy of @p parameters. Collective.
    template <int dim>
    void
    flag_cells(parallel::distributed::Triangulation<dim> &triangulation,
               const Vector<float>                       &indicators,
               const RefinementParameters                &parameters);

    /// Refinement/Contact layers: a flagged cell with a face on one of
    /// @p contact_ids takes the cells behind it along, @p layers deep in
    /// all (1: nothing more). The front is exchanged with the ghosts, so
    /// the result does not depend on the partition. Collective.
    template <int dim>
    void
    flag_layers_behind_faces(parallel::distributed::Triangulation<dim> &triangulation,
                             const std::set<types::boundary_id>        &contact_ids,
                             const unsigned int                         layers);
  } // namespace Marking
} // namespace contact_fem

#endif
