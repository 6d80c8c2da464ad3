// The input checks of a scene on its coarse mesh (InputChecks): the contact
// pairs, the boundary ids and the memory the mesh will need.
#include <contact_fem/core/format.h>
#include <contact_fem/simulator/input_checks.h>
#include <contact_fem/geometry/mesh_queries.h>
#include <contact_fem/core/resources.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <vector>

namespace contact_fem
{
  namespace
  {
    /// Fraction of the bounding box of @p cell inside @p box: how much of
    /// the cell a box refines, after enough refinements.
    template <int dim, typename Cell, typename Box>
    double
    fraction_inside(const Cell &cell, const Box &box)
    {
      const BoundingBox<dim> bounds = cell->bounding_box();
      double                 inside = 1.;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double low  = std::max(bounds.get_boundary_points().first[d], box.lower[d]);
          const double high = std::min(bounds.get_boundary_points().second[d], box.upper[d]);
          const double width =
            bounds.get_boundary_points().second[d] - bounds.get_boundary_points().first[d];
          inside *= width > 0. ? std::max(0., high - low) / width : 0.;
        }
      return inside;
    }

    /// The loads that a support on the same boundary takes whole: a
    /// Traction whose every component is held (Fixed or Prescribed
    /// displacement on its boundary), a Pressure whose boundary's normal has
    /// no component that is not held (to 1e-6 of the unit normal, on every
    /// face). Such a load goes straight into the support and deforms
    /// nothing; the run used to "converge" on contact forces of round-off
    /// without a word. Empty if none.
    template <int dim>
    std::string
    loads_held_by_supports(const Triangulation<dim> &coarse, const BoundaryConditions &bc)
    {
      std::map<types::boundary_id, std::set<unsigned int>> held;
      for (const auto &c : bc.displacements)
        held[c.boundary_id].insert(c.component);
      std::vector<std::string> found;
      const auto               name = [](const types::boundary_id id) {
        return "boundary " + std::to_string(static_cast<unsigned int>(id));
      };
      for (const auto &t : bc.tractions)
        if (held.count(t.boundary_id) && held.at(t.boundary_id).size() == dim)
          found.push_back("Boundary conditions/Traction on " + name(t.boundary_id));
      for (const auto &p : bc.pressures)
        {
          if (!held.count(p.boundary_id))
            continue;
          const auto &components = held.at(p.boundary_id);
          bool        absorbed = true, any = false;
          for (const auto &cell : coarse.active_cell_iterators())
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == p.boundary_id)
                {
                  const Tensor<1, dim> n = outward_normal<dim>(cell, f);
                  any                    = true;
                  for (unsigned int d = 0; d < dim; ++d)
                    if (!components.count(d) && std::abs(n[d]) > 1e-6 * n.norm())
                      absorbed = false;
                }
          if (any && absorbed)
            found.push_back("Boundary conditions/Pressure on " + name(p.boundary_id));
        }
      if (found.empty())
        return "";
      std::string text = found[0];
      for (unsigned int k = 1; k < found.size(); ++k)
        text += ", " + found[k];
      return text +
             " acts only along components that Boundary conditions/Fixed or Prescribed "
             "displacement hold on the same boundary: the support takes the whole load, which "
             "deforms nothing (a load meant for a free boundary, or a support meant for "
             "another one?)";
    }
  } // namespace

  template <int dim>
  InputChecks<dim>::InputChecks(const Scene<dim>         &scene,
                                const Materials<dim>     &materials,
                                const BoundaryConditions &boundary_conditions,
                                const LoadStepping       &load_stepping,
                                const ContactParameters  &contact_parameters,
                                const unsigned int        degree,
                                const MPI_Comm            comm)
    : scene(scene)
    , materials(materials)
    , boundary_conditions(boundary_conditions)
    , load_stepping(load_stepping)
    , contact_parameters(contact_parameters)
    , degree(degree)
    , comm(comm)
  {}

  template <int dim>
  std::string
  InputChecks<dim>::check_scene_before_meshing(InclinedSupports<dim>                     &inclined_supports,
                                               parallel::distributed::Triangulation<dim> &mesh) const
  {
    // The scene without its global refinements, refinement boxes and
    // distortion: cheap to build, and the mesh those refinements multiply.
    // A scene without them is that mesh (the Hertz scenes, whose own
    // refinement rounds are part of it): built once, into @p mesh, and not
    // again by the run.
    std::unique_ptr<parallel::distributed::Triangulation<dim>> own;
    const parallel::distributed::Triangulation<dim>           *checked = &mesh;
    if (scene.global_refinements > 0 || !scene.refinement_boxes.empty() || scene.distortion > 0.)
      {
        Scene<dim> coarse_scene         = scene;
        coarse_scene.global_refinements = 0;
        coarse_scene.refinement_boxes.clear();
        coarse_scene.distortion = 0.;
        own = std::make_unique<parallel::distributed::Triangulation<dim>>(comm);
        create_scene_mesh(coarse_scene, *own);
        checked = own.get();
      }
    else
      create_scene_mesh(scene, mesh);
    const auto &coarse = *checked;
    check_value_ranges(coarse);
    check_boundary_ids(coarse);
    inclined_supports.initialize(coarse, boundary_conditions.rollers, contact_parameters.pairs);
    check_contact_pairs(coarse);
    // Warnings, printed one a line (each "Warning: ... .").
    const std::string memory = check_memory_estimate(coarse);
    const std::string held   = loads_held_by_supports(coarse, boundary_conditions);
    return memory.empty() ? held : held.empty() ? memory : memory + ".\nWarning: " + held;
  }

  template <int dim>
  void
  InputChecks<dim>::check_boundary_ids(const Triangulation<dim> &coarse) const
  {
    // A boundary id that no face carries would hold, load or couple nothing,
    // silently: the whole body free, a load lost, a contact pair without
    // faces. Typical of a Gmsh mesh saved without physical surfaces, or whose
    // tagged surfaces are not those of the volumes.
    std::vector<std::pair<std::string, types::boundary_id>> named;
    for (const auto &c : boundary_conditions.displacements)
      named.emplace_back(c.key, c.boundary_id);
    for (const auto id : boundary_conditions.rollers)
      named.emplace_back("Boundary conditions/Rollers", id);
    for (const auto &c : boundary_conditions.pressures)
      named.emplace_back("Boundary conditions/Pressure", c.boundary_id);
    for (const auto &c : boundary_conditions.tractions)
      named.emplace_back("Boundary conditions/Traction", c.boundary_id);
    for (const auto &pair : contact_parameters.pairs)
      {
        const std::string text = std::to_string(static_cast<unsigned int>(pair.slave)) + ": " +
                                 std::to_string(static_cast<unsigned int>(pair.master));
        named.emplace_back("Contact/Pairs: the slave of pair '" + text + "'", pair.slave);
        named.emplace_back("Contact/Pairs: the master of pair '" + text + "'", pair.master);
      }
    for (const auto &pair : contact_parameters.tied_pairs)
      {
        const std::string text = std::to_string(static_cast<unsigned int>(pair.slave)) + ": " +
                                 std::to_string(static_cast<unsigned int>(pair.master));
        named.emplace_back("Contact/Tied pairs: the slave of pair '" + text + "'", pair.slave);
        named.emplace_back("Contact/Tied pairs: the master of pair '" + text + "'", pair.master);
      }

    const std::vector<types::boundary_id> ids = coarse.get_boundary_ids();
    for (const auto &[key, id] : named)
      {
        if (std::find(ids.begin(), ids.end(), id) != ids.end())
          continue;
        std::string carried;
        for (const auto other : ids)
          carried +=
            (carried.empty() ? "" : ", ") + std::to_string(static_cast<unsigned int>(other));
        std::string message = key + ": boundary id " +
                              std::to_string(static_cast<unsigned int>(id)) +
                              " is on no face of the mesh; its boundary faces carry " +
                              (ids.size() == 1 ? "the id " : "the ids ") + carried +
                              (scene.type == "mesh file" && ids.front() == 0 ?
                                 " (0: the faces without a physical tag)." :
                                 ".");
        if (scene.type == "mesh file")
          {
            const std::string surface = dim == 3 ? "surface" : "curve";
            message += " In a Gmsh mesh a face gets a boundary id from the physical tag "
                       "of its " +
                       surface + " (Physical " + (dim == 3 ? "Surface" : "Curve") +
                       "); a mesh saved without one, or "
                       "whose tagged " +
                       surface +
                       "s are not those the cells were meshed "
                       "on (a duplicate of a " +
                       surface +
                       ", e.g. with the built-in kernel "
                       "and Geometry.AutoCoherence = 0: run Coherence;), has none.";
          }
        AssertThrow(false, ExcMessage(message));
      }
  }

  template <int dim>
  void
  InputChecks<dim>::check_contact_pairs(const Triangulation<dim> &tria) const
  {
    // A support on a whole slave surface acts on the DoFs that the contact
    // (or tying) constraints set: the two conflict, and a normal one made
    // every node inactive and stopped as "no contact ... nothing held the
    // loaded body". A support under the contact is the master's side.
    const auto refuse_support_on = [&](const auto &pairs, const std::string &pairs_key) {
      for (const auto &pair : pairs)
        for (const auto &c : boundary_conditions.displacements)
          AssertThrow(c.boundary_id != pair.slave,
                      ExcMessage(c.key + ": boundary " +
                                 std::to_string(static_cast<unsigned int>(c.boundary_id)) +
                                 " is the slave surface of " + pairs_key + " '" +
                                 std::to_string(static_cast<unsigned int>(pair.slave)) + ": " +
                                 std::to_string(static_cast<unsigned int>(pair.master)) +
                                 "', whose nodes the contact constraints move; a support "
                                 "there conflicts with them. Hold the body elsewhere, or "
                                 "swap the pair so that the supported surface is the "
                                 "master."));
    };
    refuse_support_on(contact_parameters.pairs, "Contact/Pairs");
    refuse_support_on(contact_parameters.tied_pairs, "Contact/Tied pairs");

    // Mortar contact needs two bodies: a surface in contact with another
    // surface of its own body would be self-contact, which the mortar
    // interface does not implement; it used to be accepted and fail later
    // as a "load that separates the bodies".
    for (const auto &pair : contact_parameters.pairs)
      for (const auto body : bodies_of_surface(tria, pair.slave))
        AssertThrow(bodies_of_surface(tria, pair.master).count(body) == 0,
                    ExcMessage("Contact/Pairs: pair '" +
                               std::to_string(static_cast<unsigned int>(pair.slave)) + ": " +
                               std::to_string(static_cast<unsigned int>(pair.master)) +
                               "': both surfaces belong to body " +
                               std::to_string(static_cast<unsigned int>(body)) +
                               " (material id); a contact pair joins surfaces of two "
                               "different bodies (self-contact is not implemented)."));
  }

  template <int dim>
  std::string
  InputChecks<dim>::refinement_keys() const
  {
    std::vector<std::string> keys;
    if (scene.global_refinements > 0)
      keys.push_back("Geometry/Global refinements = " + std::to_string(scene.global_refinements));
    if (!scene.refinement_boxes.empty())
      keys.push_back("Geometry/Local refinements");
    if (keys.empty())
      keys.push_back(scene.type == "hertz cylinder" ?
                       "Geometry/Hertz cylinder/Cylinder refinements and Contact refinements" :
                     scene.type == "hertz sphere" ?
                       "Geometry/Hertz sphere/Sphere refinements and Plate refinements" :
                     scene.type == "contact blocks" ?
                       "Geometry/Contact blocks/Lower cells and Upper cells" :
                       "Geometry/Mesh file");
    std::string text = keys[0];
    for (unsigned int k = 1; k < keys.size(); ++k)
      text += " with " + keys[k];
    return text;
  }

  template <int dim>
  std::string
  InputChecks<dim>::check_memory_estimate(
    const parallel::distributed::Triangulation<dim> &coarse) const
  {
    // Uniform refinement multiplies the cells by 2^dim; a box multiplies the
    // cells inside it by 2^dim per round (its 2:1 balance adds a few more).
    const double per_refinement = std::pow(2., dim);
    const double refined        = std::pow(per_refinement, scene.global_refinements);
    double       cells          = coarse.n_global_active_cells() * refined;
    for (const auto &box : scene.refinement_boxes)
      {
        double inside = 0.;
        for (const auto &cell : coarse.active_cell_iterators())
          if (cell->is_locally_owned())
            inside += fraction_inside<dim>(cell, box);
        inside = Utilities::MPI::sum(inside, comm) * refined;
        cells += inside * (std::pow(per_refinement, box.rounds) - 1.);
      }
    // dim DoFs per node, and about degree^dim nodes per cell.
    const double    dofs  = dim * std::pow(degree, dim) * cells;
    const double    bytes = estimated_memory(dofs, Utilities::MPI::n_mpi_processes(comm));
    AvailableMemory available;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      available = available_memory();
    available.bytes  = Utilities::MPI::broadcast(comm, available.bytes, 0);
    available.source = Utilities::MPI::broadcast(comm, available.source, 0);
    if (!(available.bytes > 0.))
      return "";

    std::ostringstream estimate;
    estimate << refinement_keys() << ": the mesh will have about " << significant(cells, 2)
             << " cells and " << significant(dofs, 2) << " DoFs (Q" << degree
             << "), which need about " << format_bytes(bytes)
             << " of memory (about 4 kB per DoF, measured), ";
    AssertThrow(bytes <= available.bytes,
                ExcMessage(estimate.str() + "more than the " + format_bytes(available.bytes) +
                           " available (" + available.source +
                           "). Refine less: each refinement multiplies the cells by " +
                           significant(per_refinement, 2) + "."));
    if (bytes > 0.5 * available.bytes)
      return estimate.str() + "more than half of the " + format_bytes(available.bytes) +
             " available (" + available.source + ")";
    return "";
  }

  template <int dim>
  std::string
  InputChecks<dim>::memory_shortage(const unsigned int cycle,
                                    const double       old_dofs,
                                    const double       new_dofs) const
  {
    AvailableMemory available;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      available = available_memory();
    available.bytes     = Utilities::MPI::broadcast(comm, available.bytes, 0);
    available.source    = Utilities::MPI::broadcast(comm, available.source, 0);
    available.whole_run = Utilities::MPI::broadcast(comm, available.whole_run, 0);
    if (!(available.bytes > 0.))
      return "";
    const unsigned int processes = Utilities::MPI::n_mpi_processes(comm);
    const double       needed    = estimated_memory(new_dofs, processes);
    // What the run may reach: the figure itself when it is the run's whole
    // budget, else what is still free beyond what the finished cycle holds.
    const double budget = available.whole_run ?
                            available.bytes :
                            available.bytes + estimated_memory(old_dofs, processes);
    if (needed <= budget)
      return "";
    return "the mesh of cycle " + std::to_string(cycle) + " has " + significant(new_dofs, 2) +
           " DoFs, which need about " + format_bytes(needed) +
           " of memory (about 4 kB per DoF, measured), more than the " + format_bytes(budget) +
           " this run may use (" + available.source +
           "). The adaptive loop stops here, before the memory runs out; the results of "
           "cycle " +
           std::to_string(cycle - 1) +
           " are kept. Allow fewer cells (Refinement/Maximum cells) or more memory.";
  }

  template class InputChecks<2>;
  template class InputChecks<3>;
} // namespace contact_fem
