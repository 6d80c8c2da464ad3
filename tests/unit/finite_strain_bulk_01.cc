// The finite-strain cell (FiniteStrainBulk) on one distorted cell, Q1 and Q2
// in 2D and 3D, neo-Hookean body 1 (E = 100, nu = 0.3) at a smooth,
// non-homogeneous displacement of size 0.1 (strains up to ~30 %):
// - the internal force f_i against the central difference of the cell's
//   strain energy in u_i, and the tangent K against the central difference
//   of f, each with steps h = 1e-3, 5e-4, 2.5e-4: the errors fall by 4 per
//   halving (second order, the ratios printed), so f = dW/du and K = df/du;
//   (K is stored symmetric: the check of all its entries is that of its
//   symmetry);
// - the same for F-bar (Q1), whose force and tangent are the derivatives
//   of int W(F-bar) dV;
// - Newton on the cell with the DoFs of its face x = 0 held and the others
//   loaded by the internal force of half the displacement above (its face
//   x = 0 held): the residuals
//   fall quadratically (r_k+1 / r_k^2 stays bounded, printed).

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <contact_fem/material/finite_strain_bulk.h>

#include "unit_test_materials.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>

using namespace dealii;
using namespace contact_fem;

namespace
{
  template <int dim>
  void
  check_cell(const unsigned int degree, const bool f_bar = false)
  {
    Triangulation<dim> tria;
    GridGenerator::hyper_cube(tria);
    // A distorted cell: the last vertex moved off the cube.
    tria.begin_active()->vertex(GeometryInfo<dim>::vertices_per_cell - 1) *= 1.2;
    const FESystem<dim> fe(FE_Q<dim>(degree), dim);
    DoFHandler<dim>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const MappingQ<dim>   mapping(1);
    const Materials<dim>  materials = make_materials<dim>("0", "100", "0.3", "neo-hookean");
    FiniteStrainBulk<dim> bulk(materials, mapping, fe, f_bar);
    const auto            cell = dof_handler.begin_active();
    const unsigned int    n    = fe.n_dofs_per_cell();
    Vector<double>        u(n), f(n);
    FullMatrix<double>    K;
    // A smooth field at the support points (on the unit cell).
    for (unsigned int i = 0; i < n; ++i)
      {
        const Point<dim>  &p = fe.unit_support_point(i);
        const unsigned int c = fe.system_to_component_index(i).first;
        u(i)                 = 0.1 * std::sin(1. + 2. * p[0] - 3. * p[1] + c * (1. + p[dim - 1]));
      }

    std::cout << dim << "D Q" << degree << (f_bar ? " F-bar" : "") << ":" << std::endl;
    bulk.linearise(cell, u, K, f);

    // Largest errors of f and K against the central differences with step h.
    const auto errors = [&](const double h) {
      double             error_f = 0., error_K = 0.;
      Vector<double>     fp(n), fm(n);
      FullMatrix<double> Kp;
      for (unsigned int j = 0; j < n; ++j)
        {
          Vector<double> up(u), um(u);
          up(j) += h, um(j) -= h;
          const double Wp = bulk.linearise(cell, up, Kp, fp).energy;
          const double Wm = bulk.linearise(cell, um, Kp, fm).energy;
          error_f         = std::max(error_f, std::abs((Wp - Wm) / (2. * h) - f(j)));
          for (unsigned int i = 0; i < n; ++i)
            error_K = std::max(error_K, std::abs((fp(i) - fm(i)) / (2. * h) - K(i, j)));
        }
      return std::make_pair(error_f, error_K);
    };
    const auto e1 = errors(1e-3), e2 = errors(5e-4), e3 = errors(2.5e-4);
    std::cout << std::fixed << std::setprecision(1) << "  f against dW/du: error ratios "
              << e1.first / e2.first << " " << e2.first / e3.first << std::endl
              << "  K against df/du: error ratios " << e1.second / e2.second << " "
              << e2.second / e3.second << std::defaultfloat << std::endl;

    // Newton from zero: the DoFs of the face x = 0 held, the others loaded
    // so that the solution is u / 2 with those DoFs zeroed.
    std::vector<types::global_dof_index> dofs(n), face_dofs(fe.n_dofs_per_face());
    cell->get_dof_indices(dofs);
    cell->face(0)->get_dof_indices(face_dofs);
    std::vector<bool> held(n, false);
    Vector<double>    target(u);
    target *= 0.5;
    for (unsigned int i = 0; i < n; ++i)
      if (std::find(face_dofs.begin(), face_dofs.end(), dofs[i]) != face_dofs.end())
        held[i] = true, target(i) = 0.;
    Vector<double> load(n), x(n), r(n);
    bulk.linearise(cell, target, K, load);
    std::cout << "  Newton |r_k| / |r_0| and r_k / r_(k-1)^2:";
    double first = 0., previous = 0.;
    for (unsigned int k = 0; k < 10; ++k)
      {
        bulk.linearise(cell, x, K, r);
        r -= load;
        for (unsigned int i = 0; i < n; ++i)
          if (held[i])
            {
              r(i) = 0.;
              for (unsigned int j = 0; j < n; ++j)
                K(i, j) = K(j, i) = (i == j ? 1. : 0.);
            }
        const double norm = r.l2_norm() / (k == 0 ? (first = r.l2_norm()) : first);
        if (norm < 1e-13)
          break;
        std::cout << std::endl << "    " << std::scientific << std::setprecision(1) << norm;
        if (k > 0)
          std::cout << "  " << norm / (previous * previous);
        std::cout << std::defaultfloat;
        previous = norm;
        K.gauss_jordan();
        Vector<double> dx(n);
        K.vmult(dx, r);
        x -= dx;
      }
    Vector<double> difference(x);
    difference -= target;
    std::cout << std::endl
              << "  solution = the displacement to 1e-12: "
              << (difference.linfty_norm() < 1e-12 ? "yes" : "no") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_cell<2>(1);
  check_cell<2>(2);
  check_cell<3>(1);
  check_cell<3>(2);
  check_cell<2>(1, true);
  check_cell<3>(1, true);
}
