#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <contact_fem/geometry/manifold_mapping.h>

#include <array>

namespace contact_fem
{
  namespace
  {
    /// MappingQ with its support points callable (for cells that are not
    /// charted by a transfinite interpolation).
    template <int dim>
    class ManifoldMappingQ : public MappingQ<dim>
    {
    public:
      using MappingQ<dim>::MappingQ;
      using MappingQ<dim>::compute_mapping_support_points;
    };

    /// The curved geometry of a line or face: null if it is straight (the
    /// flat id, or the transfinite interpolation, whose lines and faces
    /// inside a body are straight in the chart of the coarse cells).
    template <int dim, typename Object>
    const Manifold<dim> *
    own_manifold(const Object &object, const Triangulation<dim> &tria)
    {
      if (object->manifold_id() == numbers::flat_manifold_id)
        return nullptr;
      const Manifold<dim> &m = tria.get_manifold(object->manifold_id());
      return dynamic_cast<const TransfiniteInterpolationManifold<dim> *>(&m) ? nullptr : &m;
    }

    /// The transfinite chart of a coarse cell: its vertices and the
    /// geometry of its lines and (3D) faces.
    template <int dim>
    struct CoarseChart
    {
      static constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
      static constexpr unsigned int n_lines    = GeometryInfo<dim>::lines_per_cell;
      static constexpr unsigned int n_faces    = GeometryInfo<dim>::faces_per_cell;

      std::array<Point<dim>, n_vertices>            vertices;
      std::array<const Manifold<dim> *, n_lines>    lines;
      std::array<const Manifold<dim> *, n_faces>    faces;

      explicit CoarseChart(const typename Triangulation<dim>::cell_iterator &coarse)
      {
        const Triangulation<dim> &tria = coarse->get_triangulation();
        for (unsigned int v = 0; v < n_vertices; ++v)
          vertices[v] = coarse->vertex(v);
        for (unsigned int l = 0; l < n_lines; ++l)
          lines[l] = own_manifold(coarse->line(l), tria);
        for (unsigned int f = 0; f < n_faces; ++f)
          faces[f] = dim == 3 ? own_manifold(coarse->face(f), tria) : nullptr;
      }

      /// Product over the directions of @p fixed of the linear shape that
      /// is 1 on the side of @p corner: the blending weight of an entity.
      static double
      weight(const Point<dim> &x, const unsigned int corner, const std::array<bool, dim> &fixed)
      {
        const Point<dim> u = GeometryInfo<dim>::unit_cell_vertex(corner);
        double           w = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          if (fixed[d])
            w *= u[d] > 0.5 ? x[d] : 1. - x[d];
        return w;
      }

      /// The directions along which the vertices @p v of an entity agree.
      template <std::size_t n>
      static std::array<bool, dim>
      fixed_directions(const std::array<unsigned int, n> &v)
      {
        std::array<bool, dim> fixed;
        for (unsigned int d = 0; d < dim; ++d)
          {
            fixed[d] = true;
            for (const unsigned int i : v)
              fixed[d] = fixed[d] && GeometryInfo<dim>::unit_cell_vertex(i)[d] ==
                                       GeometryInfo<dim>::unit_cell_vertex(v[0])[d];
          }
        return fixed;
      }

      /// Line @p l at the coordinate of @p x along it.
      Point<dim>
      line_point(const unsigned int l, const Point<dim> &x) const
      {
        const std::array<unsigned int, 2> v = {{GeometryInfo<dim>::line_to_cell_vertices(l, 0),
                                                GeometryInfo<dim>::line_to_cell_vertices(l, 1)}};
        const std::array<bool, dim>       fixed = fixed_directions(v);
        double                            t     = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          if (!fixed[d])
            t = x[d];
        const std::array<Point<dim>, 2> ends    = {{vertices[v[0]], vertices[v[1]]}};
        const std::array<double, 2>     weights = {{1. - t, t}};
        if (lines[l] == nullptr)
          return weights[0] * ends[0] + weights[1] * ends[1];
        return lines[l]->get_new_point(ArrayView<const Point<dim>>(ends.data(), 2),
                                       ArrayView<const double>(weights.data(), 2));
      }

      /// Face @p f (3D) at the projection of @p x: its manifold, or the
      /// transfinite interpolation of its four lines if it is flat.
      Point<dim>
      face_point(const unsigned int f, const Point<dim> &x) const
      {
        std::array<unsigned int, 4> v;
        for (unsigned int i = 0; i < 4; ++i)
          v[i] = GeometryInfo<dim>::face_to_cell_vertices(f, i);
        std::array<bool, dim> in_face = fixed_directions(v);
        for (auto &&d : in_face)
          d = !d;
        std::array<Point<dim>, 4> corners;
        std::array<double, 4>     weights;
        for (unsigned int i = 0; i < 4; ++i)
          {
            corners[i] = vertices[v[i]];
            weights[i] = weight(x, v[i], in_face);
          }
        if (faces[f] != nullptr)
          return faces[f]->get_new_point(ArrayView<const Point<dim>>(corners.data(), 4),
                                         ArrayView<const double>(weights.data(), 4));
        Point<dim> p;
        for (unsigned int i = 0; i < 4; ++i)
          p -= weights[i] * corners[i];
        for (unsigned int k = 0; k < 4; ++k)
          {
            const unsigned int          l = GeometryInfo<dim>::face_to_cell_lines(f, k);
            std::array<bool, dim>       across;
            const std::array<bool, dim> fixed = fixed_directions(
              std::array<unsigned int, 2>{{GeometryInfo<dim>::line_to_cell_vertices(l, 0),
                                           GeometryInfo<dim>::line_to_cell_vertices(l, 1)}});
            for (unsigned int d = 0; d < dim; ++d)
              across[d] = fixed[d] && in_face[d];
            p += weight(x, GeometryInfo<dim>::line_to_cell_vertices(l, 0), across) *
                 line_point(l, x);
          }
        return p;
      }

      /// Gordon-Hall: the faces' points, minus the lines', plus the
      /// vertices' (3D); the lines' minus the vertices' (2D).
      Point<dim>
      point(const Point<dim> &x) const
      {
        Point<dim>   p;
        const double vertex_sign = dim == 2 ? -1. : 1.;
        for (unsigned int v = 0; v < n_vertices; ++v)
          p += vertex_sign * weight(x, v, fixed_directions(std::array<unsigned int, 1>{{v}})) *
               vertices[v];
        const double line_sign = dim == 2 ? 1. : -1.;
        for (unsigned int l = 0; l < n_lines; ++l)
          {
            const unsigned int a = GeometryInfo<dim>::line_to_cell_vertices(l, 0);
            const unsigned int b = GeometryInfo<dim>::line_to_cell_vertices(l, 1);
            p += line_sign * weight(x, a, fixed_directions(std::array<unsigned int, 2>{{a, b}})) *
                 line_point(l, x);
          }
        if constexpr (dim == 3)
          for (unsigned int f = 0; f < n_faces; ++f)
            {
              const Point<dim> u     = GeometryInfo<dim>::unit_cell_vertex(
                GeometryInfo<dim>::face_to_cell_vertices(f, 0));
              const double     w     = u[f / 2] > 0.5 ? x[f / 2] : 1. - x[f / 2];
              p += w * face_point(f, x);
            }
        return p;
      }
    };
  } // namespace

  template <int dim>
  std::vector<Point<dim>>
  transfinite_points(const typename Triangulation<dim>::cell_iterator &cell,
                     const std::vector<Point<dim>>                    &unit_points)
  {
    // The sub-box of the coarse cell's chart: child c of an isotropically
    // refined cell is the half along direction d given by bit d of c.
    Point<dim> lower;
    double     size   = 1.;
    auto       coarse = cell;
    for (; coarse->level() > 0; coarse = coarse->parent())
      {
        if (coarse->parent()->refinement_case() != RefinementCase<dim>::isotropic_refinement)
          return {};
        const unsigned int child = coarse->parent()->child_iterator_to_index(coarse);
        for (unsigned int d = 0; d < dim; ++d)
          lower[d] = 0.5 * (lower[d] + ((child >> d) & 1));
        size *= 0.5;
      }
    if (dynamic_cast<const TransfiniteInterpolationManifold<dim> *>(&coarse->get_manifold()) ==
        nullptr)
      return {};
    const CoarseChart<dim> chart(coarse);
    // A sphere's refinement of a face is not the sub-box (see the header).
    for (const Manifold<dim> *face : chart.faces)
      if (face != nullptr && dynamic_cast<const ChartManifold<dim> *>(face) == nullptr)
        return {};
    std::vector<Point<dim>> points;
    points.reserve(unit_points.size());
    for (const auto &x : unit_points)
      points.push_back(chart.point(lower + size * x));
    return points;
  }

  template <int dim>
  void
  fill_mapping_cache(const Triangulation<dim> &tria, MappingQCache<dim> &cache)
  {
    // FE_Q's support points (Gauss-Lobatto, hierarchic) are the mapping's.
    const FE_Q<dim>                fe(cache.get_degree());
    const std::vector<Point<dim>> &unit_points = fe.get_unit_support_points();
    const ManifoldMappingQ<dim>    mapping_q(cache.get_degree());
    const auto                     points_of = [&](const auto &cell) {
      std::vector<Point<dim>> points = transfinite_points<dim>(cell, unit_points);
      if (points.empty())
        return mapping_q.compute_mapping_support_points(cell);
      // The mapping's vertices are the triangulation's (as for MappingQ).
      for (const unsigned int v : cell->vertex_indices())
        points[v] = cell->vertex(v);
      return points;
    };
    if (!tria.has_hanging_nodes())
      {
        cache.initialize(tria, points_of);
        return;
      }

    // A continuous field per coordinate, whose hanging values become those
    // of the coarse side's polynomial.
    DoFHandler<dim> position(tria);
    position.distribute_dofs(fe);
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(position, relevant);
    AffineConstraints<double> hanging(relevant);
    DoFTools::make_hanging_node_constraints(position, hanging);
    hanging.close();
    const IndexSet                                        &owned = position.locally_owned_dofs();
    std::array<LinearAlgebra::distributed::Vector<double>, dim> x;
    for (auto &component : x)
      component.reinit(owned, relevant, tria.get_communicator());
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : position.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const std::vector<Point<dim>> points = points_of(cell);
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (owned.is_element(dofs[i]))
              for (unsigned int d = 0; d < dim; ++d)
                x[d](dofs[i]) = points[i][d];
        }
    for (auto &component : x)
      {
        hanging.distribute(component);
        component.update_ghost_values();
      }

    cache.initialize(tria, [&](const typename Triangulation<dim>::cell_iterator &cell) {
      if (!cell->is_active() || cell->is_artificial())
        return points_of(cell);
      const typename DoFHandler<dim>::cell_iterator dof_cell(&tria, cell->level(), cell->index(),
                                                             &position);
      std::vector<types::global_dof_index>          cell_dofs(fe.n_dofs_per_cell());
      dof_cell->get_dof_indices(cell_dofs);
      std::vector<Point<dim>> points(cell_dofs.size());
      for (unsigned int i = 0; i < cell_dofs.size(); ++i)
        for (unsigned int d = 0; d < dim; ++d)
          points[i][d] = x[d](cell_dofs[i]);
      // A hanging vertex too stays the triangulation's, which the contact
      // faces are checked against (see the header).
      for (const unsigned int v : cell->vertex_indices())
        points[v] = cell->vertex(v);
      return points;
    });
  }

  template std::vector<Point<2>>
  transfinite_points<2>(const Triangulation<2>::cell_iterator &, const std::vector<Point<2>> &);
  template std::vector<Point<3>>
  transfinite_points<3>(const Triangulation<3>::cell_iterator &, const std::vector<Point<3>> &);
  template void
  fill_mapping_cache<2>(const Triangulation<2> &, MappingQCache<2> &);
  template void
  fill_mapping_cache<3>(const Triangulation<3> &, MappingQCache<3> &);
} // namespace contact_fem
