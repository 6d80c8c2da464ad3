// Gmsh physical names standing for material and boundary ids in the input.
#ifndef contact_fem_physical_names_h
#define contact_fem_physical_names_h

#include <deal.II/base/parameter_handler.h>

#include <contact_fem/geometry/mesh_file.h>

#include <map>
#include <string>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /**
   * The physical names of a mesh file: those of its cells (dimension dim)
   * name bodies (material ids), those of its faces (dimension dim - 1)
   * name surfaces (boundary ids). Wherever the input takes an id it may
   * take the name instead: substitute() replaces the names by their ids in
   * the keys, before they are parsed.
   */
  class PhysicalNames
  {
  public:
    PhysicalNames() = default;
    PhysicalNames(const std::vector<PhysicalName> &names,
                  const unsigned int               dim,
                  const std::string               &file);

    /// Replaces the names in the keys that take ids: Boundary
    /// conditions/Fixed, Prescribed displacement, Pressure, Traction (the
    /// boundary before ':'), Fixed points and Output/Displacement probes
    /// (the body before '@'), Contact/Pairs (both sides of ':'),
    /// Materials/Material ids (each entry) and Geometry/Manifolds. A word in
    /// an id's place that is neither a number nor a name of the right kind
    /// is refused, naming the key and the names the file has.
    void
    substitute(ParameterHandler &prm) const;

  private:
    /// @p text ('entry; entry; ...') with the id before @p separator in
    /// each entry replaced, and with @p both_sides also the one after it.
    std::string
    replace_ids(const std::string &text,
                const std::string &key,
                const bool         bodies,
                const char         separator,
                const bool         both_sides) const;

    std::string
    id_of(const std::string &word, const std::string &key, const bool bodies) const;

    std::string                         file;
    std::map<std::string, unsigned int> body_ids, surface_ids;
  };
} // namespace contact_fem

#endif
