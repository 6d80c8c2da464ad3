#include <contact_fem/solvers/load_step_control.h>

#include <algorithm>
#include <cmath>

namespace contact_fem
{
  unsigned int
  LoadStepControl::n_steps_left() const
  {
    // A remainder below a millionth of a step is the round-off of the sum.
    const double left = (parameters.end_time - t_done) / step;
    return left <= 1e-6 ? 0 : static_cast<unsigned int>(std::ceil(left - 1e-6));
  }

  LoadStepControl::LoadStepControl(const LoadStepping &parameters,
                                   const double        start_time,
                                   const unsigned int  n_steps)
    : parameters(parameters)
    , nominal_step(parameters.end_time / n_steps)
    , t_done(start_time)
    , step(nominal_step)
  {}

  bool
  LoadStepControl::finished() const
  {
    return !(t_done < parameters.end_time * (1. - 1e-12));
  }

  double
  LoadStepControl::next_time() const
  {
    return std::min(parameters.end_time, t_done + step);
  }

  bool
  LoadStepControl::at_smallest_step() const
  {
    // A step below 1e-12 of the end time cannot advance the load.
    return !(step / parameters.split_factor > 1e-12 * parameters.end_time);
  }

  bool
  LoadStepControl::at_deepest_split() const
  {
    // The step sizes are the nominal one over powers of the split factor;
    // the margin only absorbs the round-off of those divisions.
    return step / parameters.split_factor <
           nominal_step / std::pow(parameters.split_factor, parameters.max_splits) * (1. - 1e-9);
  }

  bool
  LoadStepControl::split()
  {
    if (splits >= parameters.max_splits || at_smallest_step() || at_deepest_split())
      return false;
    if (!(step < nominal_step))
      creep_start = t_done;
    ++splits;
    successes_since_split = 0;
    step /= parameters.split_factor;
    return true;
  }

  bool
  LoadStepControl::accept()
  {
    t_done = next_time();
    splits = 0;
    if (step < nominal_step && !finished() && ++successes_since_split == 2)
      {
        step                  = std::min(nominal_step, step * parameters.split_factor);
        successes_since_split = 0;
        return true;
      }
    return false;
  }
} // namespace contact_fem
