#include <deal.II/base/quadrature_lib.h>

#include <contact_fem/material/finite_strain_bulk.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace contact_fem
{
  namespace
  {
    /// The displacement gradient H = F - I = sum_i u_i e_(c_i) (x) g_i
    /// (the laws take H: I + H would round it to 1e-16 absolute).
    template <int dim>
    Tensor<2, dim>
    displacement_gradient(const Vector<double>              &u,
                          const std::vector<unsigned int>   &component,
                          const std::vector<Tensor<1, dim>> &g)
    {
      Tensor<2, dim> H;
      for (unsigned int i = 0; i < u.size(); ++i)
        H[component[i]] += u(i) * g[i];
      return H;
    }
  } // namespace

  template <int dim>
  FiniteStrainBulk<dim>::FiniteStrainBulk(const Materials<dim>     &materials,
                                          const Mapping<dim>       &mapping,
                                          const FiniteElement<dim> &fe,
                                          const bool                f_bar)
    : fe_values(mapping, fe, QGauss<dim>(fe.degree + 1), update_gradients | update_JxW_values)
    , component(fe.n_dofs_per_cell())
    , g(fe.n_dofs_per_cell())
    , f_bar(f_bar)
  {
    AssertThrow(!f_bar || fe.degree == 1,
                ExcMessage("Finite element/Volumetric strain = B-bar: the finite-strain bodies "
                           "(Materials/Models) then use F-bar, which is implemented for Q1 "
                           "only; use Finite element/Degree = 1 or Volumetric strain = "
                           "standard."));
    // Each shape function of the vector element moves one component: its
    // gradient is the row component[i] with the scalar gradient g_i.
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      component[i] = fe.system_to_component_index(i).first;
    for (const auto &[id, constants] : materials.bodies)
      if (auto law = HyperelasticLaw<dim>::create(constants.model, constants))
        laws[id] = std::move(law);
  }

  template <int dim>
  const HyperelasticLaw<dim> *
  FiniteStrainBulk<dim>::law(const types::material_id id) const
  {
    const auto it = laws.find(id);
    return it == laws.end() ? nullptr : it->second.get();
  }

  template <int dim>
  Tensor<2, dim>
  FiniteStrainBulk<dim>::gradient_at(const unsigned int    q,
                                     const Vector<double> &u,
                                     CellLinearisation    &result)
  {
    for (unsigned int i = 0; i < u.size(); ++i)
      g[i] = fe_values.shape_grad_component(i, q, component[i]);
    const Tensor<2, dim> H = displacement_gradient(u, component, g);
    result.smallest_jacobian =
      std::min(result.smallest_jacobian, 1. + HyperelasticLaw<dim>::jacobian_minus_one(H));
    return H;
  }

  template <int dim>
  typename FiniteStrainBulk<dim>::CellLinearisation
  FiniteStrainBulk<dim>::linearise(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                   const Vector<double>                                 &u,
                                   FullMatrix<double>                                   &K,
                                   Vector<double> &internal_force)
  {
    const HyperelasticLaw<dim> &material = *law(cell->material_id());
    fe_values.reinit(cell);
    const unsigned int n = u.size();
    K.reinit(n, n);
    internal_force.reinit(n);
    if (f_bar)
      return linearise_f_bar(material, u, K, internal_force);
    CellLinearisation result;
    result.smallest_jacobian = std::numeric_limits<double>::max();
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      {
        const Tensor<2, dim> H = gradient_at(q, u, result);
        if (!(result.smallest_jacobian > 0.))
          return result;
        const double         dV = fe_values.JxW(q);
        const Tensor<2, dim> P  = material.first_piola(H);
        const Tensor<4, dim> A  = material.first_piola_tangent(H);
        result.energy += material.energy(H) * dV;
        for (unsigned int i = 0; i < n; ++i)
          {
            internal_force(i) += (P[component[i]] * g[i]) * dV;
            // A_{c_i J k L} g_i[J]: the row of i, contracted with g_j below.
            Tensor<1, dim> Ag[dim];
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int J = 0; J < dim; ++J)
                for (unsigned int L = 0; L < dim; ++L)
                  Ag[k][L] += g[i][J] * A[component[i]][J][k][L];
            for (unsigned int j = 0; j <= i; ++j)
              K(i, j) += (Ag[component[j]] * g[j]) * dV;
          }
      }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i + 1; j < n; ++j)
        K(i, j) = K(j, i);
    return result;
  }

  template <int dim>
  typename FiniteStrainBulk<dim>::CellLinearisation
  FiniteStrainBulk<dim>::linearise_f_bar(const HyperelasticLaw<dim> &material,
                                         const Vector<double>       &u,
                                         FullMatrix<double>         &K,
                                         Vector<double>             &internal_force)
  {
    // With alpha = (J0 / J)^(1/dim), F-bar = alpha F; J0 = (1/V) int J dV,
    // the cell's mean volume ratio (mean dilatation: a homogeneous
    // deformation keeps J0 = J and its derivative the mean of J's, so the
    // F-bar force is the standard one there and the element passes the
    // patch test on any hexahedron; J0 at the cell centre did not where the
    // cell's Jacobian varies: its derivative, grad N_i at the centre, is not
    // the mean of grad N_i). With a_i = F^-T : E_i (E_i = e_(c_i) (x) g_i,
    // the gradient of shape function i) = d ln J / du_i and
    // abar_i = d ln J0 / du_i = (1/(V J0)) int J a_i dV:
    //   d alpha / du_i    = alpha / dim (abar_i - a_i),
    //   d F-bar / du_i    = alpha E_i + F d alpha / du_i,
    //   d2 alpha/du_i du_j = alpha / dim^2 (abar_i - a_i)(abar_j - a_j)
    //                      + alpha / dim (L_ij + tr(B_j B_i)),
    // B_i = F^-1 E_i, tr(B_j B_i) = h_i[c_j] h_j[c_i] with h_i = F^-T g_i,
    // L_ij = d2 ln J0 / du_i du_j
    //      = (1/(V J0)) int J (a_i a_j - tr(B_j B_i)) dV - abar_i abar_j.
    const unsigned int n = u.size();
    CellLinearisation  result;
    result.smallest_jacobian = std::numeric_limits<double>::max();
    std::vector<Tensor<1, dim>> h(n);
    std::vector<double>         abar(n, 0.);
    FullMatrix<double>          L(n, n);
    // First pass: J0 - 1 (as a mean of J - 1: no cancellation), abar, L.
    double volume = 0., J0m1 = 0.;
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      {
        const Tensor<2, dim> H   = gradient_at(q, u, result);
        const double         Jm1 = HyperelasticLaw<dim>::jacobian_minus_one(H);
        if (!(1. + Jm1 > 0.))
          return result;
        const Tensor<2, dim> F_inverse_transpose = transpose(invert(identity_plus(H)));
        const double         dV = fe_values.JxW(q), JdV = (1. + Jm1) * dV;
        volume += dV;
        J0m1 += Jm1 * dV;
        for (unsigned int i = 0; i < n; ++i)
          h[i] = F_inverse_transpose * g[i];
        for (unsigned int i = 0; i < n; ++i)
          {
            abar[i] += h[i][component[i]] * JdV;
            for (unsigned int j = 0; j <= i; ++j)
              L(i, j) += (h[i][component[i]] * h[j][component[j]] -
                          h[i][component[j]] * h[j][component[i]]) *
                         JdV;
          }
      }
    J0m1 /= volume;
    const double J0V = (1. + J0m1) * volume;
    for (unsigned int i = 0; i < n; ++i)
      abar[i] /= J0V;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j <= i; ++j)
        L(i, j) = L(i, j) / J0V - abar[i] * abar[j];
    std::vector<double>         dalpha(n);
    std::vector<Tensor<2, dim>> dF_bar(n), AdF(n);
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      {
        const Tensor<2, dim> H   = gradient_at(q, u, result);
        const double         Jm1 = HyperelasticLaw<dim>::jacobian_minus_one(H);
        // alpha - 1 and F-bar - I = alpha H + (alpha - 1) I without
        // cancellation (the laws take the displacement gradient).
        const double   alpha_minus_one = std::expm1((std::log1p(J0m1) - std::log1p(Jm1)) / dim);
        const double   alpha           = 1. + alpha_minus_one;
        Tensor<2, dim> H_bar           = alpha * H;
        for (unsigned int d = 0; d < dim; ++d)
          H_bar[d][d] += alpha_minus_one;
        const Tensor<2, dim> F = identity_plus(H), F_inverse_transpose = transpose(invert(F));
        const Tensor<2, dim> P  = material.first_piola(H_bar);
        const Tensor<4, dim> A  = material.first_piola_tangent(H_bar);
        const double         dV = fe_values.JxW(q), P_F = scalar_product(P, F);
        result.energy += material.energy(H_bar) * dV;
        for (unsigned int i = 0; i < n; ++i)
          {
            h[i]      = F_inverse_transpose * g[i];
            dalpha[i] = alpha / dim * (abar[i] - h[i][component[i]]);
            dF_bar[i] = dalpha[i] * F;
            dF_bar[i][component[i]] += alpha * g[i];
            AdF[i] = double_contract<2, 0, 3, 1>(A, dF_bar[i]);
            internal_force(i) += scalar_product(P, dF_bar[i]) * dV;
          }
        for (unsigned int i = 0; i < n; ++i)
          {
            const double PE_i = P[component[i]] * g[i];
            for (unsigned int j = 0; j <= i; ++j)
              {
                const double PE_j    = P[component[j]] * g[j];
                const double d2alpha = alpha / (dim * dim) * (abar[i] - h[i][component[i]]) *
                                         (abar[j] - h[j][component[j]]) +
                                       alpha / dim *
                                         (L(i, j) + h[i][component[j]] * h[j][component[i]]);
                K(i, j) += (scalar_product(dF_bar[i], AdF[j]) + dalpha[j] * PE_i +
                            dalpha[i] * PE_j + P_F * d2alpha) *
                           dV;
              }
          }
      }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i + 1; j < n; ++j)
        K(i, j) = K(j, i);
    return result;
  }

  template class FiniteStrainBulk<2>;
  template class FiniteStrainBulk<3>;
} // namespace contact_fem
