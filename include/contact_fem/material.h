// Linear elastic materials of the bodies of a scene, one per material id.
#ifndef contact_fem_material_h
#define contact_fem_material_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/types.h>

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

    /// Lame's first parameter.
    double
    lambda() const;
    /// Shear modulus.
    double
    mu() const;
  };

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

    /// Von Mises stress of an in-plane (2D: plane strain) stress state of material @p id.
    double
    von_mises(const types::material_id id, const SymmetricTensor<2, dim> &stress) const;
  };
} // namespace contact_fem

#endif
