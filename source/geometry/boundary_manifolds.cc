#include <deal.II/base/utilities.h>
#include <deal.II/grid/manifold_lib.h>

#include <contact_fem/core/format.h>
#include <contact_fem/geometry/boundary_manifolds.h>
#include <contact_fem/geometry/mesh_file.h>
#include <contact_fem/core/parameters.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>

namespace contact_fem
{
  namespace
  {
    /// Relative distance from its surface up to which a vertex counts as on
    /// it: far above the round-off of written coordinates (Kratos' 6-digit
    /// meshes: 1e-6), far below a wrong centre or radius.
    constexpr double on_surface_tolerance = 1e-4;

    std::string
    number(const double value, const int digits = 8)
    {
      std::ostringstream text;
      text << std::setprecision(digits) << (std::abs(value) < 1e-300 ? 0. : value);
      return text.str();
    }

    /// The forms of an entry in @p dim dimensions, for messages.
    std::string
    expected_forms(const unsigned int dim)
    {
      return dim == 2 ? "'id: circle cx, cy, R' (centre and radius R > 0)" :
                        "'id: sphere cx, cy, cz, R' or 'id: cylinder px, py, pz, dx, dy, "
                        "dz, R' (a point on the axis, its direction, the radius R > 0)";
    }

    /// The numbers of 'a, b, c'; false if one is not a finite number.
    bool
    parse_numbers(const std::string &text, std::vector<double> &values)
    {
      values.clear();
      try
        {
          for (const std::string &entry : Utilities::split_string_list(text, ','))
            {
              std::size_t end = 0;
              values.push_back(std::stod(entry, &end));
              if (end != entry.size() || !std::isfinite(values.back()))
                return false;
            }
        }
      catch (...)
        {
          return false;
        }
      return true;
    }

    /// The boundary faces of @p coarse with @p id: their distinct vertices.
    template <int dim>
    std::vector<Point<dim>>
    boundary_vertices(const Triangulation<dim> &coarse, const types::boundary_id id)
    {
      std::set<unsigned int> indices;
      for (const auto &cell : coarse.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == id)
            for (unsigned int v = 0; v < cell->face(f)->n_vertices(); ++v)
              indices.insert(cell->face(f)->vertex_index(v));
      std::vector<Point<dim>> points;
      for (const unsigned int v : indices)
        points.push_back(coarse.get_vertices()[v]);
      return points;
    }

    /// What the vertices of a boundary do fit, for the message about a
    /// surface they do not lie on.
    template <int dim>
    std::string
    fitted_surface(const BoundaryManifold<dim> &m, const std::vector<Point<dim>> &points)
    {
      if (m.kind == "cylinder")
        return "";
      Point<dim> centre;
      double     radius = 0., deviation = 0.;
      if (!fit_sphere(points, centre, radius, deviation) ||
          deviation > on_surface_tolerance * radius)
        return " Its vertices do not lie on one " + m.kind +
               " (a flat boundary, or several "
               "arcs: give each its own boundary id).";
      std::string text = std::to_string(m.boundary_id) + ": " + m.kind + " ";
      // In the user's coordinates (the mesh may be computed moved).
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double c = centre[d] + message_origin[d];
          text += number(std::abs(c) < 1e-12 * radius ? 0. : c) + ", ";
        }
      return " Its vertices lie on '" + text + number(radius) + "'.";
    }
  } // namespace

  template <int dim>
  double
  BoundaryManifold<dim>::distance_from_surface(const Point<dim> &p) const
  {
    Tensor<1, dim> r = p - centre;
    if (kind == "cylinder")
      r -= (r * axis) * axis;
    return r.norm() - radius;
  }

  template <int dim>
  Point<dim>
  BoundaryManifold<dim>::closest_point(const Point<dim> &p) const
  {
    Tensor<1, dim> r = p - centre;
    if (kind == "cylinder")
      r -= (r * axis) * axis;
    return p + (radius / r.norm() - 1.) * r;
  }

  template <int dim>
  std::unique_ptr<Manifold<dim>>
  BoundaryManifold<dim>::make_manifold() const
  {
    if (kind == "circle")
      return std::make_unique<PolarManifold<dim>>(centre);
    if (kind == "sphere")
      return std::make_unique<SphericalManifold<dim>>(centre);
    if constexpr (dim == 3)
      return std::make_unique<CylindricalManifold<dim>>(axis, centre);
    AssertThrow(false, ExcInternalError());
    return nullptr;
  }

  template <int dim>
  std::vector<BoundaryManifold<dim>>
  parse_boundary_manifolds(const std::string &text, const std::string &key)
  {
    std::vector<BoundaryManifold<dim>> result;
    for (const auto &[id, surface] : split_key_value_list(text, key))
      {
        BoundaryManifold<dim> m;
        m.boundary_id    = parse_boundary_id(id, key);
        m.entry          = id + ": " + surface;
        const auto space = surface.find_first_of(" \t");
        m.kind           = surface.substr(0, space);
        std::vector<double> v;
        const bool          numbers_ok =
          space != std::string::npos && parse_numbers(surface.substr(space + 1), v);
        const std::size_t n     = (dim == 2 && m.kind == "circle")   ? 3 :
                                  (dim == 3 && m.kind == "sphere")   ? 4 :
                                  (dim == 3 && m.kind == "cylinder") ? 7 :
                                                                       0;
        bool              valid = n > 0 && numbers_ok && v.size() == n && v.back() > 0.;
        if (valid)
          {
            for (unsigned int d = 0; d < dim; ++d)
              m.centre[d] = v[d];
            m.radius = v.back();
            if (m.kind == "cylinder")
              {
                for (unsigned int d = 0; d < dim; ++d)
                  m.axis[d] = v[dim + d];
                valid = m.axis.norm() > 0.;
                if (valid)
                  m.axis /= m.axis.norm();
              }
          }
        AssertThrow(valid, ExcMessage(key + ": entry '" + m.entry + "' is not of the form " +
                                      expected_forms(dim) + "."));
        for (const auto &other : result)
          AssertThrow(other.boundary_id != m.boundary_id,
                      ExcMessage(key + ": boundary " + id + " has two entries ('" + other.entry +
                                 "' and '" + m.entry + "')."));
        result.push_back(m);
      }
    return result;
  }

  template <int dim>
  void
  check_boundary_manifolds(const std::vector<BoundaryManifold<dim>> &manifolds,
                           const Triangulation<dim>                 &coarse,
                           const std::string                        &key)
  {
    for (const auto &m : manifolds)
      {
        const std::vector<Point<dim>> points = boundary_vertices(coarse, m.boundary_id);
        AssertThrow(!points.empty(), ExcMessage(key + ": entry '" + m.entry +
                                                "': the mesh has no boundary "
                                                "faces with id " +
                                                std::to_string(m.boundary_id) + "."));
        const Point<dim> *worst = &points[0];
        for (const auto &p : points)
          if (std::abs(m.distance_from_surface(p)) > std::abs(m.distance_from_surface(*worst)))
            worst = &p;
        const double off = m.distance_from_surface(*worst);
        AssertThrow(std::abs(off) <= on_surface_tolerance * m.radius,
                    ExcMessage(key + ": entry '" + m.entry + "': vertex " +
                               coordinates_text(*worst) + " of boundary " +
                               std::to_string(m.boundary_id) + " lies " + number(std::abs(off), 3) +
                               (off > 0. ? " outside" : " inside") + " the " + m.kind +
                               " (allowed: " + number(on_surface_tolerance) +
                               " R = " + number(on_surface_tolerance * m.radius, 3) +
                               "); a wrong centre or radius would move the boundary "
                               "under refinement." +
                               fitted_surface(m, points)));
      }
  }

  template <int dim>
  void
  place_new_vertices_on_manifolds(const std::vector<BoundaryManifold<dim>> &manifolds,
                                  const unsigned int                        first_new_vertex,
                                  Triangulation<dim>                       &coarse)
  {
    std::vector<bool> moved(coarse.n_vertices(), false);
    for (const auto &cell : coarse.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        for (const auto &m : manifolds)
          if (face->at_boundary() && face->boundary_id() == m.boundary_id)
            for (unsigned int v = 0; v < face->n_vertices(); ++v)
              if (const unsigned int i = face->vertex_index(v); i >= first_new_vertex && !moved[i])
                {
                  face->vertex(v) = m.closest_point(face->vertex(v));
                  moved[i]        = true;
                }
  }

  template <int dim>
  void
  set_manifold_ids(const std::vector<BoundaryManifold<dim>> &manifolds,
                   const bool                                curved_interior,
                   Triangulation<dim>                       &coarse)
  {
    // Entry k of the list -> manifold id k + 1.
    std::map<types::boundary_id, types::manifold_id> ids;
    for (unsigned int k = 0; k < manifolds.size(); ++k)
      ids[manifolds[k].boundary_id] = k + 1;
    std::set<types::material_id> curved_bodies;
    for (const auto &cell : coarse.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && ids.count(cell->face(f)->boundary_id()))
          curved_bodies.insert(cell->material_id());
    // Interior first: set_all_manifold_ids also sets the boundary faces,
    // which get their own ids after.
    if (curved_interior)
      for (const auto &cell : coarse.active_cell_iterators())
        if (curved_bodies.count(cell->material_id()))
          cell->set_all_manifold_ids(interior_manifold_id);
    for (const auto &cell : coarse.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && ids.count(cell->face(f)->boundary_id()))
          cell->face(f)->set_all_manifold_ids(ids[cell->face(f)->boundary_id()]);
  }

  template <int dim>
  void
  attach_manifolds(const std::vector<BoundaryManifold<dim>> &manifolds,
                   const bool                                curved_interior,
                   Triangulation<dim>                       &tria)
  {
    for (unsigned int k = 0; k < manifolds.size(); ++k)
      tria.set_manifold(k + 1, *manifolds[k].make_manifold());
    if (curved_interior && !manifolds.empty())
      {
        TransfiniteInterpolationManifold<dim> interior;
        interior.initialize(tria);
        tria.set_manifold(interior_manifold_id, interior);
      }
  }

  template <int dim>
  void
  check_refinement_on_manifolds(const std::vector<BoundaryManifold<dim>> &manifolds,
                                const bool                                curved_interior,
                                const Triangulation<dim>                 &coarse,
                                const std::string                        &key)
  {
    if (manifolds.empty())
      return;
    Triangulation<dim> trial;
    trial.copy_triangulation(coarse);
    attach_manifolds(manifolds, curved_interior, trial);
    for (const auto &cell : trial.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->manifold_id() != numbers::flat_manifold_id &&
            cell->face(f)->manifold_id() != interior_manifold_id)
          cell->set_refine_flag();
    const std::string what =
      ": a coarse cell at a curved boundary is too distorted for its curved face (e.g. a "
      "thin cell along a concave arc, or straight edges that cross the arc). Mesh that "
      "region with more, better shaped coarse cells.";
    try
      {
        trial.execute_coarsening_and_refinement();
      }
    catch (...)
      {
        AssertThrow(false,
                    ExcMessage(key + ": refining the mesh on these manifolds failed" + what));
      }
    unsigned int n_inverted = 0;
    Point<dim>   first;
    for (const auto &cell : trial.active_cell_iterators())
      if (cell->level() > 0 && is_inverted<dim>(cell) && n_inverted++ == 0)
        first = cell->center();
    AssertThrow(n_inverted == 0,
                ExcMessage(key + ": refining the mesh on these manifolds inverts " +
                           std::to_string(n_inverted) + " cell(s), the first near " +
                           coordinates_text(first) + what));
  }

  template struct BoundaryManifold<2>;
  template struct BoundaryManifold<3>;
  template std::vector<BoundaryManifold<2>>
  parse_boundary_manifolds<2>(const std::string &, const std::string &);
  template std::vector<BoundaryManifold<3>>
  parse_boundary_manifolds<3>(const std::string &, const std::string &);
  template void
  check_boundary_manifolds<2>(const std::vector<BoundaryManifold<2>> &,
                              const Triangulation<2> &,
                              const std::string &);
  template void
  check_boundary_manifolds<3>(const std::vector<BoundaryManifold<3>> &,
                              const Triangulation<3> &,
                              const std::string &);
  template void
  place_new_vertices_on_manifolds<2>(const std::vector<BoundaryManifold<2>> &,
                                     unsigned int,
                                     Triangulation<2> &);
  template void
  place_new_vertices_on_manifolds<3>(const std::vector<BoundaryManifold<3>> &,
                                     unsigned int,
                                     Triangulation<3> &);
  template void
  set_manifold_ids<2>(const std::vector<BoundaryManifold<2>> &, bool, Triangulation<2> &);
  template void
  set_manifold_ids<3>(const std::vector<BoundaryManifold<3>> &, bool, Triangulation<3> &);
  template void
  attach_manifolds<2>(const std::vector<BoundaryManifold<2>> &, bool, Triangulation<2> &);
  template void
  attach_manifolds<3>(const std::vector<BoundaryManifold<3>> &, bool, Triangulation<3> &);
  template void
  check_refinement_on_manifolds<2>(const std::vector<BoundaryManifold<2>> &,
                                   bool,
                                   const Triangulation<2> &,
                                   const std::string &);
  template void
  check_refinement_on_manifolds<3>(const std::vector<BoundaryManifold<3>> &,
                                   bool,
                                   const Triangulation<3> &,
                                   const std::string &);
} // namespace contact_fem
