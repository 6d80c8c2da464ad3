// The files a run writes into its output directory: which names are
// contact_fem's, the removal of an earlier run's files, the check that the
// directory can take the new ones, and crash-safe writing.
#ifndef contact_fem_output_files_h
#define contact_fem_output_files_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>

#include <functional>
#include <stdexcept>
#include <string>

namespace contact_fem
{
  /// Whether @p name (without directory) is a file that contact_fem writes:
  /// summary.json, log.txt, convergence.csv, pressure_profile.csv,
  /// solution.pvd, solution_NNN.pvtu / solution_NNN.R.vtu,
  /// error_indicators_NN.pvtu / error_indicators_NN.R.vtu, and the temporary
  /// files of write_file_atomically() and of the write check.
  bool
  is_output_file_name(const std::string &name);

  /// What prepare_output_directory() found.
  struct OutputDirectoryReport
  {
    /// Files of an earlier run removed.
    unsigned int removed = 0;
    /// The scene of that run (from its log.txt or summary.json); empty if
    /// unknown.
    std::string earlier_scene;
  };

  /**
   * Makes @p directory ready for a run, before any work: creates it if
   * needed, removes the files of an earlier run (only names for which
   * is_output_file_name() holds; other files stay), and checks that a file
   * can be created in it and that no name the run writes is taken by
   * something that is not a file (e.g. a directory log.txt). Locks the
   * directory for this process (its file .contact_fem.lock, flock(2)): a
   * directory that another live run holds is refused. Throws with a
   * message naming the path otherwise. Rank 0 does the file-system work and
   * the other ranks wait for its result, so that every rank returns or
   * throws the same. Collective.
   */
  OutputDirectoryReport
  prepare_output_directory(const std::string &directory, const MPI_Comm comm);

  /// Writes @p text to @p path through a temporary file renamed over it:
  /// a run that is killed or fails meanwhile (a full disk) leaves the
  /// previous complete version or none, never half a file. Returns the
  /// reason of a failure (strerror, e.g. "No space left on device"), or an
  /// empty string.
  std::string
  write_file_atomically(const std::string &path, const std::string &text);

  /// A result file that could not be written during a run (a full disk).
  struct OutputFailure : public std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };

  /// Throws OutputFailure "Output: cannot write '@p path' (reason)" on every
  /// rank if @p problem is not empty on some rank. Collective.
  void
  throw_if_unwritten(const std::string &path, const std::string &problem, const MPI_Comm comm);

  /// Writes the text of @p make (called on rank 0 only) to @p base.csv (the
  /// latest cycle's) and @p base_cycle_K.csv (K = @p cycle) in
  /// @p directory, each through write_file_atomically(), and throws on
  /// every rank if either could not be written. Collective.
  void
  write_cycle_csv(const std::string                  &directory,
                  const std::string                  &base,
                  const unsigned int                  cycle,
                  const std::function<std::string()> &make,
                  const MPI_Comm                      comm);

  /// Writes this rank's piece of @p data and (rank 0) the .pvtu record that
  /// lists the pieces, named as deal.II's write_vtu_with_pvtu_record():
  /// @p directory/@p base_NNN.R.vtu and @p base_NNN.pvtu, each through
  /// write_file_atomically(), so that a full disk leaves no truncated VTU
  /// and the message names the file. Returns the .pvtu name without the
  /// directory. Collective.
  template <int dim>
  std::string
  write_vtu_pieces(const dealii::DataOutInterface<dim, dim> &data,
                   const std::string                        &directory,
                   const std::string                        &base,
                   const unsigned int                        counter,
                   const unsigned int                        n_digits,
                   const MPI_Comm                            comm);
} // namespace contact_fem

#endif
