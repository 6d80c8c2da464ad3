// The computing frame: a mesh far from the origin is computed moved next to
// it, and everything the input states in coordinates is taken there.
#ifndef contact_fem_model_frame_h
#define contact_fem_model_frame_h

#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /**
   * The computing frame's origin in the user's coordinates: zero, except
   * for a mesh file far from the origin (choose_frame_origin()).
   *
   * Why: deal.II computes cell measures and the pull-backs of curved
   * manifolds from absolute coordinates; 1e4 model sizes from the origin
   * those lose the digits of small cells (a valid mesh is refused, a
   * refinement fails). Computing next to the origin makes every result
   * independent of where the mesh lies.
   *
   * The input speaks in the user's coordinates (loads and prescribed
   * displacements as functions of x, y, z; fixed points, probes,
   * refinement boxes, manifolds, the analytical solution's centre), and so
   * do the pressure profile and the messages (message_origin). The VTU
   * files hold 32-bit points, which far from the origin cannot tell small
   * cells apart: they are written in the computing frame, and summary.json
   * and the log state its origin (coordinate_origin).
   */
  template <int dim>
  struct ModelFrame
  {
    Tensor<1, dim> origin;

    Point<dim>
    to_model(const Point<dim> &user) const
    {
      return user - origin;
    }

    Point<dim>
    to_user(const Point<dim> &model) const
    {
      return model + origin;
    }

    bool
    shifted() const
    {
      return origin.norm_square() > 0.;
    }
  };

  /**
   * The origin of the computing frame for a mesh whose nodes span the box
   * [@p lower, @p upper] (3 coordinates; in 2D z is left alone): zero if the
   * box's centre lies within 10 times its extent of the origin (deal.II
   * computes exactly enough there, and the results of such meshes stay what
   * they were); otherwise the centre rounded to a multiple of the power of
   * two at or above the extent: a node and the origin then share their
   * leading digits, so that subtracting it loses nothing, and the origin
   * prints short.
   */
  Point<3>
  choose_frame_origin(const Point<3> &lower, const Point<3> &upper, const unsigned int dim);

  /**
   * A function of the user's coordinates and time (a load or prescribed
   * displacement of the input: expressions in x, y, (z,) t) evaluated at
   * points of the computing frame.
   */
  template <int dim>
  class UserFunction : public Function<dim>
  {
  public:
    UserFunction(const std::vector<std::string> &expressions, const ModelFrame<dim> &frame);

    double
    value(const Point<dim> &p, const unsigned int component = 0) const override
    {
      return parser.value(frame.to_user(p), component);
    }

    void
    set_time(const double time) override
    {
      Function<dim>::set_time(time);
      parser.set_time(time);
    }

  private:
    FunctionParser<dim> parser;
    ModelFrame<dim>     frame;
  };
} // namespace contact_fem

#endif
