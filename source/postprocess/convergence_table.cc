#include <contact_fem/postprocess/convergence_table.h>
#include <contact_fem/postprocess/output_files.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace contact_fem
{
  namespace
  {
    /// A number of a record with 8 digits; an unknown value (no reference,
    /// no analytical solution) stays empty.
    std::string
    number(const Json &value)
    {
      std::ostringstream s;
      if (std::isfinite(value.number_value()))
        s << std::setprecision(8) << value.number_value();
      return s.str();
    }
  } // namespace

  template <int dim>
  ConvergenceTable<dim>::ConvergenceTable(const std::string              &path,
                                          const std::vector<ContactPair> &pairs,
                                          const MPI_Comm                  comm)
    : path(path)
    , n_pairs(pairs.size())
    , comm(comm)
  {
    const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    if (root)
      {
        file.open(path);
        file << "cycle,cells,dofs,active_slave_nodes,estimator,estimated_error,"
                "relative_estimated_error,effectivity_index,p_max_relative_error,"
                "a_error,pressure_l2_relative_error,energy_error,"
                "newton_iterations,wall_time,cumulative_wall_time,"
                "max_contact_pressure,pressure_reference_l2_relative_error";
        for (const auto &pair : pairs)
          {
            const std::string name =
              "pair_" + std::to_string(pair.slave) + "_" + std::to_string(pair.master);
            file << ',' << name << "_normal_force," << name
                 << (dim == 2 ? "_contact_length" : "_contact_area");
          }
        file << '\n';
      }
    throw_if_unwritten(path, !root || file.good() ? "" : "the write failed: a full disk?", comm);
  }

  template <int dim>
  void
  ConvergenceTable<dim>::add_row(const Json        &r,
                                 const std::string &estimator,
                                 const unsigned int newton_iterations,
                                 const double       cumulative_time)
  {
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      {
        file << number(r["cycle"]) << ',' << number(r["n_cells"]) << ',' << number(r["n_dofs"])
             << ',' << number(r["contact"]["active_slave_nodes"]) << ',' << estimator << ','
             << number(r["estimated_error"]) << ',' << number(r["relative_estimated_error"]) << ','
             << number(r["effectivity_index"]) << ','
             << number(r["analytical"]["p_max_relative_error"]) << ','
             << number(r["analytical"]["a_error"]) << ',' << number(r["pressure_l2_relative_error"])
             << ',' << number(r["energy_error"]) << ',' << newton_iterations << ','
             << number(r["wall_time"]) << ',' << cumulative_time << ','
             << number(r["contact"]["max_contact_pressure"]) << ','
             << number(r["pressure_reference_l2_relative_error"]);
        // Per contact pair, from the cycle's last load step: the magnitude
        // of the normal force and the contact length (2D) or area (3D).
        const Json &steps = r["load_steps"];
        const Json &pairs = steps[steps.size() - 1]["forces"]["pairs"];
        for (unsigned int p = 0; p < n_pairs; ++p)
          {
            const Json &force   = pairs[p]["normal_force"];
            double      squared = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              squared += force[d].number_value() * force[d].number_value();
            file << ',' << number(Json(std::sqrt(squared))) << ','
                 << number(pairs[p][dim == 2 ? "contact_length" : "contact_area"]);
          }
        file << std::endl;
      }
    const bool ok = dealii::Utilities::MPI::this_mpi_process(comm) != 0 || file.good();
    throw_if_unwritten(path, ok ? "" : "the write failed: a full disk?", comm);
  }

  template class ConvergenceTable<2>;
  template class ConvergenceTable<3>;
} // namespace contact_fem
