// Derivatives of the 2D mortar operators of one slave/master face pair with
// respect to the node coordinates (source/contact/mortar_linearisation.cc:
// forward AD of the mortar kernel) against central finite differences of
// the double path, for deterministic random perturbations of
//  - flat matching faces (Q1),
//  - flat non-matching faces, partly overlapping (a master end inside),
//  - tilted faces (Q1),
//  - curved Q2 faces, partly overlapping,
//  - a Q1 master with both end nodes inside a Q2 slave face,
//  - Q1 elements on a curved Q2 geometry,
//  - two masters meeting inside the slave face (Q1, Q2): the dual basis on
//    both overlaps, whose shared end moves with the masters' common node.
// Quantities: averaged unit nodal normals (through the neighbouring slave
// faces), overlap ends on both faces, dual basis coefficients, D, M, the
// weighted gap vector and its normal part. For every derivative, the
// finite-difference error at h, h/2, h/4 (h = 1e-3 face length) falls at
// second order (both observed orders in [1.8, 2.2]) unless it is round-off
// already at h (below 1e-9 of the group's scale: the quantity is at most
// quadratic in that coordinate), and at h/4 it is below 1e-5 of the
// group's scale (its largest derivative or value per length). The branch
// decisions (which ends bound the overlap) are the same at every perturbed
// point. The AD values equal the double path exactly, and D, M and the
// weighted gap equal integrate_pair() exactly.
#include <contact_fem/contact/mortar_linearisation.h>

#include "unit_test_random.h"

#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <string>

using namespace dealii;
using namespace contact_fem;
using namespace contact_fem::Mortar;

namespace
{
  using Curve = std::function<Point<2>(const double)>;

  /**
   * Three slave faces of geometry degree @p degree on @p slave (parameters
   * -1..0, 0..1 and 1..2; the middle one is the pair's slave face, its
   * normal pointing up), a master face of degree @p master_degree on
   * @p master from parameter @p from to @p to, every point moved by up to
   * 0.02 at random. @p element_degree: that of the DoFs on both (0:
   * isoparametric).
   */
  PairPatch
  make_patch(const unsigned int degree,
             const unsigned int master_degree,
             const unsigned int element_degree,
             const Curve       &slave,
             const Curve       &master,
             const double       from,
             const double       to,
             Random            &random)
  {
    PairPatch patch;
    for (const double s : {-1., 0., 1., 2.})
      patch.points.push_back(slave(s));
    for (unsigned int f = 0; f < 3; ++f)
      {
        PairPatch::Face face;
        face.nodes          = {f, f + 1};
        face.orientation    = -1.;
        face.element_degree = element_degree;
        if (degree == 2)
          {
            face.nodes.push_back(patch.points.size());
            patch.points.push_back(slave(f - 0.5));
          }
        patch.slave_faces.push_back(face);
      }
    std::swap(patch.slave_faces[0], patch.slave_faces[1]);
    const unsigned int m = patch.points.size();
    patch.points.push_back(master(from));
    patch.points.push_back(master(to));
    patch.master.nodes          = {m, m + 1};
    patch.master.element_degree = element_degree;
    if (master_degree == 2)
      {
        patch.master.nodes.push_back(m + 2);
        patch.points.push_back(master(0.5 * (from + to)));
      }
    for (Point<2> &p : patch.points)
      for (unsigned int d = 0; d < 2; ++d)
        p[d] += 0.02 * random.next();
    return patch;
  }

  /// A second master face of @p patch on @p master from its master's end
  /// node 1 to parameter @p to (@p from: that node's parameter), its other
  /// nodes moved by up to 0.02 at random.
  void
  add_second_master(PairPatch   &patch,
                    const Curve &master,
                    const double from,
                    const double to,
                    Random      &random)
  {
    PairPatch::Face face = patch.master;
    face.nodes           = {patch.master.nodes[1], static_cast<unsigned int>(patch.points.size())};
    patch.points.push_back(master(to));
    if (patch.master.nodes.size() == 3)
      {
        face.nodes.push_back(patch.points.size());
        patch.points.push_back(master(0.5 * (from + to)));
      }
    for (unsigned int i = 1; i < face.nodes.size(); ++i)
      for (unsigned int d = 0; d < 2; ++d)
        patch.points[face.nodes[i]][d] += 0.02 * random.next();
    patch.other_masters.push_back(face);
  }

  /// Every quantity of @p r, by group.
  std::vector<std::pair<std::string, const Linearised *>>
  quantities(const LinearisedPair &r)
  {
    std::vector<std::pair<std::string, const Linearised *>> list;
    const auto add_vectors = [&](const std::string &group, const auto &vectors) {
      for (const auto &v : vectors)
        for (const Linearised &c : v)
          list.emplace_back(group, &c);
    };
    add_vectors("nodal normals", r.normals);
    for (const Linearised *c : {&r.xi_begin, &r.xi_end, &r.eta_begin, &r.eta_end})
      list.emplace_back("overlap ends", c);
    add_vectors("dual basis", r.dual_coefficients);
    for (const Linearised &c : r.D)
      list.emplace_back("D", &c);
    add_vectors("M", r.M);
    add_vectors("weighted gap", r.weighted_gap);
    for (const Linearised &c : r.normal_gap)
      list.emplace_back("normal gap", &c);
    return list;
  }

  /// Whether AD and double values agree exactly, and D, M, gap with
  /// integrate_pair().
  void
  check_values(const PairPatch &patch, const LinearisedPair &exact, const LinearisedPair &values)
  {
    const auto a = quantities(exact), b = quantities(values);
    bool       same = a.size() == b.size();
    for (unsigned int i = 0; same && i < a.size(); ++i)
      same = a[i].second->value == b[i].second->value;
    std::cout << "  AD values = double path: " << (same ? "yes" : "NO") << std::endl;

    const LineFace slave  = patch.line_face(patch.slave_faces[0]),
                   master = patch.line_face(patch.master);
    std::vector<Tensor<1, 2>> normals;
    for (const auto &n : values.normals)
      normals.push_back(Tensor<1, 2>({n[0].value, n[1].value}));
    std::vector<std::pair<double, double>> intervals = {
      {values.xi_begin.value, values.xi_end.value}};
    for (const PairPatch::Face &other : patch.other_masters)
      if (double lower, upper; overlap(slave, normals, patch.line_face(other), lower, upper))
        intervals.emplace_back(lower, upper);
    std::cout << "  dual basis on " << intervals.size() << " overlap(s)" << std::endl;
    const auto       A = dual_basis_coefficients(slave, intervals);
    SegmentOperators ops;
    bool equal = integrate_pair(slave, normals, A, master, n_quadrature_points(slave, master), ops);
    for (unsigned int j = 0; equal && j < ops.D.size(); ++j)
      {
        equal = ops.D[j] == values.D[j].value &&
                ops.weighted_gap[j][0] == values.weighted_gap[j][0].value &&
                ops.weighted_gap[j][1] == values.weighted_gap[j][1].value;
        for (unsigned int l = 0; l < ops.M.n(); ++l)
          equal = equal && ops.M(j, l) == values.M[j][l].value;
      }
    std::cout << "  D, M, weighted gap = integrate_pair(): " << (equal ? "yes" : "NO") << std::endl;
  }

  /// The values of all quantities with coordinate @p i of @p patch moved
  /// by @p h into @p v; false if the overlap's bounding ends differ from
  /// @p ends there.
  bool
  perturbed_values(PairPatch                 patch,
                   const unsigned int        i,
                   const double              h,
                   const std::array<int, 2> &ends,
                   std::vector<double>      &v)
  {
    patch.points[i / 2][i % 2] += h;
    LinearisedPair r;
    if (!linearise_pair(patch, false, r) || r.bounding_master_ends != ends)
      return false;
    v.clear();
    for (const auto &q : quantities(r))
      v.push_back(q.second->value);
    return true;
  }

  /// Central-difference errors |FD(h_k) - derivative| for h_k = h, h/2,
  /// h/4, per quantity of @p exact and coordinate; false if a perturbed
  /// point takes other branches.
  bool
  difference_errors(const PairPatch                                 &patch,
                    const LinearisedPair                            &exact,
                    const double                                     h,
                    std::vector<std::vector<std::array<double, 3>>> &errors)
  {
    const auto         list = quantities(exact);
    const unsigned int n    = 2 * patch.points.size();
    errors.assign(list.size(), std::vector<std::array<double, 3>>(n));
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int k = 0; k < 3; ++k)
        {
          const double        hk = h / (1 << k);
          std::vector<double> plus, minus;
          if (!perturbed_values(patch, i, hk, exact.bounding_master_ends, plus) ||
              !perturbed_values(patch, i, -hk, exact.bounding_master_ends, minus))
            return false;
          for (unsigned int q = 0; q < list.size(); ++q)
            errors[q][i][k] =
              std::abs((plus[q] - minus[q]) / (2. * hk) - list[q].second->derivatives[i]);
        }
    return true;
  }

  void
  check_derivatives(const std::string &name, const PairPatch &patch)
  {
    LinearisedPair exact, values;
    if (!linearise_pair(patch, true, exact) || !linearise_pair(patch, false, values))
      {
        std::cout << name << ": no overlap" << std::endl;
        return;
      }
    const unsigned int n = 2 * patch.points.size();
    std::cout << name << " (" << n << " coordinates, overlap bounded by master ends "
              << exact.bounding_master_ends[0] << ", " << exact.bounding_master_ends[1]
              << "; -1: slave end)" << std::endl;
    check_values(patch, exact, values);

    const std::vector<unsigned int> &s      = patch.slave_faces[0].nodes;
    const double                     length = (patch.points[s[1]] - patch.points[s[0]]).norm();
    std::vector<std::vector<std::array<double, 3>>> errors;
    const bool same_branches = difference_errors(patch, exact, 1e-3 * length, errors);
    std::cout << "  same branches at every perturbed point: " << (same_branches ? "yes" : "NO")
              << std::endl;
    if (!same_branches)
      return;

    const auto                    list = quantities(exact);
    std::vector<std::string>      groups;
    std::map<std::string, double> scale;
    for (const auto &[group, q] : list)
      {
        if (scale.count(group) == 0)
          groups.push_back(group);
        scale[group] = std::max(scale[group], std::abs(q->value) / length);
        for (const double d : q->derivatives)
          scale[group] = std::max(scale[group], std::abs(d));
      }
    for (const std::string &group : groups)
      {
        unsigned int count = 0, bad = 0;
        double       worst = 0.;
        for (unsigned int q = 0; q < list.size(); ++q)
          if (list[q].first == group)
            for (unsigned int i = 0; i < n; ++i, ++count)
              {
                const auto  &e         = errors[q][i];
                const double order_1   = std::log2(e[0] / e[1]);
                const double order_2   = std::log2(e[1] / e[2]);
                const bool   round_off = e[0] <= 1e-9 * scale[group];
                const bool   second =
                  order_1 >= 1.8 && order_1 <= 2.2 && order_2 >= 1.8 && order_2 <= 2.2;
                worst = std::max(worst, e[2] / scale[group]);
                if (!round_off && !second && ++bad <= 3)
                  std::cout << "    " << group << " #" << q << " coordinate " << i << ": errors "
                            << e[0] << " " << e[1] << " " << e[2] << std::endl;
              }
        std::cout << "  " << group << ": " << count
                  << " derivatives, error at second order or round-off: "
                  << (bad == 0 ? "yes" : "NO")
                  << ", error at h/4 below 1e-5 of the scale: " << (worst < 1e-5 ? "yes" : "NO")
                  << std::endl;
      }
  }
} // namespace

int
main()
{
  Random      random(2026);
  const Curve flat = [](const double s) {
    return Point<2>(s, 0.);
  };
  const Curve above = [](const double s) {
    return Point<2>(s, 0.05);
  };
  check_derivatives("flat, matching, Q1", make_patch(1, 1, 0, flat, above, 1., 0., random));
  check_derivatives("flat, non-matching, partly overlapping, Q1",
                    make_patch(1, 1, 0, flat, above, 1.5, 0.4, random));
  check_derivatives("tilted, Q1", make_patch(
                                    1, 1, 0,
                                    [](const double s) {
                                      return Point<2>(s, 0.3 * s);
                                    },
                                    [](const double s) {
                                      return Point<2>(s, 0.4 - 0.2 * s);
                                    },
                                    1.3, 0.2, random));
  const Curve bump = [](const double s) {
    return Point<2>(s, -0.3 * s * s);
  };
  const Curve bowl = [](const double s) {
    return Point<2>(s, 0.05 + 0.2 * (s - 0.5) * (s - 0.5));
  };
  check_derivatives("curved, partly overlapping, Q2",
                    make_patch(2, 2, 0, bump, bowl, 1.4, 0.35, random));
  check_derivatives("master end nodes inside the slave face, Q2 slave, Q1 master",
                    make_patch(2, 1, 0, bump, above, 0.8, 0.25, random));
  check_derivatives("Q1 elements on a curved Q2 geometry",
                    make_patch(2, 2, 1, bump, bowl, 1.3, 0.3, random));
  for (const unsigned int degree : {1u, 2u})
    {
      PairPatch patch = make_patch(degree, degree, 0, bump, bowl, 1.5, 0.45, random);
      add_second_master(patch, bowl, 0.45, -0.6, random);
      check_derivatives("two masters meeting inside the slave face, Q" + std::to_string(degree),
                        patch);
    }
}
