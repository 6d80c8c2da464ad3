#include <deal.II/base/mpi.h>

#include <contact_fem/core/interruption.h>

#include <csignal>
#include <cstring>

namespace contact_fem
{
  namespace
  {
    volatile std::sig_atomic_t signal_received = 0;

    // Async-signal-safe: records the signal, nothing else.
    extern "C" void
    record_signal(int signal)
    {
      signal_received = signal;
    }
  } // namespace

  void
  install_interrupt_handlers()
  {
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_handler = record_signal;
    sigemptyset(&action.sa_mask);
    // The first signal asks the run to stop; a second one kills it.
    action.sa_flags = SA_RESETHAND | SA_RESTART;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
  }

  int
  received_signal(const MPI_Comm comm)
  {
    return dealii::Utilities::MPI::max(static_cast<int>(signal_received), comm);
  }

  Interrupted::Interrupted(const int signal)
    : std::runtime_error(std::string("interrupted by ") + (signal == SIGINT  ? "SIGINT" :
                                                           signal == SIGTERM ? "SIGTERM" :
                                                                               "a signal"))
    , signal(signal)
  {}

  void
  stop_if_interrupted(const MPI_Comm comm)
  {
    if (const int signal = received_signal(comm))
      throw Interrupted(signal);
  }
} // namespace contact_fem
