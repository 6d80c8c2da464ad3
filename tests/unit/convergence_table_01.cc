// ConvergenceTable: the header names the columns of each contact pair (2D:
// contact length, 3D: contact area); a row takes its numbers from a cycle
// record as summary.json keeps it, with the magnitude of each pair's
// normal force from the last load step, and leaves the values a record
// lacks (no analytical solution, no estimate) empty. Values hand-made:
// the force (3, 4) has magnitude 5, the force (0, 0, 2) magnitude 2.

#include <deal.II/base/mpi.h>

#include <contact_fem/postprocess/convergence_table.h>

#include <cstdio>
#include <fstream>
#include <iostream>

namespace
{
  using contact_fem::Json;

  Json
  vector(const std::vector<double> &values)
  {
    Json v = Json::array();
    for (const double x : values)
      v.push(x);
    return v;
  }

  template <int dim>
  void
  write_table(const std::vector<double> &force, const char *extent_key)
  {
    const std::string path = "convergence_" + std::to_string(dim) + "d.csv";
    const std::vector<contact_fem::ContactPair> pairs(1, contact_fem::ContactPair{3, 4});
    contact_fem::ConvergenceTable<dim>          table(path, pairs, MPI_COMM_WORLD);
    Json pair   = Json::object().set("normal_force", vector(force)).set(extent_key, 0.75);
    Json forces = Json::object().set("pairs", Json::array().push(pair));
    // Two load steps: only the last one's forces count.
    Json steps = Json::array()
                   .push(Json::object().set("forces", Json::object()))
                   .push(Json::object().set("forces", forces));
    Json record =
      Json::object()
        .set("cycle", 2u)
        .set("n_cells", 128u)
        .set("n_dofs", 1234u)
        .set("contact",
             Json::object().set("active_slave_nodes", 17u).set("max_contact_pressure", 5.25))
        .set("estimated_error", 0.125)
        .set("wall_time", 1.5)
        .set("load_steps", steps);
    table.add_row(record, "spr contact", 9, 4.5);
    std::ifstream in(path);
    std::cout << in.rdbuf();
    std::remove(path.c_str());
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  write_table<2>({3., 4.}, "contact_length");
  write_table<3>({0., 0., 2.}, "contact_area");
}
