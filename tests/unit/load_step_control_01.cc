// LoadStepControl without a scene: four nominal steps to t = 1, the second
// step failing twice (split to 1/16), then converging: the step grows back
// by the split factor after every two converged steps, never beyond the
// nominal 1/4, and the path ends exactly at 1. A step that keeps failing
// is split at most "Maximum step splits" times in a row. A point of the
// path that no step passes (every step beyond t = 0.3 fails) is approached
// by converged sub-steps, which reset the splits in a row but not the
// depth: the step stops at 1/8 of the nominal one instead of creeping on.

#include <contact_fem/solvers/load_step_control.h>

#include <iostream>

using namespace contact_fem;

int
main()
{
  LoadStepping parameters;
  parameters.end_time     = 1.;
  parameters.n_steps      = 4;
  parameters.max_splits   = 3;
  parameters.split_factor = 2;

  LoadStepControl control(parameters, 0., parameters.n_steps);
  unsigned int    attempts = 0;
  while (!control.finished())
    {
      const double time = control.next_time();
      ++attempts;
      // The attempts to reach t = 0.5 and t = 0.375 fail.
      if (attempts == 2 || attempts == 3)
        {
          const bool split = control.split();
          std::cout << "step to " << time << " failed: split " << (split ? "yes" : "no")
                    << ", new step " << control.step_size() << std::endl;
          continue;
        }
      const bool grew = control.accept();
      std::cout << "converged at " << control.converged_time()
                << (grew ? ", step grows to " : ", step ") << control.step_size() << std::endl;
    }
  std::cout << "finished at " << control.converged_time() << " after " << attempts << " attempts"
            << std::endl;

  LoadStepControl stubborn(parameters, 0., parameters.n_steps);
  unsigned int    splits = 0;
  while (stubborn.split())
    ++splits;
  std::cout << "a step that keeps failing is split " << splits << " times (maximum "
            << parameters.max_splits << "), down to " << stubborn.step_size() << std::endl;

  LoadStepControl creeping(parameters, 0., parameters.n_steps);
  unsigned int    failures = 0;
  while (!creeping.finished())
    {
      if (creeping.next_time() > 0.3)
        {
          ++failures;
          if (!creeping.split())
            break;
          continue;
        }
      creeping.accept();
    }
  std::cout << "a point no step passes: " << failures << " failed attempts, stopped at t = "
            << creeping.converged_time() << " with step " << creeping.step_size()
            << (creeping.at_deepest_split() ? " (the deepest split)" : "") << ", creeping from t = "
            << creeping.creep_start_time() << std::endl;
}
