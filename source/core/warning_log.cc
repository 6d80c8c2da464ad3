#include <contact_fem/core/warning_log.h>

#include <algorithm>
#include <sstream>

namespace contact_fem
{
  bool
  WarningLog::add(const std::string &kind, const unsigned int cycle)
  {
    const auto entry = std::find_if(entries.begin(), entries.end(), [&](const Entry &e) {
      return e.kind == kind;
    });
    if (entry != entries.end())
      {
        // Several warnings of one kind in a cycle (one per body) count once
        // and are all printed in the first cycle that gives the kind.
        if (entry->cycles.back() != cycle)
          entry->cycles.push_back(cycle);
        return entry->cycles.size() == 1;
      }
    entries.push_back({kind, {cycle}});
    return true;
  }

  std::string
  WarningLog::repeats() const
  {
    std::ostringstream text;
    for (const Entry &entry : entries)
      if (entry.cycles.size() > 1)
        {
          text << "Warning '" << entry.kind << "' recurred: given in " << entry.cycles.size()
               << " cycles:";
          for (const unsigned int cycle : entry.cycles)
            text << ' ' << cycle;
          text << " (printed in the first; summary.json cycles[]." << entry.kind
               << " holds each)\n";
        }
    return text.str();
  }

  Json
  WarningLog::to_json() const
  {
    Json all = Json::object();
    for (const Entry &entry : entries)
      {
        Json cycles = Json::array();
        for (const unsigned int cycle : entry.cycles)
          cycles.push(cycle);
        all.set(entry.kind, Json::object()
                              .set("count", static_cast<unsigned int>(entry.cycles.size()))
                              .set("cycles", cycles));
      }
    return all;
  }
} // namespace contact_fem
