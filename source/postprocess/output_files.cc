#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <contact_fem/postprocess/output_files.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  namespace
  {
    namespace fs = std::filesystem;

    /// A problem with the output directory, with the message for the user.
    struct OutputError : public std::runtime_error
    {
      using std::runtime_error::runtime_error;
    };

    void
    require(const bool condition, const std::string &message)
    {
      if (!condition)
        throw OutputError(message);
    }

    /// Created and removed again to test that the directory takes new files.
    const std::string write_check_name = ".contact_fem-write-check";
    /// The suffix of write_file_atomically()'s temporary files.
    const std::string partial_suffix = ".partial";

    /// The scene named by an earlier run's log.txt ("contact_fem: scene
    /// 'NAME', ...") or summary.json ("scene": "NAME"); empty if neither
    /// names one.
    std::string
    earlier_scene(const std::string &directory)
    {
      const std::pair<std::string, std::regex> sources[] = {
        {"log.txt", std::regex("^contact_fem: scene '([^']*)'")},
        {"summary.json", std::regex("\"scene\" *: *\"([^\"]*)\"")}};
      for (const auto &[file, pattern] : sources)
        {
          std::ifstream in(directory + "/" + file);
          std::string   line;
          for (unsigned int n = 0; n < 20 && std::getline(in, line); ++n)
            {
              std::smatch match;
              if (std::regex_search(line, match, pattern))
                return match[1];
            }
        }
      return "";
    }

    /// Removes the files of an earlier run; throws naming the first one
    /// that cannot be removed, or a name of the run taken by something else
    /// (a directory, ...).
    unsigned int
    remove_earlier_outputs(const std::string &directory)
    {
      std::vector<fs::path> ours;
      for (const auto &entry : fs::directory_iterator(directory))
        if (is_output_file_name(entry.path().filename().string()))
          ours.push_back(entry.path());
      unsigned int removed = 0;
      for (const auto &path : ours)
        {
          std::error_code error;
          const auto      status = fs::symlink_status(path, error);
          require(fs::is_regular_file(status) || fs::is_symlink(status),
                  "Output directory: '" + path.string() +
                    "' is in the way of a file this run writes (it is " +
                    (fs::is_directory(status) ? "a directory" : "not a file") +
                    "); remove or rename it.");
          fs::remove(path, error);
          require(!error, "Output directory: cannot remove '" + path.string() +
                            "', a file of an earlier run: " + error.message() + ".");
          ++removed;
        }
      return removed;
    }

    /// Throws naming @p directory unless a file can be created in it.
    void
    check_writable(const std::string &directory)
    {
      const std::string path = directory + "/" + write_check_name;
      errno                  = 0;
      std::FILE *file        = std::fopen(path.c_str(), "w");
      const int  open_error  = errno;
      const bool written     = file && std::fputs("x", file) >= 0;
      const bool closed      = file && std::fclose(file) == 0;
      std::remove(path.c_str());
      require(file && written && closed, "Output directory: '" + directory +
                                           "' is not writable: cannot create '" + path + "' (" +
                                           std::strerror(file ? EIO : open_error) + ").");
    }

    /// The lock file that marks a directory as taken by a live run.
    const std::string lock_name = ".contact_fem.lock";

    /// Takes the lock of @p directory for the rest of this process: an
    /// flock(2) on its lock file, which the kernel releases when the
    /// process ends however it ends, so that the lock of a dead run never
    /// blocks. The file holds the pid of the run, for the message.
    void
    lock_directory(const std::string &directory)
    {
      static std::string locked;
      const std::string  path = fs::weakly_canonical(directory).string() + "/" + lock_name;
      if (locked == path)
        return;
      const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
      require(fd >= 0, "Output directory: cannot create the lock file '" + path + "' (" +
                         std::strerror(errno) + ").");
      if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
        {
          const int  error   = errno;
          char       pid[32] = {};
          const auto n       = ::pread(fd, pid, sizeof(pid) - 1, 0);
          ::close(fd);
          require(false, "Output directory: '" + directory + "' is in use by another " +
                           "contact_fem run" +
                           (n > 0 ? " (process " + std::string(pid, n) + ")" : std::string()) +
                           (error == EWOULDBLOCK ? "" : std::string(": ") + std::strerror(error)) +
                           "; two runs would mix their files. Wait for it to end, or give "
                           "this run another --output-directory.");
        }
      const std::string pid = std::to_string(::getpid());
      const bool        written =
        ::ftruncate(fd, 0) == 0 && ::pwrite(fd, pid.c_str(), pid.size(), 0) == ssize_t(pid.size());
      (void)written; // the pid only improves a message
      locked = path; // fd stays open: the lock lasts as long as the process
    }

    /// The work of prepare_output_directory() on rank 0.
    OutputDirectoryReport
    prepare_on_this_process(const std::string &directory)
    {
      std::error_code error;
      fs::create_directories(directory, error);
      // The first part of the path that exists and is not a directory (a
      // file of that name) is what stops it: say which.
      std::string blocking;
      for (fs::path part = fs::path(directory).lexically_normal(); !part.empty();
           part = part.parent_path())
        {
          std::error_code ignored;
          if (fs::exists(part, ignored) && !fs::is_directory(part, ignored))
            blocking = part.string();
          if (part == part.parent_path())
            break;
        }
      require(!error && fs::is_directory(directory),
              "Output directory: cannot create '" + directory + "': " +
                (!blocking.empty() ?
                   "'" + blocking + "' is a file, not a directory; name another directory, or "
                                    "remove the file" :
                   (error ? error.message() : "it exists and is not a directory")) +
                ".");
      check_writable(directory);
      lock_directory(directory);
      OutputDirectoryReport report;
      report.earlier_scene = earlier_scene(directory);
      report.removed       = remove_earlier_outputs(directory);
      return report;
    }
  } // namespace

  void
  write_cycle_csv(const std::string                  &directory,
                  const std::string                  &base,
                  const unsigned int                  cycle,
                  const std::function<std::string()> &make,
                  const MPI_Comm                      comm)
  {
    const std::string latest = directory + "/" + base + ".csv";
    const std::string of_cycle =
      directory + "/" + base + "_cycle_" + std::to_string(cycle) + ".csv";
    std::string latest_problem, cycle_problem;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      {
        const std::string text = make();
        latest_problem         = write_file_atomically(latest, text);
        cycle_problem          = write_file_atomically(of_cycle, text);
      }
    throw_if_unwritten(latest, latest_problem, comm);
    throw_if_unwritten(of_cycle, cycle_problem, comm);
  }

  bool
  is_output_file_name(const std::string &name)
  {
    // The VTU names are deal.II's write_vtu_with_pvtu_record(): base_NNN.pvtu
    // and base_NNN.RANK.vtu (vtu_output.cc).
    static const std::regex pattern(
      "(summary\\.json|log\\.txt|convergence\\.csv|"
      "(pressure|tying)_profile(_cycle_[0-9]+)?\\.csv|forces\\.csv|"
      "(solution|contact_surface|tied_surface)(_cycle_[0-9]+)?\\.pvd|error_indicators\\.pvd|"
      "(contact|tied)_surface_[0-9]+\\.vtu)"
      "(\\.partial)?|"
      "(solution|error_indicators)_[0-9]+\\.([0-9]+\\.vtu|pvtu)|"
      "\\.contact_fem-write-check");
    return std::regex_match(name, pattern);
  }

  OutputDirectoryReport
  prepare_output_directory(const std::string &directory, const MPI_Comm comm)
  {
    // The others wait for rank 0's verdict: a message, or the report.
    std::string           failure;
    OutputDirectoryReport report;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          report = prepare_on_this_process(directory);
        }
      catch (const OutputError &e)
        {
          failure = e.what();
        }
      catch (const std::exception &e)
        {
          // std::filesystem errors (e.g. a directory that cannot be listed)
          failure = std::string("Output directory: '") + directory + "': " + e.what() + ".";
        }
    failure = Utilities::MPI::broadcast(comm, failure, 0);
    AssertThrow(failure.empty(), ExcMessage(failure));
    report.removed       = Utilities::MPI::broadcast(comm, report.removed, 0);
    report.earlier_scene = Utilities::MPI::broadcast(comm, report.earlier_scene, 0);
    return report;
  }

  std::string
  write_file_atomically(const std::string &path, const std::string &text)
  {
    const std::string partial = path + partial_suffix;
    std::string       problem;
    errno           = 0;
    std::FILE *file = std::fopen(partial.c_str(), "wb");
    if (!file)
      return std::strerror(errno);
    const bool written =
      std::fwrite(text.data(), 1, text.size(), file) == text.size() && std::fflush(file) == 0;
    const int  error  = errno;
    const bool closed = std::fclose(file) == 0;
    if (!written || !closed)
      problem = std::strerror(error != 0 ? error : errno != 0 ? errno : EIO);
    else if (std::rename(partial.c_str(), path.c_str()) != 0)
      problem = std::strerror(errno);
    // Never leave half a file behind (a full disk).
    if (!problem.empty())
      std::remove(partial.c_str());
    return problem;
  }

  void
  throw_if_unwritten(const std::string &path, const std::string &problem, const MPI_Comm comm)
  {
    std::string first;
    for (const std::string &p : Utilities::MPI::all_gather(comm, problem))
      if (first.empty())
        first = p;
    if (!first.empty())
      throw OutputFailure("Output: cannot write '" + path + "' (" + first + ").");
  }

  template <int dim>
  std::string
  write_vtu_pieces(const DataOutInterface<dim, dim> &data,
                   const std::string                &directory,
                   const std::string                &base,
                   const unsigned int                counter,
                   const unsigned int                n_digits,
                   const MPI_Comm                    comm)
  {
    const unsigned int rank       = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n          = Utilities::MPI::n_mpi_processes(comm);
    const std::string  stem       = base + "_" + Utilities::int_to_string(counter, n_digits);
    const auto         piece_name = [&](const unsigned int r) {
      return stem + "." + Utilities::int_to_string(r, Utilities::needed_digits(n - 1)) + ".vtu";
    };
    std::ostringstream piece;
    data.write_vtu(piece);
    const std::string piece_path = directory + piece_name(rank);
    throw_if_unwritten(piece_path, write_file_atomically(piece_path, piece.str()), comm);

    const std::string record_name = stem + ".pvtu";
    std::string       problem;
    if (rank == 0)
      {
        std::vector<std::string> pieces;
        for (unsigned int r = 0; r < n; ++r)
          pieces.push_back(piece_name(r));
        std::ostringstream record;
        data.write_pvtu_record(record, pieces);
        problem = write_file_atomically(directory + record_name, record.str());
      }
    throw_if_unwritten(directory + record_name, problem, comm);
    return record_name;
  }

  template std::string
  write_vtu_pieces<2>(const DataOutInterface<2, 2> &,
                      const std::string &,
                      const std::string &,
                      const unsigned int,
                      const unsigned int,
                      const MPI_Comm);
  template std::string
  write_vtu_pieces<3>(const DataOutInterface<3, 3> &,
                      const std::string &,
                      const std::string &,
                      const unsigned int,
                      const unsigned int,
                      const MPI_Comm);
} // namespace contact_fem
