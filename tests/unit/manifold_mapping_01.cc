// fill_mapping_cache() (source/geometry/manifold_mapping.cc) on a disc
// (2D), a ball and a cylinder (3D): a circle (sphere, cylinder) on the
// boundary, a transfinite interpolation inside, as the Hertz scenes and
// Geometry/Manifolds. The ball's cells keep MappingQ's points (sphere).
//  - uniform refinement: the support points equal those deal.II's
//    MappingQ takes from the manifolds up to the tolerance of its
//    pull-backs (largest distance 4e-10 of the cell diameter);
//  - local refinement: at every hanging face, points of each refined side
//    lie on the coarse side's polynomial face (the distance of the point
//    from its pull-back onto the coarse face, relative to the fine cell's
//    diameter); deal.II's MappingQ (the cache before) is printed beside it
//    to show that the check sees the gap. Degree 3 keeps a gap at the
//    hanging vertex (the triangulation's, not on the coarse cubic).
// Run serially and on 2 ranks (the hanging points of ghost cells).
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/manifold_lib.h>

#include <contact_fem/geometry/manifold_mapping.h>

#include <iomanip>
#include <iostream>

using namespace dealii;
using namespace contact_fem;

namespace
{
  /// A disc (2D) or ball (3D) on a circle (sphere), or (3D) a cylinder
  /// along x on a CylindricalManifold; a transfinite interpolation inside.
  template <int dim>
  void
  make_body(parallel::distributed::Triangulation<dim> &tria, const bool cylinder)
  {
    if constexpr (dim == 3)
      if (cylinder)
        GridGenerator::cylinder(tria, 1., 1.);
    if (!cylinder)
      GridGenerator::hyper_ball(tria, Point<dim>(), 1.);
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_all_manifold_ids(1);
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == 0)
          cell->face(f)->set_all_manifold_ids(0);
    if constexpr (dim == 3)
      if (cylinder)
        tria.set_manifold(0, CylindricalManifold<dim>(0));
    if (!cylinder)
      tria.set_manifold(0, SphericalManifold<dim>());
    TransfiniteInterpolationManifold<dim> interior;
    interior.initialize(tria);
    tria.set_manifold(1, interior);
  }

  /// Largest distance, in cell diameters, between the points of @p a and
  /// @p b at the mapping support points of the locally owned cells.
  template <int dim>
  double
  largest_difference(const Triangulation<dim> &tria,
                     const Mapping<dim>       &a,
                     const Mapping<dim>       &b,
                     const unsigned int        degree)
  {
    const FE_Q<dim>                fe(degree);
    const std::vector<Point<dim>> &unit  = fe.get_unit_support_points();
    double                         worst = 0.;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &u : unit)
          worst = std::max(worst, a.transform_unit_to_real_cell(cell, u).distance(
                                    b.transform_unit_to_real_cell(cell, u)) /
                                    cell->diameter());
    return Utilities::MPI::max(worst, MPI_COMM_WORLD);
  }

  /// Largest distance, in fine cell diameters, of points of the refined
  /// sides of hanging faces from the coarse side's face. The coarse cell is
  /// locally owned, its refined neighbours owned or ghosts.
  template <int dim>
  double
  largest_hanging_gap(const Triangulation<dim> &tria, const Mapping<dim> &mapping)
  {
    std::vector<Point<dim>> samples; // on the face x_0 = 0 of the unit cell
    for (unsigned int i = 0; i <= 4; ++i)
      for (unsigned int j = 0; j <= (dim == 3 ? 4 : 0); ++j)
        samples.emplace_back(dim == 2 ? Point<dim>(0., 0.13 + 0.185 * i) :
                                        Point<dim>(0., 0.13 + 0.185 * i, 0.09 + 0.2 * j));
    double worst = 0.;
    for (const auto &coarse : tria.active_cell_iterators())
      if (coarse->is_locally_owned())
        for (const auto f : coarse->face_indices())
          if (!coarse->at_boundary(f) && coarse->face(f)->has_children())
            for (unsigned int c = 0; c < coarse->face(f)->n_children(); ++c)
              {
                const auto   fine      = coarse->neighbor_child_on_subface(f, c);
                unsigned int fine_face = 0;
                while (fine->face(fine_face) != coarse->face(f)->child(c))
                  ++fine_face;
                for (const auto &s : samples)
                  {
                    // The sample moved onto face fine_face of the unit cell.
                    Point<dim> u = s;
                    std::swap(u[0], u[fine_face / 2]);
                    u[fine_face / 2]           = fine_face % 2;
                    const Point<dim> x         = mapping.transform_unit_to_real_cell(fine, u);
                    Point<dim>       on_coarse = mapping.transform_real_to_unit_cell(coarse, x);
                    on_coarse[f / 2]           = f % 2;
                    worst =
                      std::max(worst,
                               mapping.transform_unit_to_real_cell(coarse, on_coarse).distance(x) /
                                 fine->diameter());
                  }
              }
    return Utilities::MPI::max(worst, MPI_COMM_WORLD);
  }

  template <int dim>
  void
  check(const unsigned int degree, const bool cylinder, ConditionalOStream &out)
  {
    parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
    make_body(tria, cylinder);
    // The 3D bodies refined once: the cylinder then has 80 cells, 1760
    // after the local refinement, with hanging faces whose fine side is a
    // ghost on both of 2 ranks (56 and 16); refined twice (12176 cells) it
    // cost three times this test's run.
    tria.refine_global(dim == 2 ? 2 : 1);
    MappingQCache<dim> cache(degree);
    fill_mapping_cache(tria, cache);
    const MappingQ<dim> manifolds(degree);
    out << (cylinder ? "cylinder" :
            dim == 2 ? "disc" :
                       "ball")
        << ", degree " << degree << ", " << tria.n_global_active_cells()
        << " cells, uniform: difference from MappingQ "
        << (largest_difference(tria, cache, manifolds, degree) < 1e-9 ? "< 1e-9" : "too large")
        << std::endl;

    // Two rounds of local refinement: hanging faces inside and on cells
    // at the sphere.
    for (unsigned int round = 0; round < 2; ++round)
      {
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned() && cell->center()[0] > 0.1 && cell->center()[1] > -0.2)
            cell->set_refine_flag();
        tria.execute_coarsening_and_refinement();
      }
    fill_mapping_cache(tria, cache);
    MappingQCache<dim> before(degree);
    before.initialize(manifolds, tria);
    const double gap        = largest_hanging_gap(tria, cache);
    const double gap_before = largest_hanging_gap(tria, before);
    out << "  locally refined, " << tria.n_global_active_cells()
        << " cells: hanging faces conforming (gap < 1e-10 h): " << (gap < 1e-10 ? "yes" : "no")
        << "; MappingQ's gap above 1e-6 h: " << (gap_before > 1e-6 ? "yes" : "no") << std::endl;
    // Degree 3: the hanging vertex (the triangulation's) is no support
    // point of the coarse cubic.
    if (gap >= 1e-10)
      out << "  gap below a tenth of MappingQ's: " << (gap < 0.1 * gap_before ? "yes" : "no")
          << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ConditionalOStream out(std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
  check<2>(2, false, out);
  check<2>(3, false, out);
  check<3>(2, false, out);
  check<3>(2, true, out);
}
