#include <contact_fem/geometry/hexahedron_shape.h>

#include <algorithm>
#include <cmath>

namespace contact_fem
{
  namespace
  {
    /// Gmsh's hexahedron on the reference cube [-1, 1]^3.
    constexpr int reference[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                     {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

    /// The node that differs from @p node in reference coordinate @p axis only.
    unsigned int
    neighbour(const unsigned int node, const unsigned int axis)
    {
      for (unsigned int other = 0; other < 8; ++other)
        {
          bool match = true;
          for (unsigned int d = 0; d < 3; ++d)
            match = match && ((d == axis) != (reference[other][d] == reference[node][d]));
          if (match)
            return other;
        }
      return node;
    }
  } // namespace

  HexahedronCheck
  check_hexahedron(const std::array<Point<3>, 8> &x)
  {
    HexahedronCheck check;

    double longest = 0.;
    for (unsigned int i = 0; i < 8; ++i)
      for (unsigned int d = 0; d < 3; ++d)
        longest = std::max(longest, x[i].distance(x[neighbour(i, d)]));
    for (unsigned int i = 0; i < 8; ++i)
      for (unsigned int d = 0; d < 3; ++d)
        {
          const unsigned int j = neighbour(i, d);
          if (i < j && !(x[i].distance(x[j]) > 1e-10 * longest))
            {
              check.shape  = HexahedronShape::collapsed_edge;
              check.first  = i;
              check.second = j;
              return check;
            }
        }

    // The corner Jacobians, each relative to its edge lengths.
    std::array<double, 8> corner;
    for (unsigned int i = 0; i < 8; ++i)
      {
        Tensor<1, 3> edge[3];
        double       lengths = 1.;
        for (unsigned int d = 0; d < 3; ++d)
          {
            // Along the reference axis: towards +1 from a corner at -1.
            edge[d] = (x[neighbour(i, d)] - x[i]) * static_cast<double>(-reference[i][d]);
            lengths *= edge[d].norm();
          }
        corner[i] = edge[0] * cross_product_3d(edge[1], edge[2]) / lengths;
      }
    check.min_corner = *std::min_element(corner.begin(), corner.end());
    check.max_corner = *std::max_element(corner.begin(), corner.end());

    constexpr double flat = 1e-8;
    const auto smallest   = std::min_element(corner.begin(), corner.end(), [](double a, double b) {
      return std::abs(a) < std::abs(b);
    });
    if (std::abs(*smallest) <= flat)
      {
        check.shape = HexahedronShape::flat;
        check.first = check.second = static_cast<unsigned int>(smallest - corner.begin());
        return check;
      }
    check.n_negative =
      static_cast<unsigned int>(std::count_if(corner.begin(), corner.end(), [](const double c) {
        return c < 0.;
      }));
    if (check.n_negative == 0)
      return check;
    if (check.n_negative == 8)
      {
        check.shape = HexahedronShape::mirrored;
        return check;
      }
    check.shape = HexahedronShape::twisted;
    check.first = check.second =
      static_cast<unsigned int>(std::find_if(corner.begin(), corner.end(),
                                             [](const double c) {
                                               return c < 0.;
                                             }) -
                                corner.begin());
    return check;
  }
} // namespace contact_fem
