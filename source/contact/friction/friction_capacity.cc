#include <contact_fem/contact/friction/friction_capacity.h>

namespace contact_fem
{
  std::string
  exceeded_friction_capacity(const std::vector<unsigned int> &free_bodies,
                             const std::string               &free_translations)
  {
    std::string held = "nothing holds the bodies tangentially";
    if (free_bodies.empty() && !free_translations.empty())
      held = "friction at its bound is all that holds " + free_translations +
             " (the supports leave that translation free, and it is tangential to the "
             "contact)";
    if (!free_bodies.empty())
      {
        std::string ids;
        for (const unsigned int id : free_bodies)
          ids += (ids.empty() ? "" : ", ") + std::to_string(id);
        held = "friction at its bound is all that holds " +
               std::string(free_bodies.size() == 1 ? "body " : "bodies ") + ids +
               " tangentially (no support does)";
      }
    return "every active contact node slips (none sticks), so " + held +
           ": the tangential load exceeds the friction capacity of the contact (mu times "
           "the normal force under Coulomb, the bound times the contact length under "
           "Tresca) and no equilibrium exists, or, after a change of the load direction, "
           "the iterate overshot (then a smaller step sticks: the step is split). A load "
           "beyond the capacity needs a support or a prescribed displacement.";
  }
} // namespace contact_fem
