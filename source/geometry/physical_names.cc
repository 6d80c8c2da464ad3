#include <deal.II/base/utilities.h>

#include <contact_fem/geometry/physical_names.h>

#include <algorithm>
#include <cctype>

namespace contact_fem
{
  namespace
  {
    bool
    is_number(const std::string &word)
    {
      return !word.empty() && std::all_of(word.begin(), word.end(), [](const unsigned char c) {
        return std::isdigit(c) != 0;
      });
    }

    std::string
    listed(const std::map<std::string, unsigned int> &names)
    {
      std::string text;
      for (const auto &[name, id] : names)
        text += (text.empty() ? "" : ", ") + name + " (" + std::to_string(id) + ")";
      return text.empty() ? "none" : text;
    }
  } // namespace

  PhysicalNames::PhysicalNames(const std::vector<PhysicalName> &names,
                               const unsigned int               dim,
                               const std::string               &file)
    : file(file)
  {
    for (const auto &n : names)
      if (n.dimension == static_cast<int>(dim) || n.dimension + 1 == static_cast<int>(dim))
        {
          auto &ids = n.dimension == static_cast<int>(dim) ? body_ids : surface_ids;
          // The input takes a number as an id: a name '4' of the tag 3 would
          // silently stand for the tag 4 (a pair '3: 4' reversed).
          AssertThrow(!is_number(n.name) || n.name == std::to_string(n.tag),
                      ExcMessage("Geometry/Mesh file: '" + file + "' gives the physical name '" +
                                 n.name + "' to the tag " + std::to_string(n.tag) + " of " +
                                 (n.dimension == static_cast<int>(dim) ? "cells" : "faces") +
                                 ": the input reads a number as an id, so '" + n.name +
                                 "' would stand for the tag " + n.name +
                                 ", not this one; give it a name that is not a number."));
          const auto [entry, inserted] = ids.emplace(n.name, n.tag);
          AssertThrow(inserted || entry->second == static_cast<unsigned int>(n.tag),
                      ExcMessage("Geometry/Mesh file: '" + file + "' gives the physical name '" +
                                 n.name + "' to the tags " + std::to_string(entry->second) +
                                 " and " + std::to_string(n.tag) + " of " +
                                 (n.dimension == static_cast<int>(dim) ? "cells" : "faces") +
                                 "; a name must stand for one id."));
        }
  }

  std::string
  PhysicalNames::id_of(const std::string &word, const std::string &key, const bool bodies) const
  {
    if (word.empty() || is_number(word))
      return word;
    const auto &ids   = bodies ? body_ids : surface_ids;
    const auto  found = ids.find(word);
    // "5, 6" where the key separates ids by ';': say so, not "no such name".
    bool listed_numbers = word.find(',') != std::string::npos;
    for (const std::string &part : Utilities::split_string_list(word, ','))
      listed_numbers = listed_numbers && is_number(part);
    AssertThrow(
      found != ids.end(),
      ExcMessage(key + ": '" + word + "' is neither a " + (bodies ? "material id" : "boundary id") +
                 " nor a physical name of the " + (bodies ? "bodies (cells)" : "surfaces (faces)") +
                 " of the mesh file '" + file + "' (its names: " + listed(ids) + ")" +
                 (listed_numbers ? "; ids are separated by ';' here, e.g. '" +
                                     Utilities::split_string_list(word, ',')[0] + "; " +
                                     Utilities::split_string_list(word, ',')[1] + "'." :
                                   ".")));
    return std::to_string(found->second);
  }

  std::string
  PhysicalNames::replace_ids(const std::string &text,
                             const std::string &key,
                             const bool         bodies,
                             const char         separator,
                             const bool         both_sides) const
  {
    std::string result;
    for (const std::string &entry : Utilities::split_string_list(text, ';'))
      {
        const auto at = entry.find(separator);
        if (at == std::string::npos)
          {
            result += (result.empty() ? "" : "; ") + entry;
            continue;
          }
        const std::string rest = entry.substr(at + 1);
        const std::string fixed =
          id_of(Utilities::trim(entry.substr(0, at)), key, bodies) +
          (separator == '@' ? " @" : ":") +
          (both_sides ? " " + id_of(Utilities::trim(rest), key, bodies) : rest);
        result += (result.empty() ? "" : "; ") + fixed;
      }
    return result;
  }

  void
  PhysicalNames::substitute(ParameterHandler &prm) const
  {
    // Also without names: a word in an id's place then says that the file
    // has none.
    const auto replace = [&](const std::string &section, const std::string &name, const bool bodies,
                             const char separator, const bool both_sides) {
      prm.enter_subsection(section);
      const std::string text = prm.get(name);
      if (!Utilities::trim(text).empty())
        prm.set(name, replace_ids(text, section + "/" + name, bodies, separator, both_sides));
      prm.leave_subsection();
    };
    for (const std::string name : {"Fixed", "Prescribed displacement", "Pressure", "Traction"})
      replace("Boundary conditions", name, false, ':', false);
    replace("Boundary conditions", "Fixed points", true, '@', false);
    // Lists of bare ids: each word replaced.
    const auto replace_list = [&](const std::string &section, const std::string &name,
                                  const bool bodies, const char separator) {
      prm.enter_subsection(section);
      std::string ids;
      for (const std::string &word : Utilities::split_string_list(prm.get(name), separator))
        ids += (ids.empty() ? "" : std::string(1, separator) + " ") +
               id_of(word, section + "/" + name, bodies);
      prm.set(name, ids);
      prm.leave_subsection();
    };
    replace_list("Boundary conditions", "Rollers", false, ';');
    replace("Output", "Displacement probes", true, '@', false);
    replace("Contact", "Pairs", false, ':', true);
    replace("Contact", "Tied pairs", false, ':', true);
    replace("Geometry", "Manifolds", false, ':', false);
    replace_list("Materials", "Material ids", true, ',');
  }
} // namespace contact_fem
