// The total-Lagrangian cell residual and tangent of hyperelastic bodies.
#ifndef contact_fem_finite_strain_bulk_h
#define contact_fem_finite_strain_bulk_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <contact_fem/material/hyperelastic_law.h>
#include <contact_fem/material/material.h>

#include <map>
#include <memory>

namespace contact_fem
{
  using namespace dealii;

  /**
   * The bulk of the finite-strain bodies (Materials/Models other than
   * linear), total-Lagrangian on the reference configuration: per cell and
   * displacement u the internal force f_i = int grad N_i : P(F) dV, its
   * tangent K_ij = int grad N_i : dP/dF : grad N_j dV (consistent, so
   * Newton converges quadratically) and the strain energy int W(F) dV, with
   * F = I + grad u. The driver reassembles these at every Newton iterate;
   * linear bodies keep their precomputed matrices.
   *
   * With @p f_bar (Q1 only) the law is evaluated at F-bar = (J0 / J)^(1/dim)
   * F (de Souza Neto et al. 1996), J0 = (1/V) int det F dV the cell's mean
   * volume ratio (mean dilatation; the patch test holds on any cell): the
   * volume change is one value per cell, so nearly incompressible bodies do
   * not lock (the finite-strain counterpart of the mean-dilatation B-bar;
   * in 2D the plane-strain form, exponent 1/2). Here it is variational: f
   * and K are the first and second derivatives of int W(F-bar) dV, so K
   * stays symmetric; a homogeneous deformation has F-bar = F.
   *
   * Implemented in source/material/finite_strain_bulk.cc.
   */
  template <int dim>
  class FiniteStrainBulk
  {
  public:
    /// Throws if @p f_bar and the element is not Q1.
    FiniteStrainBulk(const Materials<dim>     &materials,
                     const Mapping<dim>       &mapping,
                     const FiniteElement<dim> &fe,
                     const bool                f_bar = false);

    /// The law of material id @p id; null for a linear body.
    const HyperelasticLaw<dim> *
    law(const types::material_id id) const;

    /// What linearise() gives of one cell.
    struct CellLinearisation
    {
      double energy = 0.;
      /// Smallest det F at the quadrature points: <= 0 means an inverted
      /// element (the law is then not evaluated further).
      double smallest_jacobian = 0.;
    };

    /// The tangent @p K and internal force @p internal_force of @p cell
    /// (of a finite-strain body) at its DoF values @p u.
    CellLinearisation
    linearise(const typename DoFHandler<dim>::active_cell_iterator &cell,
              const Vector<double>                                 &u,
              FullMatrix<double>                                   &K,
              Vector<double>                                       &internal_force);

  private:
    /// The displacement gradient H = F - I at quadrature point @p q
    /// (fe_values on the cell) of the DoF values @p u; fills g and takes
    /// det F into @p result's smallest Jacobian.
    Tensor<2, dim>
    gradient_at(const unsigned int q, const Vector<double> &u, CellLinearisation &result);
    /// The F-bar tangent and force (see the class).
    CellLinearisation
    linearise_f_bar(const HyperelasticLaw<dim> &material,
                    const Vector<double>       &u,
                    FullMatrix<double>         &K,
                    Vector<double>             &internal_force);

    std::map<types::material_id, std::unique_ptr<HyperelasticLaw<dim>>> laws;
    FEValues<dim>                                                       fe_values;
    /// Per shape function: its component and scalar gradient at the
    /// present quadrature point.
    std::vector<unsigned int>   component;
    std::vector<Tensor<1, dim>> g;
    /// Whether the law is evaluated at F-bar (Q1 only).
    bool f_bar;
  };
} // namespace contact_fem

#endif
