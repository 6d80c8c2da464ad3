// support_lever_arms(): the kinematic pre-check of the held-rotation probe.
// For supports whose answer is known by hand: the lever arm with which they
// hold each rotation (the largest motion of a fixed DoF under the rigid
// motion with a unit rotation that moves them least), zero for a rotation
// they do not hold. Covers 2D and 3D, a free rotation (one fixed point, a
// line of points along the axis), a tiny lever arm (two fixed points close
// together), clamped edges and planes, and a plane meshed densely at one end
// (the lever arm must stay of the size of the plane, not shrink with the
// mean distance of its DoFs). The fixed DoFs are dealt out to the ranks in
// turn: the output does not depend on the number of MPI ranks.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <contact_fem/solvers/rigid_body_modes.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace dealii;
using namespace contact_fem;

namespace
{
  template <int dim>
  void
  print_lever_arms(const std::string                &name,
                   const std::vector<FixedDof<dim>> &all,
                   const double                      size,
                   ConditionalOStream               &out)
  {
    const MPI_Comm             comm    = MPI_COMM_WORLD;
    const unsigned int         rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int         n_ranks = Utilities::MPI::n_mpi_processes(comm);
    std::vector<FixedDof<dim>> mine;
    for (unsigned int i = rank; i < all.size(); i += n_ranks)
      mine.push_back(all[i]);
    const std::vector<double> levers = support_lever_arms(mine, Point<dim>(), size, comm);
    out << name << ":";
    for (unsigned int r = 0; r < levers.size(); ++r)
      {
        // Round-off of a free rotation prints as 0.
        const double lever = levers[r] < 1e-10 ? 0. : levers[r];
        out << "  " << (dim == 2 ? 'z' : "xyz"[r]) << " " << std::fixed << std::setprecision(4)
            << lever;
      }
    out << std::endl;
  }

  template <int dim>
  FixedDof<dim>
  fixed(const Point<dim> &point, const unsigned int component)
  {
    return {point, component};
  }

  /// The points of a square of side 2 about the origin, normal to @p
  /// normal, n x n of them, each with its coordinates s^grading (s in
  /// [-1, 1], the sign kept): grading > 1 crowds them toward the middle.
  std::vector<Point<3>>
  square(const unsigned int normal, const unsigned int n, const double grading = 1.)
  {
    std::vector<Point<3>> points;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          const auto coordinate = [&](const unsigned int k) {
            const double s = -1. + 2. * k / (n - 1);
            return std::copysign(std::pow(std::abs(s), grading), s);
          };
          Point<3> p;
          p[(normal + 1) % 3] = coordinate(i);
          p[(normal + 2) % 3] = coordinate(j);
          points.push_back(p);
        }
    return points;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ConditionalOStream out(std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
  out << "lever arm over the size per rotation axis (0: not held)" << std::endl;

  // 2D.
  print_lever_arms<2>("2D no supports", {}, 1., out);
  print_lever_arms<2>("2D u_x fixed at (0, -4) and (0, 4): 4",
                      {fixed(Point<2>(0, -4), 0), fixed(Point<2>(0, 4), 0)}, 1., out);
  print_lever_arms<2>("2D the same over a size of 8: 0.5",
                      {fixed(Point<2>(0, -4), 0), fixed(Point<2>(0, 4), 0)}, 8., out);
  print_lever_arms<2>("2D u_x fixed at two points 0.01 apart: 0.005",
                      {fixed(Point<2>(0, 1), 0), fixed(Point<2>(0, 1.01), 0)}, 1., out);
  print_lever_arms<2>("2D one point fixed in x and y: free",
                      {fixed(Point<2>(3, 1), 0), fixed(Point<2>(3, 1), 1)}, 1., out);
  {
    std::vector<FixedDof<2>> edge, crowded;
    for (unsigned int i = 0; i <= 20; ++i)
      for (unsigned int d = 0; d < 2; ++d)
        {
          const double s = -1. + i / 10.;
          edge.push_back(fixed(Point<2>(s, -1), d));
          // Crowded toward x = -1 (a mesh graded toward a corner).
          crowded.push_back(fixed(Point<2>(-1. + 2. * std::pow((s + 1.) / 2., 4), -1), d));
        }
    print_lever_arms<2>("2D clamped edge y = -1, x in [-1, 1]: 1", edge, 1., out);
    print_lever_arms<2>("2D the same edge meshed densely at x = -1: of the edge's size", crowded,
                        1., out);
  }

  // 3D.
  print_lever_arms<3>("3D no supports", {}, 1., out);
  {
    std::vector<FixedDof<3>> plane, two_planes, graded;
    for (const auto &p : square(0, 11))
      plane.push_back(fixed(p, 0));
    two_planes = plane;
    for (const auto &p : square(1, 11))
      two_planes.push_back(fixed(p, 1));
    for (const auto &p : square(0, 11, 4.))
      graded.push_back(fixed(p, 0));
    print_lever_arms<3>("3D u_x fixed on the plane x = 0: y 1, z 1, x free", plane, 1., out);
    print_lever_arms<3>("3D the same plane meshed densely at its middle: y 1, z 1, x free", graded,
                        1., out);
    print_lever_arms<3>("3D u_x on x = 0 and u_y on y = 0 (symmetry planes): all held", two_planes,
                        1., out);
  }
  // The fixed points of prm/two_cylinders_3d.prm (the slices z = 0, 1 are
  // held by other supports): only the rotation about z is held by them.
  print_lever_arms<3>("3D u_x fixed at (0, +-4, 0), (0, +-4, 1): z 4, y 0.5, x free",
                      {fixed(Point<3>(0, -4, 0), 0), fixed(Point<3>(0, 4, 0), 0),
                       fixed(Point<3>(0, -4, 1), 0), fixed(Point<3>(0, 4, 1), 0)},
                      1., out);
  {
    std::vector<FixedDof<3>> line;
    for (unsigned int i = 0; i <= 4; ++i)
      for (const unsigned int d : {0u, 2u})
        line.push_back(fixed(Point<3>(0, -2. + i, 0), d));
    print_lever_arms<3>("3D u_x, u_z fixed along the y axis, y in [-2, 2]: x 2, z 2, y free", line,
                        1., out);
  }
}
