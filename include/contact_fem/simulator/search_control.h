// The contact search of the load steps: the room it leaves for the motion
// of the surfaces, the wider searches when an iterate outruns it, and the
// penetration check behind a "converged".
#ifndef contact_fem_search_control_h
#define contact_fem_search_control_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/contact_parameters.h>
#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/simulator/newton_failure.h>

#include <map>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /**
   * Sizes and repeats the search of a contact interface over the load
   * steps of an adaptive cycle, and checks each converged iterate against
   * the whole master surface. A search that pairs other faces restarts the
   * formulation's load step; the caller then rebuilds its sparsity pattern.
   * Made per mesh; all references outlive the control.
   */
  template <int dim>
  class SearchControl
  {
  public:
    SearchControl(ContactInterface<dim>    &interface,
                  ContactFormulation<dim>  &contact,
                  const ContactParameters  &parameters,
                  TimerOutput              &timer,
                  const ConditionalOStream &pcout);

    /// Searches the interface with the motion the step may bring (per pair,
    /// predicted from @p prescribed, the largest change of a prescribed
    /// displacement, and the last step) from the step's start
    /// @p displacement, and starts the formulation's load step.
    void
    start_step(const std::vector<double> &displacement,
               const double               prescribed,
               const double               step_size,
               const StepStart            start);

    /// During Newton: if the iterate @p displacement moved the surfaces
    /// farther than the search reaches, makes room for 1.5 times that
    /// motion and searches again; returns whether it did.
    bool
    extend_if_outrun(const std::vector<double> &displacement);

    /// Contact/Kinematics = current, during Newton: searches and
    /// linearises the operators on the iterate @p displacement; returns
    /// whether other faces are coupled than before (the sparsity pattern
    /// must then be rebuilt).
    bool
    follow(const std::vector<double> &displacement);

    /// The penetration check of a converged iterate @p displacement of load
    /// step @p step at @p time: true if it holds (the step's motion is then
    /// recorded), false after a wider search (Newton goes on); throws a
    /// NewtonFailure if it fails for good.
    bool
    accept(const std::vector<double> &displacement,
           const unsigned int         step,
           const double               time,
           const double               step_size);

    /// Per slave node (its x DoF, every node on every rank): the depth in
    /// the master that the penetration check allows it at @p displacement
    /// (what its gap explains, plus the tolerance); for the
    /// interpenetration check.
    std::map<types::global_dof_index, double>
    allowed_depths(const std::vector<double> &displacement) const;

    /// Of the last accepted step: the largest unexplained penetration over
    /// the element size.
    double
    last_penetration_excess() const
    {
      return penetration_excess;
    }

  private:
    /// The slave node that penetrates the master most beyond what its own
    /// mortar gap (and a small-sliding linearisation) accounts for.
    struct PenetrationCheck
    {
      double excess = 0.; ///< over the node's element size
      /// The worst slave node or hanging slave vertex.
      typename ContactInterface<dim>::SlaveNode node;
      bool                                      hanging     = false;
      double                                    penetration = 0., allowed = 0.;
    };
    /// Every slave node and hanging slave vertex against the whole master
    /// surface (ContactInterface::surface_distances()), each rank those it
    /// owns; the same on every rank. Collective.
    PenetrationCheck
    check_penetration(const std::vector<double> &displacement) const;
    /// What a slave node's own mortar gap and a small-sliding
    /// linearisation account for of its penetration (zero if unpaired).
    double
    allowed_penetration(const typename ContactInterface<dim>::SlaveNode &s,
                        const std::vector<double>                       &displacement) const;
    /// The diagnosis of a failed check_penetration(); splittable with
    /// updated kinematics only.
    NewtonFailure
    penetration_failure(const PenetrationCheck &check,
                        const unsigned int      step,
                        const double            time) const;
    /// Makes room for twice the motion allowance of @p pair plus @p depth
    /// and searches again.
    void
    widen(const std::vector<double> &displacement, const unsigned int pair, const double depth);
    /// Search and integration on @p configuration with the present motion
    /// allowance, and the linearisation with current kinematics.
    void
    search(const std::vector<double> &configuration);
    /// Searches the same configuration with the present motion allowance
    /// and restarts the formulation's active set from @p displacement.
    void
    search_again(const std::vector<double> &displacement);

    ContactInterface<dim>    &interface;
    ContactFormulation<dim>  &contact;
    const ContactParameters  &parameters;
    TimerOutput              &timer;
    const ConditionalOStream &pcout;

    /// The search reaches this many times the motion it is sized for.
    static constexpr double search_growth = 1.5;
    /// Wider searches for an unpaired penetrating node before giving up.
    static constexpr unsigned int max_searches_after_check = 3;
    /// Small sliding: the normal turns by less than this (radians) along
    /// the slip of a node, so a linearised gap errs by less than this times
    /// the slip (check_penetration()).
    static constexpr double max_sliding_angle = 0.1;

    /// Per pair: the motion allowance of the current search, and the
    /// relative surface motion of the last accepted step (with its size),
    /// from which the next step's is predicted.
    std::vector<double> motion_allowance, last_step_motion;
    double              last_step_size = 0.;
    /// The interface displacement at the start of the current load step.
    std::vector<double> step_start_displacement;
    /// Wider searches since the step's start.
    unsigned int searches_after_check = 0;
    double       penetration_excess   = 0.;
  };
} // namespace contact_fem

#endif
