// The forces of a load step: the reaction of every support and the force
// every contact pair transmits, for the console, summary.json and the
// history file forces.csv (a force-displacement curve is one plot of it).
#ifndef contact_fem_forces_h
#define contact_fem_forces_h

#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/contact_parameters.h>
#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/core/json.h>
#include <contact_fem/simulator/scene_parameters.h>

#include <ostream>
#include <string>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /**
   * Sign convention: every force is the one that acts ON a body, in global
   * components. A support's reaction is the force the support exerts on
   * the body it holds (it balances the loads: loads + reactions = 0); a
   * pair's force is the one the master surface exerts on the slave body
   * (the master body takes the opposite), split along the interface normal
   * of each slave node into a normal and a tangential part.
   */
  template <int dim>
  struct ForceReport
  {
    /// The reaction of the prescribed-displacement components of one
    /// boundary id (a DoF held by two boundaries counts for the first of
    /// the input), or of the fixed points of one body.
    struct Support
    {
      std::string    label;  ///< "boundary 2", "fixed points of body 1"
      std::string    column; ///< "boundary_2", "fixed_points_1" (CSV)
      Tensor<1, dim> force;
    };
    struct Pair
    {
      ContactPair    pair;
      Tensor<1, dim> normal, tangential;
      /// The contact area (2D: length per unit thickness): the sum of the
      /// mortar weights D_j of the active slave nodes.
      double area = 0.;
      /// With friction: the active slave nodes that stick and that slip
      /// (-1 without friction: not reported).
      int n_stick = -1, n_slip = -1;
    };
    std::vector<Support> supports;
    std::vector<Pair>    pairs;
    /// The largest force of the report: components below 1e-6 of it are
    /// printed as 0 (the equilibrium of a converged Newton iteration
    /// holds to about that, below it the digits are round-off).
    double scale = 0.;

    void
    print(std::ostream &out, const double time) const;
    Json
    to_json() const;
    /// The CSV header and row of forces.csv after "cycle,step,t".
    std::string
    csv_header() const;
    std::string
    csv_row() const;
  };

  /// What compute_forces() reads: the converged state of a load step.
  template <int dim>
  struct ForceInputs
  {
    const DoFHandler<dim> &dof_handler;
    /// K u - f (owned entries) and the Dirichlet constraints whose DoFs
    /// carry the reactions.
    const TrilinosWrappers::MPI::Vector      &residual;
    const AffineConstraints<double>          &dirichlet;
    const std::vector<DisplacementCondition> &displacements;
    /// The fixed points: what else the Dirichlet constraints hold.
    const std::vector<PointCondition> &points;
    /// Null without contact.
    const ContactInterface<dim>   *interface;
    const ContactFormulation<dim> *contact;
    /// The contact force at the interface DoFs (internal: taken out of the
    /// residual where a support holds a contact node).
    const std::vector<double>      &contact_force;
    const std::vector<ContactPair> &pairs;
    /// Boundary conditions/Rollers: every component of their nodes carries
    /// a part of the reaction (normal to the boundary).
    const std::vector<types::boundary_id> &rollers;
  };

  template <int dim>
  ForceReport<dim>
  compute_forces(const ForceInputs<dim> &in);

  /// The reaction at the held DoF @p dof (owned): K u - f there, less the
  /// contact force (internal) where it belongs to a contact node of
  /// @p interface (null without contact).
  template <int dim>
  double
  held_dof_reaction(const TrilinosWrappers::MPI::Vector &residual,
                    const ContactInterface<dim>         *interface,
                    const std::vector<double>           &contact_force,
                    const types::global_dof_index        dof);
} // namespace contact_fem

#endif
