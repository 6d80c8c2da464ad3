// The checks of a scene's input that need its mesh, done before any work:
// numbers that overflow double precision, boundary ids on no face, contact
// pairs within one body, a mesh that will not fit in memory.
#ifndef contact_fem_input_checks_h
#define contact_fem_input_checks_h

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>

#include <contact_fem/contact/contact_parameters.h>
#include <contact_fem/geometry/scene.h>
#include <contact_fem/material/material.h>
#include <contact_fem/simulator/inclined_supports.h>
#include <contact_fem/simulator/scene_parameters.h>
#include <contact_fem/solvers/solver_parameters.h>

#include <string>

namespace contact_fem
{
  using namespace dealii;

  /**
   * Reads the parsed input of a scene (all of which outlives it) and
   * throws, naming the key or the mesh file, where it cannot be run.
   */
  template <int dim>
  class InputChecks
  {
  public:
    InputChecks(const Scene<dim>         &scene,
                const Materials<dim>     &materials,
                const BoundaryConditions &boundary_conditions,
                const LoadStepping       &load_stepping,
                const ContactParameters  &contact_parameters,
                const unsigned int        degree,
                const MPI_Comm            comm);

    /// Builds the scene without its global and box refinements and checks
    /// on that mesh the value ranges, the boundary ids, the rollers (and
    /// initialises @p inclined_supports from them), the contact pairs and
    /// the memory the full mesh will need. Returns a warning when the mesh
    /// takes more than half the available memory, else "". Collective.
    /// A scene without global refinements, boxes or distortion is built
    /// into the empty @p mesh (its final mesh, built once); @p mesh stays
    /// empty otherwise.
    std::string
    check_scene_before_meshing(InclinedSupports<dim>                     &inclined_supports,
                               parallel::distributed::Triangulation<dim> &mesh) const;

    /// Builds the mesh of @p coarse_scene (the scene itself, or its coarse
    /// mesh for the early checks); a library exception becomes a message
    /// naming the geometry key (and the distance from the origin where that
    /// is the likely cause).
    void
    create_scene_mesh(const Scene<dim>                          &coarse_scene,
                      parallel::distributed::Triangulation<dim> &coarse) const;

    /// The parameters that set the size of the mesh, for messages.
    std::string
    refinement_keys() const;

    /// Why adaptive cycle @p cycle, with @p new_dofs DoFs after a cycle
    /// with @p old_dofs, would exhaust the memory the run may use (RAM,
    /// cgroup, ulimit -v), or an empty string if it fits. Collective.
    std::string
    memory_shortage(const unsigned int cycle, const double old_dofs, const double new_dofs) const;

  private:
    /// "Geometry/Mesh file 'name'" or the subsection of a built-in scene.
    std::string
    geometry_key() const;
    /// Refuses coordinates, moduli and loads whose products overflow
    /// double precision, naming the key or mesh file.
    void
    check_value_ranges(const Triangulation<dim> &coarse) const;
    /// Refuses a load or prescribed displacement that is not a finite number
    /// (or a load whose force over @p area overflows) at a vertex of its
    /// boundary at a time of the load path, naming the key.
    void
    check_load_path(const Triangulation<dim> &coarse, const double area) const;
    /// Refuses a boundary id named by a boundary condition or a contact pair
    /// that no face of @p coarse carries, naming the key and the id.
    void
    check_boundary_ids(const Triangulation<dim> &coarse) const;
    /// Refuses a contact pair whose two surfaces belong to the same body.
    void
    check_contact_pairs(const Triangulation<dim> &tria) const;
    /// Refuses a mesh whose estimated memory exceeds what the machine has
    /// available; the warning of check_scene_before_meshing().
    std::string
    check_memory_estimate(const parallel::distributed::Triangulation<dim> &coarse) const;

    const Scene<dim>         &scene;
    const Materials<dim>     &materials;
    const BoundaryConditions &boundary_conditions;
    const LoadStepping       &load_stepping;
    const ContactParameters  &contact_parameters;
    const unsigned int        degree;
    const MPI_Comm            comm;
  };
} // namespace contact_fem

#endif
