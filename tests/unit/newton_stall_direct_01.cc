// NewtonMonitor: a flat |r_u| with a settled active set is accepted as
// "converged to linear-solver accuracy" with an iterative solver (the
// solver's tolerance), but with a direct solver only at the round-off of
// its terms (1e3 eps |K| |u|, set_round_off()): the stall of a chain of
// contact pairs (flat at |r_u| = 6.5e-2, the multipliers settled) was
// accepted before. Here that residual is 6.5e-3 of the step's largest,
// within the 1e-2 bound of a linear problem; the same sequence is assessed
// four ways.

#include <contact_fem/solvers/newton_monitor.h>

#include <iostream>

int
main()
{
  using contact_fem::NewtonMonitor;
  contact_fem::NewtonParameters parameters;
  const double                  r_u[] = {10., 1.0, 6.5e-2, 6.5e-2, 6.5e-2};
  for (const bool direct : {false, true})
    for (const double round_off : {1e-14, 1e-4})
      {
        NewtonMonitor monitor(parameters);
        if (direct)
          monitor.set_direct_solver();
        std::cout << (direct ? "direct" : "iterative") << ", eps |K| |u| = " << round_off << ':';
        for (unsigned int it = 0; it < 5; ++it)
          {
            if (monitor.wants_round_off(it))
              monitor.set_round_off(round_off);
            // The multipliers settled (1e-6 of their first value).
            const auto a = monitor.assess(it, r_u[it], it < 2 ? 1. : 1e-6, it < 2 ? 1 : 0, false);
            std::cout << ' ' << (a.converged ? "converged" : "-");
            if (a.converged)
              break;
          }
        std::cout << '\n';
      }
}
