// What the machine offers a run: the memory it may still use, and the
// memory a mesh will need.
#ifndef contact_fem_resources_h
#define contact_fem_resources_h

#include <cstdint>
#include <string>

namespace contact_fem
{
  /// The memory still available to this run, in bytes, and where the figure
  /// comes from (for messages); 0 bytes if unknown.
  struct AvailableMemory
  {
    double      bytes = 0.;
    std::string source;
    /// Whether @p bytes is what the whole run may use (given by
    /// CONTACT_FEM_AVAILABLE_MEMORY), not what is still free beside what it
    /// holds already.
    bool whole_run = false;
  };

  /// The smallest of MemAvailable in /proc/meminfo, what a cgroup (v2:
  /// memory.max - memory.current, v1: memory.limit_in_bytes -
  /// memory.usage_in_bytes) still grants, and what the address-space limit
  /// (ulimit -v, RLIMIT_AS) leaves beside the process' address space
  /// (VmSize): a batch job's limit is often far below the machine's free
  /// memory. The environment variable
  /// CONTACT_FEM_AVAILABLE_MEMORY (bytes) replaces both, for job limits the
  /// program cannot see and for tests that must not depend on the machine.
  AvailableMemory
  available_memory();

  /// Memory of a run with @p dofs degrees of freedom on @p processes MPI
  /// processes, in bytes. Measured with /usr/bin/time -v (maximum resident
  /// set size) on prm/hertz.prm at commit 1d40637 (Release, serial, VTU
  /// written): Q1 with 2.26k / 36k / 144k cells (4.9k / 74k / 292k DoFs)
  /// took 201 / 445 / 1272 MB, Q2 with 2.26k / 9k / 36k cells (19k / 75k /
  /// 294k DoFs) 247 / 439 / 1231 MB: about 3.8 kB (Q1) and 3.7 kB (Q2) per
  /// DoF beyond the 200 MB of a small run (libraries, MPI). The direct
  /// solver's factors grow like n log n, so larger runs need somewhat more
  /// per DoF; the estimate rounds up to 4 kB.
  double
  estimated_memory(const double dofs, const unsigned int processes);

  /// @p bytes as "1.2 GB" (for messages).
  std::string
  format_bytes(const double bytes);
} // namespace contact_fem

#endif
