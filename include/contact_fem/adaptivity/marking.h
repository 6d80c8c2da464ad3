// Marking cells for refinement: by their indicators, the master faces
// opposite flagged slave faces, and the cell layers behind flagged
// contact-surface cells.
#ifndef contact_fem_marking_h
#define contact_fem_marking_h

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/vector.h>

#include <contact_fem/adaptivity/refinement.h>
#include <contact_fem/contact/contact_interface.h>

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
    /// all (1: nothing more); with @p along_surface (Refinement/Contact
    /// layers along the surface) each layer also takes the front's
    /// neighbours along the surface, else only the column straight
    /// behind. The front is exchanged with the ghosts, so the result does
    /// not depend on the partition. Collective.
    template <int dim>
    void
    flag_layers_behind_faces(parallel::distributed::Triangulation<dim> &triangulation,
                             const std::set<types::boundary_id>        &contact_ids,
                             const unsigned int                         layers,
                             const bool                                 along_surface = true);

    /**
     * Used with friction: stick ties a slave node to the master face it
     * projects on, and where the slave faces are finer than the master's,
     * the tangential multiplier oscillates from node to node around the
     * right mean (the adaptive Cattaneo spike, doc/validation.md). So a
     * flagged slave face takes along the master faces the last search
     * coupled it with, where these would be more than sqrt(2) times as
     * long as its children. Each rank decides for its own flagged slave
     * faces and the master faces so marked are exchanged, so the result
     * does not depend on the partition. Collective.
     */
    template <int dim>
    void
    flag_master_faces_opposite_flagged_slave_faces(DoFHandler<dim>             &dof_handler,
                                                   const ContactInterface<dim> &interface);
  } // namespace Marking
} // namespace contact_fem

#endif
