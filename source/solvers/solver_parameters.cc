#include <contact_fem/solvers/solver_parameters.h>

namespace contact_fem
{
  void
  LoadStepping::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Load stepping");
    prm.declare_entry("End time", "1", Patterns::Double(),
                      "Pseudo-time of the last load step; loads and prescribed "
                      "displacements are functions of t. Must be > 0.");
    prm.declare_entry("Number of load steps", "1", Patterns::Integer(),
                      "Equal load steps from t = 0 to the end time; at least 1.");
    prm.declare_entry("Maximum step splits", "4", Patterns::Integer(0, 30),
                      "When Newton fails on a step (no convergence, NaN, singular "
                      "system), the step is split and retried from the last "
                      "converged state, at most this many times in a row, and "
                      "never below the nominal step over Split factor to this "
                      "power (converged sub-steps do not restore that depth).");
    prm.declare_entry("Split factor", "2", Patterns::Integer(2, 100),
                      "Number of sub-steps a failing step is split into.");
    prm.leave_subsection();
  }

  void
  LoadStepping::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Load stepping");
    end_time     = prm.get_double("End time");
    const std::string end_text = prm.get("End time"); // as written, for the message
    const int n  = prm.get_integer("Number of load steps");
    max_splits   = prm.get_integer("Maximum step splits");
    split_factor = prm.get_integer("Split factor");
    prm.leave_subsection();
    AssertThrow(end_time > 0. && std::isfinite(end_time),
                ExcMessage("Load stepping/End time: got " + end_text +
                           "; expected a value > 0."));
    AssertThrow(n >= 1 && n <= 100000,
                ExcMessage("Load stepping/Number of load steps: got " + std::to_string(n) +
                           "; expected an integer from 1 to 100000."));
    n_steps = n;
  }

  void
  NewtonParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    prm.declare_entry("Maximum iterations", "20", Patterns::Integer(1, 1000),
                      "Semi-smooth Newton iterations allowed per load step.");
    prm.declare_entry("Displacement relative tolerance", "1e-4", Patterns::Double(0.),
                      "Converged when |r_u| / |r_u at iteration 0| is below this "
                      "(or the absolute test holds), for the equilibrium residual "
                      "r_u of the free DoFs.");
    prm.declare_entry("Displacement absolute tolerance", "1e-9", Patterns::Double(0.),
                      "Absolute bound on |r_u|. Units: force. Must be > 0 "
                      "(residuals stall at round-off). Capped at 1e-9 E_max L^(dim-1) "
                      "(E_max the largest Young's modulus, L the model's largest "
                      "extent), so that a scene in small units is not accepted "
                      "before a unit-sized one would be.");
    prm.declare_entry("Multiplier relative tolerance", "1e-4", Patterns::Double(0.),
                      "Same for the complementarity residual of the multipliers.");
    prm.declare_entry("Multiplier absolute tolerance", "1e-9", Patterns::Double(0.),
                      "Absolute bound on the multiplier residual. Units: length. "
                      "Must be > 0 (residuals stall at round-off). Capped at 1e-9 L "
                      "(L the model's largest extent).");
    prm.declare_entry("Damping", "1", Patterns::Double(0.),
                      "Step length alpha in (0, 1] of every Newton update, u <- u + "
                      "alpha du. Below 1 it damps an active set that cycles between "
                      "states, at the price of linear convergence (each iteration "
                      "removes the fraction alpha of the remaining error).");
    prm.leave_subsection();
  }

  void
  NewtonParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    max_iterations                  = prm.get_integer("Maximum iterations");
    displacement_relative_tolerance = prm.get_double("Displacement relative tolerance");
    displacement_absolute_tolerance = prm.get_double("Displacement absolute tolerance");
    multiplier_relative_tolerance   = prm.get_double("Multiplier relative tolerance");
    multiplier_absolute_tolerance   = prm.get_double("Multiplier absolute tolerance");
    damping                         = prm.get_double("Damping");
    prm.leave_subsection();
    // The residuals are computed in double precision: they stall at
    // round-off (measured on prm/hertz.prm: |r_u| ~ 1e-14, |r_lambda| ~
    // 2e-16) and never reach 0. Where a residual starts at round-off (a
    // step that changes nothing, a multiplier residual of nodes that stay
    // as they are) the relative test cannot pass either, so an absolute
    // tolerance of 0 makes such steps fail after their iterations, and
    // step splits do not help.
    const auto check_absolute = [](const double tolerance, const std::string &name) {
      AssertThrow(
        tolerance > 0.,
        ExcMessage(
          "Newton/" + name +
          " absolute tolerance is 0; expected a value > 0 (default 1e-9): a residual computed in "
          "double precision stalls at round-off and never reaches 0, and "
          "where it starts at round-off the relative test cannot pass "
          "either, so such a load step could not converge. To rely on "
          "the relative test, set it far below the residuals (e.g. 1e-30)."));
    };
    check_absolute(displacement_absolute_tolerance, "Displacement");
    check_absolute(multiplier_absolute_tolerance, "Multiplier");
    AssertThrow(damping > 0. && damping <= 1.,
                ExcMessage("Newton/Damping: expected a value in (0, 1]."));
  }
} // namespace contact_fem
