#include <contact_fem/adaptivity/refinement.h>

namespace contact_fem
{
  void
  RefinementParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Refinement");
    prm.declare_entry("Number of cycles", "1", Patterns::Integer(1, 50),
                      "Solve / estimate / refine cycles. The first cycle steps "
                      "the load; later cycles start from the transferred "
                      "solution and solve at the end time in one step.");
    prm.declare_entry("Estimator", "spr contact",
                      Patterns::Selection("spr contact|spr|kelly|global"),
                      "Refinement indicator: 'spr contact' = superconvergent "
                      "patch recovery of the stress whose value at an active "
                      "slave node also satisfies the contact traction (the N_j-"
                      "weighted mean of sigma* n over the node's slave faces "
                      "equals its contact force, which acts along the deformed "
                      "normal, per unit reference length); 'spr' = the same without "
                      "contact terms; 'kelly' = gradient jumps; 'global' = "
                      "uniform refinement (the SPR-contact estimate is still "
                      "reported).");
    prm.declare_entry("Strategy", "fixed fraction",
                      Patterns::Selection("fixed fraction|fixed number|maximum"),
                      "Marking: 'fixed fraction' refines the fewest cells whose "
                      "indicators eta_K sum to the refine fraction of the sum "
                      "over all cells (deal.II's L1 norm: a sum of eta_K, not of "
                      "eta_K^2, so more cells than that fraction of eta^2), 'fixed "
                      "number' that fraction of the cells, 'maximum' the cells "
                      "whose indicator exceeds the fraction times the largest.");
    prm.declare_entry("Refine fraction", "0.3", Patterns::Double(0., 1.),
                      "Fraction used by the marking strategy.");
    prm.declare_entry("Coarsen fraction", "0", Patterns::Double(0., 1.),
                      "Fraction of cells (or error) to coarsen; 0 = none.");
    prm.declare_entry("Contact layers", "2", Patterns::Integer(1, 5),
                      "A contact-surface cell marked for refinement takes the "
                      "cells behind it along, this many layers deep in all "
                      "(1: the marking alone). A single refined layer on a "
                      "coarser interior puts hanging nodes right behind the "
                      "surface, whose alternating stiffness makes the contact "
                      "pressure oscillate node by node (0.3 % at p_max in the "
                      "Hertz study, doc/convergence.md).");
    prm.declare_entry("Contact layers along the surface", "true", Patterns::Bool(),
                      "true: each contact layer also takes the flagged cells' "
                      "neighbours along the contact surface (a buffer that keeps "
                      "the level change off the marked cells; on a coarse mesh it "
                      "spreads a few marked cells over the whole contact zone, "
                      "doc/validation.md, 3D Cattaneo-Mindlin); false: only the "
                      "column straight behind each flagged contact cell, so the "
                      "refinement along the surface follows the marking.");
    prm.declare_entry("Maximum level", "20", Patterns::Integer(1, 30),
                      "Cells at this refinement level are not refined further.");
    prm.declare_entry("Maximum cells", "1000000", Patterns::Integer(1),
                      "No refinement once the mesh has this many cells.");
    prm.declare_entry("Compare with plain SPR", "false", Patterns::Bool(),
                      "When the SPR-contact estimate is computed (every "
                      "estimator but 'spr'), also compute plain SPR on the "
                      "same solution and report it (plain_spr_estimated_error "
                      "in summary.json; with a reference energy its "
                      "effectivity), so that the two are compared on identical "
                      "meshes. A study diagnostic: its time is not counted in "
                      "the cycle's wall time.");
    prm.leave_subsection();
  }

  void
  RefinementParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Refinement");
    n_cycles             = prm.get_integer("Number of cycles");
    estimator            = prm.get("Estimator");
    strategy             = prm.get("Strategy");
    refine_fraction      = prm.get_double("Refine fraction");
    coarsen_fraction     = prm.get_double("Coarsen fraction");
    contact_layers       = prm.get_integer("Contact layers");
    layers_along_surface = prm.get_bool("Contact layers along the surface");
    max_level            = prm.get_integer("Maximum level");
    max_cells            = prm.get_integer("Maximum cells");
    compare_plain_spr    = prm.get_bool("Compare with plain SPR");
    prm.leave_subsection();
    AssertThrow(refine_fraction + coarsen_fraction <= 1.,
                ExcMessage("Refinement: Refine fraction + Coarsen fraction must "
                           "not exceed 1."));
  }
} // namespace contact_fem
