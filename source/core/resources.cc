#include <contact_fem/core/resources.h>

#include <sys/resource.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace contact_fem
{
  namespace
  {
    /// The first number in @p file, or -1 if there is none ("max" in a
    /// cgroup v2 file means no limit).
    double
    number_in_file(const std::string &file)
    {
      std::ifstream in(file);
      double        value = -1.;
      if (!(in >> value))
        return -1.;
      return value;
    }

    /// MemAvailable of /proc/meminfo in bytes, or -1.
    double
    meminfo_available()
    {
      std::ifstream in("/proc/meminfo");
      std::string   key;
      double        kilobytes = 0.;
      std::string   unit;
      while (in >> key >> kilobytes >> unit)
        if (key == "MemAvailable:")
          return 1024. * kilobytes;
      return -1.;
    }

    /// What a cgroup limit still grants in bytes, or -1 if there is none.
    double
    cgroup_available()
    {
      const std::pair<std::string, std::string> files[] = {
        {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory.current"},
        {"/sys/fs/cgroup/memory/memory.limit_in_bytes",
         "/sys/fs/cgroup/memory/memory.usage_in_bytes"}};
      for (const auto &[limit_file, usage_file] : files)
        {
          const double limit = number_in_file(limit_file), usage = number_in_file(usage_file);
          // cgroup v1 writes a huge number for "no limit".
          if (limit > 0. && usage >= 0. && limit < 1e18)
            return limit - usage;
        }
      return -1.;
    }

    /// What RLIMIT_AS (ulimit -v) leaves beside this process' address
    /// space (VmSize of /proc/self/status) in bytes, or -1 without a limit.
    double
    address_space_available()
    {
      rlimit limit;
      if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
        return -1.;
      std::ifstream in("/proc/self/status");
      std::string   line;
      double        used = 0.;
      while (std::getline(in, line))
        if (line.compare(0, 7, "VmSize:") == 0)
          used = 1024. * std::atof(line.c_str() + 7);
      return std::max(1., static_cast<double>(limit.rlim_cur) - used);
    }
  } // namespace

  AvailableMemory
  available_memory()
  {
    AvailableMemory result;
    if (const char *given = std::getenv("CONTACT_FEM_AVAILABLE_MEMORY"))
      {
        result.bytes     = std::atof(given);
        result.source    = "CONTACT_FEM_AVAILABLE_MEMORY";
        result.whole_run = true;
        return result;
      }
    const double meminfo = meminfo_available(), cgroup = cgroup_available();
    if (meminfo > 0.)
      result = {meminfo, "MemAvailable in /proc/meminfo", false};
    if (cgroup >= 0. && (meminfo <= 0. || cgroup < meminfo))
      result = {cgroup, "the memory limit of this process' cgroup", false};
    const double address_space = address_space_available();
    if (address_space >= 0. && (result.bytes <= 0. || address_space < result.bytes))
      result = {address_space,
                "the address-space limit (ulimit -v) beside this process' "
                "address space",
                false};
    return result;
  }

  double
  estimated_memory(const double dofs, const unsigned int processes)
  {
    constexpr double bytes_per_dof = 4e3, bytes_per_process = 2e8;
    return bytes_per_dof * dofs + bytes_per_process * processes;
  }

  std::string
  format_bytes(const double bytes)
  {
    const double       unit  = bytes >= 1e12 ? 1e12 : bytes >= 1e9 ? 1e9 : 1e6;
    const double       value = bytes / unit;
    std::ostringstream text;
    text << std::fixed << std::setprecision(value >= 10. ? 0 : 1) << value
         << (unit == 1e12 ? " TB" :
             unit == 1e9  ? " GB" :
                            " MB");
    return text.str();
  }
} // namespace contact_fem
