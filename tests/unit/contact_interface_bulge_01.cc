// The penetration check's distance to a curved Q2 master face that bulges
// beyond the box of its nodes, in 2D and 3D. Lower block [0, 1]^dim (2
// cells along x, the slave top), upper block one cell [0, 1]^(dim-1) x
// [1.1, 2.1] (its base the master), Q2. The master nodes at x = 1 are
// lifted by delta = 0.4, so the master base becomes the quadratic
// z(x) = 1.1 + delta/2 xi (xi + 1), xi = 2x - 1, which dips to 1.1 -
// delta/8 = 1.05 at x = 1/4, below all of its nodes (z >= 1.1). The slave
// node at x = 1/4 is 0.05 below the dip: outside the master. A search box
// of the nodes alone misses the dip: the check then found no face and
// reported this node as penetrating by infinity (a converged run failed
// as "not a contact solution"). Each slave node's distance is compared
// with a brute-force minimum over 20,001 points of the master curve
// (independent of the closest-point iteration of ContactInterface).

#include <deal.II/base/mpi.h>
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
  constexpr double gap0 = 0.1, delta = 0.4;

  /// Height of the deformed master base over x.
  double
  master_height(const double x)
  {
    const double xi = 2. * x - 1.;
    return 1. + gap0 + 0.5 * delta * xi * (xi + 1.);
  }

  template <int dim>
  void
  make_blocks(Triangulation<dim> &tria)
  {
    Triangulation<dim>        lower, upper;
    std::vector<unsigned int> lower_cells(dim, 1), upper_cells(dim, 1);
    lower_cells[0] = 2;
    Point<dim> upper_low, upper_high, lower_high;
    for (unsigned int d = 0; d < dim; ++d)
      upper_high[d] = lower_high[d] = 1.;
    upper_low[dim - 1] = 1. + gap0;
    upper_high[dim - 1] += 1. + gap0;
    GridGenerator::subdivided_hyper_rectangle(lower, lower_cells, Point<dim>(), lower_high);
    GridGenerator::subdivided_hyper_rectangle(upper, upper_cells, upper_low, upper_high);
    GridGenerator::merge_triangulations(lower, upper, tria);
    label_stacked_blocks(tria, gap0);
  }

  template <int dim>
  void
  run()
  {
    Triangulation<dim> tria;
    make_blocks(tria);
    const FESystem<dim> fe(FE_Q<dim>(2), dim);
    DoFHandler<dim>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const MappingQ<dim>  mapping(2);
    const Materials<dim> materials = make_materials<dim>("1, 2", "100, 200", "0, 0");

    AffineConstraints<double> no_dirichlet, no_hanging;
    no_dirichlet.close();
    no_hanging.close();
    ContactInterface<dim> interface;
    interface.initialize(mapping, dof_handler, {ContactPair{3, 4}}, no_dirichlet, no_hanging,
                         materials, MPI_COMM_WORLD);

    std::vector<double> u(interface.dofs().size(), 0.);
    for (const auto &node : interface.nodes)
      if (node.master && std::abs(node.reference[0] - 1.) < 1e-12)
        u[interface.position(node.dofs[dim - 1])] = delta;
    interface.update(u, 3.);

    const std::vector<double> distances = interface.surface_distances(interface.slave_nodes, u);
    std::cout << dim << "D, " << distances.size() << " slave nodes" << std::endl;
    bool   all_agree = true;
    double at_dip    = 0.;
    for (unsigned int i = 0; i < distances.size(); ++i)
      {
        const Point<dim> &X = interface.nodes[interface.slave_nodes[i].node].reference;
        // The master base does not depend on y: the distance is that to
        // the curve in the (x, z) plane.
        double best = std::numeric_limits<double>::infinity();
        for (unsigned int a = 0; a <= 20000; ++a)
          {
            const double x = 0.00005 * a;
            best           = std::min(best, std::hypot(x - X[0], master_height(x) - X[dim - 1]));
          }
        all_agree = all_agree && std::abs(distances[i] - best) < 1e-6;
        if (std::abs(X[0] - 0.25) < 1e-12)
          at_dip = std::max(at_dip, std::abs(distances[i] - best));
      }
    std::cout << "  every distance agrees with the brute force to 1e-6: " << all_agree << std::endl
              << "  slave nodes under the dip (x = 1/4, exact distance 0.05): "
              << (at_dip < 1e-6 ? "agree" : "differ") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run<2>();
  run<3>();
}
