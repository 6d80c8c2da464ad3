#include <deal.II/base/utilities.h>

#include <contact_fem/contact/friction/frictional_law.h>
#include <contact_fem/core/parameters.h>

#include <cmath>
#include <sstream>

namespace contact_fem
{
  namespace
  {
    std::string
    plain(const double value)
    {
      std::ostringstream s;
      s << value;
      return s.str();
    }
  } // namespace

  std::string
  FrictionalLaw::description() const
  {
    return (law_kind == Kind::coulomb ? "coulomb " : "tresca ") + plain(law_parameter);
  }

  std::unique_ptr<FrictionalLaw>
  FrictionalLaw::create(const std::string &text, const std::string &key)
  {
    std::istringstream in(text);
    std::string        name, value_text, rest;
    in >> name >> value_text >> rest;
    const std::string expected =
      "; expected 'coulomb MU' (MU >= 0, the friction coefficient) or 'tresca BOUND' "
      "(BOUND >= 0, the slip bound, a stress).";
    AssertThrow(!name.empty() && !value_text.empty() && rest.empty(),
                ExcMessage(key + ": got '" + Utilities::trim(text) + "'" + expected));
    double      value = -1.;
    std::size_t end   = 0;
    try
      {
        value = std::stod(value_text, &end);
      }
    catch (...)
      {
        end = 0;
      }
    AssertThrow(end == value_text.size() && std::isfinite(value),
                ExcMessage(key + ": '" + value_text + "' is not a number" + expected));
    if (name == "coulomb")
      {
        AssertThrow(value >= 0., ExcMessage(key + ": the friction coefficient must be >= 0, got " +
                                            value_text + "."));
        return std::make_unique<CoulombFriction>(value);
      }
    if (name == "tresca")
      {
        AssertThrow(value >= 0.,
                    ExcMessage(key + ": the Tresca bound must be >= 0, got " + value_text + "."));
        return std::make_unique<TrescaFriction>(value);
      }
    AssertThrow(false, ExcMessage(key + ": unknown frictional law '" + name + "'" + expected));
    return nullptr;
  }

  void
  FrictionParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry("Friction", "", Patterns::Anything(),
                      "Frictional law of the pairs, for the frictional formulations: "
                      "'coulomb MU' (slip bound MU * p) or 'tresca BOUND' (a "
                      "constant slip bound, a stress) for every pair, or per pair by "
                      "its slave boundary id: '3: coulomb 0.2; 5: tresca 0.01'. Empty: "
                      "frictionless (the frictionless formulations take no law).");
    prm.declare_entry("Pure slip", "false", Patterns::Bool(),
                      "Frictional formulations: every active node slips (no stick "
                      "set), in the direction of its trial traction; for scenes "
                      "known to slip everywhere.");
    prm.leave_subsection();
  }

  void
  FrictionParameters::parse_parameters(ParameterHandler &prm)
  {
    laws = parse_laws(prm);
    prm.enter_subsection("Contact");
    pure_slip = prm.get_bool("Pure slip");
    prm.leave_subsection();
  }

  std::vector<std::shared_ptr<const FrictionalLaw>>
  FrictionParameters::parse_laws(ParameterHandler &prm)
  {
    const std::string key = "Contact/Friction";
    prm.enter_subsection("Contact");
    const std::string text = Utilities::trim(prm.get("Friction"));
    prm.leave_subsection();
    ContactParameters contact;
    contact.parse_parameters(prm);
    std::vector<std::shared_ptr<const FrictionalLaw>> laws;
    if (text.empty())
      return laws;
    // Without pairs the law would act nowhere (and a frictional formulation
    // would then say that no law is given).
    AssertThrow(!contact.pairs.empty(),
                ExcMessage(key + ": '" + text +
                           "' is given, but Contact/Pairs is empty: friction acts between "
                           "the surfaces of a contact pair. Give the pairs as 'slave id: "
                           "master id', or leave Contact/Friction empty."));
    if (text.find(':') == std::string::npos)
      {
        const std::shared_ptr<const FrictionalLaw> law = FrictionalLaw::create(text, key);
        laws.assign(contact.pairs.size(), law);
        return laws;
      }
    laws.resize(contact.pairs.size());
    for (const auto &[id_text, law_text] : split_key_value_list(text, key))
      {
        const types::boundary_id id    = parse_boundary_id(id_text, key);
        bool                     found = false;
        for (unsigned int p = 0; p < contact.pairs.size(); ++p)
          if (contact.pairs[p].slave == id)
            {
              AssertThrow(!laws[p],
                          ExcMessage(key + ": slave surface " + id_text + " is given two laws."));
              laws[p] = FrictionalLaw::create(law_text, key);
              found   = true;
            }
        AssertThrow(found, ExcMessage(key + ": " + id_text +
                                      " is not the slave surface of any pair of Contact/Pairs."));
      }
    for (unsigned int p = 0; p < contact.pairs.size(); ++p)
      AssertThrow(laws[p], ExcMessage(key + ": no law for the pair with slave surface " +
                                      std::to_string(contact.pairs[p].slave) +
                                      "; give one per pair, or one law for all pairs."));
    return laws;
  }
} // namespace contact_fem
