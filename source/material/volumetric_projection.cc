#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values_extractors.h>

#include <contact_fem/material/volumetric_projection.h>

namespace contact_fem
{
  template <int dim>
  VolumetricProjection<dim>::VolumetricProjection(const Mapping<dim>       &mapping,
                                                  const FiniteElement<dim> &fe)
    : n_basis(fe.degree == 1 ? 1 : dim + 1)
    , fe_values(mapping, fe, QGauss<dim>(fe.degree + 1), update_gradients | update_JxW_values)
    , projection(n_basis, fe.n_dofs_per_cell())
  {
    AssertThrow(fe.degree <= 2, ExcMessage("Finite element/Volumetric strain: B-bar is implemented "
                                           "for degrees 1 and 2."));
  }

  template <int dim>
  double
  VolumetricProjection<dim>::basis(const unsigned int k, const Point<dim> &reference_point) const
  {
    // Centred on the reference cell, so the mass matrix is well conditioned.
    return k == 0 ? 1. : reference_point[k - 1] - 0.5;
  }

  template <int dim>
  void
  VolumetricProjection<dim>::reinit(const typename DoFHandler<dim>::active_cell_iterator &cell)
  {
    fe_values.reinit(cell);
    const FEValuesExtractors::Vector displacement(0);
    const auto                      &quadrature = fe_values.get_quadrature();
    const unsigned int               n_dofs     = fe_values.dofs_per_cell;

    // M theta = G u: mass matrix of the basis and its products with div phi.
    FullMatrix<double> mass(n_basis, n_basis), divergence(n_basis, n_dofs);
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      for (unsigned int k = 0; k < n_basis; ++k)
        {
          const double b_k = basis(k, quadrature.point(q)) * fe_values.JxW(q);
          for (unsigned int l = 0; l < n_basis; ++l)
            mass(k, l) += b_k * basis(l, quadrature.point(q));
          for (unsigned int i = 0; i < n_dofs; ++i)
            divergence(k, i) += b_k * fe_values[displacement].divergence(i, q);
        }
    mass.gauss_jordan();
    mass.mmult(projection, divergence);
  }

  template <int dim>
  double
  VolumetricProjection<dim>::shape_value(const unsigned int i,
                                         const Point<dim>  &reference_point) const
  {
    double theta = 0.;
    for (unsigned int k = 0; k < n_basis; ++k)
      theta += projection(k, i) * basis(k, reference_point);
    return theta;
  }

  template <int dim>
  double
  VolumetricProjection<dim>::value(const Vector<double> &local_values,
                                   const Point<dim>     &reference_point) const
  {
    double theta = 0.;
    for (unsigned int i = 0; i < local_values.size(); ++i)
      theta += local_values[i] * shape_value(i, reference_point);
    return theta;
  }

  template class VolumetricProjection<2>;
  template class VolumetricProjection<3>;
} // namespace contact_fem
