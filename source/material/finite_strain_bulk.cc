#include <deal.II/base/quadrature_lib.h>

#include <contact_fem/material/finite_strain_bulk.h>

#include <algorithm>
#include <limits>

namespace contact_fem
{
  template <int dim>
  FiniteStrainBulk<dim>::FiniteStrainBulk(const Materials<dim>     &materials,
                                          const Mapping<dim>       &mapping,
                                          const FiniteElement<dim> &fe)
    : fe_values(mapping,
                fe,
                QGauss<dim>(fe.degree + 1),
                update_gradients | update_JxW_values)
  {
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
  typename FiniteStrainBulk<dim>::CellLinearisation
  FiniteStrainBulk<dim>::linearise(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                   const Vector<double>                                 &u,
                                   FullMatrix<double>                                   &K,
                                   Vector<double> &internal_force)
  {
    const HyperelasticLaw<dim> &material = *law(cell->material_id());
    fe_values.reinit(cell);
    const FiniteElement<dim> &fe = fe_values.get_fe();
    const unsigned int        n  = fe.n_dofs_per_cell();
    K.reinit(n, n);
    internal_force.reinit(n);
    // Each shape function of the vector element moves one component: its
    // gradient is the row component(i) with the scalar gradient g_i.
    std::vector<unsigned int> component(n);
    for (unsigned int i = 0; i < n; ++i)
      component[i] = fe.system_to_component_index(i).first;
    std::vector<Tensor<1, dim>> g(n);
    CellLinearisation           result;
    result.smallest_jacobian = std::numeric_limits<double>::max();
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      {
        Tensor<2, dim> F;
        for (unsigned int d = 0; d < dim; ++d)
          F[d][d] = 1.;
        for (unsigned int i = 0; i < n; ++i)
          {
            g[i] = fe_values.shape_grad_component(i, q, component[i]);
            F[component[i]] += u(i) * g[i];
          }
        const double J           = determinant(F);
        result.smallest_jacobian = std::min(result.smallest_jacobian, J);
        if (!(J > 0.))
          return result;
        const double         dV = fe_values.JxW(q);
        const Tensor<2, dim> P  = material.first_piola(F);
        const Tensor<4, dim> A  = material.first_piola_tangent(F);
        result.energy += material.energy(F) * dV;
        for (unsigned int i = 0; i < n; ++i)
          {
            internal_force(i) += (P[component[i]] * g[i]) * dV;
            // A_{c_i J c_j L} g_i[J]: the row of i, contracted with g_j below.
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

  template class FiniteStrainBulk<2>;
  template class FiniteStrainBulk<3>;
} // namespace contact_fem
