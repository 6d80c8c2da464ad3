#include <contact_fem/contact/contact_parameters.h>
#include <contact_fem/core/parameters.h>

namespace contact_fem
{
  void
  ContactParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry("Pairs", "", Patterns::Anything(),
                      "Contact pairs as 'slave boundary id: master boundary id; "
                      "...'. Empty: no contact (plain elasticity, no contact code "
                      "runs). The slave side carries the multipliers: make it the "
                      "finer and softer surface." +
                        not_set_help(true),
                      true);
    prm.declare_entry("Allow loss of contact", "false", Patterns::Bool(),
                      "If false, a converged step without any active contact node "
                      "stops the run with a 'no contact' diagnosis (the load pulls "
                      "the bodies apart); if true the run goes on.");
    prm.declare_entry("Search factor", "3", Patterns::Double(0.),
                      "Tuning knob of the broad phase: the bounding box of a slave "
                      "face is enlarged by this factor times its length, plus the "
                      "motion the step may bring (predicted from the prescribed "
                      "displacements and the previous step, and enlarged during "
                      "Newton whenever an iterate moves farther). Correctness does "
                      "not depend on it: after convergence every slave node is "
                      "checked against the whole master surface.");
    prm.declare_entry("Kinematics", "small", Patterns::Selection("small|updated"),
                      "'small': the mortar operators (pairing, normals, D, M) are "
                      "built on the reference configuration and the gap is linear in "
                      "the displacement, consistent with the small-strain bulk: "
                      "frictionless results do not depend on the load steps (small "
                      "sliding, small rotations). 'updated': the operators are "
                      "rebuilt on the configuration X + u of the start of every load "
                      "step (follows larger sliding, but the answer then depends on "
                      "the number of load steps and adaptive cycles; see "
                      "doc/design.md).");
    prm.declare_entry("Penetration tolerance", "0.05", Patterns::Double(0.),
                      "After a step converges, every slave node is located against "
                      "the whole master surface of its pair (R-tree, closest point). "
                      "A node that penetrates by more than this fraction of its "
                      "element size beyond what its own mortar gap accounts for (the "
                      "search missed it, or the geometry moved beyond the operators) "
                      "makes the step search again, split, or stop with a "
                      "diagnosis.");
    prm.leave_subsection();
  }


  void
  ContactParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    pairs.clear();
    const std::string pairs_key = "Contact/Pairs";
    for (const auto &[s, m] : split_key_value_list(prm.get("Pairs"), pairs_key))
      {
        const ContactPair pair{parse_boundary_id(s, pairs_key), parse_boundary_id(m, pairs_key)};
        AssertThrow(pair.slave != pair.master, ExcMessage(pairs_key + ": pair '" + s + ": " + m +
                                                          "' has the same surface on both sides."));
        for (const auto &other : pairs)
          AssertThrow(other.slave != pair.slave && other.master != pair.slave &&
                        other.slave != pair.master,
                      ExcMessage(pairs_key + ": surface " + s +
                                 " appears in two pairs; a slave surface may belong to "
                                 "one pair only and may not be a master elsewhere."));
        pairs.push_back(pair);
      }
    search_factor         = prm.get_double("Search factor");
    updated_kinematics    = prm.get("Kinematics") == "updated";
    penetration_tolerance = prm.get_double("Penetration tolerance");
    allow_loss_of_contact = prm.get_bool("Allow loss of contact");
    prm.leave_subsection();
    AssertThrow(search_factor > 0., ExcMessage("Contact/Search factor: expected a value > 0."));
    AssertThrow(penetration_tolerance > 0.,
                ExcMessage("Contact/Penetration tolerance: expected a value > 0."));
  }
} // namespace contact_fem
