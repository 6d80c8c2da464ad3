// A 2D slave face whose end normals cross (an indented slave face under a
// die: the normals of its ends lean towards each other) against a distant,
// steep master face beside and above the crossing (the die's flank): the
// chord lines of the normals meet the master's line on either side of the
// master face, so the ends' projections bracket it, yet no normal line
// between them reaches it (the map xi -> eta is not monotone there).
// Mortar::overlap() used to report an overlap (taking the nearer slave end
// for the master ends that lie outside both end normal lines), and
// integrate_pair() then stopped the run: "a quadrature point of its overlap
// that does not project onto the master face" (the ironing scene with
// slides of 0.75 element lengths per load step, on the first Newton iterate
// of a step). Now the faces do not overlap. The same slave face against a
// master just above it still overlaps it over its whole length.
#include <contact_fem/contact/mortar.h>

#include <cmath>
#include <iostream>

using namespace dealii;
using namespace contact_fem;

namespace
{
  Mortar::LineFace
  segment(const Point<2> &a, const Point<2> &b)
  {
    Mortar::LineFace face;
    face.nodes = {a, b};
    return face;
  }

  void
  report(const std::string &name, const Mortar::LineFace &master)
  {
    const Mortar::LineFace          slave = segment(Point<2>(0., 0.), Point<2>(1., 0.));
    const double                    a     = std::acos(-1.) / 6.; // 30 degrees
    const std::vector<Tensor<1, 2>> normals = {Tensor<1, 2>({std::sin(a), std::cos(a)}),
                                               Tensor<1, 2>({-std::sin(a), std::cos(a)})};
    double                          lower = 0., upper = 0.;
    const bool                      overlaps = Mortar::overlap(slave, normals, master, lower, upper);
    std::cout << name << ": overlap " << (overlaps ? "yes" : "no");
    if (overlaps)
      std::cout << ", slave parameters [" << lower << ", " << upper << "]";
    FullMatrix<double> A(2, 2);
    A(0, 0) = A(1, 1) = 1.;
    Mortar::SegmentOperators ops;
    const bool               integrated = Mortar::integrate_pair(slave, normals, A, master, 3, ops);
    std::cout << "; integrate_pair " << (integrated ? "integrates" : "finds no overlap")
              << std::endl;
  }
} // namespace

int
main()
{
  report("steep master beside the normals' crossing",
         segment(Point<2>(3., 2.), Point<2>(2.9, 0.3)));
  report("master above the slave, before the crossing",
         segment(Point<2>(1.5, 0.1), Point<2>(-0.5, 0.1)));
}
