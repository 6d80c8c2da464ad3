// The console of a run and its copy log.txt in the output directory.
#ifndef contact_fem_run_log_h
#define contact_fem_run_log_h

#include <deal.II/base/mpi.h>

#include <contact_fem/postprocess/output_files.h>

#include <fstream>
#include <ostream>
#include <streambuf>
#include <string>

namespace contact_fem
{
  /// An output stream that writes to the console and, once attached, to a log file.
  class TeeStream : public std::ostream
  {
  public:
    explicit TeeStream(std::ostream &console);
    /// Also write to @p file from now on.
    void
    attach(std::ostream &file);
    /// Whether writing to the file failed (it is then no longer written;
    /// the console goes on).
    bool
    file_failed() const;

  private:
    class Buffer : public std::streambuf
    {
    public:
      std::streambuf *first = nullptr, *second = nullptr;
      bool            file_failed = false;

    protected:
      int
      overflow(int c) override;
      int
      sync() override;

    private:
      void
      drop_file();
    } buffer;
  };

  /**
   * The console of a run (std::cout) and, once the output directory is
   * open, its copy log.txt there. Only rank 0 writes the file.
   */
  class RunLog
  {
  public:
    explicit RunLog(const MPI_Comm comm);

    /// The console; what it gets goes to log.txt too once open() has run.
    std::ostream &
    stream()
    {
      return console;
    }

    /// Prepares @p directory for the run (prepare_output_directory()) and
    /// opens log.txt in it; throws naming the path if either fails.
    /// Collective.
    OutputDirectoryReport
    open(const std::string &directory);

    /// Says how many files of an earlier run open() removed: in the log
    /// only when they were @p scene_name's own (a rerun replaces its
    /// results, and the console stays the same for every rerun), on the
    /// console otherwise.
    void
    report_earlier_outputs(const OutputDirectoryReport &report, const std::string &scene_name);

    /// Ends log.txt (only: main() prints it on the console) with the error
    /// that stopped the run before its first solve, so that the log of a
    /// refused input says why. Nothing if the log is not open.
    void
    note_error(const std::string &message);

    /// Whether writing log.txt failed during the run (a full disk).
    bool
    failed() const
    {
      return console.file_failed();
    }

  private:
    MPI_Comm      comm;
    std::string   directory;
    std::ofstream file;
    TeeStream     console;
  };
} // namespace contact_fem

#endif
