// Test driver for bad input: runs contact_fem on the .prm file given as the
// argument, prints what it said (with the test directory replaced by <dir>,
// so the output does not depend on where the sources are) and its exit
// status. Succeeds only if contact_fem failed with a non-zero exit code and
// did not crash (no signal, no abort).
//
// The run starts in a fresh working directory (the output directory
// 'results' of an earlier run of the test is removed). Lines of the .prm
// file of the form '# driver: DIRECTIVE' prepare the case:
//   # driver: args ARGUMENTS         more command-line arguments (after
//                                    --output-directory results)
//   # driver: env NAME=VALUE         an environment variable of the run
//   # driver: parameter directory    run on a directory named scene.prm
//                                    instead of the .prm file
//   # driver: parameter PATH         run on PATH instead of the .prm file
//   # driver: fifo PATH              a named pipe (FIFO) at PATH
//   # driver: hold-lock DIR          hold the output-directory lock of DIR
//                                    (as a live run does) during the run;
//                                    the driver's pid prints as <pid>
//   # driver: signal NAME REGEX      send signal NAME (INT or TERM) to the
//                                    run once a line of its output matches
//   # driver: show PATH REGEX        after the run, print the lines of
//                                    file PATH that match
//   # driver: mkdir PATH             a directory (in the working directory)
//   # driver: write PATH [TEXT]      a file holding TEXT
//   # driver: read-only PATH         a directory nobody may write to: the
//                                    run then has no root privileges (root
//                                    ignores permissions)
//   # driver: list PATH              after the run, print the names in PATH
//   # driver: keep REGEX             print only the lines of the run that
//                                    contain a match (for runs whose other
//                                    lines are round-off, e.g. after a
//                                    singular solve)
//   # driver: file-size-limit BYTES  no file of the run may grow beyond
//                                    BYTES (RLIMIT_FSIZE, with SIGXFSZ
//                                    ignored: writes fail as on a full
//                                    disk)
//   # driver: mask REGEX             replace each match in the printed text
//                                    by '...' (a part decided by round-off,
//                                    e.g. the step at which a run fails)
#include <fcntl.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  namespace fs = std::filesystem;

  struct Case
  {
    std::string                                      arguments;
    std::vector<std::pair<std::string, std::string>> environment;
    bool                                             parameter_directory = false;
    std::string                                      parameter_file;
    std::vector<std::string>                         read_only, listed;
    std::vector<std::pair<std::string, std::string>> shown;
    std::string                                      keep, mask, signal_pattern;
    int                                              signal          = 0;
    long                                             file_size_limit = -1;
  };

  /// Lets the test directory be removed again by a non-root user.
  void
  make_writable(const fs::path &path)
  {
    std::error_code error;
    if (fs::is_directory(fs::symlink_status(path, error)))
      {
        fs::permissions(path, fs::perms::owner_all, fs::perm_options::add, error);
        for (const auto &entry : fs::directory_iterator(path, error))
          make_writable(entry.path());
      }
  }

  /// Reads the directives of @p prm and prepares the working directory.
  Case
  prepare(const std::string &prm)
  {
    make_writable("results");
    fs::remove_all("results");
    Case              c;
    std::ifstream     in(prm);
    std::string       line;
    const std::string marker = "# driver: ";
    while (std::getline(in, line))
      {
        if (line.compare(0, marker.size(), marker) != 0)
          continue;
        std::istringstream words(line.substr(marker.size()));
        std::string        directive, argument, rest;
        words >> directive >> argument;
        std::getline(words, rest);
        rest = rest.empty() ? rest : rest.substr(1);
        if (directive == "args")
          c.arguments += " " + argument + (rest.empty() ? "" : " " + rest);
        else if (directive == "env")
          {
            const auto eq = argument.find('=');
            c.environment.emplace_back(argument.substr(0, eq), argument.substr(eq + 1));
          }
        else if (directive == "file-size-limit")
          c.file_size_limit = std::stol(argument);
        else if (directive == "parameter" && argument == "directory")
          c.parameter_directory = true;
        else if (directive == "parameter")
          c.parameter_file = argument;
        else if (directive == "fifo")
          {
            fs::remove(argument);
            mkfifo(argument.c_str(), 0644);
          }
        else if (directive == "hold-lock")
          {
            // Kept open (and locked) until the driver ends.
            fs::create_directories(argument);
            const int fd = open((argument + "/.contact_fem.lock").c_str(), O_RDWR | O_CREAT, 0644);
            const std::string pid = std::to_string(getpid());
            if (fd < 0 || flock(fd, LOCK_EX | LOCK_NB) != 0 || ftruncate(fd, 0) != 0 ||
                write(fd, pid.c_str(), pid.size()) != ssize_t(pid.size()))
              std::exit(2);
          }
        else if (directive == "signal")
          {
            c.signal         = argument == "INT" ? SIGINT : SIGTERM;
            c.signal_pattern = rest;
          }
        else if (directive == "show")
          c.shown.emplace_back(argument, rest);
        else if (directive == "mkdir")
          fs::create_directories(argument);
        else if (directive == "write")
          {
            if (fs::path(argument).has_parent_path())
              fs::create_directories(fs::path(argument).parent_path());
            std::ofstream(argument) << rest << (rest.empty() ? "" : "\n");
          }
        else if (directive == "read-only")
          {
            fs::create_directories(argument);
            c.read_only.push_back(argument);
          }
        else if (directive == "list")
          c.listed.push_back(argument);
        else if (directive == "keep")
          c.keep = argument + (rest.empty() ? "" : " " + rest);
        else if (directive == "mask")
          c.mask = argument + (rest.empty() ? "" : " " + rest);
        else
          {
            std::cerr << "expect_failure: unknown directive in '" << line << "'" << std::endl;
            std::exit(2);
          }
      }
    for (const auto &directory : c.read_only)
      fs::permissions(directory,
                      fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                        fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec,
                      fs::perm_options::replace);
    return c;
  }

  /// Runs @p command through the shell with the environment and privileges
  /// of @p c; returns its output (stdout and stderr) and sets @p status.
  std::string
  run(const std::string &command, const Case &c, int &status)
  {
    int channel[2];
    if (pipe(channel) != 0)
      std::exit(2);
    const pid_t child = fork();
    if (child == 0)
      {
        dup2(channel[1], 1);
        dup2(channel[1], 2);
        close(channel[0]);
        close(channel[1]);
        for (const auto &[name, value] : c.environment)
          setenv(name.c_str(), value.c_str(), 1);
        if (c.file_size_limit >= 0)
          {
            // An ignored signal stays ignored across exec: the write fails
            // with EFBIG instead of killing the run.
            std::signal(SIGXFSZ, SIG_IGN);
            const rlimit limit{static_cast<rlim_t>(c.file_size_limit),
                               static_cast<rlim_t>(c.file_size_limit)};
            if (setrlimit(RLIMIT_FSIZE, &limit) != 0)
              std::exit(3);
          }
        if (!c.read_only.empty() && geteuid() == 0)
          {
            // nobody: permissions apply again.
            setenv("HOME", "/tmp", 1);
            if (setgid(65534) != 0 || setuid(65534) != 0)
              {
                std::printf("expect_failure: cannot drop root privileges for a "
                            "read-only directory\n");
                std::exit(3);
              }
          }
        execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char *>(nullptr));
        std::exit(127);
      }
    close(channel[1]);
    std::string            text;
    std::array<char, 4096> buffer;
    ssize_t                n;
    bool                   signalled = c.signal == 0;
    while ((n = read(channel[0], buffer.data(), buffer.size())) > 0)
      {
        text.append(buffer.data(), n);
        if (!signalled && std::regex_search(text, std::regex(c.signal_pattern)))
          {
            kill(child, c.signal);
            signalled = true;
          }
      }
    close(channel[0]);
    waitpid(child, &status, 0);
    return text;
  }
} // namespace

int
main(int argc, char **argv)
{
  if (argc != 2)
    {
      std::cerr << "usage: expect_failure FILE.prm" << std::endl;
      return 2;
    }
  const std::string prm       = argv[1];
  const std::string directory = prm.substr(0, prm.find_last_of('/'));
  const Case        c         = prepare(prm);

  std::string parameter_file = c.parameter_file.empty() ? prm : c.parameter_file;
  if (c.parameter_directory)
    {
      parameter_file = "scene.prm";
      fs::remove_all(parameter_file);
      fs::create_directory(parameter_file);
    }
  // With a signal to send, the shell is replaced by the run (exec), so
  // that the signal reaches the run itself.
  const std::string command = std::string(c.signal != 0 ? "exec " : "") + CONTACT_FEM_EXECUTABLE +
                              " '" + parameter_file + "' --output-directory results" + c.arguments +
                              " 2>&1";
  int         status = 0;
  std::string text   = run(command, c, status);

  for (std::size_t pos = text.find(directory); pos != std::string::npos; pos = text.find(directory))
    text.replace(pos, directory.size(), "<dir>");
  if (!c.mask.empty())
    text = std::regex_replace(text, std::regex(c.mask), "...");
  const std::string pid = "process " + std::to_string(getpid());
  for (std::size_t pos = text.find(pid); pos != std::string::npos; pos = text.find(pid))
    text.replace(pos, pid.size(), "process <pid>");
  if (c.keep.empty())
    std::cout << text;
  else
    {
      const std::regex   pattern(c.keep);
      std::istringstream lines(text);
      std::string        line;
      while (std::getline(lines, line))
        if (std::regex_search(line, pattern))
          std::cout << line << std::endl;
    }

  for (const auto &listed : c.listed)
    {
      std::set<std::string> names;
      std::error_code       error;
      for (const auto &entry : fs::directory_iterator(listed, error))
        names.insert(entry.path().filename().string());
      std::cout << "files in " << listed << ":";
      for (const auto &name : names)
        std::cout << " " << name;
      std::cout << std::endl;
    }
  for (const auto &[path, pattern] : c.shown)
    {
      std::ifstream in(path);
      std::string   line;
      std::cout << path << ":" << std::endl;
      while (std::getline(in, line))
        if (std::regex_search(line, std::regex(pattern)))
          std::cout << line << std::endl;
    }
  for (const auto &read_only : c.read_only)
    make_writable(read_only);

  const bool exited = WIFEXITED(status);
  const int  code   = exited ? WEXITSTATUS(status) : -1;
  std::cout << "exit status: " << (exited ? (code != 0 ? "non-zero" : "zero") : "crashed")
            << std::endl;
  return (exited && code != 0) ? 0 : 1;
}
