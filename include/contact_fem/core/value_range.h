// The range of input magnitudes that double precision carries through a
// solve.
#ifndef contact_fem_value_range_h
#define contact_fem_value_range_h

namespace contact_fem
{
  /// The largest coordinate, modulus times length^(dim - 1) or load times
  /// length^(dim - 1) the input may hold: norms square forces and overflow
  /// from about 1.3e154, cell volumes cube lengths (1e300 at this bound),
  /// and the penalty (1e4 E / h), the number of DoFs and refinement need
  /// room above it.
  constexpr double largest_input_magnitude = 1e100;
} // namespace contact_fem

#endif
