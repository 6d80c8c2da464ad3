// Superconvergent patch recovery (SPR, Zienkiewicz-Zhu) of the stress and the
// resulting a posteriori error estimator, with optional contact-traction terms
// at the slave nodes (in the spirit of the "SPR-C" recoveries that impose known
// boundary tractions on the recovered stress).
#ifndef contact_fem_stress_recovery_h
#define contact_fem_stress_recovery_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <contact_fem/material/material.h>
#include <contact_fem/material/volumetric_projection.h>

#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /// A weighted point of the slave surface (see ContactNodeTraction).
  template <int dim>
  struct TractionSample
  {
    Point<dim>     point;
    Tensor<1, dim> normal; ///< outward unit normal of the surface there
    double         weight;
  };

  /**
   * Contact traction known at one slave node j: the traction vector
   * sigma* n of the recovered stress on the slave surface.
   *
   * A dual-mortar multiplier is not a point value of the pressure: the
   * contact force of node j is int N_j p ds, so lambda_j is the N_j-weighted
   * mean of the pressure over the support of N_j, which differs from the
   * point value by O(h^2). Imposing it pointwise would cap the recovery at
   * that accuracy (below the O(h^3) of degree-2 SPR). So when @p samples
   * (the quadrature points of the node's slave faces, weights w_q =
   * quadrature weight * |dx/dxi| * N_j) are given, the condition is imposed
   * on the same weighted mean:
   *   sum_q w_q e . sigma*(x_q) . n_q = (e . traction) sum_q w_q
   * for e = the node's normal and its tangents. Without samples it is
   * imposed at @p location with n_q = @p normal.
   */
  template <int dim>
  struct ContactNodeTraction
  {
    /// Position of the slave node (a support point of the displacement
    /// element on the slave surface: a vertex, or for degree 2 also an edge
    /// midpoint / face centre). Decides which patches get the condition.
    Point<dim> location;
    /// Outward unit normal of the slave surface at the node (it is normalized
    /// again internally); splits the condition into the normal row and the
    /// tangential rows, which have their own penalties.
    Tensor<1, dim> normal;
    /// The (mean) traction vector sigma* n; -p n for a frictionless contact
    /// pressure p with the normal n of the reference configuration. Per
    /// reference area: for a finite-strain body it is compared with J
    /// sigma* F^-T n.
    Tensor<1, dim> traction;
    /// Weighted points of the support of the node (may be empty).
    std::vector<TractionSample<dim>> samples = {};
    /// false: the node's condition is not imposed (an inactive slave node);
    /// its recovered stress is only reported (Result::node_stresses).
    bool imposed = true;
    /// The node's displacement DoF of component 0, if known: then only the
    /// support points that carry it get the node (not those of another
    /// body's node at the same place, whose side face may also face along
    /// a deformed normal at a corner).
    types::global_dof_index dof = numbers::invalid_dof_index;
  };

  /**
   * The SPR error estimator of the elastic stress.
   *
   * Outline (details in source/stress_recovery.cc):
   *
   * - sigma_h = C(material id) : eps(u_h) is sampled at the Gauss points of
   *   every cell: the centre for p = 1, the (p + 1)-point rule per
   *   direction for p >= 2 (p = displacement degree). For a finite-strain
   *   body (Materials/Models) sigma_h is the law's Cauchy stress at F = I +
   *   grad u_h, recovered at the reference points (symmetric, so the same
   *   fits apply), and its contact condition compares the nominal traction
   *   J sigma* F^-T N (Nanson) with the node's traction per reference area.
   * - For every vertex and every body (material id) whose cells touch the
   *   vertex, the patch is the set of active cells of that body that have the
   *   vertex as one of their vertices. Each stress component is fitted there by
   *   least squares with a complete polynomial of degree p in coordinates
   *   centred at the vertex and scaled by the patch radius. Bodies are never
   *   mixed, also if two bodies share a vertex.
   * - Patches with too few / degenerate sampling points (boundary and corner
   *   vertices) use the average of the full fits of the neighbouring vertices
   *   (the vertices of the patch cells), evaluated at the point in question,
   *   which is the classical Zienkiewicz-Zhu treatment of boundary nodes.
   *   Degenerate includes unstable: a fit of full rank whose Lebesgue
   *   constant on the patch (max over the patch's cell vertices x of
   *   sum_i |w_i(x)|, sigma*(x) = sum_i w_i(x) sigma_h(x_i)) exceeds 8 (3D Q1
   *   boundary patches at coarse-fine boundaries, whose cell centres lie
   *   near a plane; regular patches have 2.5-6.5).
   * - Contact terms: the recovered value at a contact node (a support point
   *   of the recovered field on a boundary face whose outward normal points
   *   along the node's normal, i.e. on the slave side) is its fitted value
   *   shifted so that the traction condition holds: the node's patch problem
   *   augmented by the penalty terms alpha_n (n.r)^2 + alpha_t |(I - n n) r|^2,
   *   r = t - sigma* n (in the weighted-mean form of ContactNodeTraction when
   *   it has samples), t = the node's traction, alpha = the dimensionless
   *   Settings penalties weighing the condition against the fitted value.
   *   Only the node's own value carries its condition: the fits of the
   *   neighbouring patches stay plain least-squares fits.
   * - The recovered field sigma* is a continuous FE_Q(p) field: the value at a
   *   support point is the mean of the (effective) fits of the vertices of the
   *   geometric object the support point belongs to; hanging support points
   *   take their values from the hanging-node constraints.
   * - eta_K^2 = int_K (sigma* - sigma_h) : C^{-1} : (sigma* - sigma_h), C
   *   the linear law of the body (for a finite-strain body that of its
   *   small-strain limit, the tangent at F = I).
   */
  /// How StressRecovery imposes the contact tractions; its keys live in the
  /// subsection "Refinement".
  struct StressRecoverySettings
  {
    /// false: plain SPR, the contact nodes only report their recovered
    /// stress.
    bool contact_terms = true;
    /// Weight of (n.sigma*.n + p)^2 against the squared change of the
    /// node's fitted value: the normal traction moves alpha / (1 + alpha)
    /// of the way to the condition.
    double penalty_normal = 1e4;
    /// Weight of |(I - n n) sigma* n|^2 (frictionless: zero shear traction)
    /// on the same scale; the shear moves alpha / (2 + alpha) of the way.
    double penalty_tangential = 1e4;

    static void
    declare_parameters(ParameterHandler &prm);
    /// Reads the penalties (contact_terms is the caller's choice).
    void
    parse_parameters(ParameterHandler &prm);
  };

  template <int dim>
  class StressRecovery
  {
  public:
    using Settings = StressRecoverySettings;

    struct Result
    {
      /// Size triangulation.n_active_cells(); eta_K on locally owned cells, 0
      /// elsewhere.
      Vector<float> cell_indicators;
      /// eta = sqrt(sum_K eta_K^2) over all ranks.
      double estimated_error = 0;
      /// sqrt(sum_K int_K sigma_h : eps_h) over all ranks (for a finite-strain
      /// body eps_h = C^{-1} : sigma_h of its small-strain limit).
      double solution_energy_norm = 0;
      /// eta / solution_energy_norm (0 if both vanish, +inf if only the
      /// energy norm vanishes).
      double relative_error = 0;
      /// Per contact node (in the order given, the same on every rank): the
      /// recovered stress sigma*(x_j) at the node, with the node's
      /// correction if it was imposed. Plain SPR (contact_terms = false)
      /// reports it too, so the two recoveries can be compared. Zero for a
      /// node that is not a support point of a slave face.
      std::vector<SymmetricTensor<2, dim>> node_stresses;
    };

    /**
     * Compute the estimate. @p dof_handler carries FESystem(FE_Q<dim>(p), dim)
     * on a (parallel::distributed or serial) triangulation, @p solution is the
     * ghosted (locally relevant) displacement, @p contact_nodes must be the
     * same list on every rank. With @p volumetric (B-bar) the FE stresses
     * use its projected volumetric strain. Collective over the
     * triangulation's communicator.
     */
    static Result
    estimate(const Mapping<dim>                          &mapping,
             const DoFHandler<dim>                       &dof_handler,
             const TrilinosWrappers::MPI::Vector         &solution,
             const Materials<dim>                        &materials,
             const std::vector<ContactNodeTraction<dim>> &contact_nodes,
             const Settings                              &settings,
             VolumetricProjection<dim>                   *volumetric = nullptr);
  };
} // namespace contact_fem

#endif
