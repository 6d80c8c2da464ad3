#include <contact_fem/core/format.h>
#include <contact_fem/solvers/newton_monitor.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace contact_fem
{
  namespace
  {
    /// Residuals below this fraction of their first value in a load step
    /// are round-off: their digits differ between machines and partitions
    /// (at ~1e-14 of it), so they are not printed as numbers.
    constexpr double round_off_ratio = 1e-10;

    /// "= value", or "< tolerance" for a residual below its tolerance, or
    /// "at round-off" for one below round_off_ratio of its first value
    /// @p reference (which differ between runs and must not reach compared
    /// output).
    std::string
    residual_text(const double value, const double tolerance, const double reference)
    {
      return value <= tolerance                  ? "< " + scientific(tolerance, 0) :
             value < round_off_ratio * reference ? std::string("at round-off") :
                                                   "= " + scientific(value);
    }

    /// The two cells of a residual: at or below its absolute tolerance, or
    /// at round-off of its first value, neither it nor its ratio is printed
    /// as a number, so that reruns and MPI runs print the same table.
    /// @p largest: the largest value of the step, whose round-off the
    /// residuals carry (not the reference of the ratio, which may be less).
    std::string
    cells(const double ratio, const double value, const double tolerance, const double largest)
    {
      std::ostringstream s;
      if (value <= tolerance)
        s << std::setw(11) << "-"
          << " | " << std::setw(9) << ("< " + scientific(tolerance, 0));
      else if (value < round_off_ratio * largest)
        s << std::setw(11) << ("< " + scientific(round_off_ratio, 0)) << " | " << std::setw(9)
          << "round-off";
      else
        s << std::setw(11) << scientific(ratio) << " | " << std::setw(9) << scientific(value, 2);
      return s.str();
    }
  } // namespace

  NewtonMonitor::NewtonMonitor(const NewtonParameters &parameters, const bool nonlinear)
    : parameters(parameters)
    , nonlinear(nonlinear)
    , absolute_u(parameters.displacement_absolute_tolerance)
    , absolute_lambda(parameters.multiplier_absolute_tolerance)
  {}

  void
  NewtonMonitor::set_scene_units(const double force,
                                 const double length,
                                 const double load_displacement,
                                 const double coordinate_size)
  {
    // The defaults (1e-9) are those of a model of unit size and modulus;
    // a model in smaller units gets the same bounds relative to its own
    // scale, still seven orders above the round-off of the residuals
    // (about 1e-16 of the forces and coordinates).
    absolute_u      = std::min(parameters.displacement_absolute_tolerance, 1e-9 * force);
    absolute_lambda = std::min(parameters.multiplier_absolute_tolerance, 1e-9 * length);
    // A load below the scene's scale: a residual at the unit cap may be a
    // fair part of the load itself (measured: the 3D frictional patch at
    // loads x 1e-9, its whole residual below 1e-9 from the start, accepted
    // with a stick/slip change pending and the pressures 2.6 % off).
    // Zero (no load, an unloaded step) leaves the caps as they are.
    if (load_displacement > 0.)
      {
        const double load_share = std::min(1., load_displacement / length);
        absolute_u              = std::min(absolute_u, 1e-6 * force * load_share);
        // No gap is resolved below the round-off of the coordinates; 100
        // units of it leave the round-off of a converged gap far below.
        const double gap_round_off =
          100. * std::numeric_limits<double>::epsilon() * coordinate_size;
        absolute_lambda =
          std::min(absolute_lambda, std::max(1e-6 * load_displacement, gap_round_off));
        // Nor below the round-off of the displacements in the gap: a load
        // that moves the bodies by more than about 1e4 model sizes (the 2D
        // patch pressed by 2e10 at E = 100: the gap residual stalled at
        // 2.8e-8, 20 iterations and 4 splits, "more load steps").
        absolute_lambda = std::max(absolute_lambda, 100. * std::numeric_limits<double>::epsilon() *
                                                      load_displacement);
      }
  }

  double
  NewtonMonitor::reference_u() const
  {
    // The largest residual of the step, up to its initial one (the load
    // increment and the contact changes the step start sees): an overshoot
    // is no measure of the forces. Measured: the 3D Hertz quarter sphere
    // with penalty Coulomb friction and updated kinematics, step 4 of 4,
    // initial residual 2.7e5, the first slip solve's 5.6e9: accepted at
    // 4.8e-6 of that (2.7e4), 1.8e-4 of the forces out of balance. An
    // initial residual at the absolute tolerance (nothing changed at the
    // step start) is no scale either: the largest then, as before.
    return initial_u > absolute_u ? std::min(largest_u, initial_u) : largest_u;
  }

  NewtonMonitor::Assessment
  NewtonMonitor::assess(const unsigned int iteration,
                        const double       r_u,
                        const double       r_lambda,
                        const unsigned int changes,
                        const bool         searched_again)
  {
    Assessment a;
    last_u       = r_u;
    last_lambda  = r_lambda;
    last_changes = changes;
    if (iteration == 0)
      initial_u = r_u;
    largest_u          = std::max(largest_u, r_u);
    reference_lambda   = std::max(reference_lambda, r_lambda);
    const double ref_u = reference_u();
    a.ratio_u          = ref_u > 0. ? r_u / ref_u : 0.;
    a.ratio_lambda     = reference_lambda > 0. ? r_lambda / reference_lambda : 0.;

    a.residuals_small =
      (a.ratio_u <= parameters.displacement_relative_tolerance || r_u <= absolute_u) &&
      (a.ratio_lambda <= parameters.multiplier_relative_tolerance || r_lambda <= absolute_lambda);
    // Nodes with lambda = 0 and g = 0 to round-off (a gap closing exactly
    // at this load) may flip state forever without changing anything:
    // with both residuals at round-off the active set counts as settled.
    const bool at_round_off = r_u <= absolute_u && r_lambda <= absolute_lambda;
    // With a settled active set each further solve returns the same
    // displacement: a residual that stops decreasing is the accuracy of the
    // linear solver (very large stiffness contrasts), not a failure.
    // Bounded: a residual above 1e-2 of the step's is a failure whatever its
    // trend. Flat: a settled active set, and the residual decreases by less
    // than half what the (damped) update should remove (damped iterations
    // shrink the residual by a fixed factor: not stagnation).
    const bool flat = iteration > 1 && changes == 0 && previous_changes == 0 &&
                      r_u > (1. - 0.5 * parameters.damping) * previous_r_u;
    // A nonlinear problem's Newton iteration may fall by less than half
    // per iteration long before the linear solver's accuracy (measured:
    // ratio 7e-3 after 0.5, sheared neo-Hookean block at nu = 0.499; 3e-4
    // after 6e-4, a stiff penalty with friction on the current
    // configuration, which the 1e-2 bound accepted 1.5e-5 out of balance).
    const double stagnation_bound = nonlinear ? 1e-8 : 1e-2;
    // The multipliers may be at round-off from the start (no node changed
    // its pressure): their ratio is then noise, their absolute value small.
    // (Nonlinear problems only: the linear scenes keep their iterations.)
    const bool lambda_settled = a.ratio_lambda <= parameters.multiplier_relative_tolerance ||
                                (nonlinear && r_lambda <= parameters.multiplier_absolute_tolerance);
    // A direct solve's residual is the round-off of its terms (measured
    // 0.3 to 0.8 of eps |K| |u|, floor_hint()): a flat residual far above
    // that is a stall, not the solver's accuracy (a chain of contact pairs
    // whose multipliers mixed the two pairs' forces at the shared node,
    // flat at |r_u| = 6.5e-2, was accepted here; unit/newton_stall_direct_01).
    constexpr double solver_round_off_units = 1e3;
    const bool       at_solver_accuracy = !direct || r_u <= solver_round_off_units * round_off_u;
    const bool stagnating = parameters.damping == 1. && flat && a.ratio_u <= stagnation_bound &&
                            lambda_settled && at_solver_accuracy;
    // Flat with both residuals eight orders below their start: round-off,
    // which no tolerance below it can wait for.
    a.stalled   = flat && a.ratio_u <= 1e-8 && a.ratio_lambda <= 1e-8;
    a.converged = iteration > 0 && !searched_again &&
                  ((a.residuals_small && (changes == 0 || at_round_off)) || stagnating);
    // The run of flat iterations, for floor_hint().
    if (flat)
      {
        if (floor_run.empty())
          floor_run.push_back(previous_r_u);
        floor_run.push_back(r_u);
      }
    else
      floor_run.clear();
    previous_changes = iteration > 0 ? changes : 1;
    previous_r_u     = r_u;
    return a;
  }

  std::string
  NewtonMonitor::header(const std::string &contact_cells, const bool iterative)
  {
    return std::string(
             "    | it | disp. ratio | disp. abs | mult. ratio | mult. abs | changes | active |") +
           contact_cells + (iterative ? " lin. it |" : "");
  }

  double
  NewtonMonitor::displacement_target() const
  {
    return std::max(parameters.displacement_relative_tolerance * reference_u(), absolute_u);
  }

  std::string
  NewtonMonitor::row(const unsigned int                 iteration,
                     const unsigned int                 changes,
                     const unsigned int                 n_active,
                     const Assessment                  &a,
                     const std::string                 &contact_cells,
                     const std::optional<unsigned int> &linear_iterations) const
  {
    std::ostringstream s;
    s << "    | " << std::setw(2) << iteration << " | "
      << cells(a.ratio_u, last_u, absolute_u, largest_u) << " | "
      << cells(a.ratio_lambda, last_lambda, absolute_lambda, reference_lambda) << " | "
      << std::setw(7) << (iteration == 0 ? std::string("-") : std::to_string(changes)) << " | "
      << std::setw(6) << n_active << " |";
    s << contact_cells;
    if (linear_iterations)
      s << " " << std::setw(7)
        << (iteration == 0 ? std::string("-") : std::to_string(*linear_iterations)) << " |";
    s << (a.converged ?
            (a.residuals_small ? " converged" : " converged to linear-solver accuracy") :
            "");
    return s.str();
  }

  std::string
  NewtonMonitor::floor_hint() const
  {
    // A floor: three flat iterations in a row with the active set settled,
    // and no trend over them (a slowly converging iteration, at 0.8 per
    // iteration, falls by more than half over the run), within
    // round_off_units of the round-off of the residual's terms, eps |K| |u|
    // (set_round_off()). Newton then no longer lowers |r_u|: neither more
    // iterations nor smaller steps do. Measured: the floors are 0.3 to 0.8
    // of eps |K| |u|, which a displacement far larger than the load's own
    // sets (the 3D hemisphere at 1e-8 of its load: lifted rigidly by 3.1e-2
    // to close its pole's weighted gap, 8e-9 of elastic approach; 2D blocks
    // closing an initial gap: the floor in proportion to the gap, the same
    // at loads 100 times apart; doc/design.md).
    // Only |r_u| in the way: the multipliers' residual met its tolerance.
    const bool lambda_met =
      last_lambda <= absolute_lambda ||
      (reference_lambda > 0. &&
       last_lambda <= parameters.multiplier_relative_tolerance * reference_lambda);
    if (floor_run.size() < 4 || last_u <= displacement_target() || !lambda_met)
      return "";
    const auto [lowest, highest] = std::minmax_element(floor_run.begin(), floor_run.end());
    // Above the round-off of its terms, a flat run is no floor: a load
    // step too large, which splitting may cure.
    constexpr double round_off_units = 10.;
    if (*lowest < 0.5 * *highest || !(*highest <= round_off_units * round_off_u))
      return "";
    // Reachable: twice the floor's highest value, one digit rounded up.
    const double scale     = std::pow(10., std::floor(std::log10(2. * *highest)));
    const double reachable = std::ceil(2. * *highest / scale) * scale;
    return " |r_u| stagnated at " + scientific(*highest, 0) + " over the last " +
           std::to_string(floor_run.size() - 1) +
           " iterations with no active-set change: that is the round-off floor of this "
           "system's residual, the round-off of its terms (machine epsilon times |K| |u| = " +
           scientific(round_off_u, 0) +
           ": a displacement large beside the load's own, such as a rigid motion that closes "
           "an initial gap). Newton's updates no longer lower it, and a smaller step lowers "
           "the tolerance with the load, not the floor; it is above the displacement "
           "tolerance asked for (" +
           scientific(displacement_target(), 0) +
           "). Reachable: Newton/Displacement absolute tolerance = " + scientific(reachable, 0) +
           " (or a relative tolerance of " + scientific(reachable / reference_u(), 0) + ").";
  }

  std::string
  NewtonMonitor::last_residuals() const
  {
    return "(last: |r_u| " + residual_text(last_u, absolute_u, largest_u) + ", |r_lambda| " +
           residual_text(last_lambda, absolute_lambda, reference_lambda) + ", " +
           std::to_string(last_changes) + " active-set changes)";
  }
} // namespace contact_fem
