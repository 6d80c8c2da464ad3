// Formatting of numbers for console output that tests compare.
#ifndef contact_fem_format_h
#define contact_fem_format_h

#include <deal.II/base/point.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace contact_fem
{
  /**
   * @p value in scientific notation with @p digits decimals, or with one
   * more where it lies within 0.2 % of a unit of the last digit from a
   * rounding tie. Exact binary fractions sit on decimal ties (the ratios of
   * a damped Newton iteration are 2^-k: 2^-6 = 1.5625e-02), and there
   * round-off noise decides the last digit: 1.562e-02 on one machine,
   * 1.563e-02 on another. With the extra digit the value is printed as it
   * is (1.5625e-02), and noise cannot move it. The band is 20 times the
   * noise of the printed residuals (1e-7 of their value at most, 1e-4 of a
   * unit at 4 digits) and catches 1 value in 250 that is not a tie.
   */
  inline std::string
  scientific(const double value, const unsigned int digits = 3)
  {
    // Three guard digits beyond the last printed one.
    std::ostringstream guarded;
    guarded << std::scientific << std::setprecision(digits + 3) << value;
    const std::string text     = guarded.str();
    const auto        exponent = text.find('e');
    // inf and nan have no exponent: printed as they are.
    const int guard =
      exponent != std::string::npos && exponent >= 3 ? std::stoi(text.substr(exponent - 3, 3)) : 0;
    const bool         near_tie = std::abs(guard - 500) <= 2;
    std::ostringstream s;
    s << std::scientific << std::setprecision(digits + (near_tie ? 1 : 0)) << value;
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
      s << scientific(value, 4);
    return s.str();
  }
  /// Where the origin of the computing frame lies in the user's (mesh
  /// file's) coordinates: a mesh far from the origin is computed moved next
  /// to it (ModelFrame). Set once the mesh file is read; the contact room
  /// reports positions of the computing frame, and messages add this to
  /// speak in the user's coordinates.
  inline std::array<double, 3> message_origin{};

  /// "(x, y)" or "(x, y, z)" of a point of the computing frame, in the
  /// user's coordinates, with 8 significant digits, for messages (denormal
  /// coordinates print as 0).
  template <int dim>
  std::string
  coordinates_text(const dealii::Point<dim> &p)
  {
    std::ostringstream text;
    text << std::setprecision(8) << "(";
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double x = p[d] + message_origin[d];
        text << (d > 0 ? ", " : "") << (std::abs(x) < 1e-300 ? 0. : x);
      }
    text << ")";
    return text.str();
  }

  /// @p value with @p digits significant digits (default float format).
  inline std::string
  significant(const double value, const unsigned int digits)
  {
    std::ostringstream s;
    s << std::setprecision(digits) << value;
    return s.str();
  }

  /// A force (a net reaction, a load, a contact force), or "0 (...)" when
  /// it is below 1e-10 of the forces of the scene: displacement-driven
  /// scenes have no net reaction, and the round-off left (1e-15 serial,
  /// 9e-16 on two ranks in kratos_patch_01; any sign) must not be printed
  /// as a number.
  inline std::string
  force_text(const double force, const double force_scale)
  {
    std::ostringstream s;
    if (std::abs(force) < 1e-10 * force_scale)
      s << "0 (< 1e-10 of the forces)";
    else
      s << force;
    return s.str();
  }
} // namespace contact_fem

#endif
