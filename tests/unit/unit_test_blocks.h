// The ids of two stacked blocks in a unit test: the lower block (material
// 1) ends at height 1, the upper one (material 2) starts at 1 + gap; the
// lower block's top gets boundary id 3, the upper block's base id 4, every
// other boundary face 0 (the test's pairs say which is the slave).
#ifndef contact_fem_unit_test_blocks_h
#define contact_fem_unit_test_blocks_h

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

#endif
