// available_memory() under an address-space limit (ulimit -v, issue 26): a
// batch job's limit is often far below the machine's free memory, and an
// adaptive loop must stop before it. The test limits its own address space
// to its current size (VmSize) plus 300 MB: what is left must be reported
// as about 300 MB, from the limit (the machine, cgroup and CPU do not
// matter as long as they grant more than that). CONTACT_FEM_AVAILABLE_MEMORY
// replaces every other source.

#include <contact_fem/core/resources.h>

#include <sys/resource.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

using namespace contact_fem;

namespace
{
  double
  address_space_size()
  {
    std::ifstream in("/proc/self/status");
    std::string   line;
    while (std::getline(in, line))
      if (line.compare(0, 7, "VmSize:") == 0)
        return 1024. * std::atof(line.c_str() + 7);
    return 0.;
  }
} // namespace

int
main()
{
  unsetenv("CONTACT_FEM_AVAILABLE_MEMORY");
  constexpr double headroom = 3e8;
  rlimit           limit;
  getrlimit(RLIMIT_AS, &limit);
  limit.rlim_cur = static_cast<rlim_t>(address_space_size() + headroom);
  if (setrlimit(RLIMIT_AS, &limit) != 0)
    {
      std::cout << "setrlimit failed" << std::endl;
      return 1;
    }
  const AvailableMemory limited = available_memory();
  std::cout << "source: " << limited.source << std::endl
            << "about the 300 MB left (250 to 300 MB): "
            << (limited.bytes > 2.5e8 && limited.bytes <= headroom ? "yes" : "no") << std::endl
            << "whole run: " << (limited.whole_run ? "yes" : "no") << std::endl;

  setenv("CONTACT_FEM_AVAILABLE_MEMORY", "2.5e8", 1);
  const AvailableMemory given = available_memory();
  std::cout << "source: " << given.source << ", " << format_bytes(given.bytes)
            << ", whole run: " << (given.whole_run ? "yes" : "no") << std::endl;
}
