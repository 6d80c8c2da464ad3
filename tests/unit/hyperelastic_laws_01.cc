// The finite-strain laws (Materials/Models) against their own strain
// energy, E = 100, nu = 0.3 (lambda = 57.69, mu = 38.46), at a deformation
// gradient F = I + H with |H| ~ 0.3, in 2D (plane strain) and 3D:
// - P = dW/dF: the central difference of W with steps h = 1e-2, 5e-3,
//   2.5e-3 differs from P by c h^2, so the error falls by 4 per halving
//   (the ratios printed);
// - dP/dF the same way against the central difference of P;
// - frame indifference: F -> QF with a rotation Q leaves W and S unchanged
//   and rotates P -> QP and sigma -> Q sigma Q^T;
// - the small-strain limit: at F = I + t G, t = 1e-6, the Cauchy stress is
//   the linear law's C : sym(t G) up to O(t^2) (relative difference ~t);
// - at strain 1e-12 (H = t G given, not F) the stress and the energy are
//   the linear law's to 1e-8: the laws take H = F - I, since I + H would
//   keep H only to 1e-16 absolute;
// - the 3D Cauchy stress of a plane-strain body (Materials::
//   finite_strain_stress(), for the VTU output): sigma_zz = lambda ln J / J
//   at F = diag(1.25, 1) (neo-Hookean), sigma_xx as the 2D law's;
// - Materials/Models: the names and the default.

#include <deal.II/base/mpi.h>

#include <contact_fem/material/hyperelastic_law.h>
#include <contact_fem/material/material.h>

#include "unit_test_materials.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>

using namespace dealii;
using namespace contact_fem;

namespace
{
  /// A fixed, non-symmetric gradient of size ~0.3 (no random numbers: the
  /// output must repeat).
  template <int dim>
  Tensor<2, dim>
  deformation_gradient()
  {
    Tensor<2, dim> F;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        F[i][j] = (i == j ? 1. : 0.) + 0.3 * std::sin(1. + 3. * i + 7. * j);
    return F;
  }

  /// The displacement gradient H = F - I that the laws take.
  template <int dim>
  Tensor<2, dim>
  gradient(const Tensor<2, dim> &F)
  {
    Tensor<2, dim> H = F;
    for (unsigned int d = 0; d < dim; ++d)
      H[d][d] -= 1.;
    return H;
  }

  template <int dim>
  Tensor<2, dim>
  rotation()
  {
    Tensor<2, dim> Q;
    const double   c = std::cos(0.7), s = std::sin(0.7);
    Q[0][0] = c, Q[0][1] = -s, Q[1][0] = s, Q[1][1] = c;
    if (dim == 3)
      {
        Q[dim - 1][dim - 1] = 1.;
        // Followed by a rotation about x.
        Tensor<2, dim> R;
        const double   c2 = std::cos(-1.1), s2 = std::sin(-1.1);
        R[0][0] = 1., R[1][1] = c2, R[1][2] = -s2, R[2][1] = s2, R[2][2] = c2;
        Q = R * Q;
      }
    return Q;
  }

  /// Largest entry of |P - dW/dF by central differences with step h|.
  template <int dim>
  double
  stress_error(const HyperelasticLaw<dim> &law, const Tensor<2, dim> &F, const double h)
  {
    const Tensor<2, dim> P     = law.first_piola(gradient(F));
    double               error = 0.;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        {
          Tensor<2, dim> Fp = F, Fm = F;
          Fp[i][j] += h, Fm[i][j] -= h;
          const double dW = (law.energy(gradient(Fp)) - law.energy(gradient(Fm))) / (2. * h);
          error           = std::max(error, std::abs(dW - P[i][j]));
        }
    return error;
  }

  /// Largest entry of |dP/dF - its central difference with step h|.
  template <int dim>
  double
  tangent_error(const HyperelasticLaw<dim> &law, const Tensor<2, dim> &F, const double h)
  {
    const Tensor<4, dim> A     = law.first_piola_tangent(gradient(F));
    double               error = 0.;
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int l = 0; l < dim; ++l)
        {
          Tensor<2, dim> Fp = F, Fm = F;
          Fp[k][l] += h, Fm[k][l] -= h;
          const Tensor<2, dim> dP =
            (law.first_piola(gradient(Fp)) - law.first_piola(gradient(Fm))) / (2. * h);
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              error = std::max(error, std::abs(dP[i][j] - A[i][j][k][l]));
        }
    return error;
  }

  template <int dim>
  void
  print_ratios(const std::string &what,
               double (*error)(const HyperelasticLaw<dim> &, const Tensor<2, dim> &, const double),
               const HyperelasticLaw<dim> &law)
  {
    const Tensor<2, dim> F = deformation_gradient<dim>();
    std::cout << "  " << what << ": error ratios under step halving";
    double previous = error(law, F, 1e-2);
    bool   small    = previous < 1e-2 * law.first_piola(gradient(F)).norm();
    for (const double h : {5e-3, 2.5e-3})
      {
        const double e = error(law, F, h);
        std::cout << " " << std::fixed << std::setprecision(1) << previous / e;
        previous = e;
      }
    std::cout << std::defaultfloat << "; error below 1e-2 |P|: " << (small ? "yes" : "no")
              << std::endl;
  }

  template <int dim>
  void
  check_law(const ElasticModel model)
  {
    const ElasticConstants c{100., 0.3, model};
    const auto             law = HyperelasticLaw<dim>::create(model, c);
    std::cout << dim << "D " << to_string(model) << ":" << std::endl;
    print_ratios<dim>("P against dW/dF", &stress_error<dim>, *law);
    print_ratios<dim>("dP/dF against the difference of P", &tangent_error<dim>, *law);

    const Tensor<2, dim> F = deformation_gradient<dim>(), Q = rotation<dim>();
    const Tensor<2, dim> QF    = Q * F;
    const double         scale = law->first_piola(gradient(F)).norm();
    const double         dW    = std::abs(law->energy(gradient(QF)) - law->energy(gradient(F))) /
                      std::abs(law->energy(gradient(F)));
    const double dS =
      (law->second_piola(gradient(QF)) - law->second_piola(gradient(F))).norm() / scale;
    const double dP =
      (law->first_piola(gradient(QF)) - Q * law->first_piola(gradient(F))).norm() / scale;
    const SymmetricTensor<2, dim> sigma = law->cauchy_stress(gradient(F));
    const double                  dsigma =
      (Tensor<2, dim>(law->cauchy_stress(gradient(QF))) - Q * Tensor<2, dim>(sigma) * transpose(Q))
        .norm() /
      sigma.norm();
    std::cout << "  rotated F: W, S, P and sigma frame-indifferent to 1e-13: "
              << (std::max({dW, dS, dP, dsigma}) < 1e-13 ? "yes" : "no") << std::endl;

    // Small-strain limit against the linear law.
    const double   t = 1e-6;
    Tensor<2, dim> G = deformation_gradient<dim>(), F_small;
    for (unsigned int d = 0; d < dim; ++d)
      G[d][d] -= 1.;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        F_small[i][j] = (i == j ? 1. : 0.) + t * G[i][j];
    const SymmetricTensor<2, dim> eps = t * symmetrize(G);
    const SymmetricTensor<2, dim> linear =
      c.lambda() * trace(eps) * unit_symmetric_tensor<dim>() + 2. * c.mu() * eps;
    const double difference =
      (law->cauchy_stress(gradient(F_small)) - linear).norm() / linear.norm();
    std::cout << "  strain 1e-6: Cauchy stress = linear law's to " << std::scientific
              << std::setprecision(0) << difference << std::defaultfloat
              << " relative (O(strain)): " << (difference < 10. * t ? "yes" : "no") << std::endl;

    // Strain 1e-12 (a tiny load on finite-strain bodies): from H = t G the
    // stress and the energy keep their digits. Formed as I + H, F held H
    // only to 1e-16 absolute: 1e-4 relative in the stress, and the energy,
    // O(t^2) after the cancellation of O(t) terms, had no correct digit.
    const double                  tiny     = 1e-12;
    const Tensor<2, dim>          H_tiny   = tiny * G;
    const SymmetricTensor<2, dim> eps_tiny = tiny * symmetrize(G);
    const SymmetricTensor<2, dim> sigma_tiny =
      c.lambda() * trace(eps_tiny) * unit_symmetric_tensor<dim>() + 2. * c.mu() * eps_tiny;
    const double W_linear    = 0.5 * (sigma_tiny * eps_tiny);
    const double stress_tiny = (law->cauchy_stress(H_tiny) - sigma_tiny).norm() / sigma_tiny.norm();
    const double energy_tiny = std::abs(law->energy(H_tiny) - W_linear) / W_linear;
    std::cout << "  strain 1e-12: Cauchy stress and energy = linear law's to 1e-8 relative: "
              << (std::max(stress_tiny, energy_tiny) < 1e-8 ? "yes" : "no") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const ElasticModel model : {ElasticModel::neo_hookean, ElasticModel::saint_venant_kirchhoff})
    {
      check_law<2>(model);
      check_law<3>(model);
    }
  // The 3D stress of a plane-strain body (VTU output): F = diag(1.25, 1),
  // F_zz = 1, so sigma_zz = lambda ln J / J for neo-Hookean.
  {
    const Materials<2> materials = make_materials<2>("1", "100", "0.3", "neo-hookean");
    Tensor<2, 2>       grad_u;
    grad_u[0][0]                       = 0.25;
    const SymmetricTensor<2, 3> sigma  = materials.finite_strain_stress(1, grad_u);
    const double                lambda = materials.constants(1).lambda(), J = 1.25;
    std::cout << std::setprecision(9) << "plane strain, F = diag(1.25, 1): sigma_zz " << sigma[2][2]
              << " (lambda ln J / J = " << lambda * std::log(J) / J << "), sigma_xx " << sigma[0][0]
              << " (2D law: "
              << NeoHookean<2>(lambda, materials.constants(1).mu())
                   .cauchy_stress(gradient(unit_symmetric_tensor<2>() + Tensor<2, 2>(grad_u)))[0][0]
              << ")" << std::endl;
  }
  std::cout << "linear has no hyperelastic law: "
            << (HyperelasticLaw<2>::create(ElasticModel::linear, ElasticConstants()) ? "no" : "yes")
            << std::endl;
  for (const std::string name : {"linear", "neo-hookean", "saint-venant-kirchhoff"})
    std::cout << "model '" << name << "' reads back as '" << to_string(parse_elastic_model(name, 0))
              << "'" << std::endl;
  try
    {
      parse_elastic_model("neo-hooke", 1);
    }
  catch (const std::exception &e)
    {
      const std::string what = e.what();
      const auto        at   = what.find("Materials/");
      std::cout << "unknown model: "
                << (at == std::string::npos ? std::string("error without the key") :
                                              what.substr(at, what.find('\n', at) - at))
                << std::endl;
    }
}
