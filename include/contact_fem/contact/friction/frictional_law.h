// The plug-in point of the frictional laws: the slip bound of a slave node
// as a function of its contact pressure, and the laws of each contact pair.
#ifndef contact_fem_frictional_law_h
#define contact_fem_frictional_law_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <contact_fem/contact/contact_parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /**
   * A frictional law: the tangential traction a node can carry before it
   * slips (its slip bound, or threshold) as a function of the contact
   * pressure p >= 0, and the derivative of that bound with respect to p,
   * which the semi-smooth Newton iteration needs for a consistent
   * linearisation of the slip condition |t| = threshold(p).
   *
   * A new law is one class derived from this one and one line in
   * FrictionalLaw::create().
   */
  class FrictionalLaw
  {
  public:
    virtual ~FrictionalLaw() = default;

    /// The slip bound at contact pressure @p p (>= 0), a stress.
    virtual double
    threshold(const double p) const = 0;

    /// d threshold / d p at @p p.
    virtual double
    threshold_derivative(const double p) const = 0;

    /// How the .prm names the law with its parameter ("coulomb 0.2").
    virtual std::string
    description() const = 0;

    /// A law from its .prm text "coulomb MU" or "tresca BOUND"; @p key
    /// names the entry in error messages.
    static std::unique_ptr<FrictionalLaw>
    create(const std::string &text, const std::string &key);
  };

  /// Coulomb: threshold mu p.
  class CoulombFriction : public FrictionalLaw
  {
  public:
    explicit CoulombFriction(const double mu)
      : mu(mu)
    {}

    double
    threshold(const double p) const override
    {
      return mu * p;
    }

    double
    threshold_derivative(const double) const override
    {
      return mu;
    }

    std::string
    description() const override;

  private:
    double mu;
  };

  /// Tresca: a threshold independent of the pressure (of an active node).
  class TrescaFriction : public FrictionalLaw
  {
  public:
    explicit TrescaFriction(const double bound)
      : bound(bound)
    {}

    double
    threshold(const double) const override
    {
      return bound;
    }

    double
    threshold_derivative(const double) const override
    {
      return 0.;
    }

    std::string
    description() const override;

  private:
    double bound;
  };

  /**
   * The keys Contact/Friction and Contact/Pure slip. Friction: one law for every pair ("coulomb 0.2"), or one
   * per pair by its slave boundary id ("3: coulomb 0.2; 5: tresca 0.01").
   */
  struct FrictionParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    /// The law of every pair of Contact/Pairs, in that order; empty when
    /// the key is empty. Throws naming the key on bad input.
    static std::vector<std::shared_ptr<const FrictionalLaw>>
    parse_laws(ParameterHandler &prm);
  };
} // namespace contact_fem

#endif
