// Small queries of a mesh shared by the set-up checks and the diagnoses.
#ifndef contact_fem_mesh_queries_h
#define contact_fem_mesh_queries_h

#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <set>

namespace contact_fem
{
  /// The material ids (bodies) of the cells with a face on boundary @p id.
  /// The coarse cells carry the boundary ids and are known on every rank,
  /// so the answer is the same everywhere.
  template <int dim>
  std::set<dealii::types::material_id>
  bodies_of_surface(const dealii::Triangulation<dim> &tria, const dealii::types::boundary_id id)
  {
    std::set<dealii::types::material_id> bodies;
    for (const auto &cell : tria.cell_iterators_on_level(0))
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == id)
          bodies.insert(cell->material_id());
    return bodies;
  }

  /// The model's size: the longest side of the bounding box of the coarse
  /// cells (every rank holds them, so the answer is the same everywhere).
  /// A length that does not change when the model is moved, unlike the
  /// largest coordinate.
  template <int dim>
  double
  model_extent(const dealii::Triangulation<dim> &tria)
  {
    dealii::Point<dim> lower = tria.begin(0)->vertex(0);
    dealii::Point<dim> upper = lower;
    for (const auto &cell : tria.cell_iterators_on_level(0))
      for (const auto v : cell->vertex_indices())
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d] = std::min(lower[d], cell->vertex(v)[d]);
            upper[d] = std::max(upper[d], cell->vertex(v)[d]);
          }
    double extent = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      extent = std::max(extent, upper[d] - lower[d]);
    return extent;
  }
} // namespace contact_fem

#endif
