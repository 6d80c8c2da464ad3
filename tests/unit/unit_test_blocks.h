// The ids of two stacked blocks in a unit test: the lower block (material
// 1) ends at height 1, the upper one (material 2) starts at 1 + gap; the
// lower block's top gets boundary id 3, the upper block's base id 4, every
// other boundary face 0 (the test's pairs say which is the slave).
#ifndef contact_fem_unit_test_blocks_h
#define contact_fem_unit_test_blocks_h

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <cmath>

template <int dim>
void
label_stacked_blocks(dealii::Triangulation<dim> &tria, const double gap)
{
  for (const auto &cell : tria.active_cell_iterators())
    {
      const bool is_upper = cell->center()[dim - 1] > 1.;
      cell->set_material_id(is_upper ? 2 : 1);
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const double height = cell->face(f)->center()[dim - 1];
            if (is_upper && std::abs(height - (1. + gap)) < 1e-12)
              cell->face(f)->set_boundary_id(4);
            else if (!is_upper && std::abs(height - 1.) < 1e-12)
              cell->face(f)->set_boundary_id(3);
            else
              cell->face(f)->set_boundary_id(0);
          }
    }
}

/// The 3D blocks of the linearisation and tiling tests in @p tria, labelled:
/// a 3 x 3 cell lower block on the unit square under a 2 x 2 cell upper
/// block 0.05 above it that overhangs it by 0.1 on every side (no
/// coincident rims, whose clipping would change topology inside a
/// difference).
inline void
make_stacked_blocks_3d(dealii::Triangulation<3> &tria)
{
  using dealii::Point;
  dealii::Triangulation<3> lower, upper;
  dealii::GridGenerator::subdivided_hyper_rectangle(lower, {3, 3, 1}, Point<3>(0., 0., 0.),
                                                    Point<3>(1., 1., 1.));
  dealii::GridGenerator::subdivided_hyper_rectangle(upper, {2, 2, 1}, Point<3>(-0.1, -0.1, 1.05),
                                                    Point<3>(1.1, 1.1, 2.05));
  dealii::GridGenerator::merge_triangulations(lower, upper, tria);
  label_stacked_blocks(tria, 0.05);
}

/// The 2D blocks of the linearisation tests in @p tria, labelled: a 3 cell
/// lower block on the unit square under a 2 cell upper block 0.05 above it
/// (non-matching).
inline void
make_stacked_blocks(dealii::Triangulation<2> &tria)
{
  using dealii::Point;
  dealii::Triangulation<2> lower, upper;
  dealii::GridGenerator::subdivided_hyper_rectangle(lower, {3, 1}, Point<2>(0., 0.),
                                                    Point<2>(1., 1.));
  dealii::GridGenerator::subdivided_hyper_rectangle(upper, {2, 1}, Point<2>(0., 1.05),
                                                    Point<2>(1., 2.05));
  dealii::GridGenerator::merge_triangulations(lower, upper, tria);
  label_stacked_blocks(tria, 0.05);
}

inline void
make_stacked_blocks(dealii::Triangulation<3> &tria)
{
  make_stacked_blocks_3d(tria);
}

#endif
