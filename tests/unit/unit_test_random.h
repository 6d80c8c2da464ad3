// Deterministic random numbers for the unit tests: the same sequence on
// every platform.
#ifndef contact_fem_unit_test_random_h
#define contact_fem_unit_test_random_h

#include <cstdint>

/// Numbers in [-1, 1] from a linear congruential generator.
class Random
{
public:
  explicit Random(const std::uint64_t seed)
    : state(seed)
  {}

  double
  next()
  {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return 2. * static_cast<double>(state >> 11) / 9007199254740992. - 1.;
  }

private:
  std::uint64_t state;
};

#endif
