// The geometry of a scene: built-in meshes or a Gmsh file, with the bodies
// named by material id and the surfaces by boundary id.
#ifndef contact_fem_scene_h
#define contact_fem_scene_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>

#include <contact_fem/geometry/boundary_manifolds.h>
#include <contact_fem/geometry/mesh_file.h>
#include <contact_fem/geometry/model_frame.h>

#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /**
   * Builds the coarse mesh of a scene on a parallel::distributed::Triangulation.
   *
   * Built-in geometries and their ids (the shipped .prm files rely on them):
   *
   * "hertz cylinder": a half-disc of radius R (material 1) whose lowest point
   * touches the top of a plate (material 2) at the origin of x.
   * @code
   *        1 (flat top, loaded)
   *   ______________________
   *   \                    /
   *    \  3 (arc, slave)  /      disc centre (0, t + R)
   *      \______________/
   *   ___________o__________    4 (plate top, master), contact at (0, t)
   *  |           2          |   plate [-w, w] x [0, t], base 2 fixed
   * @endcode
   * The mesh is refined toward the contact zone: cells closer to the
   * segment |x| < "Refinement half width" of the plate top than "Grading
   * factor" times their diameter are refined, "Contact refinements" times in the disc and "Plate
   * contact refinements" times in the plate.
   *
   * "hertz sphere" (3D): a quarter of a hemisphere of radius R (material 1),
   * curved side down, whose lowest point touches the top of a quarter plate
   * (material 2) at the origin of x and y; the planes x = 0 and y = 0 are
   * planes of symmetry of the full hemisphere on its plate.
   * @code
   *   z  ________________ 1 (flat top z = t + R, loaded)
   *   ^ |              /
   *   | |5, 6        /   3 (curved surface, slave; sphere centre (0, 0, t + R))
   *   | |_______ _ /
   *   | o________________ 4 (plate top z = t, master), contact at (0, 0, t)
   *   | |       2        |   plate [0, w] x [0, w] x [0, t], base 2
   *   +-----------------> x
   * @endcode
   * 5: the symmetry plane x = 0, 6: the symmetry plane y = 0 (both bodies);
   * 0: the outer sides of the plate. The hemisphere's coarse mesh is one
   * inner block and three cells under the three patches of its curved
   * surface; the patch around the lowest point reaches "Pole patch angle"
   * from it (45 degrees: three patches alike; less: finer cells at the
   * contact for the same number of cells). "Sphere refinements" and "Plate
   * refinements" refine each body uniformly; then "Contact refinements"
   * graded rounds refine the hemisphere toward the disc of radius
   * "Refinement radius" on the plate top, as for the Hertz cylinder.
   *
   * "contact blocks": a lower block [0, W] x [0, H] (material 2, top = 4,
   * bottom = 2, left side = 6) and an upper block [0, W] x [H + gap, 2H + gap]
   * (material 1, bottom = 3, top = 1, left side = 5), meshed with different
   * numbers of cells (non-matching interface). Other faces have id 0.
   *
   * "mesh file": a Gmsh .msh file; bodies and surfaces carry the physical
   * tags of the file as material and boundary ids. The file is read and
   * checked in parse_parameters() (so --validate checks it too): ASCII,
   * complete, quadrilaterals (hexahedra), no body cut by unmerged nodes,
   * and the surfaces of Geometry/Manifolds on their circles (spheres,
   * cylinders). Boundaries that look like polygons of a curve but have no
   * manifold are remembered for chord_warning().
   *
   * Implemented in source/scene.cc.
   */
  /// One key that a built-in scene fills in when the input does not set it.
  struct BuiltinSetting
  {
    std::string path; ///< "Subsection/Key"
    std::string value;
  };

  /// The values a built-in scene (Geometry/Type) gives its loads, supports,
  /// pairs and materials when the input does not set those keys; empty for
  /// "mesh file", which gets no load, support, pair or material it does not
  /// ask for.
  std::vector<BuiltinSetting>
  builtin_scene_settings(const std::string &type);

  /// The paths ("Subsection/Key") of builtin_scene_settings(), and whether a
  /// mesh-file scene must set them (Contact/Pairs and the Materials).
  std::vector<std::pair<std::string, bool>>
  builtin_scene_keys();

  /// The sentences of the documentation of Geometry/Type that list the
  /// values of builtin_scene_settings().
  std::string
  builtin_scene_help();

  template <int dim>
  class Scene
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    /// @p prm_directory resolves relative mesh file names.
    void
    parse_parameters(ParameterHandler &prm, const std::string &prm_directory);

    /// Creates the mesh (with global refinements) and attaches the manifolds;
    /// once per parse_parameters() for a mesh file.
    void
    create_mesh(parallel::distributed::Triangulation<dim> &tria) const;

    /// For a run that refines the mesh: a warning naming the boundaries of
    /// the mesh file that look curved but have no manifold (refinement
    /// keeps their chords), with the parameter that fixes it; empty if none.
    std::string
    chord_warning() const;

    /// Checks that the mesh has these material ids and no inverted or
    /// degenerate cells; throws with the parameter name otherwise. (Boundary
    /// ids are checked before meshing, with the key that names them:
    /// ContactProblem::check_boundary_ids().)
    static void
    check_mesh(const parallel::distributed::Triangulation<dim> &tria,
               const std::set<types::material_id>              &material_ids);

    /// Whether the mesh has curved boundaries (manifolds other than flat).
    bool
    has_curved_boundary() const
    {
      return type == "hertz cylinder" || type == "hertz sphere" || !manifolds.empty();
    }

    std::string type;
    std::string mesh_file;
    /// Where the mesh is computed (a mesh file far from the origin is moved
    /// next to it on reading); the keys of the input stay in the user's
    /// coordinates and go through it.
    ModelFrame<dim> frame;
    unsigned int    global_refinements = 0;
    double          distortion         = 0.;

    /// Geometry/Local refinements: cells whose centre lies in the box are
    /// refined 'rounds' times (after the global refinements). In the user's
    /// coordinates.
    struct RefinementBox
    {
      unsigned int rounds = 0;
      Point<dim>   lower, upper;
    };
    std::vector<RefinementBox> refinement_boxes;

    /// Refines the boxes of refinement_boxes; throws if a box holds no cell.
    void
    refine_boxes(parallel::distributed::Triangulation<dim> &tria) const;

  private:
    /// Reads and checks the mesh file into coarse_mesh; its physical names
    /// replace the ids they stand for in @p prm (PhysicalNames).
    void
    read_mesh_file(ParameterHandler &prm);
    /// Whether the cells of a body with a curved boundary follow it inside
    /// (a transfinite interpolation) or keep straight interior lines.
    bool
    curved_interior() const;
    /// The mesh file's coarse mesh with its manifolds, into @p tria.
    void
    create_from_mesh_file(parallel::distributed::Triangulation<dim> &tria) const;
    /// The built-in Hertz half-disc on its plate, graded toward the
    /// contact zone (2D).
    void
    create_hertz_mesh(parallel::distributed::Triangulation<dim> &tria) const;
    /// The built-in quarter hemisphere on its quarter plate (3D).
    void
    create_hertz_sphere_mesh(parallel::distributed::Triangulation<dim> &tria) const;
    /// The built-in stacked blocks (2D).
    void
    create_contact_blocks(parallel::distributed::Triangulation<dim> &tria) const;

  public:
    /// Geometry/Manifolds: the surfaces of boundary ids of a mesh file, in
    /// the computing frame (the entries' text in the user's coordinates).
    std::vector<BoundaryManifold<dim>> manifolds;
    /// The coarse mesh of a mesh file, read and checked by
    /// parse_parameters(), with the manifold ids set; released by
    /// create_mesh() once copied (a large mesh need not be held twice).
    mutable std::shared_ptr<Triangulation<dim>> coarse_mesh;
    /// Boundaries of the mesh file that look like polygons of a curve and
    /// have no manifold.
    std::vector<PolygonalBoundary<dim>> polygonal_boundaries;
    /// What the reader split ("24 tetrahedra split into 96 hexahedra"), or
    /// empty: the mesh file's cells were read as they are.
    std::string mesh_note;
    /// Boundary elements of the mesh file on nodes of their own, given the
    /// faces at their coordinates (MeshFileInfo::orphan_note); empty if none.
    std::string facet_note;

    struct Hertz
    {
      double       radius                = 8.;
      double       plate_half_width      = 10.;
      double       plate_thickness       = 1.;
      double       refinement_half_width = 0.5;
      unsigned int cylinder_refinements  = 2;
      unsigned int contact_refinements   = 6;
      double       grading_factor        = 4.;
      unsigned int plate_refinements     = 3;
    } hertz;

    struct HertzSphere
    {
      double       radius              = 6.1237;
      double       plate_width         = 4.;
      double       plate_thickness     = 1.;
      double       pole_patch_angle    = 45.; ///< degrees
      unsigned int sphere_refinements  = 3;
      unsigned int plate_refinements   = 0;
      unsigned int contact_refinements = 0;
      double       refinement_radius   = 2.;
      double       grading_factor      = 4.;
      double       gap                 = 0.;    ///< of the lowest point above the plate
      bool         half                = false; ///< y >= 0 only (else x, y >= 0)
    } hertz_sphere;

    struct Blocks
    {
      double       width = 1., height = 1., gap = 0.;
      unsigned int lower_cells = 3, upper_cells = 5;
    } blocks;
  };
} // namespace contact_fem

#endif
