// The frictional laws: threshold T(p) and dT/dp of Coulomb (mu p) and Tresca
// (a constant bound) at hand-computed points, the kind, parameter and
// description a law keeps from its .prm text, and the errors of bad text;
// FrictionParameters: one law for all pairs, one per pair by slave id, and
// Pure slip.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <contact_fem/contact/contact_parameters.h>
#include <contact_fem/contact/friction/frictional_law.h>

#include <iostream>

using namespace dealii;
using namespace contact_fem;

namespace
{
  void
  print_law(const std::string &text)
  {
    const auto law = FrictionalLaw::create(text, "Test/Friction");
    std::cout << "'" << text << "': " << law->description() << ", kind "
              << (law->kind() == FrictionalLaw::Kind::coulomb ? "coulomb" : "tresca")
              << ", parameter " << law->parameter() << ", frictionless " << law->frictionless()
              << std::endl;
    for (const double p : {0., 0.5, 2.})
      std::cout << "  p = " << p << ": T = " << law->threshold(p)
                << ", dT/dp = " << law->threshold_derivative(p) << std::endl;
  }

  void
  print_error(const std::string &text)
  {
    try
      {
        FrictionalLaw::create(text, "Test/Friction");
        std::cout << "'" << text << "': accepted (wrong)" << std::endl;
      }
    catch (const std::exception &e)
      {
        const std::string what = e.what();
        const auto        at   = what.find("Test/Friction");
        std::cout << "'" << text << "': "
                  << (at == std::string::npos ? what : what.substr(at, what.find('\n', at) - at))
                  << std::endl;
      }
  }

  void
  print_parameters(const std::string &friction, const std::string &pure_slip)
  {
    ParameterHandler prm;
    ContactParameters::declare_parameters(prm);
    FrictionParameters::declare_parameters(prm);
    prm.enter_subsection("Contact");
    prm.set("Pairs", "3: 4; 5: 6");
    prm.set("Friction", friction);
    prm.set("Pure slip", pure_slip);
    prm.leave_subsection();
    FrictionParameters parameters;
    parameters.parse_parameters(prm);
    std::cout << "Friction = '" << friction << "', Pure slip = " << pure_slip << ": "
              << parameters.laws.size() << " laws (";
    for (const auto &law : parameters.laws)
      std::cout << " " << law->description();
    std::cout << " ), pure slip " << parameters.pure_slip << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // Coulomb mu = 0.3: T = 0, 0.15, 0.6 and dT/dp = 0.3 at p = 0, 0.5, 2.
  print_law("coulomb 0.3");
  // Tresca 0.02: T = 0.02 and dT/dp = 0 at every p.
  print_law("tresca 0.02");
  // No friction at all: both laws with a zero parameter.
  print_law("coulomb 0");
  print_law("tresca 0");

  print_error("coulomb");
  print_error("coulomb -0.1");
  print_error("tresca x");
  print_error("amontons 0.2");
  print_error("coulomb 0.2 0.3");

  print_parameters("", "false");
  print_parameters("coulomb 0.2", "true");
  print_parameters("5: tresca 0.01; 3: coulomb 0.4", "false");
}
