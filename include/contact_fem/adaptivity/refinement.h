// Parameters of the adaptive refinement loop.
#ifndef contact_fem_refinement_h
#define contact_fem_refinement_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace contact_fem
{
  using namespace dealii;

  struct RefinementParameters
  {
    unsigned int n_cycles             = 1;
    std::string  estimator            = "spr contact"; ///< spr contact|spr|kelly|global
    std::string  strategy             = "fixed fraction";
    double       refine_fraction      = 0.3;
    double       coarsen_fraction     = 0.;
    unsigned int contact_layers       = 2;    ///< cell layers refined below a contact face
    bool         layers_along_surface = true; ///< the layers also spread along the contact surface
    unsigned int max_level            = 20;
    unsigned int max_cells            = 1000000;
    /// Also compute plain SPR on the same solution (studies of what the
    /// contact terms change); its time is left out of the cycle's wall time.
    bool compare_plain_spr = false;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };
} // namespace contact_fem

#endif
