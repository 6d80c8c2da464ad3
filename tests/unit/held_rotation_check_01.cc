// The held-rotation check of whole runs, as summary.json records it
// (cycles[].held_rotation_check): per body in contact, the rotations its
// supports hold (their probe is skipped) and those probed, with the side
// of the limit 50 of the probe's theta G V. A wrong pre-check fails it
// either way: a rotation called held that the supports do not hold loses
// its probe and its warning; one they hold but called free costs a probe.
// - 3D, prm/hertz_3d.prm coarse, without symmetry planes: the flat top of
//   the hemisphere pushed down (u_z prescribed) and its centre held in x
//   and y. The top face holds the rotations about x and y; the rotation
//   about the vertical axis is held by the frictionless contact alone, so z
//   is probed and warns. The plate (base clamped) is held about every axis.
// - The same with a point of the rim held in y against that rotation: in
//   3D a fixed point is no support for the pre-check (its stiffness falls
//   with the element size), so z is still probed; now below 50.
// - 2D, prm/hertz.prm with its fixed points (u_x at the lowest point of the
//   arc and at the centre of the top, 8 apart): held.
// - 2D, the upper fixed point lowered to 0.5 above the lower one (a lever
//   arm of 0.06 radii of gyration): probed, and the probe warns.
// Run on coarse meshes, the log discarded. The output does not depend on
// the number of MPI ranks.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <contact_fem/simulator/contact_problem.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <iostream>
#include <sstream>
#include <string>

using namespace dealii;
using namespace contact_fem;

namespace
{
  /// The prm/ folder of the sources. From SOURCE_DIR (absolute, set by
  /// deal_ii_pickup_tests), not __FILE__: ccache's base_dir makes __FILE__
  /// relative to the build directory, and the test then found no prm/.
  std::string
  prm_directory()
  {
    return std::string(SOURCE_DIR) + "/../../prm";
  }

  /// The words of an array of summary.json, or "-" if it is empty.
  std::string
  words(const boost::property_tree::ptree &array)
  {
    std::string text;
    for (const auto &item : array)
      text += (text.empty() ? "" : " ") + item.second.get_value<std::string>();
    return text.empty() ? "-" : text;
  }

  /// Prints the held-rotation check of the last cycle of the run in @p
  /// directory and its rotation warning.
  void
  print_check(const std::string &directory, ConditionalOStream &out)
  {
    boost::property_tree::ptree summary;
    boost::property_tree::read_json(directory + "/summary.json", summary);
    const auto &cycle = summary.get_child("cycles").back().second;
    for (const auto &body : cycle.get_child("held_rotation_check"))
      {
        const auto &record = body.second;
        out << "  body " << record.get<unsigned int>("body")
            << ": held by supports: " << words(record.get_child("held_by_supports"))
            << "; probed: " << words(record.get_child("probed")) << std::endl;
        // Only the side of the limit 50: the values are round-off of a
        // nearly singular system.
        for (const auto &[axis, compliance] : record.get_child("probe_compliances"))
          out << "    " << axis << ": theta G V "
              << (compliance.get_value<double>() > 50. ? "above" : "below") << " 50" << std::endl;
      }
    const auto warning = cycle.get_optional<std::string>("rotation_warning");
    out << "  rotation warning: "
        << (warning ? warning->substr(0, warning->find(" is held")) : std::string("none"))
        << std::endl;
  }

  /// Runs prm/hertz.prm (2D) or prm/hertz_3d.prm (3D) with @p settings on
  /// top, and prints its held-rotation check.
  template <int dim>
  void
  check(const std::string &name, const std::string &settings, ConditionalOStream &out)
  {
    const std::string directory = "results_" + name;
    ParameterHandler  prm;
    ContactProblem<2>::declare_parameters(prm);
    prm.parse_input_from_string("include " + prm_directory() +
                                (dim == 2 ? "/hertz.prm\n" : "/hertz_3d.prm\n") + settings +
                                "set Output directory = " + directory +
                                "\nsubsection Output\n  set Write VTU = false\nend\n");
    // The run's log would make the output depend on round-off.
    std::ostringstream log;
    std::streambuf    *console = std::cout.rdbuf(log.rdbuf());
    int                code    = 0;
    {
      ContactProblem<dim> problem(prm, name, prm_directory());
      code = problem.run();
    }
    std::cout.rdbuf(console);

    out << name << ": exit code " << code << std::endl;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      print_check(directory, out);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ConditionalOStream out(std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);

  const std::string sphere = "subsection Geometry\n  subsection Hertz sphere\n"
                             "    set Contact refinements = 0\n  end\nend\n"
                             "subsection Boundary conditions\n"
                             "  set Fixed                   = 2: xyz\n"
                             "  set Pressure                =\n"
                             "  set Prescribed displacement = 1: z = -0.1*t\n";
  check<3>("3d_free_vertical_axis", sphere + "  set Fixed points = 1 @ 0, 0, 7.1237: xy\nend\n",
           out);
  check<3>("3d_vertical_axis_on_a_point",
           sphere + "  set Fixed points = 1 @ 0, 0, 7.1237: xy; 1 @ 6.1237, 0, 7.1237: y\nend\n",
           out);
  const std::string disc = "subsection Geometry\n  subsection Hertz cylinder\n"
                           "    set Contact refinements = 4\n  end\nend\n";
  check<2>("2d_fixed_points", disc, out);
  check<2>("2d_fixed_points_close",
           disc + "subsection Boundary conditions\n"
                  "  set Fixed points = 1 @ 0, 1: x; 1 @ 0, 1.5: x\n"
                  "end\n",
           out);
}
