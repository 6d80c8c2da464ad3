// LoadStepControl without a scene: four nominal steps to t = 1, the second
// step failing twice (split to 1/16), then converging: the step grows back
// by the split factor after every two converged steps, never beyond the
// nominal 1/4, and the path ends exactly at 1. A step that keeps failing
// is split at most "Maximum step splits" times in a row.

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
}
