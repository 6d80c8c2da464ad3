#include <deal.II/base/exceptions.h>

#include <contact_fem/material/hyperelastic_law.h>
#include <contact_fem/material/material.h>

#include <cmath>

namespace contact_fem
{
  namespace
  {
    /// (A (x) B)_IJKL = 1/2 (A_IK B_JL + A_IL B_JK): the symmetric product
    /// that dC^-1/dC = -(C^-1 (x) C^-1) and the identity (A = B = I) use.
    template <int dim>
    SymmetricTensor<4, dim>
    symmetric_product(const SymmetricTensor<2, dim> &A)
    {
      SymmetricTensor<4, dim> T;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = k; l < dim; ++l)
              T[i][j][k][l] = 0.5 * (A[i][k] * A[j][l] + A[i][l] * A[j][k]);
      return T;
    }
  } // namespace

  ElasticModel
  parse_elastic_model(const std::string &name, const unsigned int entry)
  {
    for (const ElasticModel model :
         {ElasticModel::linear, ElasticModel::neo_hookean, ElasticModel::saint_venant_kirchhoff})
      if (name == to_string(model))
        return model;
    AssertThrow(false,
                ExcMessage("Materials/Models: entry " + std::to_string(entry + 1) + " is '" + name +
                           "'; expected linear, neo-hookean or saint-venant-kirchhoff."));
    return ElasticModel::linear;
  }

  std::string
  to_string(const ElasticModel model)
  {
    switch (model)
      {
        case ElasticModel::neo_hookean:
          return "neo-hookean";
        case ElasticModel::saint_venant_kirchhoff:
          return "saint-venant-kirchhoff";
        default:
          return "linear";
      }
  }

  template <int dim>
  std::unique_ptr<HyperelasticLaw<dim>>
  HyperelasticLaw<dim>::create(const ElasticModel model, const ElasticConstants &constants)
  {
    switch (model)
      {
        case ElasticModel::neo_hookean:
          return std::make_unique<NeoHookean<dim>>(constants.lambda(), constants.mu());
        case ElasticModel::saint_venant_kirchhoff:
          return std::make_unique<SaintVenantKirchhoff<dim>>(constants.lambda(), constants.mu());
        default:
          return nullptr;
      }
  }

  template <int dim>
  HyperelasticLaw<dim>::HyperelasticLaw(const double lambda, const double mu)
    : lambda(lambda)
    , mu(mu)
  {}

  template <int dim>
  SymmetricTensor<2, dim>
  HyperelasticLaw<dim>::green_lagrange(const Tensor<2, dim> &H)
  {
    return 0.5 * (symmetrize(H + transpose(H)) + symmetrize(transpose(H) * H));
  }

  namespace
  {
    /// The sum of the principal 2 x 2 minors of H (the second invariant).
    template <int dim>
    double
    principal_minors(const Tensor<2, dim> &H)
    {
      double minors = 0.;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i + 1; j < dim; ++j)
          minors += H[i][i] * H[j][j] - H[i][j] * H[j][i];
      return minors;
    }

    /// x - ln(1 + x), O(x^2): its series below |x| = 0.1 (20 terms: the
    /// rest is below 1e-21 of it), where the difference would cancel.
    double
    minus_log1p_remainder(const double x)
    {
      if (!(std::abs(x) < 0.1))
        return x - std::log1p(x);
      double sum = 0.; // sum_{n >= 2} (-1)^n x^(n - 2) / n, by Horner
      for (unsigned int n = 21; n >= 2; --n)
        sum = (n % 2 == 0 ? 1. : -1.) / n + x * sum;
      return x * x * sum;
    }
  } // namespace

  template <int dim>
  double
  HyperelasticLaw<dim>::jacobian_minus_one(const Tensor<2, dim> &H)
  {
    // det(I + H) = 1 + tr H + (sum of the principal 2 x 2 minors of H) + det H
    // (in 2D the minor is det H itself).
    return trace(H) + (dim == 3 ? principal_minors(H) : 0.) + determinant(H);
  }

  template <int dim>
  Tensor<2, dim>
  HyperelasticLaw<dim>::first_piola(const Tensor<2, dim> &H) const
  {
    // F S = S + H S: S keeps its digits (not (I + H) S rounded to I + H).
    const Tensor<2, dim> S(second_piola(H));
    return S + H * S;
  }

  template <int dim>
  Tensor<4, dim>
  HyperelasticLaw<dim>::first_piola_tangent(const Tensor<2, dim> &H) const
  {
    const Tensor<2, dim>          F  = identity_plus(H);
    const SymmetricTensor<2, dim> S  = second_piola(H);
    const SymmetricTensor<4, dim> CC = material_tangent(H);
    // F_kK CC_IJKL, then F_iI in front: two contractions of dim^5 each.
    Tensor<4, dim> FC; // (I, J, k, L)
    for (unsigned int I = 0; I < dim; ++I)
      for (unsigned int J = 0; J < dim; ++J)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int L = 0; L < dim; ++L)
            for (unsigned int K = 0; K < dim; ++K)
              FC[I][J][k][L] += F[k][K] * CC[I][J][K][L];
    Tensor<4, dim> A;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int J = 0; J < dim; ++J)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int L = 0; L < dim; ++L)
            {
              double a = i == k ? S[J][L] : 0.;
              for (unsigned int I = 0; I < dim; ++I)
                a += F[i][I] * FC[I][J][k][L];
              A[i][J][k][L] = a;
            }
    return A;
  }

  template <int dim>
  SymmetricTensor<2, dim>
  HyperelasticLaw<dim>::cauchy_stress(const Tensor<2, dim> &H) const
  {
    return symmetrize(first_piola(H) * transpose(identity_plus(H))) / (1. + jacobian_minus_one(H));
  }

  template <int dim>
  double
  NeoHookean<dim>::energy(const Tensor<2, dim> &H) const
  {
    // mu/2 (tr C - 3) - mu ln J = mu (tr E - ln J) (C_zz = 1 in plane
    // strain) is O(H^2) from two O(H) terms: summed as (tr E - (J - 1)) +
    // ((J - 1) - ln J), each without the cancellation (tr H drops out of the
    // first analytically, the second is its series at small J - 1).
    const double J_minus_one = this->jacobian_minus_one(H);
    const double log_J       = std::log1p(J_minus_one);
    const double trace_E_minus_J =
      0.5 * scalar_product(H, H) - (dim == 3 ? principal_minors(H) : 0.) - determinant(H);
    return this->mu * (trace_E_minus_J + minus_log1p_remainder(J_minus_one)) +
           0.5 * this->lambda * log_J * log_J;
  }

  template <int dim>
  SymmetricTensor<2, dim>
  NeoHookean<dim>::second_piola(const Tensor<2, dim> &H) const
  {
    // I - C^-1 = C^-1 (C - I) = 2 C^-1 E: no cancellation at small strains.
    const SymmetricTensor<2, dim> E         = this->green_lagrange(H);
    const SymmetricTensor<2, dim> C_inverse = invert(unit_symmetric_tensor<dim>() + 2. * E);
    return 2. * this->mu * symmetrize(Tensor<2, dim>(C_inverse) * Tensor<2, dim>(E)) +
           this->lambda * std::log1p(this->jacobian_minus_one(H)) * C_inverse;
  }

  template <int dim>
  SymmetricTensor<4, dim>
  NeoHookean<dim>::material_tangent(const Tensor<2, dim> &H) const
  {
    // dS/dE = lambda C^-1 (x) C^-1 + 2 (mu - lambda ln J) dC^-1/dC, from
    // d ln J / dC = C^-1 / 2 and dC^-1/dC = -(C^-1 (x) C^-1)_sym.
    const SymmetricTensor<2, dim> C_inverse =
      invert(unit_symmetric_tensor<dim>() + 2. * this->green_lagrange(H));
    return this->lambda * outer_product(C_inverse, C_inverse) +
           2. * (this->mu - this->lambda * std::log1p(this->jacobian_minus_one(H))) *
             symmetric_product(C_inverse);
  }

  template <int dim>
  double
  SaintVenantKirchhoff<dim>::energy(const Tensor<2, dim> &H) const
  {
    const SymmetricTensor<2, dim> E = this->green_lagrange(H);
    return 0.5 * this->lambda * trace(E) * trace(E) + this->mu * (E * E);
  }

  template <int dim>
  SymmetricTensor<2, dim>
  SaintVenantKirchhoff<dim>::second_piola(const Tensor<2, dim> &H) const
  {
    const SymmetricTensor<2, dim> E = this->green_lagrange(H);
    return this->lambda * trace(E) * unit_symmetric_tensor<dim>() + 2. * this->mu * E;
  }

  template <int dim>
  SymmetricTensor<4, dim>
  SaintVenantKirchhoff<dim>::material_tangent(const Tensor<2, dim> &) const
  {
    return this->lambda *
             outer_product(unit_symmetric_tensor<dim>(), unit_symmetric_tensor<dim>()) +
           2. * this->mu * symmetric_product(unit_symmetric_tensor<dim>());
  }

  template class HyperelasticLaw<2>;
  template class HyperelasticLaw<3>;
  template class NeoHookean<2>;
  template class NeoHookean<3>;
  template class SaintVenantKirchhoff<2>;
  template class SaintVenantKirchhoff<3>;
} // namespace contact_fem
