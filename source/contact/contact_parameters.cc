#include <contact_fem/contact/contact_parameters.h>
#include <contact_fem/core/parameters.h>

namespace contact_fem
{
  namespace
  {
    std::string
    pair_text(const std::string &slave, const std::string &master)
    {
      return "'" + slave + ": " + master + "'";
    }

    /// The pairs of Contact/Tied pairs (@p text), checked against each
    /// other and against the contact @p pairs: a tied surface belongs to
    /// one pair only.
    std::vector<ContactPair>
    parse_tied_pairs(const std::string &text, const std::vector<ContactPair> &pairs)
    {
      const std::string        key = "Contact/Tied pairs";
      std::vector<ContactPair> tied;
      for (const auto &[s, m] : split_key_value_list(text, key))
        {
          const ContactPair pair{parse_boundary_id(s, key), parse_boundary_id(m, key)};
          AssertThrow(pair.slave != pair.master,
                      ExcMessage(key + ": pair " + pair_text(s, m) +
                                 " has the same surface on both sides."));
          // A surface of this pair in one of @p others is refused: "... in
          // the @p what <pair>@p advice".
          const auto refuse_shared = [&](const std::vector<ContactPair> &others,
                                         const std::string &what, const std::string &advice) {
            for (const auto id : {pair.slave, pair.master})
              for (const auto &other : others)
                AssertThrow(other.slave != id && other.master != id,
                            ExcMessage(
                              key + ": surface " + std::to_string(id) + " of pair " +
                              pair_text(s, m) + " is also in the " + what + " " +
                              pair_text(std::to_string(other.slave), std::to_string(other.master)) +
                              advice));
          };
          refuse_shared(tied, "tied pair", "; a surface may be in one tied pair only.");
          refuse_shared(pairs, "contact pair",
                        " of Contact/Pairs; a surface is either tied or in contact: give "
                        "the contact surface its own boundary id.");
          tied.push_back(pair);
        }
      return tied;
    }
  } // namespace

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
    prm.declare_entry("Tied pairs", "", Patterns::Anything(),
                      "Mesh tying: surfaces glued together as 'slave boundary id: "
                      "master boundary id; ...' (or physical names), e.g. parts of an "
                      "assembly meshed separately, or a fine insert in a coarse mesh. "
                      "The two surfaces must touch (non-matching meshes, curved or "
                      "with hanging vertices are fine); every slave node is tied to "
                      "the master by the dual-mortar coupling u_s = D^-1 M u_m in every "
                      "component, imposed as constraints, and the tying traction is "
                      "reported. A tied surface may be in no other tied or contact "
                      "pair. Empty: no tying (no tying code runs). Independent of "
                      "Pairs: a scene may have both, or only tied pairs (then no "
                      "contact formulation runs). See doc/mesh_tying.md.");
    prm.declare_entry("Tied release in tension", "false", Patterns::Bool(),
                      "Tied pairs with a tension check: a tied slave node whose normal "
                      "tying traction pulls (tension) by more than Tied release threshold "
                      "times the largest tying traction of its pair is released for good "
                      "(debonded, never tied again) and becomes a frictionless contact "
                      "node of the pair: free while the surfaces open there, held by the "
                      "normal line of 'mpc frictionless' where they would penetrate. "
                      "Decided per Newton iteration, as an active set; the answer then "
                      "depends on the load path (every adaptive cycle re-solves it). "
                      "See doc/mesh_tying.md.");
    prm.declare_entry("Tied release threshold", "1e-3", Patterns::Double(0., 1.),
                      "With Tied release in tension: the normal tension, as a fraction "
                      "of the largest tying traction of the pair at that Newton "
                      "iteration, beyond which a tied node is released (so that "
                      "round-off releases nothing). In [1e-6, 1).");
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
                      "checked against the whole master surface. Also the reach of "
                      "the one search of the tied pairs.");
    prm.declare_entry("Kinematics", "small", Patterns::Selection("small|updated|current"),
                      "'small': the mortar operators (pairing, normals, D, M) are "
                      "built on the reference configuration and the gap is linear in "
                      "the displacement, consistent with the small-strain bulk: "
                      "frictionless results do not depend on the load steps (small "
                      "sliding, small rotations). 'updated': the operators are "
                      "rebuilt on the configuration X + u of the start of every load "
                      "step (follows larger sliding, but the answer then depends on "
                      "the number of load steps and adaptive cycles; see "
                      "doc/design.md). 'current': search, segmentation, D, M, "
                      "normals and gaps on the deformed surfaces X + u of every "
                      "Newton iterate, with their consistent linearisation in the "
                      "tangent (finite deformation, large sliding; Newton "
                      "converges quadratically; see doc/finite_strain.md). "
                      "Every formulation (the frictional ones with an objective "
                      "slip), in 2D and 3D (bilinear or curved faces).");
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
    tied_pairs = parse_tied_pairs(prm.get("Tied pairs"), pairs);
    tied_release_threshold.reset();
    if (prm.get_bool("Tied release in tension"))
      {
        AssertThrow(!tied_pairs.empty(),
                    ExcMessage("Contact/Tied release in tension = true, but Contact/Tied pairs "
                               "is empty: there is no tied pair to release."));
        tied_release_threshold = prm.get_double("Tied release threshold");
        AssertThrow(*tied_release_threshold >= 1e-6 && *tied_release_threshold < 1.,
                    ExcMessage("Contact/Tied release threshold: expected a value in [1e-6, 1) "
                               "(a fraction of the pair's largest tying traction; below 1e-6 "
                               "round-off of the tractions would decide the release)."));
      }
    search_factor         = prm.get_double("Search factor");
    current_kinematics    = prm.get("Kinematics") == "current";
    updated_kinematics    = prm.get("Kinematics") == "updated" || current_kinematics;
    penetration_tolerance = prm.get_double("Penetration tolerance");
    allow_loss_of_contact = prm.get_bool("Allow loss of contact");
    prm.leave_subsection();
    AssertThrow(search_factor > 0., ExcMessage("Contact/Search factor: expected a value > 0."));
    AssertThrow(penetration_tolerance > 0.,
                ExcMessage("Contact/Penetration tolerance: expected a value > 0."));
  }
} // namespace contact_fem
