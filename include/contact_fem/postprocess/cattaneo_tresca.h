// The closed forms of the Cattaneo problem (two cylinders, Hertz contact
// half-width a, equal materials) under Tresca friction: a slip bound g
// independent of the pressure.
#ifndef contact_fem_cattaneo_tresca_h
#define contact_fem_cattaneo_tresca_h

namespace contact_fem
{
  /// The stick half-width under a monotone tangential load Q: the slip
  /// zones c < |x| < a carry g, the stick zone the traction below, whose
  /// resultant makes Q = 2 g sqrt(a^2 - c^2), so
  /// c = a sqrt(1 - (Q / (2 a g))^2); 0 from the capacity 2 a g on.
  double
  tresca_stick_half_width(const double a, const double Q, const double g);

  /// The tangential traction at @p x of a monotone load whose stick zone
  /// is |x| < @p c: g in the slip zones, and in the stick zone
  /// q = (2 g / pi) atan(sqrt((a^2 - c^2) / (c^2 - x^2))), the bounded
  /// solution of the stick condition (no relative tangential strain in
  /// |x| < c, the half-space's finite Hilbert transform); 0 outside.
  double
  tresca_traction(const double x, const double a, const double c, const double g);
} // namespace contact_fem

#endif
