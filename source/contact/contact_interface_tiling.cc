// The tiling checks of ContactInterface, the part of the contact geometry
// that differs by dimension: the overlaps of a slave face with its masters
// are intervals of a line face in 2D and polygons of a quadrilateral face in
// 3D.
#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/core/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

namespace contact_fem
{
  template <>
  void
  ContactInterface<2>::check_tiling(const unsigned int                   f,
                                    const std::vector<Mortar::LineFace> &lines,
                                    const std::vector<Tensor<1, 2>> &,
                                    const std::vector<unsigned int>   &masters,
                                    const Mortar::Kernel<2>::Overlaps &overlaps,
                                    const std::vector<unsigned int>   &facing) const
  {
    const auto &intervals     = overlaps.intervals;
    const auto &bounding_ends = overlaps.bounding_ends;
    // Walk the covered intervals of the slave face in order. Every part
    // left uncovered must end at the rim of the master surface: at a slave
    // end, or at a master node that no other facing master face shares.
    // A shared node there means that a master face which covers the gap was
    // lost by the segmentation, and the dual weights D_j of the slave nodes
    // would shrink (nodal pressures = force / D_j spike): stop instead.
    std::vector<unsigned int> order(masters.size());
    for (unsigned int k = 0; k < order.size(); ++k)
      order[k] = k;
    std::sort(order.begin(), order.end(), [&](const unsigned int a, const unsigned int b) {
      return intervals[a].first < intervals[b].first;
    });
    // Near contact (a master node closer to its slave image than a slave
    // face length) the facing master faces are a graph over the slave face,
    // so their overlaps must join; farther away the normal lines may cross
    // before they reach the master, and a gap is no sign of a lost face.
    // side: 0 for the lower end of interval k, 1 for its upper end.
    const double slave_length = lines[f].nodes[0].distance(lines[f].nodes[1]);
    const auto   check_end    = [&](const unsigned int k, const unsigned int side) {
      const int end = bounding_ends[k][side];
      if (end < 0)
        return;
      const double   xi = side == 0 ? intervals[k].first : intervals[k].second;
      const Point<2> x  = lines[masters[k]].nodes[end];
      if (x.distance(lines[f].point(xi)) > slave_length)
        return;
      const unsigned int node = faces[masters[k]].nodes[end];
      for (const unsigned int m : facing)
        AssertThrow(m == masters[k] || std::find(faces[m].nodes.begin(), faces[m].nodes.begin() + 2,
                                                      node) == faces[m].nodes.begin() + 2,
                         ExcMessage("Contact pair " + std::to_string(faces[f].pair) +
                                    ": the master faces leave a hole under the slave face from " +
                                    coordinates_text(lines[f].nodes[0]) + " to " +
                                    coordinates_text(lines[f].nodes[1]) + " at the master node " +
                                    coordinates_text(x) +
                                    ", inside the master surface. The mortar segmentation "
                                         "lost a face; the contact pressures would be wrong."));
    };
    // Overlaps meet at the slave image of their shared master node up to
    // the precision of that image.
    constexpr double meeting_tolerance = 1e-10;
    double           reach             = -1.;
    int              reach_face        = -1;
    for (const unsigned int k : order)
      {
        if (intervals[k].first > reach + meeting_tolerance)
          {
            if (reach_face >= 0)
              check_end(reach_face, 1);
            check_end(k, 0);
          }
        if (intervals[k].second > reach)
          {
            reach      = intervals[k].second;
            reach_face = k;
          }
      }
    if (reach < 1. - meeting_tolerance)
      check_end(reach_face, 1);
  }

  namespace
  {
    /// Distance in the plane from the segment [a, b] to the convex polygon
    /// @p ring (counterclockwise or clockwise): 0 where they meet.
    double
    planar_distance(const Point<2> &a, const Point<2> &b, const std::vector<Point<2>> &ring)
    {
      const auto cross = [](const Tensor<1, 2> &u, const Tensor<1, 2> &v) {
        return u[0] * v[1] - u[1] * v[0];
      };
      const auto point_to_segment = [](const Point<2> &x, const Point<2> &p, const Point<2> &q) {
        const Tensor<1, 2> d = q - p;
        const double       t =
          d.norm_square() > 0. ? std::clamp((x - p) * d / d.norm_square(), 0., 1.) : 0.;
        return x.distance(p + t * d);
      };
      // Inside: on the same side of every edge.
      bool positive = true, negative = true;
      for (std::size_t k = 0; k < ring.size(); ++k)
        {
          const double side = cross(ring[(k + 1) % ring.size()] - ring[k], a - ring[k]);
          positive          = positive && side >= 0.;
          negative          = negative && side <= 0.;
        }
      if (positive || negative)
        return 0.;
      double distance = std::numeric_limits<double>::max();
      for (std::size_t k = 0; k < ring.size(); ++k)
        {
          const Point<2> &p = ring[k], &q = ring[(k + 1) % ring.size()];
          const double    s1 = cross(q - p, a - p), s2 = cross(q - p, b - p);
          const double    s3 = cross(b - a, p - a), s4 = cross(b - a, q - a);
          if (((s1 < 0.) != (s2 < 0.)) && ((s3 < 0.) != (s4 < 0.)))
            return 0.;
          distance = std::min({distance, point_to_segment(a, p, q), point_to_segment(b, p, q),
                               point_to_segment(p, a, b), point_to_segment(q, a, b)});
        }
      return distance;
    }
  } // namespace

  template <>
  void
  ContactInterface<3>::check_tiling(const unsigned int                   f,
                                    const std::vector<Mortar::QuadFace> &quads,
                                    const std::vector<Tensor<1, 3>>     &normals,
                                    const std::vector<unsigned int>     &masters,
                                    const Mortar::Kernel<3>::Overlaps   &polygons,
                                    const std::vector<unsigned int>     &facing) const
  {
    // Neighbouring overlap polygons share their vertices (the slave images
    // of the same clipped points), so where the facing master faces cover
    // the slave face they tile its parameter square [-1, 1]^2: area 4.
    // That is expected where the slave face is near the master (closer
    // than its diameter: the master is a graph over it) and no rim edge of
    // the facing master faces (an edge only one of them has; also where
    // they meet a hanging vertex) comes within its diameter.
    const Mortar::QuadFace &slave = quads[f];
    const Point<2>          centre;
    const Point<3>          middle = slave.point(centre);
    const double            diameter =
      std::max(slave.nodes[0].distance(slave.nodes[3]), slave.nodes[1].distance(slave.nodes[2]));
    bool near = false;
    for (const unsigned int m : masters)
      {
        Point<2> eta;
        near =
          near ||
          (Mortar::project_along(quads[m], middle,
                                 Mortar::face_normal(slave, centre, faces[f].orientation), eta) &&
           std::abs(eta[0]) <= 1. && std::abs(eta[1]) <= 1. &&
           quads[m].point(eta).distance(middle) < diameter);
      }
    if (!near)
      return;
    // The slave face and the rim edges seen along its normal, in the
    // tangent plane at its centre.
    const Tensor<1, 3> n  = Mortar::face_normal(slave, centre, 1.);
    Tensor<1, 3>       e1 = slave.tangents(centre)[0];
    e1 -= (e1 * n) * n;
    e1 /= e1.norm();
    const Tensor<1, 3> e2       = cross_product_3d(n, e1);
    const auto         in_plane = [&](const Point<3> &x) {
      return Point<2>((x - middle) * e1, (x - middle) * e2);
    };
    std::vector<Point<2>> ring;
    for (const unsigned int v : {0, 1, 3, 2})
      ring.push_back(in_plane(slave.nodes[v]));
    // Per vertex edge of the facing faces: how many of them have it.
    std::map<std::pair<unsigned int, unsigned int>,
             std::pair<unsigned int, std::array<Point<3>, 2>>>
      edges;
    for (const unsigned int m : facing)
      for (const auto &[a, b] :
           {std::pair(0, 1), std::pair(2, 3), std::pair(0, 2), std::pair(1, 3)})
        {
          auto &edge = edges[std::minmax(faces[m].nodes[a], faces[m].nodes[b])];
          ++edge.first;
          edge.second = {{quads[m].nodes[a], quads[m].nodes[b]}};
        }
    // A rim edge that comes within a tenth of the diameter of the slave
    // face (curved faces bulge beyond their vertices) may bound a part that
    // is rightly uncovered.
    for (const auto &[key, edge] : edges)
      if (edge.first == 1 && planar_distance(in_plane(edge.second[0]), in_plane(edge.second[1]),
                                             ring) < 0.1 * diameter)
        return;

    // Covered area against the face's, both projected along n0 into the
    // auxiliary plane of the segmentation, where the overlaps' edges are
    // straight: exact up to round-off (Mortar::projected_area()). The sum
    // of the polygons' areas in the slave parameters is not, on curved
    // faces: an edge straight in the plane bends in the parameters, and a
    // zero-width join of the clipping (a piece that runs along a fan cut of
    // the slave and back) gains an area there. That sum stopped a run at
    // 2 % random node motion on Q2 faces with 1.00058 of the face covered,
    // the join's O(bending) area (tests/unit/contact_interface_tiling_01).
    const double area  = Mortar::projected_area(slave, normals, polygons);
    const double whole = Mortar::projected_area(slave, normals,
                                                {{Point<2>(-1., -1.), Point<2>(1., -1.),
                                                  Point<2>(1., 1.), Point<2>(-1., 1.)}});
    // Signed: negative where the slave parameters run clockwise seen
    // along n0 (both alike).
    constexpr double tiling_tolerance = 1e-8;
    AssertThrow(std::abs(area - whole) <= std::abs(whole) * tiling_tolerance,
                ExcMessage("Contact pair " + std::to_string(faces[f].pair) +
                           ": the master faces cover " + std::to_string(area / whole) +
                           " of the slave face centred at " + coordinates_text(middle) +
                           ", which lies inside the master surface. The mortar "
                           "segmentation lost or doubled a part; the contact pressures "
                           "would be wrong."));
  }
} // namespace contact_fem
