// The linear elastic law of the bodies against hand computation, body 1:
// E = 210, nu = 0.3, so lambda = E nu / ((1 + nu)(1 - 2 nu)) = 121.153846
// and mu = E / (2 (1 + nu)) = 80.7692308; body 2: E = 70, nu = 0.
// 2D (plane strain), strain (1e-3, -5e-4; 2e-4): tr = 5e-4,
//   sigma_xx = lambda tr + 2 mu 1e-3   = 0.222115385,
//   sigma_yy = lambda tr - 2 mu 5e-4   = -0.0201923077,
//   sigma_xy = 2 mu 2e-4               = 0.0323076923;
// the compliance takes it back to the strain; von Mises with
// sigma_zz = nu (sigma_xx + sigma_yy) = 0.0605769231:
//   sqrt(((sxx - syy)^2 + (syy - szz)^2 + (szz - sxx)^2) / 2 + 3 sxy^2)
//   = 0.2209005.
// The stress with a given volumetric strain (B-bar) 1e-3 instead of tr:
// sigma_xx = 0.121153846 + 0.161538462 = 0.282692308.
// 3D, uniaxial stress 1 along x in body 2 (nu = 0): strain 1 / 70 along x,
// von Mises 1. The Young's modulus range (70, 210); nu = 0.5 (incompressible)
// is refused naming the key.

#include <deal.II/base/mpi.h>

#include <contact_fem/material/material.h>

#include "unit_test_materials.h"

#include <iomanip>
#include <iostream>

using namespace dealii;
using namespace contact_fem;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(9);

  const Materials<2> materials = make_materials<2>("1, 2", "210, 70", "0.3, 0");
  std::cout << "body 1: lambda " << materials.constants(1).lambda() << ", mu "
            << materials.constants(1).mu() << std::endl;
  SymmetricTensor<2, 2> strain;
  strain[0][0]                      = 1e-3;
  strain[1][1]                      = -5e-4;
  strain[0][1]                      = 2e-4;
  const SymmetricTensor<2, 2> sigma = materials.stress(1, strain);
  std::cout << "stress: " << sigma[0][0] << " " << sigma[1][1] << " " << sigma[0][1] << std::endl;
  const SymmetricTensor<2, 2> back = materials.compliance(1, sigma);
  std::cout << "compliance of the stress is the strain: "
            << ((back - strain).norm() < 1e-14 * strain.norm() ? "yes" : "no") << std::endl
            << std::setprecision(6) << "von Mises: " << materials.von_mises(1, sigma) << std::endl
            << std::setprecision(9)
            << "stress xx with volumetric strain 1e-3: " << materials.stress(1, strain, 1e-3)[0][0]
            << std::endl;
  const auto [E_min, E_max] = materials.youngs_modulus_range();
  std::cout << "Young's modulus range: " << E_min << " " << E_max << std::endl;

  const Materials<3>    materials_3d = make_materials<3>("1, 2", "210, 70", "0.3, 0");
  SymmetricTensor<2, 3> uniaxial;
  uniaxial[0][0]                        = 1.;
  const SymmetricTensor<2, 3> strain_3d = materials_3d.compliance(2, uniaxial);
  std::cout << "3D body 2, uniaxial stress 1: strain xx " << strain_3d[0][0]
            << " (1/70 = " << 1. / 70. << "), yy " << strain_3d[1][1] << ", von Mises "
            << materials_3d.von_mises(2, uniaxial) << std::endl;

  try
    {
      make_materials<2>("1", "210", "0.5");
      std::cout << "nu = 0.5 accepted (wrong)" << std::endl;
    }
  catch (const std::exception &e)
    {
      const std::string what = e.what();
      const auto        at   = what.find("Materials/");
      std::cout << "nu = 0.5: "
                << (at == std::string::npos ? std::string("error without the key") :
                                              what.substr(at, what.find('\n', at) - at))
                << std::endl;
    }
}
