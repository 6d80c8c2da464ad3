// ContactInterface<3> on hand-made stacked blocks, without a scene: the
// lower block [0, 1]^2 x [0, 1] (2 x 2 x 1 cells, slave top, boundary id 3),
// the upper one [0, 1]^2 x [1.1, 2.1] (one cell, master base, id 4), Q1.
// Every mortar quantity is known by hand: the dual basis integrates
// functions bilinear on a slave face exactly (int Phi_j f = D_j f(x_j)), and
// the master shape functions are bilinear there, so
//   D_j = int N_j:        1/16 (corners), 1/8 (edges), 1/4 (centre),
//   M_jl = D_j N^m_l(x_j),
//   normal (0, 0, 1), gap 0.1 at every slave node,
// and the independent surface distances are 0.1 too (+inf on the rim, where
// the closest master point is on the edge of the master surface). Then the
// upper block moved by (0.25, 0, 0): the slave faces at x < 0.5 are half
// covered, the rim dual basis lives on the covered half, sum D = sum M =
// 0.75 (the overlap area), and the gaps stay 0.1.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
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
  constexpr double gap0 = 0.1;

  void
  make_blocks(Triangulation<3> &tria)
  {
    Triangulation<3> lower, upper;
    GridGenerator::subdivided_hyper_rectangle(lower, {2, 2, 1}, Point<3>(0., 0., 0.),
                                              Point<3>(1., 1., 1.));
    GridGenerator::hyper_rectangle(upper, Point<3>(0., 0., 1. + gap0), Point<3>(1., 1., 2. + gap0));
    GridGenerator::merge_triangulations(lower, upper, tria);
    label_stacked_blocks(tria, gap0);
  }

  /// Zero where |x| < 1e-13 (the printed values are hand values).
  double
  clean(const double x)
  {
    return std::abs(x) < 1e-13 ? 0. : x;
  }

  void
  print(const ContactInterface<3> &interface, const std::vector<double> &u)
  {
    const std::vector<double> distances = interface.surface_distances(interface.slave_nodes, u);
    double                    D_sum = 0., M_sum = 0.;
    for (unsigned int i = 0; i < interface.slave_nodes.size(); ++i)
      {
        const auto &s = interface.slave_nodes[i];
        const auto &X = interface.nodes[s.node].reference;
        std::cout << "  (" << X[0] << ", " << X[1] << "): paired " << s.paired
                  << ", D = " << clean(s.D) << ", int N = " << s.full_area << ", normal ("
                  << clean(s.normal[0]) << ", " << clean(s.normal[1]) << ", " << clean(s.normal[2])
                  << ")";
        if (s.paired)
          std::cout << ", gap - 0.1 = " << clean(interface.gap(s, u) - gap0);
        std::cout << ", distance " << distances[i] << std::endl;
        D_sum += s.D;
        for (const auto &[m, value] : s.M)
          {
            const Point<3> Y = interface.nodes[m].reference + interface.displacement(m, u);
            std::cout << "      M to (" << Y[0] << ", " << Y[1] << "): " << clean(value)
                      << std::endl;
            M_sum += value;
          }
      }
    std::cout << "  sum D = " << D_sum << ", sum M = " << M_sum << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(8);

  Triangulation<3> tria;
  make_blocks(tria);
  const FESystem<3> fe(FE_Q<3>(1), 3);
  DoFHandler<3>     dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const MappingQ<3> mapping(1);

  const Materials<3> materials = make_materials<3>("1, 2", "100, 200", "0, 0");

  AffineConstraints<double> no_dirichlet;
  no_dirichlet.close();
  ContactInterface<3> interface;
  interface.initialize(mapping, dof_handler, {ContactPair{3, 4}}, no_dirichlet, no_dirichlet,
                       materials, MPI_COMM_WORLD);
  std::cout << "faces: " << interface.faces.size() << ", nodes: " << interface.nodes.size()
            << std::endl;
  // Every face's orientation turns t_xi x t_eta out of its body.
  for (const auto &face : interface.faces)
    {
      const Tensor<1, 3> n =
        Mortar::face_normal(interface.face_geometry(face), Point<2>(), face.orientation);
      std::cout << "  " << (face.slave ? "slave" : "master") << " face normal (" << clean(n[0])
                << ", " << clean(n[1]) << ", " << clean(n[2]) << ")" << std::endl;
    }

  std::vector<double> u(interface.dofs().size(), 0.);
  interface.update(u, 3.);
  std::cout << "matching blocks, gap 0.1:" << std::endl;
  print(interface, u);

  // The upper block moved by 0.25 along x.
  for (unsigned int n = 0; n < interface.nodes.size(); ++n)
    if (interface.nodes[n].master)
      u[interface.position(interface.nodes[n].dofs[0])] = 0.25;
  interface.update(u, 3.);
  std::cout << "upper block moved by 0.25 along x:" << std::endl;
  print(interface, u);
  std::cout << "contact modulus " << interface.contact_modulus() << std::endl;
}
