// ContactInterface<3> with Q1 on a quadratic mapping, without a scene: the
// curved hull of deal.II's cylinder (radius 1, axis x, length 2, refined
// once) is the slave surface (id 3), its end x = -1 the master (id 4).
// Checked against values known by hand:
// - each face carries 5 geometry points (edge midpoints and centre of the
//   mapping), which lie on the cylinder, in the node order of
//   Mortar::QuadFace (node 4 nearest the midpoint of the edge of vertices
//   0 and 2, 5 of 1 and 3, 6 of 0 and 1, 7 of 2 and 3, 8 the centre);
// - quad(face, u) moves them with the bilinear interpolation of the vertex
//   displacements (for a linear field: the value of the field there);
// - the slave faces' area is the hull's, 2 pi R L = 4 pi, to the sag error
//   of biquadratic faces, far below that of the chords (MappingQ(1));
// - a geometry of degree 3 under Q1 is refused.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/material/material.h>

#include "unit_test_materials.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>

using namespace dealii;
using namespace contact_fem;

namespace
{
  double
  area(const Mortar::QuadFace &quad)
  {
    const QGauss<2> q(6);
    double          result = 0.;
    for (unsigned int i = 0; i < q.size(); ++i)
      {
        const Point<2> xi(2. * q.point(i)[0] - 1., 2. * q.point(i)[1] - 1.);
        const auto     t = quad.tangents(xi);
        result += 4. * q.weight(i) * cross_product_3d(t[0], t[1]).norm();
      }
    return result;
  }

  double
  hull_area(const ContactInterface<3> &interface)
  {
    double result = 0.;
    for (const auto &face : interface.faces)
      if (face.slave)
        result += area(interface.face_geometry(face));
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(6);

  Triangulation<3> tria;
  GridGenerator::cylinder(tria, 1., 1.);
  tria.refine_global(1);
  for (const auto &cell : tria.active_cell_iterators())
    {
      cell->set_material_id(1);
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const auto id = cell->face(f)->boundary_id();
            cell->face(f)->set_boundary_id(id == 0 ? 3 : id == 1 ? 4 : 0);
          }
    }
  const FESystem<3> fe(FE_Q<3>(1), 3);
  DoFHandler<3>     dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const Materials<3>        materials = make_materials<3>("1", "100", "0.3");
  AffineConstraints<double> none;
  none.close();
  const std::vector<ContactPair> pairs = {ContactPair{3, 4}};

  ContactInterface<3> interface;
  interface.initialize(MappingQ<3>(2), dof_handler, pairs, none, none, materials, MPI_COMM_WORLD);
  unsigned int n_slave = 0, n_master = 0, n_with_five = 0, n_in_order = 0;
  double       off_cylinder = 0.;
  for (const auto &face : interface.faces)
    {
      ++(face.slave ? n_slave : n_master);
      n_with_five += face.geometry_points.size() == 5;
      const Mortar::QuadFace quad = interface.face_geometry(face);
      if (face.slave)
        for (unsigned int k = 4; k < 9; ++k)
          off_cylinder =
            std::max(off_cylinder, std::abs(std::hypot(quad.nodes[k][1], quad.nodes[k][2]) - 1.));
      // Each geometry point is nearest to the midpoint of its own edge.
      const auto    &x            = quad.nodes;
      const Point<3> midpoints[5] = {0.5 * (x[0] + x[2]), 0.5 * (x[1] + x[3]), 0.5 * (x[0] + x[1]),
                                     0.5 * (x[2] + x[3]), 0.25 * (x[0] + x[1] + x[2] + x[3])};
      bool           in_order     = true;
      for (unsigned int k = 0; k < 5; ++k)
        for (unsigned int other = 0; other < 5; ++other)
          if (other != k && x[4 + k].distance(midpoints[other]) <= x[4 + k].distance(midpoints[k]))
            in_order = false;
      n_in_order += in_order;
    }
  std::cout << "Q1 on MappingQ(2): " << n_slave << " slave and " << n_master << " master faces, "
            << n_with_five << " with 5 geometry points, " << n_in_order
            << " in the node order of QuadFace" << std::endl;
  std::cout << "  geometry points off the cylinder: "
            << (off_cylinder < 1e-12 ? std::string("< 1e-12") : std::to_string(off_cylinder))
            << std::endl;

  // quad(face, u) moves an edge midpoint by the mean displacement of its
  // edge's vertices and the centre by that of all four.
  const auto field = [](const Point<3> &X) {
    return Tensor<1, 3>({0.1 * X[0] - 0.2 * X[2] + 0.3, 0.05 * X[1] + 0.4 * X[0], -0.1 * X[1]});
  };
  std::vector<Tensor<1, 3>> u(interface.nodes.size());
  for (unsigned int n = 0; n < interface.nodes.size(); ++n)
    u[n] = field(interface.nodes[n].reference);
  double largest_error = 0.;
  for (const auto &face : interface.faces)
    {
      const Mortar::QuadFace moved       = interface.face_geometry(face, u);
      const auto            &v           = face.nodes;
      const Tensor<1, 3>     expected[5] = {0.5 * (u[v[0]] + u[v[2]]), 0.5 * (u[v[1]] + u[v[3]]),
                                            0.5 * (u[v[0]] + u[v[1]]), 0.5 * (u[v[2]] + u[v[3]]),
                                            0.25 * (u[v[0]] + u[v[1]] + u[v[2]] + u[v[3]])};
      for (unsigned int k = 0; k < 5; ++k)
        largest_error =
          std::max(largest_error,
                   (moved.nodes[4 + k] - face.geometry_points[k] - expected[k]).norm());
    }
  std::cout << "  geometry points moved by the bilinear vertex displacement: "
            << (largest_error < 1e-14 ? std::string("ok (< 1e-14)") : std::to_string(largest_error))
            << std::endl;

  const double exact = 4. * numbers::PI;
  std::cout << "  slave area / (2 pi R L) - 1: " << hull_area(interface) / exact - 1. << std::endl;
  ContactInterface<3> chords;
  chords.initialize(MappingQ<3>(1), dof_handler, pairs, none, none, materials, MPI_COMM_WORLD);
  std::cout << "Q1 on MappingQ(1) (chords): " << chords.faces.front().geometry_points.size()
            << " geometry points, slave area / (2 pi R L) - 1: " << hull_area(chords) / exact - 1.
            << std::endl;

  ContactInterface<3> cubic;
  try
    {
      cubic.initialize(MappingQ<3>(3), dof_handler, pairs, none, none, materials, MPI_COMM_WORLD);
      std::cout << "Q1 on MappingQ(3): accepted" << std::endl;
    }
  catch (const ExceptionBase &e)
    {
      const std::string what = e.what();
      std::cout << "Q1 on MappingQ(3): refused"
                << (what.find("only for degree-1 elements on a quadratic mapping") !=
                        std::string::npos ?
                      " (the geometry may exceed the element degree only for Q1 on a "
                      "quadratic mapping)" :
                      ", with another message")
                << std::endl;
    }
}
