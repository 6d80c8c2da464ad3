// The postprocessor plug-ins and the results every cycle records, on
// hand-made states:
// 1. which plug-ins a scene wants: forces.csv always; the VTU files with
//    Output/Write VTU; the probes with Output/Displacement probes; the
//    checkerboard check and pressure_profile.csv with contact pairs (the
//    profile also needs Output/Write pressure profile); the reference
//    pressure error with contact and a reference profile; the energy error
//    with a reference potential energy. Counts: 1, 2, 2, 3, 4, 7.
// 2. the energy-norm error sqrt(2 |Pi_h + W_chord - Pi_ref|): Pi_h = -1,
//    W_chord = 0.02, Pi_ref = -1.5 give sqrt(1.04) = 1.0198039; Pi_ref =
//    -0.9 gives excess -0.08, sqrt(0.16) = 0.4 and the warning that Pi_h is below
//    the reference.
// 3. the displacement probe at the vertex (1, 1) of a unit square of body
//    1 whose displacement is (x + 2 y, 3 x y): (3, 3).
// 4. the load/reaction balance of the same square with its bottom held:
//    the residual at the four held components (bottom vertices (0, 0) and
//    (1, 0)) is r = (0.5, -1) at each vertex, so the support reaction is
//    (1, -2). A body load (-1, 2) balances it: imbalance 0. With (-1, 1.9)
//    the net is (0, -0.1); the scale is the largest of the load's
//    magnitude, the largest body load (both sqrt(4.61) = 2.1470911) and
//    half the sum of the reaction magnitudes (1.5): 0.1 / 2.1470911 =
//    0.046574643.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_fem/geometry/model_frame.h>
#include <contact_fem/postprocess/contact_results.h>
#include <contact_fem/postprocess/postprocessor.h>
#include <contact_fem/simulator/scene_parameters.h>

#include "unit_test_materials.h"

#include <iomanip>
#include <iostream>
#include <sstream>

using namespace dealii;
using namespace contact_fem;

namespace
{
  /// The plug-ins' keys, set as a scene file would set them.
  struct OutputKeys
  {
    ParameterHandler prm;
    OutputKeys(const bool vtu, const bool pressure_profile)
    {
      Postprocessor<2>::declare_all_parameters(prm);
      prm.enter_subsection("Output");
      prm.set("Write VTU", vtu);
      prm.set("Write pressure profile", pressure_profile);
      prm.leave_subsection();
    }
  };

  unsigned int
  count_wanted(const bool                vtu,
               const bool                pressure_profile,
               const OutputParameters   &output,
               const AnalyticalSolution &analytical,
               const bool                has_contact)
  {
    OutputKeys  keys(vtu, pressure_profile);
    TimerOutput timer(MPI_COMM_WORLD, std::cout, TimerOutput::never, TimerOutput::wall_times);
    return Postprocessor<2>::create_wanted({keys.prm, output, analytical, has_contact, false,
                                            [](const std::string &, const std::string &, Json &) {},
                                            timer, MPI_COMM_WORLD})
      .size();
  }

  void
  wanted_plugins()
  {
    OutputParameters   output;
    AnalyticalSolution analytical;
    output.directory = ".";
    std::cout << "plain scene: " << count_wanted(false, false, output, analytical, false)
              << std::endl;
    std::cout << "with VTU: " << count_wanted(true, false, output, analytical, false) << std::endl;
    output.displacement_probes.push_back(BodyPoint{1, {1., 1.}});
    std::cout << "with probes: " << count_wanted(false, false, output, analytical, false)
              << std::endl;
    std::cout << "with probes and contact: " << count_wanted(false, false, output, analytical, true)
              << std::endl;
    std::cout << "with the pressure profile: "
              << count_wanted(false, true, output, analytical, true) << std::endl;
    analytical.reference_pressure_profile = {{0., 1.}, {1., 0.}};
    analytical.reference_potential_energy = -1.;
    std::cout << "with everything: " << count_wanted(true, true, output, analytical, true)
              << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(8);
  wanted_plugins();

  // A unit square of body 1, Q1, with the displacement (x + 2 y, 3 x y).
  Triangulation<2> tria;
  GridGenerator::hyper_cube(tria, 0., 1., true);
  tria.begin_active()->set_material_id(1);
  const FESystem<2> fe(FE_Q<2>(1), 2);
  DoFHandler<2>     dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const MappingQ<2>             mapping(1);
  const IndexSet                owned = dof_handler.locally_owned_dofs();
  TrilinosWrappers::MPI::Vector solution(owned, MPI_COMM_WORLD), residual(owned, MPI_COMM_WORLD);
  AffineConstraints<double>     dirichlet;
  const auto                    cell = dof_handler.begin_active();
  for (const auto v : cell->vertex_indices())
    {
      const Point<2> x                       = cell->vertex(v);
      solution(cell->vertex_dof_index(v, 0)) = x[0] + 2. * x[1];
      solution(cell->vertex_dof_index(v, 1)) = 3. * x[0] * x[1];
      if (x[1] == 0.)
        for (unsigned int d = 0; d < 2; ++d)
          {
            dirichlet.add_line(cell->vertex_dof_index(v, d));
            residual(cell->vertex_dof_index(v, d)) = d == 0 ? 0.5 : -1.;
          }
    }
  dirichlet.close();
  solution.compress(VectorOperation::insert);
  residual.compress(VectorOperation::insert);

  const Materials<2>                       materials = make_materials<2>("1", "100", "0.3");
  const std::vector<DisplacementCondition> displacements;
  const std::vector<PointCondition>        points;
  const std::vector<double>                no_contact_force;
  const std::vector<ContactPair>           pairs;
  const std::vector<types::boundary_id>    rollers;
  const ForceInputs<2> forces{dof_handler, residual, dirichlet,        displacements, points,
                              nullptr,     nullptr,  no_contact_force, pairs,         rollers};
  OutputParameters     output;
  output.displacement_probes.push_back(BodyPoint{1, {1., 1.}});
  AnalyticalSolution                                      analytical;
  const std::vector<std::vector<types::global_dof_index>> probe_dofs = {
    {cell->vertex_dof_index(3, 0), cell->vertex_dof_index(3, 1)}};
  const ModelFrame<2> frame;
  const RunView<2>    view{{dof_handler, mapping, solution, materials, nullptr, nullptr},
                        forces,
                        probe_dofs,
                        solution,
                        frame,
                        output,
                        analytical,
                        nullptr,
                        nullptr,
                        0,
                        0,
                        1.,
                        MPI_COMM_WORLD};

  // 2. The energy error plug-in, on its own.
  TimerOutput timer(MPI_COMM_WORLD, std::cout, TimerOutput::never, TimerOutput::wall_times);
  for (const double reference : {-1.5, -0.9})
    {
      analytical.reference_potential_energy = reference;
      OutputParameters no_output;
      OutputKeys       keys(false, false);
      const auto       plugins = Postprocessor<2>::create_wanted(
              {keys.prm, no_output, analytical, false, false,
               [](const std::string &, const std::string &, Json &) {}, timer, MPI_COMM_WORLD});
      Json record = Json::object()
                      .set("potential_energy", -1.)
                      .set("analytical", Json::object().set("chord_gap_work", 0.02));
      std::ostringstream out;
      // The last one in rank order is the energy error (forces.csv comes
      // first and acts after load steps only).
      plugins.back()->after_cycle(view, record, out);
      std::cout << out.str() << "recorded energy_error: " << record["energy_error"].number_value()
                << std::endl;
    }

  // 3. The probe at (1, 1): vertex 3 of the square.
  const std::vector<double> probe = view.probe_displacements();
  std::cout << "probe (1, 1): " << probe[0] << ", " << probe[1] << std::endl;

  // 4. The balance of the loads against the support reactions.
  const std::function<bool(types::global_dof_index)> no_rollers = [](const auto) {
    return false;
  };
  for (const Tensor<1, 2> load : {Tensor<1, 2>({-1., 2.}), Tensor<1, 2>({-1., 1.9})})
    {
      const std::map<types::material_id, Tensor<1, 2>> body_loads = {{1, load}};
      const Json reaction = reaction_results<2>({forces, no_rollers, body_loads, 100., 3.});
      std::cout << "body load (" << load << "): reaction ("
                << reaction["support_reaction_components"][0].number_value() << ", "
                << reaction["support_reaction_components"][1].number_value()
                << "), relative imbalance " << reaction["relative_imbalance"].number_value()
                << std::endl
                << reaction_results_text(reaction, true);
    }
}
