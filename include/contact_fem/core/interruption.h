// SIGINT and SIGTERM end a run cleanly: the handler only records the
// signal; the load-step and Newton loops ask for it and stop there, so that
// summary.json says "interrupted" instead of "running" for ever.
#ifndef contact_fem_interruption_h
#define contact_fem_interruption_h

#include <deal.II/base/mpi.h>

#include <stdexcept>
#include <string>

namespace contact_fem
{
  /// Installs the handlers of SIGINT and SIGTERM. A second signal of the
  /// same kind ends the process at once (the default action).
  void
  install_interrupt_handlers();

  /// The signal received so far on any rank of @p comm, or 0. Collective.
  int
  received_signal(const MPI_Comm comm);

  /// Thrown where a run notices a signal; exit code 128 + signal.
  struct Interrupted : public std::runtime_error
  {
    explicit Interrupted(const int signal);
    int signal;
  };

  /// Throws Interrupted if any rank of @p comm received a signal. Collective.
  void
  stop_if_interrupted(const MPI_Comm comm);
} // namespace contact_fem

#endif
