#include <contact_fem/postprocess/run_log.h>

#include <iostream>
#include <sstream>

namespace contact_fem
{
  TeeStream::TeeStream(std::ostream &console)
    : std::ostream(&buffer)
  {
    buffer.first = console.rdbuf();
  }

  void
  TeeStream::attach(std::ostream &file)
  {
    flush();
    buffer.second = file.rdbuf();
  }

  bool
  TeeStream::file_failed() const
  {
    return buffer.file_failed;
  }

  // Only the console decides the state of the stream: a log file that
  // fails (a full disk, ...) used to put the whole stream into a failed
  // state, after which nothing more reached the console either. The file is
  // dropped instead and the run says so at its end.
  int
  TeeStream::Buffer::overflow(int c)
  {
    if (c == EOF)
      return !EOF;
    if (second && second->sputc(c) == EOF)
      drop_file();
    return first->sputc(c);
  }

  int
  TeeStream::Buffer::sync()
  {
    if (second && second->pubsync() != 0)
      drop_file();
    return first->pubsync();
  }

  void
  TeeStream::Buffer::drop_file()
  {
    second      = nullptr;
    file_failed = true;
  }

  RunLog::RunLog(const MPI_Comm comm)
    : comm(comm)
    , console(std::cout)
  {}

  OutputDirectoryReport
  RunLog::open(const std::string &output_directory)
  {
    directory                          = output_directory;
    const OutputDirectoryReport report = prepare_output_directory(directory, comm);
    const bool                  root   = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    if (root)
      file.open(directory + "/log.txt");
    // Collective, so that every rank stops if rank 0 could not write.
    throw_if_unwritten(directory + "/log.txt",
                       !root || static_cast<bool>(file) ? "" : "the write failed: a full disk?",
                       comm);
    if (root)
      console.attach(file);
    return report;
  }

  void
  RunLog::report_earlier_outputs(const OutputDirectoryReport &report, const std::string &scene_name)
  {
    if (report.removed == 0 || dealii::Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    std::ostringstream text;
    text << "Output directory '" << directory << "': removed " << report.removed
         << " file(s) of an earlier run";
    if (report.earlier_scene == scene_name)
      {
        console.flush();
        if (file.is_open())
          file << text.str() << " of this scene." << std::endl;
      }
    else
      console << text.str()
              << (report.earlier_scene.empty() ? std::string(" (its scene is unknown)") :
                                                 " of scene '" + report.earlier_scene + "'")
              << "." << std::endl;
  }

  void
  RunLog::note_error(const std::string &message)
  {
    if (dealii::Utilities::MPI::this_mpi_process(comm) != 0 || !file.is_open())
      return;
    console.flush();
    file << "contact_fem: error: " << message << std::endl;
  }
} // namespace contact_fem
