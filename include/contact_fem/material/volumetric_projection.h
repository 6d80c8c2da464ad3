// B-bar (selective) treatment of the volumetric strain against locking of
// nearly incompressible bodies.
#ifndef contact_fem_volumetric_projection_h
#define contact_fem_volumetric_projection_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

namespace contact_fem
{
  using namespace dealii;

  /**
   * The volumetric strain div u projected, cell by cell in L2, onto the
   * polynomials of degree p - 1 in the reference coordinates (constants for
   * Q1, linears for Q2). With it the strain energy density becomes
   *   mu eps:eps + lambda/2 theta^2,  theta = projected div u,
   * so the lambda term only constrains p - 1 degree modes per cell and does
   * not lock as nu -> 1/2 (Q2 with linear theta is the inf-sup stable
   * Q2-P1 pair in displacement form; Q1 with constant theta is the classical
   * mean-dilatation element). The stress is sigma = 2 mu eps + lambda theta I.
   *
   * Implemented in source/volumetric_projection.cc.
   */
  template <int dim>
  class VolumetricProjection
  {
  public:
    VolumetricProjection(const Mapping<dim> &mapping, const FiniteElement<dim> &fe);

    /// Computes the projection of the shape functions' divergence on @p cell.
    void
    reinit(const typename DoFHandler<dim>::active_cell_iterator &cell);

    /// Projected divergence of shape function @p i at @p reference_point.
    double
    shape_value(const unsigned int i, const Point<dim> &reference_point) const;

    /// Projected volumetric strain of the cell's DoF values @p local_values.
    double
    value(const Vector<double> &local_values, const Point<dim> &reference_point) const;

  private:
    /// Basis function k of P_{p-1} at a reference point: 1, x, y, (z).
    double
    basis(const unsigned int k, const Point<dim> &reference_point) const;

    unsigned int       n_basis;
    FEValues<dim>      fe_values;
    FullMatrix<double> projection; ///< n_basis x dofs per cell: M^{-1} G
  };
} // namespace contact_fem

#endif
