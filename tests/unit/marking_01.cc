// Marking on a column of 8 square cells (y from 0 to 8) with the indicator
// of the cell at height y the number of the cell from the bottom, 1..8
// (sum 36): which cells each strategy flags, and the contact layers.
// - Estimator global: all 8.
// - fixed number, fraction 0.25: the 2 largest (cells 7, 8).
// - fixed fraction 0.3: the largest cells whose indicators reach 0.3 * 36
//   = 10.8: 8 + 7 = 15 (cells 7, 8).
// - maximum, fraction 0.5: indicator > 0.5 * 8 = 4: cells 5..8.
// - contact layers 3 with the bottom face (id 3) a contact face and only
//   the bottom cell flagged: cells 1, 2, 3; the top cell flagged with the
//   top face (id 4) not a contact face: no layers.

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <contact_fem/adaptivity/marking.h>

#include <iostream>
#include <sstream>

using namespace dealii;
using namespace contact_fem;

namespace
{
  std::string
  text(const double value)
  {
    std::ostringstream s;
    s << value;
    return s.str();
  }

  /// A fresh column: cell k (from the bottom, 1..8) gets indicator k; the
  /// bottom face id 3, the top face id 4.
  void
  make_column(parallel::distributed::Triangulation<2> &tria, Vector<float> &indicators)
  {
    tria.clear();
    GridGenerator::subdivided_hyper_rectangle(tria, {1, 8}, Point<2>(0., 0.), Point<2>(1., 8.));
    indicators.reinit(tria.n_active_cells());
    for (const auto &cell : tria.active_cell_iterators())
      {
        indicators(cell->active_cell_index()) = std::floor(cell->center()[1]) + 1.;
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && std::abs(cell->face(f)->center()[1]) < 1e-12)
            cell->face(f)->set_boundary_id(3);
          else if (cell->face(f)->at_boundary() &&
                   std::abs(cell->face(f)->center()[1] - 8.) < 1e-12)
            cell->face(f)->set_boundary_id(4);
      }
  }

  void
  print_flagged(const std::string &label, const parallel::distributed::Triangulation<2> &tria)
  {
    std::cout << label << ":";
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->refine_flag_set())
        std::cout << " " << std::floor(cell->center()[1]) + 1.;
    std::cout << std::endl;
  }

  void
  flag_with(const std::string &estimator, const std::string &strategy, const double fraction)
  {
    parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
    Vector<float>                           indicators;
    make_column(tria, indicators);
    RefinementParameters parameters;
    parameters.estimator       = estimator;
    parameters.strategy        = strategy;
    parameters.refine_fraction = fraction;
    Marking::flag_cells(tria, indicators, parameters);
    print_flagged(estimator + ", " + strategy + " " + text(fraction), tria);
  }

  void
  layers_from(const double y)
  {
    parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
    Vector<float>                           indicators;
    make_column(tria, indicators);
    for (const auto &cell : tria.active_cell_iterators())
      if (std::abs(cell->center()[1] - y) < 1e-12)
        cell->set_refine_flag();
    Marking::flag_layers_behind_faces(tria, {3}, 3);
    print_flagged("contact layers 3 from the cell at y = " + text(y), tria);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  flag_with("global", "fixed fraction", 0.3);
  flag_with("spr contact", "fixed number", 0.25);
  flag_with("spr contact", "fixed fraction", 0.3);
  flag_with("spr contact", "maximum", 0.5);
  layers_from(0.5);
  layers_from(7.5);
}
