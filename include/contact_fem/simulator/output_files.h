// The files a run writes into its output directory: which names are
// contact_fem's, the removal of an earlier run's files, the check that the
// directory can take the new ones, and crash-safe writing.
#ifndef contact_fem_output_files_h
#define contact_fem_output_files_h

#include <deal.II/base/mpi.h>

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
   * something that is not a file (e.g. a directory log.txt). Throws with a
   * message naming the path otherwise. Rank 0 does the file-system work and
   * the other ranks wait for its result, so that every rank returns or
   * throws the same. Collective.
   */
  OutputDirectoryReport
  prepare_output_directory(const std::string &directory, const MPI_Comm comm);

  /// Writes @p text to @p path through a temporary file renamed over it:
  /// a run that is killed or fails meanwhile leaves the previous complete
  /// version or none, never half a file. Returns whether it succeeded.
  bool
  write_file_atomically(const std::string &path, const std::string &text);
} // namespace contact_fem

#endif
