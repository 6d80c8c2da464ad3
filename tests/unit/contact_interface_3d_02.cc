// The independent penetration check covers the hanging vertices of a 3D
// slave surface, which carry no multiplier. Lower block [0, 1]^2 x [0, 1]
// (2 x 2 x 1 cells, slave top, id 3) with the cell at x, y < 0.5 refined
// once: its top has two hanging vertices, (0.5, 0.25, 1) and (0.25, 0.5,
// 1), each the middle of an edge of a coarse neighbour face (parents: the
// two ends, weights 1/2). Upper block [0, 1]^2 x [1.1, 2.1] (4 x 4 x 1
// cells, master base, id 4), Q1. The master node at (0.5, 0.25, 1.1) is
// pushed down by 0.15: a spike of the master surface whose tip (z = 0.95)
// lies under the first hanging vertex. Every regular slave node stays
// outside the master (the spike's base has half-width 0.25, the nearest
// regular nodes are 0.25 away), so a check of the slave nodes alone would
// pass; the hanging vertex lies inside. Its distance is compared with a
// brute-force minimum over a fine grid of points on the four bilinear
// master faces around the spike (independent of the Gauss-Newton closest
// point of ContactInterface).

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/material/material.h>

#include "unit_test_blocks.h"
#include "unit_test_materials.h"

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace dealii;
using namespace contact_fem;

namespace
{
  constexpr double gap0 = 0.1, spike = 0.15;
  const Point<2>   spike_xy(0.5, 0.25);

  void
  make_blocks(Triangulation<3> &tria)
  {
    Triangulation<3> lower, upper;
    GridGenerator::subdivided_hyper_rectangle(lower, {2, 2, 1}, Point<3>(0., 0., 0.),
                                              Point<3>(1., 1., 1.));
    GridGenerator::subdivided_hyper_rectangle(upper, {4, 4, 1}, Point<3>(0., 0., 1. + gap0),
                                              Point<3>(1., 1., 2. + gap0));
    GridGenerator::merge_triangulations(lower, upper, tria);
    label_stacked_blocks(tria, gap0);
    // The lower block's cell at the origin, refined once.
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->material_id() == 1 && cell->center()[0] < 0.5 && cell->center()[1] < 0.5)
        cell->set_refine_flag();
    tria.execute_coarsening_and_refinement();
  }

  /// The deformed master surface over (x, y): bilinear on the 4 x 4 grid,
  /// z = 1.1 except for the spike node.
  Point<3>
  master_point(const double x, const double y)
  {
    const double h = 0.25;
    // Hat function of the spike node on the grid.
    const double hat = std::max(0., 1. - std::abs(x - spike_xy[0]) / h) *
                       std::max(0., 1. - std::abs(y - spike_xy[1]) / h);
    return Point<3>(x, y, 1. + gap0 - spike * hat);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(6);

  Triangulation<3> tria;
  make_blocks(tria);
  const FESystem<3> fe(FE_Q<3>(1), 3);
  DoFHandler<3>     dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const MappingQ<3> mapping(1);

  const Materials<3> materials = make_materials<3>("1, 2", "100, 200", "0, 0");

  AffineConstraints<double> no_dirichlet, hanging;
  no_dirichlet.close();
  DoFTools::make_hanging_node_constraints(dof_handler, hanging);
  hanging.close();
  ContactInterface<3> interface;
  interface.initialize(mapping, dof_handler, {ContactPair{3, 4}}, no_dirichlet, hanging, materials,
                       MPI_COMM_WORLD);

  std::vector<double> u(interface.dofs().size(), 0.);
  for (const auto &node : interface.nodes)
    if (node.master && Point<2>(node.reference[0], node.reference[1]).distance(spike_xy) < 1e-12)
      u[interface.position(node.dofs[2])] = -spike;
  interface.update(u, 3.);

  const auto counts = interface.count_slave_nodes();
  std::cout << "slave nodes " << counts.first << ", hanging slave vertices " << counts.second
            << " (" << interface.hanging_slave_vertices.size() << " checked)" << std::endl;

  const std::vector<double> regular = interface.surface_distances(interface.slave_nodes, u);
  std::cout << "smallest distance of a regular slave node: "
            << *std::min_element(regular.begin(), regular.end()) << std::endl;

  const std::vector<double> distances =
    interface.surface_distances(interface.hanging_slave_vertices, u);
  for (unsigned int i = 0; i < distances.size(); ++i)
    {
      const auto     &h = interface.hanging_slave_vertices[i];
      const Point<3> &X = interface.nodes[h.node].reference;
      std::cout << "hanging vertex (" << X << "): paired " << h.paired << ", parents";
      for (const auto &[parent, weight] : interface.nodes[h.node].parents)
        std::cout << " (" << interface.nodes[parent].reference << ") " << weight;
      std::cout << ", distance " << distances[i];

      // Brute force: the nearest of 801 x 801 points of the master surface
      // around the vertex, with the sign of the side (inside when the
      // surface lies above it).
      double best = std::numeric_limits<double>::infinity();
      for (unsigned int a = 0; a <= 800; ++a)
        for (unsigned int b = 0; b <= 800; ++b)
          best = std::min(best,
                          X.distance(master_point(X[0] - 0.4 + 0.001 * a, X[1] - 0.4 + 0.001 * b)));
      const double side = master_point(X[0], X[1])[2] < X[2] ? -1. : 1.;
      std::cout << ", brute force " << side * best
                << ", agree to 1e-5: " << (std::abs(distances[i] - side * best) < 1e-5)
                << std::endl;
    }
}
