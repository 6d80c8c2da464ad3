// Frictional contact as multipoint constraints: exact stick (every
// component of a sticking slave node eliminated through the dual mortar
// relation), Coulomb or Tresca slip (normal component eliminated, the
// tangential traction on the bound against the slip), the sets decided by
// the recovered reactions and the slip, without a penalty.
#ifndef contact_fem_mpc_frictional_h
#define contact_fem_mpc_frictional_h

#include <contact_fem/contact/formulations/alm_frictional.h>

namespace contact_fem
{
  /**
   * "mpc frictional": the constraints of "alm frictional" (a stick node:
   * u_j = sum_l M_jl / D_j u_l + offsets, all dim components; a slip node:
   * its normal component eliminated, its traction on the slip bound T(p)
   * along the slip direction d, through the test space), not slip treated
   * as frictionless. The sets follow the master-slave rule instead of
   * the complementarity functions, with no penalty:
   * - normal: released when the recovered pressure pulls, activated when
   *   the gap penetrates (as "mpc frictionless");
   * - a sticking node (and a slipping one before it moved in the step)
   *   slips when its recovered tangential traction reaches T(p), along
   *   that traction;
   * - a slipping node keeps slipping, its traction opposing the slip of the
   *   slave relative to the master (d = -xi / |xi|, so the direction
   *   follows the slip in 3D), and sticks when the slip turns back against
   *   d (a reversal passes through stick); a node that comes into contact
   *   while moving in the step slides in the same way if its bound holds
   *   nothing yet (Coulomb at p = 0; stuck, it would be pulled back to its
   *   place of the last step), else (Tresca) it sticks.
   * In 3D the cone term's stiffness is T(p) / |xi|, the derivative of
   * -T xi / |xi| across the slip (alm's c a / (1 - a) as c grows).
   * With Contact/Kinematics = current the Newton system is the alm's on
   * the iterate's configuration, xi the alm's objective slip.
   */
  template <int dim>
  class MpcFrictional : public AlmFrictional<dim>
  {
  public:
    using SlaveNode = typename ContactInterface<dim>::SlaveNode;

    /// Reads the shared normal keys (Contact/Penalty refused: there is
    /// none); @p friction: the laws and Pure slip.
    MpcFrictional(ParameterHandler &prm, const FrictionParameters &friction);

    /// The base's results, with penalty 0: none decides anything here.
    void
    add_results(const ContactInterface<dim> &interface, Json &contact) const override;

  protected:
    bool
    decides_active(const SlaveNode &s,
                   const double     g,
                   const bool       at_step_start,
                   const StepStart  start) const override
    {
      return this->reaction_rule(s, g, at_step_start, start);
    }

    /// The recovered pressure.
    double
    bound_pressure(const SlaveNode &s, const double) const override
    {
      return this->pressure[s.node];
    }

    TangentialVector<dim>
    stick_or_slip(const SlaveNode             &s,
                  const double                 p_bound,
                  const TangentialVector<dim> &xi) const override;

    double
    slip_cone_stiffness(const SlaveNode &s, const TangentialVector<dim> &xi) const override;

  private:
    /// A slip below this fraction of the node's size is no slip (its
    /// direction would be round-off).
    static constexpr double negligible_slip = 1e-10;
  };
} // namespace contact_fem

#endif
