// Hyperelastic laws of finite-strain bodies: strain energy, stresses and the
// material tangent as functions of the deformation gradient.
#ifndef contact_fem_hyperelastic_law_h
#define contact_fem_hyperelastic_law_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>

namespace contact_fem
{
  using namespace dealii;

  struct ElasticConstants;

  /// F = I + H from the displacement gradient H (the laws take H, which
  /// keeps small strains to full precision, and form F only where needed).
  template <int dim>
  inline Tensor<2, dim>
  identity_plus(const Tensor<2, dim> &H)
  {
    Tensor<2, dim> F = H;
    for (unsigned int d = 0; d < dim; ++d)
      F[d][d] += 1.;
    return F;
  }

  /// The elastic law of a body (Materials/Models).
  enum class ElasticModel
  {
    linear,                ///< small strain, sigma = C : eps (the default)
    neo_hookean,           ///< compressible neo-Hookean, finite strain
    saint_venant_kirchhoff ///< S = lambda tr(E) I + 2 mu E, finite strain
  };

  /// The model named @p name ('linear', 'neo-hookean', 'saint-venant-kirchhoff');
  /// throws naming the entry @p entry of Materials/Models otherwise.
  ElasticModel
  parse_elastic_model(const std::string &name, const unsigned int entry);

  /// The name of @p model as Materials/Models takes it.
  std::string
  to_string(const ElasticModel model);

  /**
   * A hyperelastic law W(F) per unit reference volume, with the Lame
   * constants of the body (the small-strain limit of every law is the
   * linear law with the same E and nu). The laws give the second
   * Piola-Kirchhoff stress S = dW/dE and its material tangent dS/dE from
   * F; the first Piola-Kirchhoff stress P = F S and its tangent dP/dF,
   * which the total-Lagrangian assembly needs, follow here for every law.
   *
   * Every function takes the displacement gradient H = grad u = F - I, not
   * F: formed as I + H, F keeps H only to 1e-16 absolute, so at strains
   * near 1e-10 the stress of F had no correct digit (a load of 2e-9 on E =
   * 100 blocks left the reactions 6e-6 out of balance and the strain energy
   * wrong by a factor 3). E = (H + H^T + H^T H)/2 and ln J = log1p(J - 1)
   * with J - 1 from the invariants of H keep their relative precision.
   *
   * In 2D the bodies are in plane strain: F is the in-plane block of the 3D
   * gradient with F_zz = 1, and the 3D law restricted to it needs no change
   * of form (tr C = C_xx + C_yy + 1 enters only as a constant).
   *
   * Implemented in source/material/hyperelastic_law.cc.
   */
  template <int dim>
  class HyperelasticLaw
  {
  public:
    /// A law of the Lame constants @p lambda and @p mu.
    HyperelasticLaw(const double lambda, const double mu);
    virtual ~HyperelasticLaw() = default;

    /// The law of @p model with @p constants; null for ElasticModel::linear.
    static std::unique_ptr<HyperelasticLaw<dim>>
    create(const ElasticModel model, const ElasticConstants &constants);

    /// Strain energy per unit reference volume at the displacement gradient H.
    virtual double
    energy(const Tensor<2, dim> &H) const = 0;
    /// Second Piola-Kirchhoff stress S = dW/dE.
    virtual SymmetricTensor<2, dim>
    second_piola(const Tensor<2, dim> &H) const = 0;
    /// Material tangent dS/dE.
    virtual SymmetricTensor<4, dim>
    material_tangent(const Tensor<2, dim> &H) const = 0;

    /// First Piola-Kirchhoff stress P = F S = S + H S = dW/dF.
    Tensor<2, dim>
    first_piola(const Tensor<2, dim> &H) const;
    /// dP/dF: A_iJkL = delta_ik S_JL + F_iI F_kK (dS/dE)_IJKL.
    Tensor<4, dim>
    first_piola_tangent(const Tensor<2, dim> &H) const;
    /// Cauchy stress sigma = P F^T / det F.
    SymmetricTensor<2, dim>
    cauchy_stress(const Tensor<2, dim> &H) const;

    /// The Green-Lagrange strain E = (H + H^T + H^T H) / 2.
    static SymmetricTensor<2, dim>
    green_lagrange(const Tensor<2, dim> &H);
    /// J - 1 = det(I + H) - 1 from the invariants of H (no cancellation).
    static double
    jacobian_minus_one(const Tensor<2, dim> &H);

  protected:
    double lambda, mu; ///< the Lame constants
  };

  /// W = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2 (Bonet and Wood's
  /// compressible neo-Hookean); S = mu (I - C^-1) + lambda ln J C^-1.
  template <int dim>
  class NeoHookean : public HyperelasticLaw<dim>
  {
  public:
    using HyperelasticLaw<dim>::HyperelasticLaw;
    double
    energy(const Tensor<2, dim> &H) const override;
    SymmetricTensor<2, dim>
    second_piola(const Tensor<2, dim> &H) const override;
    SymmetricTensor<4, dim>
    material_tangent(const Tensor<2, dim> &H) const override;
  };

  /// W = lambda/2 (tr E)^2 + mu E : E with the Green-Lagrange strain E =
  /// (C - I) / 2. Not polyconvex: it softens under strong compression (the
  /// stress vanishes again as a stretch goes to zero), so it suits large
  /// rotations with moderate strains.
  template <int dim>
  class SaintVenantKirchhoff : public HyperelasticLaw<dim>
  {
  public:
    using HyperelasticLaw<dim>::HyperelasticLaw;
    double
    energy(const Tensor<2, dim> &H) const override;
    SymmetricTensor<2, dim>
    second_piola(const Tensor<2, dim> &H) const override;
    SymmetricTensor<4, dim>
    material_tangent(const Tensor<2, dim> &H) const override;
  };
} // namespace contact_fem

#endif
