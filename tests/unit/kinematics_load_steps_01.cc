// Contact/Kinematics: with 'small' the mortar operators are those of the
// reference configuration and the frictionless, linear-elastic answer is the
// solution of one linear complementarity problem, whatever the load path:
// 1, 3 and 7 load steps give the same p_max, contact force and
// displacement of the disc top to the Newton tolerance (relative 1e-8
// here). With 'updated' the operators follow the configuration of every
// step's start, and the same runs differ by 0.1-1 %: that dependence on the
// load steps is what 'small' removes (issue 16, finding 3).

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <contact_fem/simulator/contact_problem.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

namespace
{
  using namespace dealii;

  const char *scene = R"(
set Dimension = 2
subsection Geometry
  set Type = hertz cylinder
  subsection Hertz cylinder
    set Contact refinements = 4
  end
end
subsection Materials
  set Material ids     = 1, 2
  set Young's moduli   = 200, 2e5
  set Poisson's ratios = 0.3, 0.3
end
subsection Boundary conditions
  set Fixed        = 2: xy
  set Fixed points = 1 @ 0, 1: x; 1 @ 0, 9: x
  set Pressure     = 1: 0.4*t
end
subsection Contact
  set Pairs = 3: 4
end
subsection Newton
  set Displacement relative tolerance = 1e-12
  set Multiplier relative tolerance   = 1e-12
end
subsection Output
  set Write VTU              = false
  set Write pressure profile = false
  set Print timing           = false
  set Displacement probes    = 1 @ 0, 9
end
)";

  struct Answer
  {
    double p_max, force, top;
  };

  /// Runs the scene with @p kinematics and @p steps quietly; returns what
  /// its summary.json says.
  Answer
  solve(const std::string &kinematics, const unsigned int steps)
  {
    const std::string directory = "results-" + kinematics + "-" + std::to_string(steps);
    ParameterHandler  prm;
    contact_fem::ContactProblem<2>::declare_parameters(prm);
    prm.parse_input_from_string(scene);
    prm.set("Output directory", directory);
    prm.enter_subsection("Contact");
    prm.set("Kinematics", kinematics);
    prm.leave_subsection();
    prm.enter_subsection("Load stepping");
    prm.set("Number of load steps", std::to_string(steps));
    prm.leave_subsection();

    std::ostringstream quiet;
    std::streambuf    *console = std::cout.rdbuf(quiet.rdbuf());
    int                code    = 0;
    {
      contact_fem::ContactProblem<2> problem(prm, "kinematics", ".");
      code = problem.run();
    }
    std::cout.rdbuf(console);
    AssertThrow(code == 0, ExcMessage("the run failed:\n" + quiet.str()));

    boost::property_tree::ptree summary;
    boost::property_tree::read_json(directory + "/summary.json", summary);
    const auto &cycle = summary.get_child("cycles").back().second;
    Answer      answer;
    answer.p_max = cycle.get<double>("contact.max_contact_pressure");
    answer.force = cycle.get<double>("contact.total_contact_force");
    // The probe's displacement is the array [ux, uy].
    answer.top = cycle.get_child("displacement_probes")
                   .front()
                   .second.get_child("displacement")
                   .back()
                   .second.get_value<double>();
    return answer;
  }

  double
  relative_difference(const Answer &a, const Answer &b)
  {
    return std::max({std::abs(a.p_max - b.p_max) / std::abs(b.p_max),
                     std::abs(a.force - b.force) / std::abs(b.force),
                     std::abs(a.top - b.top) / std::abs(b.top)});
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                       root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  for (const std::string kinematics : {"small", "updated"})
    {
      const Answer one     = solve(kinematics, 1);
      double       largest = 0.;
      for (const unsigned int steps : {3u, 7u})
        largest = std::max(largest, relative_difference(solve(kinematics, steps), one));
      if (root)
        {
          std::cout << kinematics << ": p_max with 1 step " << std::setprecision(6) << one.p_max
                    << std::endl;
          if (kinematics == "small")
            std::cout << "  3 and 7 steps give the same answer (relative 1e-8): "
                      << (largest < 1e-8 ? "yes" : "no") << std::endl;
          else
            std::cout << "  3 and 7 steps differ by more than 1e-3: "
                      << (largest > 1e-3 ? "yes" : "no") << std::endl;
        }
    }
}
