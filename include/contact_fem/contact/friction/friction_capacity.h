// The diagnosis of an iterate in which every active contact node slips:
// friction then holds the bodies tangentially nowhere.
#ifndef contact_fem_friction_capacity_h
#define contact_fem_friction_capacity_h

#include <string>
#include <vector>

namespace contact_fem
{
  /// The cause of such an iterate as the tail of a failure message:
  /// bodies @p free_bodies (held by no support), or else the translations
  /// @p free_translations of supported bodies that neither a support nor
  /// the contact's normal holds ("body 2 along (1, 0, 0)",
  /// ContactDiagnosis::friction_held_translations()), can only slide,
  /// since the load exceeds the friction capacity or, after a change of
  /// the load direction, the iterate overshot. Both empty: a singular
  /// system says that nothing holds the bodies.
  std::string
  exceeded_friction_capacity(const std::vector<unsigned int> &free_bodies,
                             const std::string               &free_translations = "");
} // namespace contact_fem

#endif
