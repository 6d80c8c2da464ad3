// Geometry/Manifolds: the true geometry of curved boundaries of a mesh
// file (circles, spheres, cylinders), so that refinement puts new vertices
// on the curve instead of on the chords of the coarse mesh.
#ifndef contact_fem_boundary_manifolds_h
#define contact_fem_boundary_manifolds_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/tria.h>

#include <memory>
#include <string>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /**
   * The surface that the faces of one boundary id lie on: 'circle' (2D,
   * centre and radius), 'sphere' (3D, centre and radius) or 'cylinder' (3D,
   * a point on the axis, its direction and the radius).
   *
   * Implemented in source/boundary_manifolds.cc.
   */
  template <int dim>
  struct BoundaryManifold
  {
    types::boundary_id boundary_id = 0;
    std::string        kind;
    Point<dim>         centre; ///< the centre, or a point on the axis
    Tensor<1, dim>     axis;   ///< cylinder only: unit direction of the axis
    double             radius = 0.;
    std::string        entry; ///< as written, for messages

    /// Distance of @p p from the centre (the axis) minus the radius.
    double
    distance_from_surface(const Point<dim> &p) const;

    /// The point of the surface nearest @p p (along the radius).
    Point<dim>
    closest_point(const Point<dim> &p) const;

    /// The deal.II manifold: PolarManifold (circle, as the built-in Hertz
    /// disc), SphericalManifold or CylindricalManifold.
    std::unique_ptr<Manifold<dim>>
    make_manifold() const;
  };

  /// Manifold ids: the entry k of the list has k + 1; the interior of
  /// every body with a curved boundary has 0 (a transfinite interpolation).
  constexpr types::manifold_id interior_manifold_id = 0;

  /// Parses 'id: circle cx, cy, R; ...' (2D) or 'id: sphere cx, cy, cz, R;
  /// id: cylinder px, py, pz, dx, dy, dz, R; ...' (3D); throws naming
  /// @p key, the entry and what was expected.
  template <int dim>
  std::vector<BoundaryManifold<dim>>
  parse_boundary_manifolds(const std::string &text, const std::string &key);

  /**
   * Checks @p manifolds against the coarse mesh @p coarse read from
   * @p file: every boundary id has faces, and every vertex of those faces
   * lies on its surface within 1e-4 of the radius (a wrong centre or
   * radius would bend the mesh without a word). Throws naming @p key and
   * the entry, with the circle (sphere) that the vertices do fit if any.
   */
  template <int dim>
  void
  check_boundary_manifolds(const std::vector<BoundaryManifold<dim>> &manifolds,
                           const Triangulation<dim>                 &coarse,
                           const std::string                        &key);

  /**
   * Moves the vertices of @p coarse from @p first_new_vertex on (those that
   * the split of a mesh file made: MeshFileInfo) that lie on a boundary
   * face of an entry of @p manifolds onto its surface: the split puts them
   * on the straight faces between the file's nodes, inside the curve by
   * the sag of the chord.
   */
  template <int dim>
  void
  place_new_vertices_on_manifolds(const std::vector<BoundaryManifold<dim>> &manifolds,
                                  unsigned int                              first_new_vertex,
                                  Triangulation<dim>                       &coarse);

  /**
   * Sets the manifold ids of @p coarse: the faces of each boundary id get
   * that of their entry; with @p curved_interior every cell of a body
   * (material id) with such a face, and all its lines and faces, first get
   * interior_manifold_id (as the built-in Hertz disc: the interior then
   * follows the curved boundary under refinement, and the quadratic
   * mapping is conforming at hanging nodes).
   */
  template <int dim>
  void
  set_manifold_ids(const std::vector<BoundaryManifold<dim>> &manifolds,
                   const bool                                curved_interior,
                   Triangulation<dim>                       &coarse);

  /// Attaches the manifold objects to @p tria, whose coarse cells carry the
  /// ids of set_manifold_ids(): the transfinite interpolation is charted on
  /// the coarse cells of @p tria itself.
  template <int dim>
  void
  attach_manifolds(const std::vector<BoundaryManifold<dim>> &manifolds,
                   const bool                                curved_interior,
                   Triangulation<dim>                       &tria);

  /**
   * Refines a copy of @p coarse (ids set) once where it touches a curved
   * boundary and throws naming @p key if a child cell is inverted or the
   * transfinite chart fails: a coarse cell too distorted for its curved
   * face (e.g. a thin cell against a concave arc).
   */
  template <int dim>
  void
  check_refinement_on_manifolds(const std::vector<BoundaryManifold<dim>> &manifolds,
                                const bool                                curved_interior,
                                const Triangulation<dim>                 &coarse,
                                const std::string                        &key);
} // namespace contact_fem

#endif
