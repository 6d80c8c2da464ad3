// The convergence test and the table of the semi-smooth Newton iteration of
// one load step.
#ifndef contact_fem_newton_monitor_h
#define contact_fem_newton_monitor_h

#include <contact_fem/solvers/solver_parameters.h>

#include <optional>
#include <string>
#include <vector>

namespace contact_fem
{
  /**
   * Follows the residuals of one load step's Newton iteration: the
   * equilibrium residual |r_u| of the free DoFs and the residual |r_lambda|
   * of the contact conditions, each relative to its largest value in the
   * step (|r_u|'s not above its value at the start of the step: an
   * overshooting iterate, e.g. a penalty's first slip solve, may have a
   * residual thousands of times the forces of the problem, against which
   * the relative test would accept forces still out of balance by a fair
   * part of the load), and the number of active-set changes. Decides
   * convergence (both residuals below their tolerance and a settled active set; or a
   * stagnating residual at the accuracy of the linear solver; or both at
   * round-off with a flickering active set) and formats the table rows, so
   * that round-off never reaches the printed digits.
   */
  class NewtonMonitor
  {
  public:
    /// @p nonlinear: the problem is nonlinear beyond its active set
    /// (finite-strain bodies, contact on the current configuration, 3D
    /// slip directions), so a slowly falling residual is Newton's
    /// pre-asymptotic phase, not the accuracy of the linear solver:
    /// stagnation then only counts at round-off (ratio 1e-8).
    explicit NewtonMonitor(const NewtonParameters &parameters, const bool nonlinear = false);

    /// The scene's own units: @p force = E_max L^(dim-1), the force a unit
    /// strain of the stiffest body carries over the model size L, and
    /// @p length = L. The absolute tolerances (in the user's units) are
    /// capped at 1e-9 of them, so that a scene in small units (a
    /// micrometre model, a rubber in MPa and metres) does not pass the
    /// absolute test long before the relative one: the convergence test
    /// then does not depend on the units. @p load_displacement (> 0 if
    /// known: the displacement the load causes, ContactDiagnosis::
    /// load_displacement_scale()) caps them further at 1e-6 of the load's
    /// own force and displacement, so that a load far below the scene's
    /// scale (a positively homogeneous problem scaled by 1e-9) is not
    /// accepted on absolute residuals that are a fair part of the load;
    /// the multiplier (gap) tolerance not below 100 units of the round-off
    /// of coordinates of size @p coordinate_size, which no gap resolves.
    void
    set_scene_units(const double force,
                    const double length,
                    const double load_displacement = 0.,
                    const double coordinate_size   = 0.);

    /// The size of the round-off of the residual at the iterate the last
    /// solve gave (ContactProblem::residual_round_off()): a flat |r_u|
    /// within round_off_units of it is a floor that no iteration lowers.
    void
    set_round_off(const double scale)
    {
      round_off_u = scale;
    }

    /// The last iteration was flat (floor_run): the next one's round-off
    /// scale is wanted.
    bool
    in_flat_run() const
    {
      return !floor_run.empty();
    }

    /// The linear solves are direct: a flat residual is accepted as their
    /// accuracy only at the round-off of its terms (assess()), so the
    /// round-off scale is wanted whenever the next iteration may be flat.
    void
    set_direct_solver()
    {
      direct = true;
    }

    /// Whether the round-off scale of the iteration @p iteration is wanted
    /// before it is assessed (with a direct solver: after a settled one).
    bool
    wants_round_off(const unsigned int iteration) const
    {
      return in_flat_run() || (direct && iteration > 1 && previous_changes == 0);
    }

    /// What the residuals of one iteration say.
    struct Assessment
    {
      double ratio_u = 0., ratio_lambda = 0.;
      /// Both residuals below their (relative or absolute) tolerance.
      bool residuals_small = false;
      bool converged       = false;
      /// Flat at round-off: no tolerance below it can be waited for.
      bool stalled = false;
    };

    /// Takes the residuals of @p iteration (0: the start of the step) with
    /// @p changes of the active set; @p searched_again: the contact search
    /// was widened in this iteration (never converged then).
    Assessment
    assess(const unsigned int iteration,
           const double       r_u,
           const double       r_lambda,
           const unsigned int changes,
           const bool         searched_again);

    /// The header of the table; with @p contact_cells the contact
    /// formulation's own columns (ContactFormulation::iteration_header(),
    /// e.g. the stick and slip counts of friction); with @p iterative the
    /// Krylov iterations of the linear solve.
    static std::string
    header(const std::string &contact_cells, const bool iterative);

    /// The row of @p iteration for the last assess(), with the contact
    /// formulation's own @p contact_cells (ContactFormulation::
    /// iteration_cells()) and with @p linear_iterations (an iterative
    /// linear solver) those.
    std::string
    row(const unsigned int                 iteration,
        const unsigned int                 changes,
        const unsigned int                 n_active,
        const Assessment                  &assessment,
        const std::string                 &contact_cells     = "",
        const std::optional<unsigned int> &linear_iterations = std::nullopt) const;

    /// The equilibrium residual at which an iterate is accepted: the
    /// larger of the absolute tolerance and the relative tolerance times
    /// the reference (the largest residual of the step so far, not above
    /// the initial one).
    double
    displacement_target() const;

    /// "(last: |r_u| ..., |r_lambda| ..., N active-set changes)" for a
    /// failure message.
    std::string
    last_residuals() const;

    /// With |r_u| above its target: " |r_u| stagnated at ..." naming the
    /// floor, its round-off scale and the tolerance reachable, when the
    /// residual has stopped falling (floor_run) within 10 units of
    /// set_round_off(); empty otherwise.
    std::string
    floor_hint() const;

    double
    last_r_u() const
    {
      return last_u;
    }

    double
    last_r_lambda() const
    {
      return last_lambda;
    }

  private:
    /// What |r_u| is measured against: its largest value in the step, not
    /// above the initial residual (unless that is at the absolute
    /// tolerance).
    double
    reference_u() const;

    NewtonParameters parameters;
    bool             nonlinear;
    bool             direct = false; ///< set_direct_solver()
    /// The absolute tolerances in use: the parameters', capped by
    /// set_scene_units().
    double absolute_u, absolute_lambda;
    /// |r_u| at iteration 0.
    double initial_u = 0.;
    /// The largest residuals of the step so far.
    double       largest_u = 0., reference_lambda = 0.;
    double       last_u = 0., last_lambda = 0., previous_r_u = 0.;
    unsigned int previous_changes = 1, last_changes = 0;
    /// |r_u| of the last iterations over which the active set stayed and
    /// the residual did not fall (each flat: above half its predecessor),
    /// with the iteration before them; cleared by any other iteration.
    std::vector<double> floor_run;
    /// set_round_off(); 0 before the first solve.
    double round_off_u = 0.;
  };
} // namespace contact_fem

#endif
