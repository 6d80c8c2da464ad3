// The exception of a load step that cannot be solved.
#ifndef contact_fem_newton_failure_h
#define contact_fem_newton_failure_h

#include <stdexcept>
#include <string>

namespace contact_fem
{
  /// Thrown when a load step cannot be solved; carries the diagnosis.
  struct NewtonFailure : public std::runtime_error
  {
    explicit NewtonFailure(const std::string &what, const bool splittable = true)
      : std::runtime_error(what)
      , splittable(splittable)
    {}
    /// false if a smaller step cannot help (e.g. the bodies separate).
    bool splittable;
  };
} // namespace contact_fem

#endif
