// Linear elastic materials of the bodies of a scene, one per material id.
#ifndef contact_fem_material_h
#define contact_fem_material_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/types.h>

#include <contact_fem/material/hyperelastic_law.h>

#include <map>
#include <string>
#include <utility>

namespace contact_fem
{
  using namespace dealii;

  /// Young's modulus and Poisson's ratio of one body.
  struct ElasticConstants
  {
    double youngs_modulus = 1.;
    double poisson_ratio  = 0.3;
    /// The law (Materials/Models); E and nu give its Lame constants.
    ElasticModel model = ElasticModel::linear;

    /// Lame's first parameter.
    double
    lambda() const;
    /// Shear modulus.
    double
    mu() const;
  };

  /// lambda / mu = 2 nu / (1 - 2 nu) of a Poisson's ratio: the ratio of the
  /// volumetric to the shear stiffness, which the stiffness matrix adds up.
  double
  lambda_over_mu(const double nu);

  /// Above this lambda / mu (1 / (10 eps) = 4.5e14, nu > 0.499999999999999)
  /// mu is within ten units of round-off of lambda: the stiffness matrix
  /// holds no digit of the shear stiffness (the Hertz scene with nu =
  /// 0.4999999999999999 and B-bar: MUMPS runs out of workspace, then finds
  /// 1771 zero pivots). Materials::parse_parameters() refuses such ratios.
  constexpr double
  max_lambda_over_mu()
  {
    return 0.1 / 2.220446049250313e-16;
  }

  /// Above this lambda / mu (nu > 0.499999995) the results lose balance
  /// beyond 1e-6 of the load (measured on the Hertz scene with B-bar: the
  /// relative reaction imbalance is about 1e-14 lambda/mu, 2.3e-7 at nu =
  /// 0.49999999, 4.6e-5 at 0.4999999999); set-up warns.
  constexpr double
  warn_lambda_over_mu()
  {
    return 1e8;
  }

  /// mu / K = 3 (1 - 2 nu) / (2 (1 + nu)) of a Poisson's ratio: as nu ->
  /// -1 the bulk modulus K vanishes next to the shear modulus mu (at a
  /// given E, mu = E / (2 (1 + nu)) grows without bound), and 1 + nu itself
  /// keeps only log10((1 + nu) / eps) digits.
  double
  shear_over_bulk(const double nu);

  /// Above this mu / K (1 / (10 eps), 1 + nu < 1e-14), 1 + nu is within
  /// ten units of round-off: Materials::parse_parameters() refuses it.
  constexpr double
  max_shear_over_bulk()
  {
    return 0.1 / 2.220446049250313e-16;
  }

  /// Above this mu / K (1 + nu < 1.5e-8) set-up warns: the body's
  /// stiffness keeps about 16 - log10(mu / K) digits.
  constexpr double
  warn_shear_over_bulk()
  {
    return 1e8;
  }

  /**
   * The isotropic linear elastic law of every body, keyed by the cells'
   * material id. In 2D the bodies are in plane strain: the out-of-plane
   * strain is zero, so the in-plane law is the 3D law restricted to the
   * plane (no modification of the constants).
   *
   * Implemented in source/material.cc.
   */
  template <int dim>
  class Materials
  {
  public:
    /// Declares the subsection "Materials".
    static void
    declare_parameters(ParameterHandler &prm);
    /// Reads the subsection "Materials"; throws with the key on bad values.
    void
    parse_parameters(ParameterHandler &prm);

    /// The constants of material id @p id; throws if the id has none.
    const ElasticConstants &
    constants(const types::material_id id) const;

    /// The material ids that have constants.
    std::map<types::material_id, ElasticConstants> bodies;

    /// Whether any body has a finite-strain (hyperelastic) law.
    bool
    finite_strain() const;

    /// Smallest and largest Young's modulus of the bodies.
    std::pair<double, double>
    youngs_modulus_range() const;

    /// sigma = C : eps for material @p id.
    SymmetricTensor<2, dim>
    stress(const types::material_id id, const SymmetricTensor<2, dim> &strain) const;

    /// sigma = 2 mu eps + lambda theta I, with theta the projected
    /// volumetric strain of the B-bar element (VolumetricProjection).
    SymmetricTensor<2, dim>
    stress(const types::material_id       id,
           const SymmetricTensor<2, dim> &strain,
           const double                   volumetric_strain) const;

    /// eps = C^{-1} : sigma for material @p id (used by energy norms of stress errors).
    SymmetricTensor<2, dim>
    compliance(const types::material_id id, const SymmetricTensor<2, dim> &stress) const;

    /// The fourth-order elasticity tensor of material @p id.
    SymmetricTensor<4, dim>
    stiffness_tensor(const types::material_id id) const;

    /// The Cauchy stress of a finite-strain body @p id (Materials/Models)
    /// at the displacement gradient @p grad_u, as the 3D tensor (in 2D of
    /// the plane-strain state F_zz = 1, so that sigma_zz is the law's).
    SymmetricTensor<2, 3>
    finite_strain_stress(const types::material_id id, const Tensor<2, dim> &grad_u) const;

    /// Von Mises stress of an in-plane (2D: plane strain) stress state of material @p id.
    double
    von_mises(const types::material_id id, const SymmetricTensor<2, dim> &stress) const;
  };
} // namespace contact_fem

#endif
