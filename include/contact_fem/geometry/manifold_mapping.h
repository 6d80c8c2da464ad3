// The support points of a curved mapping (MappingQCache), computed from the
// manifolds without the pull-backs of deal.II's transfinite interpolation,
// and conforming at hanging faces.
#ifndef contact_fem_manifold_mapping_h
#define contact_fem_manifold_mapping_h

#include <deal.II/base/point.h>
#include <deal.II/fe/mapping_q_cache.h>
#include <deal.II/grid/tria.h>

#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /**
   * The points of @p cell at the reference points @p unit_points of the
   * cell. A cell descending (by isotropic refinement) from a coarse cell
   * with a TransfiniteInterpolationManifold occupies a known sub-box of
   * that coarse cell's chart, which is its reference cell: the points are
   * the transfinite interpolation (Gordon-Hall) of the coarse cell's
   * boundary lines and faces evaluated there, with no search and no
   * Newton iteration. Straight lines and flat faces are those of the
   * transfinite or the flat manifold id. Returns an empty vector for any
   * other cell, and (3D) for a coarse cell with a curved face that is not
   * a ChartManifold (a sphere): the triangulation's refinement of such a
   * face does not follow the sub-boxes (3 % of a cell apart after three
   * levels), so MappingQ's points, pulled back from the vertices, are
   * kept there.
   */
  template <int dim>
  std::vector<Point<dim>>
  transfinite_points(const typename Triangulation<dim>::cell_iterator &cell,
                     const std::vector<Point<dim>>                    &unit_points);

  /**
   * Fills @p cache with the support points of every cell of @p tria: the
   * vertices of the triangulation, the other points by
   * transfinite_points() (cells of other manifolds as MappingQ computes
   * them). With hanging nodes the points of the active cells go through a
   * continuous FE_Q position field of the mapping's degree and its
   * hanging-node constraints, so that a refined side of a hanging face
   * lies on the coarse side's polynomial face (as a finite element field
   * is continuous there). The vertices, hanging ones too, stay the
   * triangulation's: for degree 2 a hanging vertex is the coarse line's
   * midpoint support point anyway, except on a sphere's face (3D), whose
   * refinement is not that of the chart; for degree 3 and more it lies off
   * the coarse polynomial by O(h^(p+1)). Collective on the triangulation's
   * communicator.
   */
  template <int dim>
  void
  fill_mapping_cache(const Triangulation<dim> &tria, MappingQCache<dim> &cache);
} // namespace contact_fem

#endif
