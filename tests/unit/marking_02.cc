// Refinement/Contact layers along the surface, in 2D and 3D: a block of
// 5 cells along the contact surface (5 x 5 in 3D) and 4 deep, the contact
// surface (id 3) its bottom z = 0, and only the middle bottom cell flagged;
// contact layers 3. Printed: per layer (depth 1..4, from the surface) the
// number of flagged cells and their largest distance from the middle
// column (in cells, max norm).
// - Straight behind (false): the column under the flagged cell, 1 cell in
//   each of the layers 1..3, at distance 0; nothing in layer 4.
// - Along the surface (true): each layer also takes the front's face
//   neighbours, so layer 1 takes the flagged cell's neighbours along the
//   surface and layer 2 those of these: the flagged set grows by one cell
//   sideways per layer (distance 2, 1, 0 in depths 1, 2, 3 in 2D: 5, 3, 1
//   cells; in 3D the face-neighbour diamonds: 13, 5, 1 cells).

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <contact_fem/adaptivity/marking.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

using namespace dealii;
using namespace contact_fem;

namespace
{
  template <int dim>
  void
  layers(const bool along_surface)
  {
    parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
    std::vector<unsigned int>                 repetitions(dim, 5);
    repetitions[dim - 1] = 4;
    Point<dim> top;
    for (unsigned int d = 0; d < dim; ++d)
      top[d] = repetitions[d];
    GridGenerator::subdivided_hyper_rectangle(tria, repetitions, Point<dim>(), top);
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary() && std::abs(cell->face(f)->center()[dim - 1]) < 1e-12)
          cell->face(f)->set_boundary_id(3);
    // The middle column: cell centres at 2.5 along the surface.
    const auto distance = [](const auto &cell) {
      double largest = 0.;
      for (unsigned int d = 0; d + 1 < dim; ++d)
        largest = std::max(largest, std::abs(cell->center()[d] - 2.5));
      return largest;
    };
    for (const auto &cell : tria.active_cell_iterators())
      if (distance(cell) < 1e-12 && cell->center()[dim - 1] < 1.)
        cell->set_refine_flag();
    Marking::flag_layers_behind_faces(tria, {3}, 3, along_surface);

    std::cout << dim << "D, along the surface " << (along_surface ? "true" : "false") << ":";
    for (unsigned int depth = 1; depth <= 4; ++depth)
      {
        unsigned int n       = 0;
        double       largest = 0.;
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->refine_flag_set() && std::floor(cell->center()[dim - 1]) + 1 == depth)
            {
              ++n;
              largest = std::max(largest, distance(cell));
            }
        std::cout << "  depth " << depth << ": " << n << " (" << largest << ")";
      }
    std::cout << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  layers<2>(false);
  layers<2>(true);
  layers<3>(false);
  layers<3>(true);
}
