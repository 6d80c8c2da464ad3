// check_hexahedron() (source/geometry/hexahedron_shape.cc) on cells whose
// shape is known by construction, in Gmsh's node order:
//  - the unit cube and a sheared, stretched one are valid;
//  - the cube listed from its other face first (the opposite turn) is
//    mirrored (deal.II's reader reorders it);
//  - two coincident nodes: a collapsed edge, named by its two nodes;
//  - a corner pulled into the plane of its neighbours: flat there;
//  - all eight corners in one plane: no volume (a collapsed edge first);
//  - two nodes of a face swapped: twisted, with corners of both signs.
#include <contact_fem/geometry/hexahedron_shape.h>

#include <iomanip>
#include <iostream>
#include <string>

using namespace dealii;
using namespace contact_fem;

namespace
{
  std::array<Point<3>, 8>
  unit_cube()
  {
    return {{Point<3>(0, 0, 0), Point<3>(1, 0, 0), Point<3>(1, 1, 0), Point<3>(0, 1, 0),
             Point<3>(0, 0, 1), Point<3>(1, 0, 1), Point<3>(1, 1, 1), Point<3>(0, 1, 1)}};
  }

  void
  report(const std::string &name, const std::array<Point<3>, 8> &x)
  {
    static const char    *names[] = {"valid", "mirrored", "collapsed edge", "flat", "twisted"};
    const HexahedronCheck check   = check_hexahedron(x);
    std::cout << name << ": " << names[static_cast<int>(check.shape)];
    if (check.shape != HexahedronShape::valid && check.shape != HexahedronShape::mirrored)
      std::cout << " at node " << check.first
                << (check.second != check.first ? "-" + std::to_string(check.second) : "");
    if (check.shape != HexahedronShape::collapsed_edge)
      std::cout << std::fixed << std::setprecision(4) << ", corners " << check.min_corner << " to "
                << check.max_corner << ", " << check.n_negative << " negative";
    std::cout << std::endl;
  }
} // namespace

int
main()
{
  report("unit cube", unit_cube());

  auto sheared = unit_cube();
  for (auto &p : sheared)
    p = Point<3>(2. * p[0] + 0.3 * p[2], p[1], 0.5 * p[2]);
  report("sheared and stretched cube", sheared);

  auto mirrored = unit_cube();
  for (unsigned int i = 0; i < 4; ++i)
    std::swap(mirrored[i], mirrored[i + 4]);
  report("cube listed from its top face", mirrored);

  auto collapsed = unit_cube();
  collapsed[7]   = collapsed[6];
  report("nodes 6 and 7 at one point", collapsed);

  auto flat_corner = unit_cube();
  flat_corner[7]   = Point<3>(0.5, 0.5, 1);
  report("node 7 in the plane of its neighbours", flat_corner);

  auto flat_cell = unit_cube();
  for (auto &p : flat_cell)
    p[2] = 0.;
  report("all corners in the plane z = 0", flat_cell);

  auto twisted = unit_cube();
  std::swap(twisted[6], twisted[7]);
  report("nodes 6 and 7 swapped", twisted);
}
