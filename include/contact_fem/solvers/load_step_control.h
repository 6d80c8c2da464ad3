// The load path of one cycle: steps toward the end time, split after a
// failed step, grown back after converged ones.
#ifndef contact_fem_load_step_control_h
#define contact_fem_load_step_control_h

#include <contact_fem/solvers/solver_parameters.h>

namespace contact_fem
{
  /**
   * Step control of one cycle. The load goes from @p start_time to the end
   * time of LoadStepping in steps of the nominal size; a step whose Newton
   * iteration fails is split into "Split factor" sub-steps (at most
   * "Maximum step splits" times in a row, and never below 1e-12 of the end
   * time), and after two converged steps in a row the step grows back by
   * the split factor toward the nominal size, so that one hard moment does
   * not cost small steps for the rest of the path.
   */
  class LoadStepControl
  {
  public:
    LoadStepControl(const LoadStepping &parameters,
                    const double        start_time,
                    const unsigned int  n_steps);

    /// Whether the end time has been reached.
    bool
    finished() const;

    /// The time the next step goes to.
    double
    next_time() const;

    /// The time of the last converged step.
    double
    converged_time() const
    {
      return t_done;
    }

    /// After a failed step: makes the step smaller and returns true, or
    /// returns false if no further split is allowed.
    bool
    split();

    /// After the step to next_time() converged: moves on; returns true if
    /// the step size grew back.
    bool
    accept();

    double
    step_size() const
    {
      return step;
    }

    /// The steps left to the end time at the present step size (after
    /// accept(): those after the converged one).
    unsigned int
    n_steps_left() const;

    /// Whether the step is at the floor of split(): no smaller step is
    /// tried.
    bool
    at_smallest_step() const;

    /// Whether the step is "Maximum step splits" splits below the nominal
    /// size: no smaller step is tried. Converged sub-steps reset the count
    /// of splits in a row but not this depth, so a point of the load path
    /// that no step passes is not crept toward down to at_smallest_step()
    /// (a Tresca scene took 39 failed attempts there: doc/metamorphic.md).
    bool
    at_deepest_split() const;

    /// The converged time when the step was last split from its nominal
    /// size: where the sub-steps toward a failing point started.
    double
    creep_start_time() const
    {
      return creep_start;
    }

    /// The nominal step size.
    double
    nominal_step_size() const
    {
      return nominal_step;
    }

    /// Splits in a row so far.
    unsigned int
    n_splits() const
    {
      return splits;
    }

  private:
    LoadStepping parameters;
    double       nominal_step;
    double       t_done;
    double       step;
    double       creep_start = 0.;
    unsigned int splits = 0, successes_since_split = 0;
  };
} // namespace contact_fem

#endif
