// Derivatives of the 3D mortar operators of a face pair whose edges
// coincide up to round-off (source/contact/mortar_3d.cc, clip_convex()):
// the rims of two blocks pressed together with the same lateral stretch,
// as at the converged states of the 3D current-kinematics patch test. The
// slave face is the centre of 3 x 3 flat faces of size 1/3; the master, a
// flat face just above, spans the slave face in y and half of it in x, the
// y of each of its nodes moved off the slave's edges by -1, 0 or 1 ulp (81
// cases: edges parallel or turned by round-off). Clipping then
// crosses edges that are parallel up to round-off: the crossing may lie
// anywhere along them and its exact derivative is round-off over round-off
// (it was 1e16 and more, and gave the geometric contact stiffness entries
// of 1e14). Checked: the AD values equal the double path, and every
// derivative of D, M and the weighted gap stays of the order of D per
// length (below 100 times it).
#include <contact_fem/contact/mortar_3d_linearisation.h>

#include <array>
#include <cmath>
#include <iostream>
#include <limits>

using namespace dealii;
using namespace contact_fem;
using namespace contact_fem::Mortar;

namespace
{
  constexpr double a = 1. / 3.; // face size

  double
  ulps(const double x, const int n)
  {
    double y = x;
    for (int k = 0; k < std::abs(n); ++k)
      y = std::nextafter(y, n > 0 ? 1. : -1.);
    return y;
  }

  /// The flat patch of 4 x 4 slave nodes (centre face first) and one
  /// master face over x in [a/2, 3a/2], y in [0, a], at height 1e-3 a,
  /// the y of its nodes moved by @p offsets ulps.
  QuadFacePatch
  patch_with_master(const std::array<int, 4> &offsets)
  {
    QuadFacePatch patch;
    for (unsigned int j = 0; j < 4; ++j)
      for (unsigned int i = 0; i < 4; ++i)
        patch.points.emplace_back((i - 1.) * a, (j - 1.) * a, 0.);
    const auto face = [](const unsigned int i, const unsigned int j) {
      QuadFacePatch::Face f;
      f.nodes = {4 * j + i, 4 * j + i + 1, 4 * (j + 1) + i, 4 * (j + 1) + i + 1};
      return f;
    };
    patch.slave_faces.push_back(face(1, 1));
    for (unsigned int j = 0; j < 3; ++j)
      for (unsigned int i = 0; i < 3; ++i)
        if (i != 1 || j != 1)
          patch.slave_faces.push_back(face(i, j));
    const double z = 1e-3 * a;
    patch.masters.emplace_back();
    for (unsigned int v = 0; v < 4; ++v)
      {
        patch.masters[0].nodes.push_back(patch.points.size());
        patch.points.emplace_back((v % 2 == 0 ? 0.5 : 1.5) * a, ulps(v < 2 ? 0. : a, offsets[v]),
                                  z);
      }
    return patch;
  }
} // namespace

int
main()
{
  unsigned int cases = 0, overlapping = 0, same_values = 0, bounded = 0;
  double       worst = 0.;
  for (unsigned int k = 0; k < 81; ++k)
    {
      ++cases;
      const QuadFacePatch patch = patch_with_master(
        {{int(k % 3) - 1, int(k / 3 % 3) - 1, int(k / 9 % 3) - 1, int(k / 27) - 1}});
      std::vector<LinearisedQuadPair> exact_pairs, value_pairs;
      if (!linearise_slave_face(patch, true, exact_pairs) ||
          !linearise_slave_face(patch, false, value_pairs))
        continue;
      const LinearisedQuadPair &exact = exact_pairs[0], &values = value_pairs[0];
      ++overlapping;
      // Largest |derivative| against the scale of D per length (the
      // overlap area over the face size: moving a node by one face
      // size changes D, M and the weighted gap by about that much).
      bool   same  = true;
      double scale = 0., derivative = 0.;
      for (const Linearised &d : exact.D)
        scale = std::max(scale, std::abs(d.value) / a);
      const auto check = [&](const std::vector<const Linearised *> &group) {
        for (const Linearised *q : group)
          for (const double d : q->derivatives)
            derivative = std::max(derivative, std::abs(d));
      };
      std::vector<const Linearised *> D, M, gap;
      for (unsigned int j = 0; j < exact.D.size(); ++j)
        {
          D.push_back(&exact.D[j]);
          same = same && exact.D[j].value == values.D[j].value;
          for (const Linearised &m : exact.M[j])
            M.push_back(&m);
          for (const Linearised &g : exact.weighted_gap[j])
            gap.push_back(&g);
        }
      check(D);
      check(M);
      check(gap);
      same_values += same;
      bounded += derivative <= 100. * scale;
      worst = std::max(worst, derivative / scale);
    }
  std::cout << "master edges within 1 ulp of the slave edges: " << cases << " cases, "
            << overlapping << " overlapping" << std::endl
            << "  AD values = double path: " << (same_values == overlapping ? "yes" : "NO")
            << std::endl
            << "  derivatives of D, M, weighted gap below 100 times D per length: "
            << (bounded == overlapping && overlapping > 0 ? "yes" : "NO")
            << (worst > 100. ? " (largest ratio " + std::to_string(worst) + ")" : std::string())
            << std::endl;
}
