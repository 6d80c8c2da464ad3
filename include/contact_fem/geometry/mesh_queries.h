// Small queries of a mesh shared by the set-up checks and the diagnoses.
#ifndef contact_fem_mesh_queries_h
#define contact_fem_mesh_queries_h

#include <deal.II/base/tensor.h>
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

  /// The outward unit normal of the (straight or bilinear) face @p f of
  /// @p cell: in 2D the edge turned, in 3D the cross product of the
  /// diagonals of the quadrilateral.
  template <int dim>
  dealii::Tensor<1, dim>
  outward_normal(const typename dealii::Triangulation<dim>::cell_iterator &cell,
                 const unsigned int                                        f)
  {
    const auto             face = cell->face(f);
    dealii::Tensor<1, dim> n;
    if constexpr (dim == 2)
      {
        const dealii::Tensor<1, dim> t = face->vertex(1) - face->vertex(0);
        n[0]                           = t[1];
        n[1]                           = -t[0];
      }
    else
      {
        const dealii::Tensor<1, dim> a = face->vertex(3) - face->vertex(0);
        const dealii::Tensor<1, dim> b = face->vertex(2) - face->vertex(1);
        n[0]                           = a[1] * b[2] - a[2] * b[1];
        n[1]                           = a[2] * b[0] - a[0] * b[2];
        n[2]                           = a[0] * b[1] - a[1] * b[0];
      }
    if (n * (face->center() - cell->center()) < 0.)
      n *= -1.;
    return n.norm() > 0. ? n / n.norm() : n;
  }
} // namespace contact_fem

#endif
