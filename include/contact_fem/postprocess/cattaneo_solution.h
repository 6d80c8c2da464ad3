// The Cattaneo-Mindlin solution of two elastic cylinders (plane strain), or
// of two spheres (3D, Mindlin), pressed together by P and then sheared by
// Q < mu P at constant P, and its
// comparison with the stick zone and tangential traction of a frictional run
// (nodal values in, numbers out: the run's side is cattaneo_comparison.cc).
#ifndef contact_fem_cattaneo_solution_h
#define contact_fem_cattaneo_solution_h

#include <contact_fem/core/json.h>

#include <string>
#include <utility>
#include <vector>

namespace contact_fem
{
  /// Which closed form: Cattaneo's cylinders (2D) under Coulomb friction
  /// or under Tresca friction (its bound g given as the friction
  /// parameter), or Mindlin's spheres (3D) under Coulomb friction.
  enum class CattaneoProblem
  {
    cylinders,
    cylinders_tresca,
    spheres
  };

  /**
   * Hertz contact (half-width a, peak p_max from the load P per unit
   * thickness, R* and E*) plus the Cattaneo-Mindlin tangential traction of
   * a monotonic tangential load Q at constant P, for equal materials (no
   * normal-tangential coupling):
   *   c/a  = sqrt(1 - Q / (mu P)),
   *   q(x) = mu p_max [sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2)]  |x| < c (stick),
   *   q(x) = mu p(x)                                                 c <= |x| < a (slip).
   * Under Tresca friction (bound g) the same with cattaneo_tresca.h:
   * c/a = sqrt(1 - (Q / (2 a g))^2), q = g in the slip zones.
   * With @p sphere (Mindlin, 3D) x is the distance r from the axis, a and
   * p_max = p0 those of Hertz' spheres from the load P on the whole sphere,
   * c/a = (1 - Q / (mu P))^(1/3), and q the same formula, along the load.
   */
  struct CattaneoSolution
  {
    double P = 0., Q = 0., mu = 0.; ///< loads per unit thickness (Q >= 0), Coulomb mu
    double g      = 0.;             ///< > 0: the Tresca bound instead of mu (then 0)
    bool   sphere = false;          ///< Mindlin's spheres (3D), else cylinders
    double a = 0., p_max = 0., c = 0.;
    /// Mindlin-Deresiewicz unloading from the peak Q_star (> 0) to Q (in
    /// [-Q_star, Q_star], along the peak's direction): the traction is
    ///   q = q_C(Q_star) - 2 q_C((Q_star - Q) / 2),
    /// q_C the monotone traction above; c is then the stick half-width of
    /// the second term, b = a sqrt(1 - (Q_star - Q) / (2 mu P)), and
    /// c_star that of the first.
    bool   unloading = false;
    double Q_star = 0., c_star = 0.;

    CattaneoSolution() = default;
    /// Monotone loading; Q >= mu P (full slip) gives c = 0. With @p tresca,
    /// @p mu is the Tresca bound g.
    CattaneoSolution(const double          P,
                     const double          Q,
                     const double          mu,
                     const double          radius,
                     const double          E_star,
                     const CattaneoProblem problem = CattaneoProblem::cylinders);
    /// A flag where the problem belongs would be taken for E* of the
    /// unloading constructor: refused at compile time.
    CattaneoSolution(double, double, double, double, double, bool) = delete;
    /// Unloading from @p Q_star to @p Q (Mindlin-Deresiewicz).
    CattaneoSolution(const double          P,
                     const double          Q,
                     const double          Q_star,
                     const double          mu,
                     const double          radius,
                     const double          E_star,
                     const CattaneoProblem problem = CattaneoProblem::cylinders);

    /// A tangential load below this fraction of the capacity() is none
    /// (the normal phase): far above the Newton tolerance's noise in Q (a
    /// normal step of the 3D scene leaves 4e-6 mu P), far below any load
    /// step of a path.
    static constexpr double no_tangential_load = 1e-3;

    /// The largest tangential load: mu P, or 2 a g under Tresca.
    double
    capacity() const
    {
      return g > 0. ? 2. * a * g : mu * P;
    }

    /// The largest slip bound: mu p_max, or g.
    double
    largest_bound() const
    {
      return g > 0. ? g : mu * p_max;
    }

    double
    pressure(const double x) const;

    /// The tangential traction q(x), along the direction of the load (of
    /// its peak when unloading): >= 0 for monotone loading.
    double
    tangential(const double x) const;

  private:
    /// The stick half-width (radius) c of a monotone load @p load.
    double
    stick_size(const double load) const;


    /// q_C(x) of a monotone load whose stick zone is |x| < @p stick.
    double
    monotone_traction(const double x, const double stick) const;
  };

  /**
   * The tangential load path of a run: the signed tangential loads Q_k of
   * its converged load steps, in order. 'monotone': |Q| never decreases
   * (Cattaneo); 'unloading': it rose to the peak Q_star and then fell
   * monotonically, not beyond -Q_star (Mindlin-Deresiewicz; beyond -Q_star
   * the memory of the peak is gone and the path is monotone again, the
   * other way); 'none': the load turned back a second time, for which the
   * report has no analytical solution. Changes below @p tolerance do not
   * count.
   */
  struct TangentialPath
  {
    enum class Kind
    {
      monotone,
      unloading,
      none
    } kind           = Kind::monotone;
    double direction = 0.; ///< +-1: of the (peak) load; 0 while Q = 0
    double Q         = 0.; ///< the last load along direction
    double Q_star    = 0.; ///< unloading: the peak, along direction
  };

  TangentialPath
  classify_tangential_path(const std::vector<double> &loads, const double tolerance);

  /// One slave node of the run: its position along the contact (relative
  /// to the contact centre), tangential traction t (on the slave, along the
  /// node's tangent), its nodal weight D, and its contact state. In 3D x is
  /// the distance from the axis, t the component along the load, and also:
  /// the in-plane component across the load, the coordinate along the load
  /// and the node's slave element size.
  struct CattaneoNode
  {
    double x = 0., t = 0., weight = 0.;
    bool   active = false, stick = false;
    double t_across = 0., along = 0., size = 0.;
  };

  /**
   * The run against @p exact.
   *
   * Measured stick half-width c_h: the stick nodes span [x_l, x_r]; each
   * end of the stick zone is put halfway to the next node outward (a slip
   * node, or the first node out of contact if none slips), so that
   * c_h = (e_r - e_l) / 2 with e_l = (x_l + x_{l-1}) / 2, e_r = (x_r +
   * x_{r+1}) / 2. When the discrete stick set is the set of nodes with
   * |x| < c, each end is within half a node spacing of the exact +-c:
   * |c_h - c| <= one slave element, measured in the spacing of the nodes at
   * the two ends (c_error_in_slave_elements).
   *
   * Tangential error: relative L2 error of t over all given nodes with
   * the nodal weights D (the mortar quadrature of the multiplier, as the
   * Hertz pressure error), against the exact traction sign(Q) q(x), the
   * sign being that of the resultant sum D t:
   *   sqrt(sum D (t_h - t)^2 / sum D t^2),
   * or relative to the slip bound mu p_max (sum D (mu p_max)^2 below) when
   * there is no tangential load (Q = 0, where t = 0).
   *
   * Spheres (3D): the stick radius c_h is that of the disc of the stick
   * nodes' area, c_h = sqrt(sum_stick D / (pi f)) (f the fraction of the
   * sphere modelled: its symmetry planes halve the D of their nodes), and
   * |c_h - c| is measured in the mean slave element size of the active
   * nodes; the stick zone's centre is the D-weighted mean of the stick
   * nodes' coordinate along the load; the traction error takes the
   * component across the load as error too.
   */
  struct CattaneoComparison
  {
    CattaneoSolution exact;
    unsigned int     n_stick = 0, n_slip = 0;
    bool             stick_contiguous = true; ///< no slip node between stick nodes
    double           c_h = 0., stick_center = 0.;
    double           end_spacing                  = 0.; ///< mean node spacing at the two ends
    double           c_error_in_slave_elements    = 0.;
    double           tangential_l2_relative_error = 0.;
  };

  /// @p nodes in any order. The exact traction is @p direction (+-1) times
  /// exact.tangential(x); 0 takes the sign of the resultant sum D t.
  CattaneoComparison
  compare_with_cattaneo(std::vector<CattaneoNode> nodes,
                        const CattaneoSolution   &exact,
                        const double              direction         = 0.,
                        const double              symmetry_fraction = 1.);

  Json
  to_json(const CattaneoComparison &comparison);

  /// The lines printed for a Cattaneo scene, from to_json().
  std::string
  cattaneo_report(const Json &cattaneo);

  /// A table of the load steps' comparisons (an array of to_json()):
  /// Q/(mu P), c/a, c_h/a, |c_h - c| / h and the traction's L2 error. With
  /// @p bounds (one per compared step, or one for all) also the check that
  /// every compared step has its stick radius within one slave nodal
  /// spacing and its L2 error within its bound.
  std::string
  cattaneo_steps_report(const Json &steps, const std::vector<double> &bounds = {});
} // namespace contact_fem

#endif
