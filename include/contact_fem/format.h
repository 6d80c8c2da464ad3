// Formatting of numbers for console output that tests compare.
#ifndef contact_fem_format_h
#define contact_fem_format_h

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace contact_fem
{
  /// @p x in scientific notation with @p digits after the point.
  inline std::string
  scientific(const double x, const unsigned int digits = 3)
  {
    std::ostringstream s;
    s << std::scientific << std::setprecision(digits) << x;
    return s.str();
  }

  /// The value, or "ok (< tol)" when its magnitude is below the tolerance:
  /// round-off must not reach test output (numdiff compares digits).
  inline std::string
  value_or_ok(const double value, const double tolerance)
  {
    std::ostringstream s;
    if (std::abs(value) < tolerance)
      s << "ok (< " << tolerance << ")";
    else
      s << std::setprecision(4) << std::scientific << value;
    return s.str();
  }
} // namespace contact_fem

#endif
