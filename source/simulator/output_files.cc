#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <contact_fem/simulator/output_files.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
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
          require(!error,
                  "Output directory: cannot remove '" + path.string() +
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
      require(file && written && closed,
              "Output directory: '" + directory + "' is not writable: cannot create '" +
                path + "' (" + std::strerror(file ? EIO : open_error) + ").");
    }

    /// The work of prepare_output_directory() on rank 0.
    OutputDirectoryReport
    prepare_on_this_process(const std::string &directory)
    {
      std::error_code error;
      fs::create_directories(directory, error);
      require(!error && fs::is_directory(directory),
              "Output directory: cannot create '" + directory + "': " +
                (error ? error.message() : "it exists and is not a directory") + ".");
      OutputDirectoryReport report;
      report.earlier_scene = earlier_scene(directory);
      report.removed       = remove_earlier_outputs(directory);
      check_writable(directory);
      return report;
    }
  } // namespace

  bool
  is_output_file_name(const std::string &name)
  {
    // The VTU names are deal.II's write_vtu_with_pvtu_record(): base_NNN.pvtu
    // and base_NNN.RANK.vtu (contact_output.cc).
    static const std::regex pattern(
      "(summary\\.json|log\\.txt|convergence\\.csv|pressure_profile\\.csv|solution\\.pvd)"
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

  bool
  write_file_atomically(const std::string &path, const std::string &text)
  {
    const std::string partial = path + partial_suffix;
    {
      std::ofstream out(partial);
      out << text;
      out.close();
      if (!out)
        return false;
    }
    std::error_code error;
    fs::rename(partial, path, error);
    return !error;
  }
} // namespace contact_fem
