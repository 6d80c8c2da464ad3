// The warnings of a run, each printed once however often it recurs.
#ifndef contact_fem_warning_log_h
#define contact_fem_warning_log_h

#include <contact_fem/core/json.h>

#include <string>
#include <vector>

namespace contact_fem
{
  /**
   * Counts the warnings of a run by kind (the key under which a cycle's
   * record keeps the text). An adaptive study meets the same condition in
   * every cycle; the console says it the first time and, at the end of the
   * run, how often it recurred, while every cycle's record keeps its own
   * text.
   */
  class WarningLog
  {
  public:
    /// Counts a warning of @p kind given in adaptive cycle @p cycle; true
    /// in the first cycle that gives the kind, when it is to be printed.
    bool
    add(const std::string &kind, const unsigned int cycle);

    /// One line per kind given in more than one cycle: the kind, the count
    /// and the cycles; empty if none recurred.
    std::string
    repeats() const;

    /// Whether no warning was given.
    bool
    empty() const
    {
      return entries.empty();
    }

    /// {kind: {"count": n, "cycles": [...]}} for summary.json.
    Json
    to_json() const;

  private:
    struct Entry
    {
      std::string               kind;
      std::vector<unsigned int> cycles;
    };
    /// In the order first given.
    std::vector<Entry> entries;
  };
} // namespace contact_fem

#endif
