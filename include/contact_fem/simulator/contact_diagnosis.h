// The diagnoses of what goes wrong in a run: a lost contact, a stalled
// Newton iteration, a singular system, a model beyond double precision.
#ifndef contact_fem_contact_diagnosis_h
#define contact_fem_contact_diagnosis_h

#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/contact_parameters.h>
#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/contact/friction/frictional_law.h>
#include <contact_fem/core/json.h>
#include <contact_fem/geometry/scene.h>
#include <contact_fem/material/material.h>
#include <contact_fem/simulator/newton_failure.h>
#include <contact_fem/simulator/scene_parameters.h>
#include <contact_fem/solvers/linear_solver.h>
#include <contact_fem/solvers/solver_parameters.h>

#include <map>
#include <memory>
#include <limits>
#include <string>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /**
   * Reads the scene, its mesh and the contact state of a run and names the
   * real cause of a failure or a doubtful result, most specific first.
   * Made where it is needed; everything it refers to outlives it.
   */
  template <int dim>
  class ContactDiagnosis
  {
  public:
    /// What the diagnoses read of the run.
    struct Run
    {
      const Scene<dim>         &scene;
      const Materials<dim>     &materials;
      const BoundaryConditions &boundary_conditions;
      const ContactParameters  &contact_parameters;
      const NewtonParameters   &newton_parameters;
      const DoFHandler<dim>    &dof_handler;
      const Mapping<dim>       &mapping;
      /// Null without contact pairs.
      const ContactInterface<dim>   *interface;
      const ContactFormulation<dim> *contact;
      /// The most zero pivots of a Newton solve of this cycle.
      unsigned int most_null_pivots;
    };

    explicit ContactDiagnosis(const Run &run);

    /// The resultant of the applied pressures and tractions on each body at
    /// @p time. Collective.
    std::map<types::material_id, Tensor<1, dim>>
    body_loads(const double time) const;
    /// Whether every Pressure, Traction and Prescribed displacement is
    /// exactly zero at @p time on its boundary (at the faces' quadrature
    /// points and vertices): a load whose resultant vanishes (a pressure
    /// all around a body) is not zero. Collective.
    bool
    load_vanishes(const double time) const;
    /// Why the load at @p time is at the round-off of the geometry, or "".
    std::string
    load_at_round_off(const double time) const;
    /// Why double precision cannot resolve this model (stiffness ratio,
    /// a Poisson's ratio near -1 or 0.5), or "".
    std::string
    precision_limits() const;
    /// precision_limits() as the hint of a failure message: " Likely
    /// cause: ...", or "".
    std::string
    precision_hint() const;
    /// The stiffness ratio part of precision_limits().
    std::string
    stiffness_contrast_limit() const;
    /// The part of precision_limits() of a Poisson's ratio near -1.
    std::string
    auxetic_limit() const;
    /// The failure of a step without active slave nodes at @p where at
    /// @p time: the separating load, or the real cause if the load does not
    /// separate the bodies. @p none_started: no node started the step in
    /// contact (before any solve of the step). Splittable only if contact
    /// was lost numerically @p in_iteration (a smaller step may keep it).
    /// Collective.
    NewtonFailure
    no_contact_failure(const std::string &where,
                       const double       time,
                       const bool         in_iteration,
                       const bool         none_started) const;
    /// The hint of a Newton failure; @p stalled: the residuals stopped
    /// decreasing without active-set changes.
    std::string
    non_convergence_hint(const bool stalled, const double r_u, const double r_lambda) const;
    /// What decides the linear solver: materials, cell shapes, supports.
    /// Collective.
    ProblemTraits
    problem_traits() const;
    /// The translations that only friction holds: per body that a
    /// support holds and that is in contact, the rigid-body translations
    /// that neither its supports (fixed or prescribed components, fixed
    /// points, rollers) nor the contact's normal (the mean normal of the
    /// active slave nodes of each of its pairs) hold, as "body 2 along (1,
    /// 0, 0)" (a half model on its symmetry plane, loaded along it); ""
    /// if none. Bodies without any support are problem_traits()'
    /// unsupported_bodies. Collective.
    std::string
    friction_held_translations() const;
    /// For bodies @p free_bodies (held by no support) whose active contact
    /// is one pair: the sentence that the tangential load on the body at
    /// @p time is within the friction capacity of that pair under its law
    /// of @p laws (mu times the normal load under Coulomb, the bound times
    /// the active area under Tresca), naming both; "" if it is not, or if
    /// that cannot be told. Every node slipping then comes from the
    /// bodies' own deformation or an overshooting iterate, not from a load
    /// beyond the capacity. Collective.
    std::string
    load_within_friction_capacity(const std::vector<unsigned int>                         &free_bodies,
                                  const std::vector<std::shared_ptr<const FrictionalLaw>> &laws,
                                  const double time) const;
    /// The likely cause of a singular linear system (a penalty far above
    /// its automatic value, the precision limits, a body without supports)
    /// as a sentence for a failure message, or the question whether every
    /// body is held. @p relative_residual, ||A x - b|| / ||b|| of the
    /// failed solve if known (else NaN), tells a free rigid-body mode
    /// (of order 1) from digits lost to a stiffness contrast (well below).
    /// Collective.
    std::string
    singular_system_hint(
      const double relative_residual = std::numeric_limits<double>::quiet_NaN()) const;
    /// Young's modulus of the slave side of contact pair @p pair over that
    /// of its master side (the largest of each); 0 without master faces.
    double
    slave_stiffness_ratio(const unsigned int pair) const;
    /// The warnings printed before the first solve, each a sentence: models
    /// beyond double precision, Poisson's ratios where elements of
    /// @p degree lock without B-bar (@p b_bar: it is on), a slave side much
    /// stiffer than its master. (A load at round-off is an input error.)
    std::vector<std::string>
    modelling_warnings(const unsigned int degree, const bool b_bar) const;
    /// The warning of a cycle whose @p reaction record (its relative
    /// imbalance) at @p time does not balance the load, with its likely
    /// cause; "" if it balances.
    std::string
    balance_warning(const Json &reaction, const double time) const;
    /// The warning of an unloaded state (@p load_vanishes at @p time) whose
    /// pressures are far above round-off: a preload from a slave node that
    /// starts inside its master; "" otherwise.
    std::string
    preload(const Json &contact, const double time, const bool load_vanishes) const;
    /// The warning of a state whose "contact" record @p contact has active
    /// nodes at pressures of round-off: the load is zero at @p time
    /// (@p load_vanishes; not a preload()), or every pressure is below
    /// 1e-12 of the load's stress scale (E_min times the load's displacement
    /// over the model's extent). "" if the contact presses. Collective.
    std::string
    pressureless_contact(const Json &contact, const double time, const bool load_vanishes) const;
    /// Why a converged state whose "contact" record @p contact has an
    /// active node in tension is no result (its active set was decided by
    /// rounding); "" if every active node is in compression.
    std::string
    tension_failure(const Json &contact) const;

    /// The displacement the load at @p time causes: applied force over the
    /// smallest Young's modulus, or the largest prescribed displacement.
    /// Collective.
    double
    load_displacement_scale(const double time) const;

    /// The largest distance of a vertex from the origin (of the computing
    /// frame). Collective.
    double
    largest_coordinate() const;

  private:
    /// The integral of the outward normal over boundary @p id. Collective.
    Tensor<1, dim>
    surface_normal(const types::boundary_id id) const;
    /// The nearly incompressible part of precision_limits().
    std::string
    incompressibility_limit() const;
    /// The part of precision_limits() of cells far longer than thick.
    std::string
    aspect_ratio_limit() const;
    /// The applied loads along the outward normals of the contact surfaces
    /// of their bodies: > 0 pushes the bodies together. Collective.
    double
    load_toward_contact(const double time) const;
    /// Per contact pair, over its active paired slave nodes: the sum of
    /// D_j n_j (first) and of D_j (second), from the rows this rank owns,
    /// added in node order (ContactInterface::sum_in_node_order()): the
    /// serial sums on every rank, bit for bit. Collective.
    std::pair<std::vector<Tensor<1, dim>>, std::vector<double>>
    active_normals_and_areas() const;

    Run      run;
    MPI_Comm comm;
  };
} // namespace contact_fem

#endif
