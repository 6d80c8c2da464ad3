// Gmsh mesh files: reading with messages that name the file and what is
// wrong, and checks of the coarse mesh that deal.II's reader does not make.
#ifndef contact_fem_mesh_file_h
#define contact_fem_mesh_file_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /// An entry of a Gmsh file's $PhysicalNames.
  struct PhysicalName
  {
    int         dimension = 0;
    int         tag       = 0;
    std::string name;
  };

  /// What read_gmsh() found beside the mesh.
  struct MeshFileInfo
  {
    /// The origin of the computing frame in the file's coordinates
    /// (choose_frame_origin(); zero for a mesh near the origin).
    Point<3>                  frame_origin;
    std::vector<PhysicalName> physical_names;
    /// A mesh with triangles, tetrahedra or prisms is split into
    /// quadrilaterals or hexahedra (mesh_split.h): what was split ("24
    /// tetrahedra split into 96 hexahedra"), and the first vertex the split
    /// made (the vertices before it are the file's nodes). Empty and
    /// invalid for a mesh read as it is.
    std::string split_note;
    /// Boundary elements on nodes no cell uses (Gmsh without coherence),
    /// given the faces at their coordinates: how many; empty if none.
    std::string  orphan_note;
    unsigned int first_new_vertex = numbers::invalid_unsigned_int;
  };

  /**
   * Reads the Gmsh file @p file into @p coarse after a scan of its text:
   * ASCII (MSH 1, 2.x, 4.x), complete (every section closed, the announced
   * numbers of nodes and elements present), first-order quadrilaterals or
   * triangles (dim = 2), hexahedra, tetrahedra or prisms (dim = 3) as
   * cells, no pyramids, in 2D nodes in one plane z = const, cells with a
   * positive Jacobian at every corner (or at none: the opposite turn,
   * which deal.II reorders). Each finding throws with a message naming
   * the file (and the line, the element) and the fix; deal.II's reader
   * would report a binary file as "The string <\x01", a 3D mesh as an
   * unknown element type, and take collapsed or twisted hexahedra.
   *
   * A mesh with triangles, tetrahedra or prisms is split into
   * quadrilaterals or hexahedra (mesh_split.h); the returned split_note
   * and first_new_vertex say so.
   *
   * A mesh far from the origin is read moved next to it (ModelFrame): the
   * returned frame_origin says by how much.
   *
   * Implemented in source/mesh_file.cc.
   */
  template <int dim>
  MeshFileInfo
  read_gmsh(const std::string &file, Triangulation<dim> &coarse);

  /**
   * Throws if a body (material id) of @p coarse is cut by an internal
   * crack: two of its boundary faces lie on top of each other (coincident
   * vertices that the cells on either side do not share) and at least one
   * of them has no boundary id (0: untagged in the mesh file). Such a body
   * deforms as if cut, without any message (a Gmsh mesh of several surfaces
   * without Coherence). Coincident vertices of different bodies are how
   * contact pairs are meshed, and tagged coincident faces of one body are
   * taken to be a deliberate internal surface: both pass. O(n log n): an
   * R-tree of the boundary vertices.
   */
  template <int dim>
  void
  check_unmerged_vertices(const Triangulation<dim> &coarse, const std::string &file);

  /**
   * Throws if @p coarse folds over itself: the two cells of an internal
   * face lie on the same side of it. A tangled mesh (a node moved across
   * the opposite edge or face of its elements) has such inverted elements;
   * deal.II's reader reorders each one to a positive Jacobian, so the cells
   * overlap their neighbours and the run solved a body that is not the
   * file's, without a word. Elements listed in the other turn (every
   * element, or some of them) are no fold and pass. @p origin is added to
   * the position in the message (the file's coordinates).
   */
  template <int dim>
  void
  check_folded_cells(const Triangulation<dim> &coarse,
                     const std::string        &file,
                     const Point<3>           &origin);

  /// A boundary id whose faces look like a polygonal approximation of a
  /// curved surface (see find_polygonal_boundaries()).
  template <int dim>
  struct PolygonalBoundary
  {
    types::boundary_id id        = 0;
    unsigned int       n_kinks   = 0;                  ///< joints turning by a small nonzero angle
    unsigned int       n_joints  = 0;                  ///< joints of two faces of this id
    double             min_angle = 0., max_angle = 0.; ///< of the kinks, radians
    /// Whether the vertices fit one circle (sphere), with these:
    bool       fits_sphere = false;
    Point<dim> centre;
    double     radius = 0.;
    /// 3D: whether every face normal is perpendicular to one direction (an
    /// extruded curve) and the vertices lie on a cylinder about it, with
    /// this unit axis through the point of the axis nearest the origin,
    /// and this radius. Vertices on two parallel circles also fit a sphere
    /// (an extrusion by one layer): the cylinder is the surface then.
    bool           fits_cylinder = false;
    Point<dim>     axis_point;
    Tensor<1, dim> axis;
    double         cylinder_radius = 0.;
  };

  /**
   * The boundary ids of @p coarse (except @p skip) along which neighbouring
   * faces of the same id turn by a small nonzero angle (0.006 to 30
   * degrees) at more than half of their joints, and at least at three: a
   * polygon standing for a curve. Flat boundaries (no turn) and true
   * corners (large turns) do not count. Each comes with the circle (2D) or
   * sphere (3D) fitted to its vertices, if they lie on one, and in 3D with
   * the cylinder, if its faces are those of an extruded curve.
   */
  template <int dim>
  std::vector<PolygonalBoundary<dim>>
  find_polygonal_boundaries(const Triangulation<dim>              &coarse,
                            const std::vector<types::boundary_id> &skip);

  /**
   * Least-squares circle (sphere) through @p points (the algebraic fit:
   * |x|^2 = 2 c.x + k, exact for points on a sphere). Returns false if the
   * points do not determine one (fewer than dim + 1, or collinear);
   * @p max_deviation is the largest | |x - c| - r |.
   */
  template <int dim>
  bool
  fit_sphere(const std::vector<Point<dim>> &points,
             Point<dim>                    &centre,
             double                        &radius,
             double                        &max_deviation);

  /// Whether @p cell is inverted or degenerate: a non-positive Jacobian at a
  /// corner (2D), a non-positive measure (3D), relative to its size.
  template <int dim>
  bool
  is_inverted(const typename Triangulation<dim>::cell_iterator &cell);
} // namespace contact_fem

#endif
