// The diagnosis of an iterate in which every active contact node slips:
// friction then holds the bodies tangentially nowhere.
#ifndef contact_fem_friction_capacity_h
#define contact_fem_friction_capacity_h

#include <string>
#include <vector>

namespace contact_fem
{
  /// The cause of such an iterate as the tail of a failure message:
  /// bodies @p free_bodies (held by no support; empty: a singular system
  /// says that nothing holds them) can only slide, since the load exceeds
  /// the friction capacity or, after a change of the load direction, the
  /// iterate overshot.
  std::string
  exceeded_friction_capacity(const std::vector<unsigned int> &free_bodies);
} // namespace contact_fem

#endif
