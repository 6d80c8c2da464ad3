#include <contact_fem/geometry/model_frame.h>

#include <algorithm>
#include <cmath>

namespace contact_fem
{
  Point<3>
  choose_frame_origin(const Point<3> &lower, const Point<3> &upper, const unsigned int dim)
  {
    double   extent = 0., distance = 0.;
    Point<3> centre;
    for (unsigned int d = 0; d < dim; ++d)
      {
        centre[d] = 0.5 * lower[d] + 0.5 * upper[d];
        extent    = std::max(extent, upper[d] - lower[d]);
        distance  = std::max(distance, std::abs(centre[d]));
      }
    // Near the origin nothing moves (and a mesh without extent is refused
    // elsewhere).
    constexpr double near = 10.;
    if (!(extent > 0.) || distance <= near * extent)
      return Point<3>();
    const double grid = std::exp2(std::ceil(std::log2(extent)));
    Point<3>     origin;
    for (unsigned int d = 0; d < dim; ++d)
      origin[d] = grid * std::round(centre[d] / grid);
    return origin;
  }

  template <int dim>
  UserFunction<dim>::UserFunction(const std::vector<std::string> &expressions,
                                  const ModelFrame<dim>          &frame)
    : Function<dim>(expressions.size())
    , parser(expressions.size())
    , frame(frame)
  {
    parser.initialize(dim == 2 ? "x,y,t" : "x,y,z,t", expressions, {}, true);
  }

  template class UserFunction<2>;
  template class UserFunction<3>;
} // namespace contact_fem
