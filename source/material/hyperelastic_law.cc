#include <deal.II/base/exceptions.h>

#include <contact_fem/material/hyperelastic_law.h>
#include <contact_fem/material/material.h>

#include <cmath>

namespace contact_fem
{
  namespace
  {
    /// Right Cauchy-Green tensor C = F^T F.
    template <int dim>
    SymmetricTensor<2, dim>
    right_cauchy_green(const Tensor<2, dim> &F)
    {
      return symmetrize(transpose(F) * F);
    }

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
  Tensor<2, dim>
  HyperelasticLaw<dim>::first_piola(const Tensor<2, dim> &F) const
  {
    return F * Tensor<2, dim>(second_piola(F));
  }

  template <int dim>
  Tensor<4, dim>
  HyperelasticLaw<dim>::first_piola_tangent(const Tensor<2, dim> &F) const
  {
    const SymmetricTensor<2, dim> S  = second_piola(F);
    const SymmetricTensor<4, dim> CC = material_tangent(F);
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
  HyperelasticLaw<dim>::cauchy_stress(const Tensor<2, dim> &F) const
  {
    return symmetrize(first_piola(F) * transpose(F)) / determinant(F);
  }

  template <int dim>
  double
  NeoHookean<dim>::energy(const Tensor<2, dim> &F) const
  {
    // tr C - 3 with C_zz = 1 in plane strain: tr C - dim.
    const double log_J = std::log(determinant(F));
    return 0.5 * this->mu * (trace(right_cauchy_green(F)) - dim) - this->mu * log_J +
           0.5 * this->lambda * log_J * log_J;
  }

  template <int dim>
  SymmetricTensor<2, dim>
  NeoHookean<dim>::second_piola(const Tensor<2, dim> &F) const
  {
    const SymmetricTensor<2, dim> C_inverse = invert(right_cauchy_green(F));
    return this->mu * (unit_symmetric_tensor<dim>() - C_inverse) +
           this->lambda * std::log(determinant(F)) * C_inverse;
  }

  template <int dim>
  SymmetricTensor<4, dim>
  NeoHookean<dim>::material_tangent(const Tensor<2, dim> &F) const
  {
    // dS/dE = lambda C^-1 (x) C^-1 + 2 (mu - lambda ln J) dC^-1/dC, from
    // d ln J / dC = C^-1 / 2 and dC^-1/dC = -(C^-1 (x) C^-1)_sym.
    const SymmetricTensor<2, dim> C_inverse = invert(right_cauchy_green(F));
    return this->lambda * outer_product(C_inverse, C_inverse) +
           2. * (this->mu - this->lambda * std::log(determinant(F))) * symmetric_product(C_inverse);
  }

  template <int dim>
  double
  SaintVenantKirchhoff<dim>::energy(const Tensor<2, dim> &F) const
  {
    const SymmetricTensor<2, dim> E = 0.5 * (right_cauchy_green(F) - unit_symmetric_tensor<dim>());
    return 0.5 * this->lambda * trace(E) * trace(E) + this->mu * (E * E);
  }

  template <int dim>
  SymmetricTensor<2, dim>
  SaintVenantKirchhoff<dim>::second_piola(const Tensor<2, dim> &F) const
  {
    const SymmetricTensor<2, dim> E = 0.5 * (right_cauchy_green(F) - unit_symmetric_tensor<dim>());
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
