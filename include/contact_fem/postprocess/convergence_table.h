// convergence.csv: per adaptive cycle, the DoFs, the wall time, the error
// measures and the forces of the contact pairs (doc/outputs.md).
#ifndef contact_fem_convergence_table_h
#define contact_fem_convergence_table_h

#include <deal.II/base/mpi.h>

#include <contact_fem/contact/contact_parameters.h>
#include <contact_fem/core/json.h>

#include <fstream>
#include <string>
#include <vector>

namespace contact_fem
{
  /**
   * Writes convergence.csv from the records of the adaptive cycles (the
   * entries of summary.json's cycles[]), one row per cycle as soon as it
   * ends, so that an interrupted study keeps its rows. Rank 0 writes; the
   * checks of the writes are collective.
   */
  template <int dim>
  class ConvergenceTable
  {
  public:
    /// Creates @p path with its header: the common columns, then per
    /// contact pair of @p pairs its normal force and contact length (2D)
    /// or area (3D). Throws naming the path if it cannot be written.
    ConvergenceTable(const std::string              &path,
                     const std::vector<ContactPair> &pairs,
                     const MPI_Comm                  comm);

    /// Appends the row of @p cycle_record (a value it lacks stays empty);
    /// @p estimator names the error estimator, @p newton_iterations counts
    /// those of the cycle's load steps, @p cumulative_time is the wall time
    /// of the study so far. Throws naming the path if writing fails.
    void
    add_row(const Json        &cycle_record,
            const std::string &estimator,
            const unsigned int newton_iterations,
            const double       cumulative_time);

  private:
    std::string   path;
    unsigned int  n_pairs;
    MPI_Comm      comm;
    std::ofstream file;
  };
} // namespace contact_fem

#endif
