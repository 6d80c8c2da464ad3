// The checks of imported meshes (source/mesh_file.cc and
// source/boundary_manifolds.cc) on meshes built here, each with the answer
// known by construction:
//  - polygons of a curve are found (a 16-gon of a circle, both circles of a
//    flattened annulus, with their centres and radii), flat boundaries with
//    true corners are not (a subdivided rectangle, an L-shape), nor is an
//    octagon (45 degrees per vertex is a corner, not a polygonal circle);
//  - 3D: the hull of the 16-gon extruded along z is found on its cylinder
//    (with one layer its vertices lie on a sphere too), a flattened
//    polygonal ball on its sphere and not on a cylinder;
//  - coincident vertices: two blocks of different bodies touching along a
//    line, or two touching blocks of one body whose faces there carry
//    boundary ids (a deliberate internal surface), or one body pinched at a
//    single point, pass; one body cut along untagged faces is refused;
//  - fit_sphere() recovers a sphere from 3D points and refuses collinear ones;
//  - a thin cell whose curved face sags through its opposite side is
//    refused by the trial refinement, a well-shaped one passes;
//  - 3D: the hull of deal.II's coarse cylinder (radius 1, axis x) lies on
//    'cylinder 0, 0, 0, 1, 0, 0, 1' and refines on it; a wrong radius or a
//    sphere is refused.
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <contact_fem/geometry/boundary_manifolds.h>
#include <contact_fem/geometry/mesh_file.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace dealii;
using namespace contact_fem;

namespace
{
  void
  report_polygons(const std::string &name, const Triangulation<2> &tria)
  {
    std::cout << name << ":";
    const auto found = find_polygonal_boundaries(tria, {});
    if (found.empty())
      std::cout << " no polygonal boundary";
    for (const auto &b : found)
      {
        std::cout << " boundary " << b.id << " (" << b.n_kinks << " of " << b.n_joints
                  << " joints)";
        if (b.fits_sphere)
          std::cout << std::fixed << std::setprecision(6) << " on circle (" << b.centre[0] << ", "
                    << b.centre[1] << "), R = " << b.radius << std::defaultfloat;
      }
    std::cout << std::endl;
  }

  void
  polygons()
  {
    {
      Triangulation<2> disc, flat;
      GridGenerator::hyper_ball(disc, Point<2>(1., 2.), 3.);
      disc.refine_global(2);
      GridGenerator::flatten_triangulation(disc, flat);
      report_polygons("16-gon of a circle", flat);
    }
    {
      Triangulation<2> disc, flat;
      GridGenerator::hyper_ball(disc, Point<2>(1., 2.), 3.);
      disc.refine_global(1);
      GridGenerator::flatten_triangulation(disc, flat);
      report_polygons("octagon", flat);
    }
    {
      Triangulation<2> shell, flat;
      GridGenerator::hyper_shell(shell, Point<2>(), 1., 2., 8, true);
      shell.refine_global(1);
      GridGenerator::flatten_triangulation(shell, flat);
      // flatten_triangulation keeps the boundary ids (0 inner, 1 outer).
      report_polygons("flattened annulus", flat);
    }
    {
      Triangulation<2> rectangle;
      GridGenerator::subdivided_hyper_rectangle(rectangle, {8, 4}, Point<2>(), Point<2>(4., 1.));
      report_polygons("subdivided rectangle", rectangle);
    }
    {
      Triangulation<2> l_shape;
      GridGenerator::hyper_L(l_shape);
      l_shape.refine_global(2);
      Triangulation<2> flat;
      GridGenerator::flatten_triangulation(l_shape, flat);
      report_polygons("L-shape", flat);
    }
  }

  void
  report_polygons_3d(const std::string &name, const Triangulation<3> &tria)
  {
    std::cout << name << ":";
    const auto found = find_polygonal_boundaries(tria, {});
    if (found.empty())
      std::cout << " no polygonal boundary";
    const auto clean = [](const double x) {
      return std::abs(x) < 1e-9 ? 0. : x;
    };
    std::cout << std::fixed << std::setprecision(6);
    for (const auto &b : found)
      {
        std::cout << " boundary " << b.id << " (" << b.n_kinks << " of " << b.n_joints
                  << " joints)";
        if (b.fits_cylinder)
          std::cout << " on cylinder through (" << clean(b.axis_point[0]) << ", "
                    << clean(b.axis_point[1]) << ", " << clean(b.axis_point[2]) << "), axis ("
                    << clean(b.axis[0]) << ", " << clean(b.axis[1]) << ", " << clean(b.axis[2])
                    << "), R = " << b.cylinder_radius;
        if (b.fits_sphere)
          std::cout << " on sphere (" << clean(b.centre[0]) << ", " << clean(b.centre[1]) << ", "
                    << clean(b.centre[2]) << "), R = " << b.radius;
      }
    std::cout << std::defaultfloat << std::endl;
  }

  /// Extrusions of the 16-gon of a circle (centre (1, 2), R = 3) along z:
  /// the hull is a polygonal cylinder. With one layer its vertices lie on
  /// two circles, hence on a sphere too; the cylinder is the surface (its
  /// faces are all parallel to z). A flattened polygonal ball is a sphere,
  /// not a cylinder.
  void
  polygons_3d()
  {
    Triangulation<2> disc, flat;
    GridGenerator::hyper_ball(disc, Point<2>(1., 2.), 3.);
    disc.refine_global(2);
    GridGenerator::flatten_triangulation(disc, flat);
    for (const unsigned int layers : {1u, 2u})
      {
        Triangulation<3> extruded;
        GridGenerator::extrude_triangulation(flat, layers + 1, 1., extruded);
        // Only the hull: the ends z = 0 and z = 1 are flat.
        for (const auto &cell : extruded.active_cell_iterators())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const double z = cell->face(f)->center()[2];
                cell->face(f)->set_boundary_id(std::abs(z) < 1e-12 || std::abs(z - 1.) < 1e-12 ? 5 :
                                                                                                 0);
              }
        report_polygons_3d("16-gon extruded in " + std::to_string(layers) + " layer(s)", extruded);
      }
    {
      Triangulation<3> ball, flat_ball;
      GridGenerator::hyper_ball(ball, Point<3>(1., 2., 3.), 2.);
      ball.refine_global(2);
      GridGenerator::flatten_triangulation(ball, flat_ball);
      report_polygons_3d("polygonal ball", flat_ball);
    }
  }

  /// Two unit squares side by side, not merged: [0,1]^2 and [1,2] x [0,1],
  /// with the materials and the ids of the faces on x = 1 given.
  void
  two_blocks(const std::string       &name,
             const types::material_id left_body,
             const types::material_id right_body,
             const types::boundary_id interface_id,
             const double             right_shift_y = 0.)
  {
    std::vector<Point<2>> vertices = {{0., 0.}, {1., 0.}, {0., 1.}, {1., 1.}};
    for (const auto &p : {Point<2>(1., 0.), Point<2>(2., 0.), Point<2>(1., 1.), Point<2>(2., 1.)})
      vertices.push_back(p + Point<2>(0., right_shift_y));
    std::vector<CellData<2>> cells(2, CellData<2>(4));
    for (unsigned int v = 0; v < 4; ++v)
      {
        cells[0].vertices[v] = v;
        cells[1].vertices[v] = v + 4;
      }
    cells[0].material_id = left_body;
    cells[1].material_id = right_body;
    Triangulation<2> tria;
    tria.create_triangulation(vertices, cells, SubCellData());
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && std::abs(cell->face(f)->center()[0] - 1.) < 1e-12)
          cell->face(f)->set_boundary_id(interface_id);
    try
      {
        check_unmerged_vertices(tria, "blocks.msh");
        std::cout << name << ": passes" << std::endl;
      }
    catch (const std::exception &e)
      {
        const std::string what = e.what();
        std::cout << name << ": refused ("
                  << (what.find("Coherence") != std::string::npos ? "crack, Coherence named" :
                                                                    "other")
                  << ")" << std::endl;
      }
  }

  void
  fits()
  {
    std::vector<Point<3>> points;
    const Point<3>        centre(1., -2., 0.5);
    for (unsigned int i = 0; i < 10; ++i)
      {
        const double theta = 0.3 * i, phi = 0.7 * i;
        points.push_back(centre + 2.5 * Point<3>(std::sin(theta) * std::cos(phi),
                                                 std::sin(theta) * std::sin(phi), std::cos(theta)));
      }
    Point<3>   c;
    double     r = 0., deviation = 0.;
    const bool ok = fit_sphere(points, c, r, deviation);
    std::cout << "sphere fit: " << (ok ? "found" : "none") << ", centre error "
              << (c.distance(centre) < 1e-10 ? "< 1e-10" : "large") << ", radius error "
              << (std::abs(r - 2.5) < 1e-10 ? "< 1e-10" : "large") << std::endl;
    const std::vector<Point<2>> line = {{0., 0.}, {1., 1.}, {2., 2.}, {3., 3.}};
    Point<2>                    c2;
    std::cout << "collinear points: "
              << (fit_sphere(line, c2, r, deviation) ? "fitted" : "no circle") << std::endl;
  }

  /// One cell [0,1] x [0,h] whose top face is the arc of the circle through
  /// its top corners sagging to y = y_low.
  void
  sagging_cell(const std::string &name, const double h, const double y_low)
  {
    Triangulation<2> tria;
    GridGenerator::hyper_rectangle(tria, Point<2>(), Point<2>(1., h));
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->center()[1] > 0.5 * h)
          cell->face(f)->set_boundary_id(3);
    // Centre (0.5, c) and radius c - y_low through (0, h) and (1, h).
    const double       c = (0.25 + h * h - y_low * y_low) / (2. * (h - y_low));
    std::ostringstream entry;
    entry << std::setprecision(15) << "3: circle 0.5, " << c << ", " << c - y_low;
    const auto manifolds = parse_boundary_manifolds<2>(entry.str(), "Geometry/Manifolds");
    try
      {
        check_boundary_manifolds(manifolds, tria, "Geometry/Manifolds");
        set_manifold_ids(manifolds, true, tria);
        check_refinement_on_manifolds(manifolds, true, tria, "Geometry/Manifolds");
        std::cout << name << ": passes" << std::endl;
      }
    catch (const std::exception &e)
      {
        const std::string what = e.what();
        std::cout << name << ": refused ("
                  << (what.find("inverts") != std::string::npos ? "inverted cells" : "other") << ")"
                  << std::endl;
      }
  }
  void
  cylinder(const std::string &entry)
  {
    Triangulation<3> tria;
    GridGenerator::cylinder(tria, 1., 1.);
    Triangulation<3> flat;
    GridGenerator::flatten_triangulation(tria, flat);
    try
      {
        const auto manifolds = parse_boundary_manifolds<3>(entry, "Geometry/Manifolds");
        check_boundary_manifolds(manifolds, flat, "Geometry/Manifolds");
        set_manifold_ids(manifolds, true, flat);
        check_refinement_on_manifolds(manifolds, true, flat, "Geometry/Manifolds");
        std::cout << "3D cylinder hull, '" << entry << "': passes" << std::endl;
      }
    catch (const std::exception &e)
      {
        const std::string what = e.what();
        std::cout << "3D cylinder hull, '" << entry << "': refused ("
                  << (what.find("lies") != std::string::npos ? "vertex off the surface" : "other")
                  << ")" << std::endl;
      }
  }
} // namespace

int
main()
{
  polygons();
  polygons_3d();
  two_blocks("two bodies touching along a line", 1, 2, 0);
  two_blocks("one body, untagged faces on top of each other", 1, 1, 0);
  two_blocks("one body, tagged internal surface", 1, 1, 5);
  two_blocks("one body pinched at one point", 1, 1, 0, 1.);
  fits();
  sagging_cell("cell with a shallow concave arc", 1., 0.8);
  sagging_cell("thin cell whose arc sags through its base", 0.2, -0.1);
  cylinder("0: cylinder 0, 0, 0, 1, 0, 0, 1");
  cylinder("0: cylinder 0, 0, 0, 1, 0, 0, 1.1");
  cylinder("0: sphere 0, 0, 0, 1");
}
