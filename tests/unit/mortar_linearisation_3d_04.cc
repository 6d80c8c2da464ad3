// Derivatives of the vertices of the 3D mortar segmentation with respect
// to the node coordinates: the overlap polygons of a slave face with its
// master (slave parameters (xi, eta) of the clipped polygon's vertices:
// master nodes projected inside the slave, slave corners inside the
// master, crossings of master and slave edges), as the AD path of
// linearise_slave_face() computes them (mortar_3d.cc, overlap_of(); chained
// through the averaged nodal normals, which set the auxiliary plane and the
// projection direction), against central finite differences of the double
// path's vertices at h and h/2 (h = 1e-3 of the slave face's diagonal).
// mortar_linearisation_3d_01 and _03 check D, M, the gaps and the normals,
// which are integrals over the polygons; here the vertices themselves.
//
// The slave face is the centre of a 3 x 3 patch on a curved surface, every
// node moved at random by up to 2 % of the face size; masters lie above
// it (a gap, so the projection direction matters), turned against the
// slave grid:
//  - a bilinear master inside the slave face (all vertices projected
//    master corners),
//  - a bilinear master partly overlapping (a master corner inside the
//    slave, a slave corner inside the master, two edge crossings),
//  - a bilinear master of the slave's size turned by 40 degrees (eight
//    edge crossings),
//  - a warped bilinear master (its corners 0.1 of the face size off a
//    plane, alternately up and down) partly overlapping,
//  - biquadratic faces, the slave's edges bent in its tangent plane and
//    the master's bulging: master edges cross curved slave edges (vertices
//    by bisection, derivatives by the implicit-function theorem),
//  - the partly overlapping bilinear case rotated and translated by 100
//    face sizes: its vertices and their derivatives (turned back) must equal
//    the unmoved case's within 1e-9 and 1e-8 of the scale, since the
//    geometry's tolerances are relative to the face size.
//
// Checks: the AD vertex values equal the double path's exactly; at every
// perturbed point the vertices are the same ones in the same order (same
// polygon sizes, each vertex within 1/4 of the smallest distance between
// vertices of its unperturbed position); for every derivative (each vertex
// coordinate by each patch coordinate) the finite-difference error e falls
// at second order, e(h) / e(h/2) in [3.5, 4.5], unless e(h) is round-off
// (below 1e-10 (1 + R / L) of the case's scale, its largest derivative; R
// the largest distance of a node from the origin, L the face diagonal: 3e-10
// here, 1.2e-8 for the moved case; then the vertex is at most quadratic in
// that coordinate or does not depend on it), and e(h/2) is below 1e-5 of
// the scale. A wrong derivative (off by more than the round-off bound)
// gives a ratio near 1. The median ratio is printed rounded to an integer.
#include <contact_fem/contact/mortar_3d_linearisation.h>

#include "unit_test_random.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <string>

using namespace dealii;
using namespace contact_fem;
using namespace contact_fem::Mortar;

namespace
{
  using Surface = std::function<Point<3>(const double, const double)>;

  /// Grid steps (of 1 / p) of node @p i of a face of degree @p p from its
  /// first corner.
  std::array<unsigned int, 2>
  node_offset(const unsigned int p, const unsigned int i)
  {
    const Point<2> xi = quad_node_parameter(p, i);
    return {{static_cast<unsigned int>(std::lround(0.5 * (xi[0] + 1.) * p)),
             static_cast<unsigned int>(std::lround(0.5 * (xi[1] + 1.) * p))}};
  }

  /// The slave patch: 3 x 3 faces of geometry degree @p p on @p slave over
  /// [-1, 2]^2, the centre face [0, 1]^2 first.
  QuadFacePatch
  slave_patch(const Surface &slave, const unsigned int p)
  {
    const unsigned int n = 3 * p + 1;
    QuadFacePatch      patch;
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = 0; i < n; ++i)
        patch.points.push_back(slave(-1. + double(i) / p, -1. + double(j) / p));
    const auto face = [&](const unsigned int i, const unsigned int j) {
      QuadFacePatch::Face f;
      for (unsigned int k = 0; k < (p + 1) * (p + 1); ++k)
        {
          const auto o = node_offset(p, k);
          f.nodes.push_back((p * j + o[1]) * n + p * i + o[0]);
        }
      return f;
    };
    patch.slave_faces.push_back(face(1, 1));
    for (unsigned int j = 0; j < 3; ++j)
      for (unsigned int i = 0; i < 3; ++i)
        if (i != 1 || j != 1)
          patch.slave_faces.push_back(face(i, j));
    return patch;
  }

  /// A master face of degree @p p of the points of @p master at the
  /// bilinear interpolation of @p corners ((x, y), deal.II's vertex
  /// order), edge midpoints moved out from the centre by the factor
  /// @p bulge.
  void
  add_master(QuadFacePatch                 &patch,
             const Surface                 &master,
             const std::array<Point<2>, 4> &corners,
             const unsigned int             p,
             const double                   bulge = 1.)
  {
    const auto bilinear = [&](const double s, const double t) {
      return Point<2>((1. - s) * (1. - t) * corners[0] + s * (1. - t) * corners[1] +
                      (1. - s) * t * corners[2] + s * t * corners[3]);
    };
    const Point<2>      centre = bilinear(0.5, 0.5);
    QuadFacePatch::Face face;
    for (unsigned int k = 0; k < (p + 1) * (p + 1); ++k)
      {
        const auto o = node_offset(p, k);
        Point<2>   x = bilinear(double(o[0]) / p, double(o[1]) / p);
        if (k >= 4 && k < 8)
          x = centre + bulge * (x - centre);
        face.nodes.push_back(patch.points.size());
        patch.points.push_back(master(x[0], x[1]));
      }
    patch.masters.push_back(face);
  }

  void
  perturb(QuadFacePatch &patch, Random &random)
  {
    for (Point<3> &x : patch.points)
      for (unsigned int d = 0; d < 3; ++d)
        x[d] += 0.02 * random.next();
  }

  /// The vertices of all overlap polygons of @p pairs, and the topology:
  /// per master the number of polygons, then their vertex counts.
  struct Vertices
  {
    std::vector<const Linearised *> coordinates;
    std::vector<Point<2>>           values;
    std::vector<unsigned int>       topology;
  };

  Vertices
  vertices_of(const std::vector<LinearisedQuadPair> &pairs)
  {
    Vertices v;
    for (const LinearisedQuadPair &pair : pairs)
      {
        v.topology.push_back(pair.vertices.size());
        for (const auto &polygon : pair.vertices)
          {
            v.topology.push_back(polygon.size());
            for (const auto &xi : polygon)
              {
                v.coordinates.push_back(&xi[0]);
                v.coordinates.push_back(&xi[1]);
                v.values.emplace_back(xi[0].value, xi[1].value);
              }
          }
      }
    return v;
  }

  /// The vertex values with coordinate @p i moved by @p h (@p step: the
  /// move as represented); false if the topology or a vertex is not that
  /// of @p base (a vertex farther than @p match from its position).
  bool
  perturbed_vertices(QuadFacePatch          patch,
                     const unsigned int     i,
                     const double           h,
                     const Vertices        &base,
                     const double           match,
                     std::vector<Point<2>> &values,
                     double                &step)
  {
    double      &x     = patch.points[i / 3][i % 3];
    const double start = x;
    x += h;
    step = x - start;
    std::vector<LinearisedQuadPair> pairs;
    if (!linearise_slave_face(patch, false, pairs, true))
      return false;
    const Vertices v = vertices_of(pairs);
    if (v.topology != base.topology)
      return false;
    for (unsigned int k = 0; k < v.values.size(); ++k)
      if (v.values[k].distance(base.values[k]) > match)
        return false;
    values = v.values;
    return true;
  }

  /// The derivatives of the vertices of @p patch (AD path), checked.
  std::vector<LinearisedQuadPair>
  check(const std::string &name, const QuadFacePatch &patch)
  {
    std::vector<LinearisedQuadPair> exact, doubles;
    if (!linearise_slave_face(patch, true, exact, true) ||
        !linearise_slave_face(patch, false, doubles, true))
      {
        std::cout << name << ": no overlap" << std::endl;
        return exact;
      }
    const Vertices     v = vertices_of(exact), w = vertices_of(doubles);
    const unsigned int n = 3 * patch.points.size();
    std::cout << name << " (" << n << " coordinates)" << std::endl;

    // Kinds of vertices: slave corners, on a slave edge (a crossing of
    // edges), inside the slave face (a projected master node).
    unsigned int corners = 0, on_edges = 0, inside = 0;
    for (const Point<2> &xi : v.values)
      {
        const unsigned int on = (std::abs(xi[0]) == 1.) + (std::abs(xi[1]) == 1.);
        (on == 2 ? corners : on == 1 ? on_edges : inside) += 1;
      }
    std::cout << "  " << v.values.size() << " vertices: " << inside << " inside the slave face, "
              << on_edges << " on its edges, " << corners << " at its corners" << std::endl;
    std::cout << "  AD vertex values = double path: " << (v.values == w.values ? "yes" : "NO")
              << std::endl;

    const std::vector<unsigned int> &s       = patch.slave_faces[0].nodes;
    const double                     size    = (patch.points[s[3]] - patch.points[s[0]]).norm();
    double                           closest = 2.;
    for (unsigned int a = 0; a < v.values.size(); ++a)
      for (unsigned int b = 0; b < a; ++b)
        closest = std::min(closest, v.values[a].distance(v.values[b]));

    // e[q][i][k]: |FD - derivative| of vertex coordinate q by coordinate i
    // at the step h / 2^k.
    const double                                    h = 1e-3 * size;
    std::vector<std::vector<std::array<double, 2>>> e(v.coordinates.size(),
                                                      std::vector<std::array<double, 2>>(n));
    bool                                            same = true;
    for (unsigned int i = 0; i < n && same; ++i)
      for (unsigned int k = 0; k < 2 && same; ++k)
        {
          std::vector<Point<2>> plus, minus;
          double                step_plus, step_minus;
          same = perturbed_vertices(patch, i, h / (1 << k), v, 0.25 * closest, plus, step_plus) &&
                 perturbed_vertices(patch, i, -h / (1 << k), v, 0.25 * closest, minus, step_minus);
          for (unsigned int q = 0; same && q < v.coordinates.size(); ++q)
            {
              const double fd =
                (plus[q / 2][q % 2] - minus[q / 2][q % 2]) / (step_plus - step_minus);
              e[q][i][k] = std::abs(fd - v.coordinates[q]->derivatives[i]);
            }
        }
    std::cout << "  the same vertices in the same order at every perturbed point: "
              << (same ? "yes" : "NO") << std::endl;
    if (!same)
      return exact;

    double scale = 0.;
    for (const Linearised *c : v.coordinates)
      for (const double d : c->derivatives)
        scale = std::max(scale, std::abs(d));
    // The double path's round-off is that of the coordinates, so it grows
    // with their distance from the origin in face sizes.
    double reach = 0.;
    for (const Point<3> &x : patch.points)
      reach = std::max(reach, x.norm());
    const double        round_off = 1e-10 * (1. + reach / size) * scale;
    std::vector<double> ratios;
    unsigned int        bad   = 0;
    double              worst = 0.;
    for (unsigned int q = 0; q < v.coordinates.size(); ++q)
      for (unsigned int i = 0; i < n; ++i)
        {
          const auto &eq = e[q][i];
          worst          = std::max(worst, eq[1] / scale);
          if (eq[0] <= round_off)
            continue;
          const double ratio = eq[0] / eq[1];
          ratios.push_back(ratio);
          if (!(ratio >= 3.5 && ratio <= 4.5) && ++bad <= 3)
            std::cout << "    vertex coordinate " << q << " by coordinate " << i << ": errors "
                      << eq[0] << " " << eq[1] << std::endl;
        }
    std::sort(ratios.begin(), ratios.end());
    const double median = ratios.empty() ? 0. : ratios[ratios.size() / 2];
    std::cout << "  " << v.coordinates.size() * n << " derivatives; error ratio e(h)/e(h/2) where "
              << "e(h) is above round-off: median " << std::lround(median)
              << ", all in [3.5, 4.5]: " << (bad == 0 ? "yes" : "NO")
              << "; e(h/2) below 1e-5 of the scale: " << (worst < 1e-5 ? "yes" : "NO") << std::endl;
    return exact;
  }
} // namespace

int
main()
{
  // The slave: a saddle-shaped, bulging surface, normals up.
  const Surface slave = [](const double x, const double y) {
    return Point<3>(x, y, 0.1 * x * y - 0.08 * (x * x + y * y));
  };
  // The masters: a tilted, curved surface above.
  const Surface master = [](const double x, const double y) {
    return Point<3>(x, y, 0.05 + 0.15 * x - 0.1 * y + 0.05 * x * x);
  };
  const std::array<Point<2>, 4> partial = {{{0.5, 0.4}, {1.6, 0.55}, {0.4, 1.5}, {1.5, 1.65}}};

  {
    QuadFacePatch patch = slave_patch(slave, 1);
    add_master(patch, master, {{{0.3, 0.2}, {0.8, 0.3}, {0.2, 0.7}, {0.75, 0.8}}}, 1);
    Random random(2031);
    perturb(patch, random);
    check("bilinear, a master inside the slave face", patch);
  }
  QuadFacePatch partly = slave_patch(slave, 1);
  add_master(partly, master, partial, 1);
  {
    Random random(2032);
    perturb(partly, random);
  }
  const std::vector<LinearisedQuadPair> unmoved =
    check("bilinear, partly overlapping (corners inside both, edges crossing)", partly);
  {
    QuadFacePatch           patch = slave_patch(slave, 1);
    std::array<Point<2>, 4> turned;
    const double            angle = 40. * numbers::PI / 180.;
    for (unsigned int v = 0; v < 4; ++v)
      {
        const Tensor<1, 2> r({(v % 2) - 0.5, (v / 2) - 0.5});
        turned[v] = Point<2>(0.5 + std::cos(angle) * r[0] - std::sin(angle) * r[1],
                             0.5 + std::sin(angle) * r[0] + std::cos(angle) * r[1]);
      }
    add_master(patch, master, turned, 1);
    Random random(2033);
    perturb(patch, random);
    check("bilinear, a master of the slave's size turned by 40 degrees", patch);
  }
  {
    // Corners alternately 0.1 above and below the master surface.
    const Surface warped = [&](const double x, const double y) {
      const Point<2> c    = 0.25 * (partial[0] + partial[1] + partial[2] + partial[3]);
      const double   sign = ((x - c[0]) * (y - c[1]) > 0.) ? 1. : -1.;
      return master(x, y) + Point<3>(0., 0., 0.1 * sign);
    };
    QuadFacePatch patch = slave_patch(slave, 1);
    add_master(patch, warped, partial, 1);
    Random random(2034);
    perturb(patch, random);
    check("bilinear, a warped master partly overlapping", patch);
  }
  {
    // The slave's grid lines bend in x and y (its edges bulge by 0.04);
    // the master just above, its edges bulging outward.
    const Surface curved_slave = [](const double x, const double y) {
      return Point<3>(x + 0.16 * y * (1. - y) * (2. * x - 1.),
                      y + 0.16 * x * (1. - x) * (2. * y - 1.),
                      0.1 * x * y - 0.08 * (x * x + y * y));
    };
    const Surface curved_master = [](const double x, const double y) {
      return Point<3>(x, y, 0.02 + 0.01 * x - 0.005 * y + 0.1 * x * y - 0.07 * (x * x + y * y));
    };
    QuadFacePatch patch = slave_patch(curved_slave, 2);
    add_master(patch, curved_master, partial, 2, 1.06);
    Random random(2035);
    perturb(patch, random);
    check("biquadratic, master edges crossing curved slave edges", patch);
  }
  {
    // The partly overlapping case moved rigidly: x -> R x + t.
    const Tensor<1, 3> axis  = Tensor<1, 3>({1., 2., 3.}) / std::sqrt(14.);
    const double       angle = 0.7;
    Tensor<2, 3>       R;
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        {
          R[a][b] = (a == b ? std::cos(angle) : 0.) + (1. - std::cos(angle)) * axis[a] * axis[b];
          const unsigned int c = 3 - a - b;
          if (a != b)
            R[a][b] += ((b == (a + 1) % 3) ? -1. : 1.) * std::sin(angle) * axis[c];
        }
    const Tensor<1, 3> t({100., -100., 100.});
    QuadFacePatch      moved = partly;
    for (Point<3> &x : moved.points)
      x = Point<3>(R * x + t);
    const std::vector<LinearisedQuadPair> r =
      check("the partly overlapping case turned and moved by 100", moved);
    // d xi / d x' = R (d xi / d x) per point.
    const Vertices a = vertices_of(unmoved), b = vertices_of(r);
    bool           values = a.values.size() == b.values.size(), derivatives = values;
    double         scale = 0.;
    for (const Linearised *c : a.coordinates)
      for (const double d : c->derivatives)
        scale = std::max(scale, std::abs(d));
    for (unsigned int k = 0; values && k < a.values.size(); ++k)
      values = a.values[k].distance(b.values[k]) < 1e-9;
    for (unsigned int q = 0; derivatives && q < a.coordinates.size(); ++q)
      for (unsigned int p = 0; p < moved.points.size(); ++p)
        {
          Tensor<1, 3> da, db;
          for (unsigned int d = 0; d < 3; ++d)
            {
              da[d] = a.coordinates[q]->derivatives[3 * p + d];
              db[d] = b.coordinates[q]->derivatives[3 * p + d];
            }
          derivatives = derivatives && (R * da - db).norm() < 1e-8 * scale;
        }
    std::cout << "  vertices = the unmoved case's: " << (values ? "yes" : "NO")
              << ", derivatives = the unmoved case's turned: " << (derivatives ? "yes" : "NO")
              << std::endl;
  }
}
