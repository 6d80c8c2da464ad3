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
   * A new law is one class derived from this one, one Kind and one entry
   * in FrictionalLaw::create().
   */
  class FrictionalLaw
  {
  public:
    /// The laws Contact/Friction names.
    enum class Kind
    {
      coulomb, ///< "coulomb MU": threshold MU p
      tresca   ///< "tresca BOUND": a constant threshold
    };

    FrictionalLaw(const Kind kind, const double parameter)
      : law_kind(kind)
      , law_parameter(parameter)
    {}

    virtual ~FrictionalLaw() = default;

    /// The slip bound at contact pressure @p p (>= 0), a stress.
    virtual double
    threshold(const double p) const = 0;

    /// d threshold / d p at @p p.
    virtual double
    threshold_derivative(const double p) const = 0;

    Kind
    kind() const
    {
      return law_kind;
    }

    /// The law's parameter as the .prm gives it: mu (Coulomb), the bound
    /// (Tresca).
    double
    parameter() const
    {
      return law_parameter;
    }

    /// Whether the law has no friction at all (mu = 0, bound 0): its slip
    /// sign then changes nothing.
    bool
    frictionless() const
    {
      return law_parameter == 0.;
    }

    /// How the .prm names the law with its parameter ("coulomb 0.2").
    std::string
    description() const;

    /// A law from its .prm text "coulomb MU" or "tresca BOUND"; @p key
    /// names the entry in error messages.
    static std::unique_ptr<FrictionalLaw>
    create(const std::string &text, const std::string &key);

  private:
    Kind   law_kind;
    double law_parameter;
  };

  /// Coulomb: threshold mu p.
  class CoulombFriction : public FrictionalLaw
  {
  public:
    explicit CoulombFriction(const double mu)
      : FrictionalLaw(Kind::coulomb, mu)
    {}

    double
    threshold(const double p) const override
    {
      return parameter() * p;
    }

    double
    threshold_derivative(const double) const override
    {
      return parameter();
    }
  };

  /// Tresca: a threshold independent of the pressure (of an active node).
  class TrescaFriction : public FrictionalLaw
  {
  public:
    explicit TrescaFriction(const double bound)
      : FrictionalLaw(Kind::tresca, bound)
    {}

    double
    threshold(const double) const override
    {
      return parameter();
    }

    double
    threshold_derivative(const double) const override
    {
      return 0.;
    }
  };

  /**
   * The keys Contact/Friction and Contact/Pure slip, parsed once (by
   * ContactFormulation::create() for the formulations that take a law).
   * Friction: one law for every pair ("coulomb 0.2"), or one per pair by its
   * slave boundary id ("3: coulomb 0.2; 5: tresca 0.01").
   */
  struct FrictionParameters
  {
    /// The law of every pair of Contact/Pairs, in that order; empty when
    /// the key is empty.
    std::vector<std::shared_ptr<const FrictionalLaw>> laws;
    /// Every active node slips (no stick set).
    bool pure_slip = false;

    static void
    declare_parameters(ParameterHandler &prm);

    /// Reads both keys; throws naming the key on bad input.
    void
    parse_parameters(ParameterHandler &prm);

    /// The laws of Contact/Friction alone (see laws).
    static std::vector<std::shared_ptr<const FrictionalLaw>>
    parse_laws(ParameterHandler &prm);
  };
} // namespace contact_fem

#endif
