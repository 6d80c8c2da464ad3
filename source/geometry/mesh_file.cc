#include <deal.II/base/bounding_box.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/numerics/rtree.h>

#include <contact_fem/geometry/hexahedron_shape.h>
#include <contact_fem/core/value_range.h>
#include <contact_fem/geometry/mesh_file.h>
#include <contact_fem/geometry/mesh_queries.h>
#include <contact_fem/geometry/mesh_split.h>
#include <contact_fem/geometry/model_frame.h>
#include <contact_fem/core/format.h>
#include <contact_fem/core/parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

namespace contact_fem
{
  namespace
  {
    const std::string mesh_key = "Geometry/Mesh file";

    /// The Gmsh element types that meshes of contact_fem's kind may hold,
    /// and the common ones it refuses (for a message naming them).
    struct ElementType
    {
      int          gmsh_type;
      unsigned int dim;
      unsigned int n_nodes;
      const char  *singular;
      const char  *plural;
      bool         simplex;
      bool         first_order;
    };

    const ElementType element_types[] = {
      {15, 0, 1, "point", "points", false, true},
      {1, 1, 2, "line", "lines", false, true},
      {2, 2, 3, "triangle", "triangles", true, true},
      {3, 2, 4, "quadrilateral", "quadrilaterals", false, true},
      {4, 3, 4, "tetrahedron", "tetrahedra", true, true},
      {5, 3, 8, "hexahedron", "hexahedra", false, true},
      {6, 3, 6, "prism", "prisms", true, true},
      {7, 3, 5, "pyramid", "pyramids", true, true},
      {8, 1, 3, "3-node line", "3-node lines", false, false},
      {9, 2, 6, "6-node triangle", "6-node triangles", true, false},
      {10, 2, 9, "9-node quadrilateral", "9-node quadrilaterals", false, false},
      {11, 3, 10, "10-node tetrahedron", "10-node tetrahedra", true, false},
      {12, 3, 27, "27-node hexahedron", "27-node hexahedra", false, false},
      {13, 3, 18, "18-node prism", "18-node prisms", true, false},
      {14, 3, 14, "14-node pyramid", "14-node pyramids", true, false},
      {16, 2, 8, "8-node quadrilateral", "8-node quadrilaterals", false, false},
      {17, 3, 20, "20-node hexahedron", "20-node hexahedra", false, false},
      {18, 3, 15, "15-node prism", "15-node prisms", true, false},
      {19, 3, 13, "13-node pyramid", "13-node pyramids", true, false}};

    const ElementType *
    find_element_type(const int gmsh_type)
    {
      for (const auto &type : element_types)
        if (type.gmsh_type == gmsh_type)
          return &type;
      return nullptr;
    }

    constexpr int gmsh_line = 1, gmsh_quadrilateral = 3, gmsh_hexahedron = 5;

    /// A hexahedron of the file, for the check of its shape.
    struct GmshHexahedron
    {
      long                tag;
      unsigned int        line;
      std::array<long, 8> nodes;
    };

    /// A quadrilateral of the file, for the check of its shape (2D).
    struct GmshQuadrilateral
    {
      long                tag;
      unsigned int        line;
      std::array<long, 4> nodes;
    };

    /// What the scan found in the file.
    struct Contents
    {
      std::map<int, std::size_t> elements; ///< Gmsh type -> count
      std::size_t                n_nodes    = 0;
      bool                       have_nodes = false, have_elements = false;
      double                     z_min = std::numeric_limits<double>::max(), z_max = -z_min;
      double                     extent = 0.; ///< largest |x|, |y| or |z| of a node
      /// Kept only when asked for (3D): deal.II's reader reorders inverted
      /// cells and forgets element numbers and lines, so the hexahedra are
      /// checked here, where a message can name them.
      bool keep_hexahedra = false;
      /// Every node, for the check that elements name listed nodes only.
      std::unordered_map<long, Point<3>> node_coordinates;
      std::vector<GmshHexahedron>        hexahedra;
      std::vector<GmshQuadrilateral>     quadrilaterals;
      /// The lines holding node coordinates, with the position of x among
      /// their numbers: a mesh far from the origin is handed to deal.II
      /// with these rewritten (read_gmsh()).
      std::vector<std::pair<unsigned int, unsigned int>> node_lines;
      /// $PhysicalNames: (dimension, tag, name).
      std::vector<PhysicalName> physical_names;
      /// Every element with its physical tag, for the split of meshes with
      /// triangles, tetrahedra or prisms (mesh_split.h); kept only when
      /// asked for (a second scan: a large hexahedral mesh is not held
      /// twice).
      bool                     keep_elements = false;
      std::vector<GmshElement> element_list;
      /// "element 12, line 40": the first pyramid, for its message.
      std::string first_pyramid;
      /// MSH 4.x $Entities: the physical tag of (dimension, entity tag).
      std::map<std::pair<int, int>, int> entity_physical;
      /// The boundary elements with a physical tag (lines in 2D,
      /// quadrilaterals in 3D: the cells' facets) and the nodes of the
      /// cells, for the boundary elements on nodes of their own (below).
      std::vector<GmshElement> tagged_facets;
      std::unordered_set<long> cell_nodes;
      Point<3>                 lower = Point<3>(std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::max());
      Point<3>                 upper = -lower;
    };

    /// Reads a text file line by line and knows the line number, so that
    /// every message can name it.
    class LineReader
    {
    public:
      explicit LineReader(const std::string &file)
        : file(file)
        , in(file)
      {}

      /// The next line without its line ending; false at the end of the file.
      bool
      next(std::string &line)
      {
        if (!std::getline(in, line))
          return false;
        ++line_number;
        if (!line.empty() && line.back() == '\r')
          line.pop_back();
        return true;
      }

      /// The next line, which must exist: the file is cut short otherwise.
      std::string
      require(const std::string &section, const std::string &progress)
      {
        std::string line;
        if (!next(line))
          fail_file("ends at line " + std::to_string(line_number) + " inside " + section +
                    progress + ": the file is truncated (an interrupted write or copy?).");
        return line;
      }

      /// The numbers of the next line; at least @p n_min of them.
      std::vector<double>
      numbers(const std::string &section,
              const std::string &progress,
              const std::string &form,
              const std::size_t  n_min)
      {
        const std::string   line = require(section, progress);
        std::istringstream  text(line);
        std::vector<double> values;
        double              v;
        while (text >> v)
          values.push_back(v);
        if (values.size() < n_min || !(text.eof() || Utilities::trim(line).empty()))
          fail("expected " + form + " in " + section + ", found '" + Utilities::trim(line) + "'" +
               (values.size() < n_min ? " (a line cut short: truncated file?)." : "."));
        return values;
      }

      /// The next line must be @p marker.
      void
      expect(const std::string &marker, const std::string &section)
      {
        const std::string line = Utilities::trim(require(section, ""));
        if (line != marker)
          fail("expected " + marker + ", found '" + line + "' (" + section +
               " holds more entries than its count announces?).");
      }

      [[noreturn]] void
      fail(const std::string &what) const
      {
        AssertThrow(false, ExcMessage(mesh_key + ": '" + file + "', line " +
                                      std::to_string(line_number) + ": " + what));
        std::abort();
      }

      [[noreturn]] void
      fail_file(const std::string &what) const
      {
        AssertThrow(false, ExcMessage(mesh_key + ": '" + file + "' " + what));
        std::abort();
      }

      const std::string file;
      unsigned int      line_number = 0;

    private:
      std::ifstream in;
    };

    std::string
    short_number(const double value)
    {
      std::ostringstream text;
      text << value;
      return text.str();
    }

    std::string
    count_of(const std::size_t i, const std::size_t n, const std::string &what)
    {
      return " (after " + std::to_string(i) + " of " + std::to_string(n) + " " + what + ")";
    }

    void
    record_node(LineReader                &reader,
                const long                 tag,
                const std::vector<double> &xyz,
                const unsigned int         x_column,
                Contents                  &contents)
    {
      for (const double x : xyz)
        if (!(std::abs(x) <= largest_input_magnitude))
          reader.fail("node " + std::to_string(tag) + " has the coordinate " + short_number(x) +
                      "; expected coordinates of magnitude at most " +
                      short_number(largest_input_magnitude) +
                      ": lengths multiply into areas, volumes and forces that overflow "
                      "double precision (1.8e308) beyond it. Scale the mesh (Gmsh: "
                      "Mesh.ScalingFactor).");
      contents.node_coordinates[tag] = Point<3>(xyz[0], xyz[1], xyz[2]);
      contents.node_lines.emplace_back(reader.line_number, x_column);
      for (unsigned int d = 0; d < 3; ++d)
        {
          contents.lower[d] = std::min(contents.lower[d], xyz[d]);
          contents.upper[d] = std::max(contents.upper[d], xyz[d]);
        }
      contents.z_min = std::min(contents.z_min, xyz[2]);
      contents.z_max = std::max(contents.z_max, xyz[2]);
      for (unsigned int d = 0; d < 3; ++d)
        contents.extent = std::max(contents.extent, std::abs(xyz[d]));
      ++contents.n_nodes;
    }

    /// $Nodes of MSH 1 ($NOD) and 2.x: a count, then 'tag x y z' lines.
    void
    scan_nodes_v2(LineReader &reader, const std::string &section, Contents &contents)
    {
      const auto n =
        static_cast<std::size_t>(reader.numbers(section, "", "the number of nodes", 1)[0]);
      for (std::size_t i = 0; i < n; ++i)
        {
          const auto v = reader.numbers(section, count_of(i, n, "nodes"), "'tag x y z'", 4);
          record_node(reader, static_cast<long>(v[0]), {v[1], v[2], v[3]}, 1, contents);
        }
      reader.expect(section == "$NOD" ? "$ENDNOD" : "$EndNodes", section);
    }

    /// $Nodes of MSH 4.x: entity blocks. 4.1 lists a block's tags, then its
    /// coordinates; 4.0 one 'tag x y z' line per node.
    void
    scan_nodes_v4(LineReader &reader, const double version, Contents &contents)
    {
      const std::string section  = "$Nodes";
      const auto        header   = reader.numbers(section, "", "'blocks nodes ...'", 2);
      const auto        n_blocks = static_cast<std::size_t>(header[0]);
      const auto        n_nodes  = static_cast<std::size_t>(header[1]);
      std::size_t       seen     = 0;
      for (std::size_t b = 0; b < n_blocks; ++b)
        {
          const auto block =
            reader.numbers(section, count_of(seen, n_nodes, "nodes"), "an entity block header", 4);
          const auto        n = static_cast<std::size_t>(block[3]);
          std::vector<long> tags;
          if (version >= 4.1)
            for (std::size_t i = 0; i < n; ++i)
              tags.push_back(static_cast<long>(
                reader.numbers(section, count_of(seen, n_nodes, "nodes"), "a node tag", 1)[0]));
          for (std::size_t i = 0; i < n; ++i, ++seen)
            {
              const auto v =
                reader.numbers(section, count_of(seen, n_nodes, "nodes"),
                               version >= 4.1 ? "'x y z'" : "'tag x y z'", version >= 4.1 ? 3 : 4);
              const std::size_t o = version >= 4.1 ? 0 : 1;
              record_node(reader, version >= 4.1 ? tags[i] : static_cast<long>(v[0]),
                          {v[o], v[o + 1], v[o + 2]}, o, contents);
            }
        }
      if (seen != n_nodes)
        reader.fail("$Nodes announces " + std::to_string(n_nodes) + " nodes, its blocks hold " +
                    std::to_string(seen) + ".");
      reader.expect("$EndNodes", section);
    }

    /// The number of numbers an element line of @p type must have after
    /// @p before leading ones; 0 if the type is unknown (not checked).
    std::size_t
    element_line_length(const int type, const std::size_t before)
    {
      const ElementType *t = find_element_type(type);
      return t ? before + t->n_nodes : 0;
    }

    /// Keeps the hexahedron of the element line @p v whose eight nodes
    /// start at @p first_node.
    void
    record_hexahedron(const std::vector<double> &v,
                      const std::size_t          first_node,
                      const unsigned int         line,
                      Contents                  &contents)
    {
      if (!contents.keep_hexahedra)
        return;
      GmshHexahedron hexahedron{static_cast<long>(v[0]), line, {}};
      for (unsigned int i = 0; i < 8; ++i)
        hexahedron.nodes[i] = static_cast<long>(v[first_node + i]);
      contents.hexahedra.push_back(hexahedron);
    }

    /// Keeps the quadrilateral of the element line @p v whose four nodes
    /// start at @p first_node.
    void
    record_quadrilateral(const std::vector<double> &v,
                         const std::size_t          first_node,
                         const unsigned int         line,
                         Contents                  &contents)
    {
      GmshQuadrilateral quadrilateral{static_cast<long>(v[0]), line, {}};
      for (unsigned int i = 0; i < 4; ++i)
        quadrilateral.nodes[i] = static_cast<long>(v[first_node + i]);
      contents.quadrilaterals.push_back(quadrilateral);
    }

    /// Keeps the element of line @p v (nodes from @p first_node on) with
    /// its physical tag, for the split (mesh_split.h).
    void
    record_element(const std::vector<double> &v,
                   const int                  type,
                   const std::size_t          first_node,
                   const int                  physical,
                   const unsigned int         line,
                   Contents                  &contents)
    {
      const ElementType *t = find_element_type(type);
      // keep_hexahedra: the scan of a 3D mesh, whose facets are
      // quadrilaterals (2D: lines).
      const unsigned int cell_dim = contents.keep_hexahedra ? 3 : 2;
      if (t != nullptr && t->dim == cell_dim)
        for (unsigned int i = 0; i < t->n_nodes; ++i)
          contents.cell_nodes.insert(static_cast<long>(v[first_node + i]));
      if (t != nullptr && physical > 0 &&
          type == (contents.keep_hexahedra ? gmsh_quadrilateral : gmsh_line))
        {
          GmshElement facet{type, static_cast<long>(v[0]), line, physical, {}};
          for (unsigned int i = 0; i < t->n_nodes; ++i)
            facet.nodes.push_back(static_cast<long>(v[first_node + i]));
          contents.tagged_facets.push_back(std::move(facet));
        }
      if (t != nullptr && t->dim == 3 && t->n_nodes == 5 && contents.first_pyramid.empty())
        contents.first_pyramid = "the first: element " + std::to_string(static_cast<long>(v[0])) +
                                 ", line " + std::to_string(line);
      if (t == nullptr || !contents.keep_elements)
        return;
      GmshElement element{type, static_cast<long>(v[0]), line, physical, {}};
      for (unsigned int i = 0; i < t->n_nodes; ++i)
        element.nodes.push_back(static_cast<long>(v[first_node + i]));
      contents.element_list.push_back(std::move(element));
    }

    /// Refuses an element of line @p v (nodes from @p first_node on) that
    /// names a node $Nodes does not list (deal.II's reader says only
    /// "vertex not found").
    void
    check_nodes_listed(const std::vector<double> &v,
                       const std::size_t          first_node,
                       const LineReader          &reader,
                       const Contents            &contents)
    {
      if (!contents.have_nodes)
        return;
      for (std::size_t i = first_node; i < v.size(); ++i)
        if (contents.node_coordinates.count(static_cast<long>(v[i])) == 0)
          reader.fail("element " + std::to_string(static_cast<long>(v[0])) + " uses node " +
                      std::to_string(static_cast<long>(v[i])) + ", which $Nodes does not list.");
    }

    /// $Elements (2.x: 'tag type n_tags tags... nodes...') or $ELM (1:
    /// 'tag type physical elementary n_nodes nodes...').
    void
    scan_elements_v2(LineReader &reader, const std::string &section, Contents &contents)
    {
      const auto n =
        static_cast<std::size_t>(reader.numbers(section, "", "the number of elements", 1)[0]);
      for (std::size_t i = 0; i < n; ++i)
        {
          const auto v = reader.numbers(section, count_of(i, n, "elements"), "an element line", 3);
          const int  type          = static_cast<int>(v[1]);
          const std::size_t before = section == "$ELM" ? 5 : 3 + static_cast<std::size_t>(v[2]);
          const std::size_t length = element_line_length(type, before);
          if (v.size() < length)
            reader.fail("element " + std::to_string(static_cast<long>(v[0])) + " has " +
                        std::to_string(v.size()) + " numbers, expected " + std::to_string(length) +
                        " (a line cut short: truncated file?).");
          if (length > 0)
            check_nodes_listed(v, before, reader, contents);
          if (type == gmsh_hexahedron)
            record_hexahedron(v, length - 8, reader.line_number, contents);
          if (type == gmsh_quadrilateral)
            record_quadrilateral(v, length - 4, reader.line_number, contents);
          // MSH 1: 'tag type physical ...'; 2.x: the first tag is the physical one.
          const int physical = static_cast<int>(section == "$ELM" ? v[2] : v[2] > 0 ? v[3] : 0);
          record_element(v, type, before, physical, reader.line_number, contents);
          ++contents.elements[type];
        }
      reader.expect(section == "$ELM" ? "$ENDELM" : "$EndElements", section);
    }

    /// $Elements of MSH 4.x: entity blocks 'dim tag type count' (4.0: 'tag
    /// dim type count'), then 'tag nodes...' lines.
    void
    scan_elements_v4(LineReader &reader, const double version, Contents &contents)
    {
      const std::string section    = "$Elements";
      const auto        header     = reader.numbers(section, "", "'blocks elements ...'", 2);
      const auto        n_blocks   = static_cast<std::size_t>(header[0]);
      const auto        n_elements = static_cast<std::size_t>(header[1]);
      std::size_t       seen       = 0;
      for (std::size_t b = 0; b < n_blocks; ++b)
        {
          const auto block = reader.numbers(section, count_of(seen, n_elements, "elements"),
                                            "an entity block header", 4);
          const int  type  = static_cast<int>(block[2]);
          const auto n     = static_cast<std::size_t>(block[3]);
          // 4.1: 'dim tag type count'; 4.0: 'tag dim type count'.
          const auto entity   = version >= 4.1 ? std::make_pair(int(block[0]), int(block[1])) :
                                                 std::make_pair(int(block[1]), int(block[0]));
          const auto found    = contents.entity_physical.find(entity);
          const int  physical = found == contents.entity_physical.end() ? 0 : found->second;
          for (std::size_t i = 0; i < n; ++i, ++seen)
            {
              const auto v = reader.numbers(section, count_of(seen, n_elements, "elements"),
                                            "an element line", 2);
              if (v.size() < element_line_length(type, 1))
                reader.fail("element " + std::to_string(static_cast<long>(v[0])) +
                            " is cut short (truncated file?).");
              if (element_line_length(type, 1) > 0)
                check_nodes_listed(v, 1, reader, contents);
              if (type == gmsh_hexahedron)
                record_hexahedron(v, 1, reader.line_number, contents);
              if (type == gmsh_quadrilateral)
                record_quadrilateral(v, 1, reader.line_number, contents);
              record_element(v, type, 1, physical, reader.line_number, contents);
            }
          contents.elements[type] += n;
        }
      if (seen != n_elements)
        reader.fail("$Elements announces " + std::to_string(n_elements) +
                    " elements, its blocks hold " + std::to_string(seen) + ".");
      reader.expect("$EndElements", section);
    }

    /// Skips a section this program does not need, up to its end marker.
    void
    skip_section(LineReader &reader, const std::string &section)
    {
      const std::string end = "$End" + section.substr(1);
      std::string       line;
      while (Utilities::trim(line = reader.require(section, "")) != end)
        if (!line.empty() && line[0] == '$')
          reader.fail("expected " + end + ", found '" + Utilities::trim(line) + "'.");
    }

    /// $Entities of MSH 4.x: the physical tag of each point, curve,
    /// surface and volume (one line each; the count of physical tags
    /// follows the bounding box, or a point's coordinates in 4.1).
    void
    scan_entities(LineReader &reader, const double version, Contents &contents)
    {
      const std::string section = "$Entities";
      const auto        n = reader.numbers(section, "", "'points curves surfaces volumes'", 4);
      for (int dim = 0; dim < 4; ++dim)
        for (std::size_t i = 0; i < static_cast<std::size_t>(n[dim]); ++i)
          {
            const std::size_t at         = dim == 0 && version >= 4.1 ? 4 : 7;
            const auto        v          = reader.numbers(section, "", "an entity line", at + 1);
            const auto        n_physical = static_cast<std::size_t>(v[at]);
            if (n_physical > 1)
              reader.fail("the " +
                          std::string(dim == 0 ? "point" :
                                      dim == 1 ? "curve" :
                                      dim == 2 ? "surface" :
                                                 "volume") +
                          " " + std::to_string(static_cast<long>(v[0])) + " belongs to " +
                          std::to_string(n_physical) +
                          " physical groups; contact_fem takes "
                          "one boundary or material id per entity: put it into one "
                          "physical group only.");
            if (v.size() < at + 1 + n_physical)
              reader.fail("an entity line is cut short (truncated file?).");
            contents.entity_physical[{dim, static_cast<int>(v[0])}] =
              n_physical == 1 ? static_cast<int>(v[at + 1]) : 0;
          }
      reader.expect("$EndEntities", section);
    }

    /// $PhysicalNames: a count, then 'dimension tag "name"' lines.
    void
    scan_physical_names(LineReader &reader, Contents &contents)
    {
      const std::string section = "$PhysicalNames";
      const auto        n =
        static_cast<std::size_t>(reader.numbers(section, "", "the number of names", 1)[0]);
      for (std::size_t i = 0; i < n; ++i)
        {
          const std::string  line  = reader.require(section, count_of(i, n, "names"));
          const auto         open  = line.find('"');
          const auto         close = line.rfind('"');
          std::istringstream numbers(line.substr(0, open));
          PhysicalName       name;
          if (open == std::string::npos || close == open ||
              !(numbers >> name.dimension >> name.tag))
            reader.fail("expected 'dimension tag \"name\"' in $PhysicalNames, found '" +
                        Utilities::trim(line) + "'.");
          name.name = Utilities::trim(line.substr(open + 1, close - open - 1));
          contents.physical_names.push_back(name);
        }
      reader.expect("$EndPhysicalNames", section);
    }

    /// The MSH version of the file (1 for the old format that starts with
    /// $NOD, left for the caller as @p pending section). Binary files stop
    /// here.
    double
    read_format(LineReader &reader, std::string &pending)
    {
      std::string line;
      while (reader.next(line) && Utilities::trim(line).empty())
        ;
      line = Utilities::trim(line);
      if (line == "$NOD")
        {
          pending = line;
          return 1.;
        }
      if (line != "$MeshFormat")
        reader.fail("expected $MeshFormat (or $NOD) at the start of a Gmsh mesh file, found '" +
                    line.substr(0, 40) + "'.");
      const auto v = reader.numbers("$MeshFormat", "", "'version file-type data-size'", 2);
      if (v[1] != 0.)
        reader.fail_file(
          "is a binary Gmsh file; contact_fem reads ASCII meshes only. Save it as ASCII: "
          "gmsh FILE.msh -save -format msh22 -o ASCII.msh (without -bin), or "
          "Mesh.Binary = 0; in the .geo file.");
      if (v[0] < 2. || v[0] >= 5.)
        reader.fail("MSH version " + short_number(v[0]) +
                    " is not supported; expected 2.x or 4.x (gmsh -format msh22 or msh41).");
      reader.expect("$EndMeshFormat", "$MeshFormat");
      return v[0];
    }

    Contents
    scan_gmsh(const std::string &file, const bool keep_hexahedra, const bool keep_elements)
    {
      LineReader   reader(file);
      std::string  section;
      const double version = read_format(reader, section);
      Contents     contents;
      contents.keep_hexahedra = keep_hexahedra;
      contents.keep_elements  = keep_elements;
      std::string line;
      while (!section.empty() || reader.next(line))
        {
          if (section.empty())
            section = Utilities::trim(line);
          if (section.empty())
            continue;
          if (section[0] != '$')
            reader.fail("expected a section such as $Nodes or $Elements, found '" +
                        section.substr(0, 40) + "'.");
          if (section == "$Nodes" || section == "$NOD")
            {
              version >= 4. ? scan_nodes_v4(reader, version, contents) :
                              scan_nodes_v2(reader, section, contents);
              contents.have_nodes = true;
            }
          else if (section == "$Elements" || section == "$ELM")
            {
              version >= 4. ? scan_elements_v4(reader, version, contents) :
                              scan_elements_v2(reader, section, contents);
              contents.have_elements = true;
            }
          else if (section == "$PhysicalNames")
            scan_physical_names(reader, contents);
          else if (section == "$Entities" && version >= 4.)
            scan_entities(reader, version, contents);
          else
            skip_section(reader, section);
          section.clear();
        }
      for (const auto &[have, name] : {std::make_pair(contents.have_nodes, "$Nodes"),
                                       std::make_pair(contents.have_elements, "$Elements")})
        if (!have)
          reader.fail_file("ends at line " + std::to_string(reader.line_number) + " without a " +
                           name +
                           " section: the file is truncated or not "
                           "a mesh (a .geo file? run gmsh -2 on it).");
      return contents;
    }

    /// "12 triangles, 3 prisms": the elements of @p contents that @p take selects.
    template <typename Predicate>
    std::string
    describe(const Contents &contents, const Predicate &take)
    {
      std::string text;
      for (const auto &[type, count] : contents.elements)
        {
          const ElementType *t = find_element_type(type);
          if (t && take(*t))
            text += (text.empty() ? "" : ", ") + std::to_string(count) + " " +
                    (count == 1 ? t->singular : t->plural);
        }
      return text;
    }

    /// Refuses what the scan found but deal.II's reader (or p4est) cannot
    /// take, or would take wrongly.
    void
    check_contents(const Contents &contents, const std::string &file, const unsigned int dim)
    {
      const std::string prefix = mesh_key + ": '" + file + "' ";
      const std::string Dd     = std::to_string(dim) + "D";
      unsigned int      top    = 0;
      for (const auto &[type, count] : contents.elements)
        {
          const ElementType *t = find_element_type(type);
          AssertThrow(t != nullptr,
                      ExcMessage(prefix + "holds elements of Gmsh type " + std::to_string(type) +
                                 ", which contact_fem does not read (first-order "
                                 "triangles and quadrilaterals in 2D; tetrahedra, prisms "
                                 "and hexahedra in 3D; with their boundary lines or "
                                 "faces)."));
          top = std::max(top, t->dim);
        }
      // deal.II's reader names only an unknown element type for these.
      AssertThrow(top <= dim, ExcMessage(prefix + "holds " + std::to_string(top) + "D cells (" +
                                         describe(contents,
                                                  [&](const ElementType &t) {
                                                    return t.dim == top;
                                                  }) +
                                         ") but Dimension = " + std::to_string(dim) + "."));
      AssertThrow(top == dim,
                  ExcMessage(prefix + "holds no " + Dd + " cells, only " +
                             describe(contents,
                                      [](const ElementType &) {
                                        return true;
                                      }) +
                             " (Dimension = " + std::to_string(dim) + "; mesh the " +
                             (dim == 2 ? "surfaces: gmsh -2)." :
                              top == 2 ? "volumes: gmsh -3; or, if this is a 2D (plane strain) "
                                         "mesh, run it with Dimension = 2)." :
                                         "volumes: gmsh -3).")));
      const std::string pyramids = describe(contents, [](const ElementType &t) {
        return t.n_nodes == 5 && t.dim == 3;
      });
      AssertThrow(pyramids.empty(),
                  ExcMessage(prefix + "holds " + pyramids + " (" + contents.first_pyramid +
                             "): pyramids are not supported. contact_fem splits "
                             "tetrahedra, prisms and hexahedra into hexahedra on reading, "
                             "but a pyramid has no such split that matches its neighbours' "
                             "(the region at its apex would be a cell with eight "
                             "quadrilateral faces, no hexahedron). Gmsh makes pyramids where "
                             "tetrahedra meet quadrilateral faces (a recombined surface, or "
                             "a hexahedral or prism volume beside a tetrahedral one): mesh "
                             "such volumes with tetrahedra only (no Recombine, "
                             "Mesh.RecombineAll = 0, Mesh.Recombine3DAll = 0), or the whole "
                             "model with hexahedra and prisms (Extrude with Layers and "
                             "Recombine, transfinite volumes)."));
      const std::string high_order = describe(contents, [](const ElementType &t) {
        return !t.first_order;
      });
      AssertThrow(high_order.empty(),
                  ExcMessage(prefix + "holds second-order elements (" + high_order +
                             "); contact_fem reads first-order meshes (Gmsh: "
                             "Mesh.ElementOrder = 1) and curves boundaries through "
                             "Geometry/Manifolds."));
      const double z_range = contents.z_max - contents.z_min;
      AssertThrow(dim == 3 || z_range <= 1e-10 * std::max(contents.extent, 1e-300),
                  ExcMessage(prefix + "has nodes from z = " + short_number(contents.z_min) +
                             " to z = " + short_number(contents.z_max) +
                             ": a 2D mesh must lie in a plane z = const (a surface mesh "
                             "of a 3D body cannot be read in 2D)."));
    }

    /// "(x, y, z)" with 8 significant digits.
    std::string
    coordinates_3d(const Point<3> &p)
    {
      std::ostringstream text;
      text << std::setprecision(8) << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
      return text.str();
    }

    /// Throws if @p n_bad cells are degenerate or inverted: the first
    /// (@p first) named, the others counted, then what is needed.
    void
    refuse_bad_cells(const std::string &file,
                     const std::size_t  n_bad,
                     const std::string &first,
                     const std::string &cells,
                     const std::string &need)
    {
      AssertThrow(n_bad == 0, ExcMessage(mesh_key + ": '" + file + "', " + first +
                                         (n_bad > 1 ? "; " + std::to_string(n_bad - 1) + " more " +
                                                        cells + " are degenerate or inverted" :
                                                      "") +
                                         ". " + need));
    }

    /// Refuses hexahedra that are no valid cells: deal.II's reader would
    /// take a collapsed or flat one (and fail later, or solve with a
    /// singular cell) and reorder a twisted one by its signed volume.
    /// Mirrored cells (every corner inverted: the opposite turn) pass, as
    /// deal.II reorders them.
    void
    check_hexahedra(const Contents &contents, const std::string &file)
    {
      std::size_t n_bad = 0;
      std::string first;
      for (const auto &hexahedron : contents.hexahedra)
        {
          std::array<Point<3>, 8> x;
          for (unsigned int i = 0; i < 8; ++i)
            {
              const auto node = contents.node_coordinates.find(hexahedron.nodes[i]);
              AssertThrow(node != contents.node_coordinates.end(),
                          ExcMessage(
                            mesh_key + ": '" + file + "', line " + std::to_string(hexahedron.line) +
                            ": hexahedron " + std::to_string(hexahedron.tag) + " uses node " +
                            std::to_string(hexahedron.nodes[i]) + ", which $Nodes does not list."));
              x[i] = node->second;
            }
          const HexahedronCheck check = check_hexahedron(x);
          if (check.shape == HexahedronShape::valid || check.shape == HexahedronShape::mirrored)
            continue;
          if (n_bad++ > 0)
            continue;
          const auto node = [&](const unsigned int i) {
            return "node " + std::to_string(hexahedron.nodes[i]) + " " + coordinates_3d(x[i]);
          };
          std::ostringstream what;
          what << "line " << hexahedron.line << ": hexahedron " << hexahedron.tag;
          if (check.shape == HexahedronShape::collapsed_edge)
            what << " is degenerate: its edge from " << node(check.first) << " to "
                 << node(check.second) << " has zero length (a collapsed edge; a "
                 << "hexahedron needs eight distinct corners)";
          else if (check.shape == HexahedronShape::flat)
            what << " is degenerate: it has no volume at its corner " << node(check.first)
                 << " (the three edges there lie in one plane)";
          else
            what << " is inverted: its Jacobian is negative at " << check.n_negative
                 << " of its 8 corners (the first at " << node(check.first)
                 << ") and positive at the others: a twisted, self-intersecting cell, "
                 << "its nodes not in Gmsh's hexahedron order (nodes 1-4 one face, 5-8 "
                 << "the opposite face in the same turn)";
          first = what.str();
        }
      refuse_bad_cells(file, n_bad, first, "hexahedra",
                       "contact_fem needs hexahedra with a positive Jacobian at every "
                       "corner: remesh, or fix the node order.");
    }

    /// What is wrong with the quadrilateral @p x (Gmsh order: around the
    /// cell), or an empty string: a collapsed edge, a flat corner, or a
    /// butterfly (corners of both turns). Cells listed in the opposite turn
    /// (every corner negative) pass: deal.II reorders them.
    std::string
    quadrilateral_problem(const std::array<Point<3>, 4> &x, const std::array<long, 4> &nodes)
    {
      const auto node = [&](const unsigned int i) {
        std::ostringstream text;
        text << "node " << nodes[i] << " (" << std::setprecision(8) << x[i][0] << ", " << x[i][1]
             << ")";
        return text.str();
      };
      double h = 0.;
      for (unsigned int i = 0; i < 4; ++i)
        h = std::max(h, x[i].distance(x[(i + 1) % 4]));
      unsigned int n_positive = 0, n_negative = 0;
      for (unsigned int i = 0; i < 4; ++i)
        {
          const Tensor<1, 3> a = x[(i + 1) % 4] - x[i], b = x[(i + 3) % 4] - x[i];
          if (a.norm() <= 1e-12 * h)
            return "is degenerate: its edge from " + node(i) + " to " + node((i + 1) % 4) +
                   " has zero length (a collapsed edge; a quadrilateral needs four "
                   "distinct corners)";
          const double jacobian = a[0] * b[1] - a[1] * b[0];
          if (std::abs(jacobian) <= 1e-8 * a.norm() * b.norm())
            return "is degenerate: its corner at " + node(i) +
                   " is flat (the two edges there lie on one line)";
          (jacobian > 0. ? n_positive : n_negative) += 1;
        }
      if (n_positive > 0 && n_negative > 0)
        return "is inverted: its corners turn both ways (a twisted, butterfly-shaped cell "
               "whose edges cross): its nodes are not in Gmsh's order around the cell";
      return "";
    }

    /// Refuses quadrilaterals that are no valid cells (2D), naming the line,
    /// the element and the node: deal.II's reader takes them and the run
    /// stopped later with a count of "inverted or degenerate cells" only.
    void
    check_quadrilaterals(const Contents &contents, const std::string &file)
    {
      std::size_t n_bad = 0;
      std::string first;
      for (const auto &quadrilateral : contents.quadrilaterals)
        {
          std::array<Point<3>, 4> x;
          for (unsigned int i = 0; i < 4; ++i)
            x[i] = contents.node_coordinates.at(quadrilateral.nodes[i]);
          const std::string problem = quadrilateral_problem(x, quadrilateral.nodes);
          if (!problem.empty() && n_bad++ == 0)
            first = "line " + std::to_string(quadrilateral.line) + ": quadrilateral " +
                    std::to_string(quadrilateral.tag) + " " + problem;
        }
      refuse_bad_cells(file, n_bad, first, "quadrilaterals",
                       "contact_fem needs quadrilaterals with a positive Jacobian at every "
                       "corner: remesh, or fix the node order.");
    }

    /// Refuses a split mesh (mesh_split.h) with a degenerate or inverted
    /// piece, naming the element of the file it comes from: the pieces of a
    /// valid element are valid (those of a triangle or tetrahedron are its
    /// affine images), so this finds flat simplices and twisted prisms.
    void
    check_split_cells(const SplitMesh   &split,
                      const Contents    &contents,
                      const std::string &file,
                      const unsigned int dim)
    {
      std::size_t n_bad = 0;
      std::string first;
      for (const auto &piece : split.cells)
        {
          std::string problem;
          if (dim == 3)
            {
              std::array<Point<3>, 8> x;
              for (unsigned int i = 0; i < 8; ++i)
                x[i] = split.points[piece.vertices[i]];
              const HexahedronShape shape = check_hexahedron(x).shape;
              if (shape == HexahedronShape::collapsed_edge || shape == HexahedronShape::flat)
                problem = "is degenerate (no volume there)";
              else if (shape == HexahedronShape::twisted)
                problem = "is inverted (a twisted, self-intersecting cell)";
            }
          else
            {
              std::array<Point<3>, 4> x;
              for (unsigned int i = 0; i < 4; ++i)
                x[i] = split.points[piece.vertices[i]];
              if (!quadrilateral_problem(x, std::array<long, 4>{}).empty())
                problem = "is degenerate or inverted";
            }
          if (problem.empty() || n_bad++ > 0)
            continue;
          const GmshElement &e    = contents.element_list[piece.parent];
          const long         node = e.nodes[piece.corner];
          first = "line " + std::to_string(e.line) + ": " + find_element_type(e.type)->singular +
                  " " + std::to_string(e.tag) + " " + problem + " at its node " +
                  std::to_string(node) + " " + coordinates_3d(contents.node_coordinates.at(node)) +
                  " (its corner piece of the split into " +
                  (dim == 2 ? "quadrilaterals" : "hexahedra") + ")";
        }
      refuse_bad_cells(file, n_bad, first, "split cells",
                       "contact_fem splits each cell at its corners and needs every piece "
                       "with a positive Jacobian: remesh (a flat or sliver element), or fix "
                       "the node order.");
    }
  } // namespace

  namespace
  {
    /// The text of @p file with every node moved by -@p origin (17 digits:
    /// the moved coordinates are read back exactly); the other numbers of a
    /// node line (its tag, parametric coordinates) and all other lines stay
    /// as they are.
    std::string
    moved_copy(const std::string &file, const Contents &contents, const Point<3> &origin)
    {
      std::ifstream      in(file);
      std::ostringstream out;
      out << std::setprecision(17);
      std::string  line;
      unsigned int line_number = 0;
      auto         node_line   = contents.node_lines.begin();
      while (std::getline(in, line))
        {
          ++line_number;
          if (node_line == contents.node_lines.end() || node_line->first != line_number)
            {
              out << line << '\n';
              continue;
            }
          std::istringstream words(line);
          std::string        word;
          for (unsigned int k = 0; words >> word; ++k)
            {
              out << (k > 0 ? " " : "");
              const unsigned int d = k - node_line->second;
              if (k >= node_line->second && d < 3)
                out << std::stod(word) - origin[d];
              else
                out << word;
            }
          out << '\n';
          ++node_line;
        }
      return out.str();
    }
  } // namespace

  namespace
  {
    /// A tagged boundary element of the file on nodes that no cell uses
    /// (below): its corners in the computing frame, its physical tag and
    /// its name for messages.
    template <int dim>
    struct LooseFacet
    {
      std::vector<Point<dim>> corners;
      int                     physical = 0;
      std::string             element;
    };

    template <int dim>
    Point<dim>
    in_dim(const Point<3> &x)
    {
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = x[d];
      return p;
    }

    std::string
    element_name(const GmshElement &e)
    {
      return "boundary element " + std::to_string(e.tag) + " (line " + std::to_string(e.line) +
             ", physical tag " + std::to_string(e.physical) + ")";
    }

    /// The tagged facets of an unsplit mesh on nodes no cell uses.
    template <int dim>
    std::vector<LooseFacet<dim>>
    loose_facets(const Contents &contents, const Point<3> &origin)
    {
      std::vector<LooseFacet<dim>> loose;
      for (const GmshElement &facet : contents.tagged_facets)
        if (std::any_of(facet.nodes.begin(), facet.nodes.end(), [&](const long n) {
              return contents.cell_nodes.count(n) == 0;
            }))
          {
            LooseFacet<dim> f{{}, facet.physical, element_name(facet)};
            for (const long n : facet.nodes)
              f.corners.push_back(in_dim<dim>(Point<3>(contents.node_coordinates.at(n) - origin)));
            loose.push_back(std::move(f));
          }
      return loose;
    }

    /// The same for a split mesh: the pieces of tagged facets (dimension
    /// dim - 1) with a point that no split cell uses.
    template <int dim>
    std::vector<LooseFacet<dim>>
    loose_facets(const SplitMesh &split, const std::vector<GmshElement> &elements)
    {
      std::vector<bool> in_cell(split.points.size(), false);
      for (const auto &piece : split.cells)
        for (const unsigned int v : piece.vertices)
          in_cell[v] = true;
      std::vector<LooseFacet<dim>> loose;
      for (const auto &piece : split.boundary)
        if (piece.physical > 0 && piece.vertices.size() == (dim == 3 ? 4u : 2u) &&
            std::any_of(piece.vertices.begin(), piece.vertices.end(), [&](const unsigned int v) {
              return !in_cell[v];
            }))
          {
            LooseFacet<dim> f{{}, piece.physical, element_name(elements[piece.parent])};
            for (const unsigned int v : piece.vertices)
              f.corners.push_back(in_dim<dim>(split.points[v]));
            loose.push_back(std::move(f));
          }
      return loose;
    }

    /**
     * Gmsh without coherence (the built-in kernel with Geometry.AutoCoherence
     * = 0, some extrusions) writes boundary elements on nodes of their own,
     * at the coordinates of the cells' nodes. deal.II's reader drops them
     * without a word, and their faces keep boundary id 0: a contact surface
     * or a support half missing (meshes/ironing_3d.msh lost 39 of its 78
     * tagged faces). Such an element (or each piece of it, in a split mesh)
     * gets the face of the mesh whose vertices it meets, within 1e-6 of its
     * size. Returns how many file elements; throws for one that meets no
     * face, or the faces of two bodies.
     */
    template <int dim>
    unsigned int
    assign_loose_facets(const std::vector<LooseFacet<dim>> &loose,
                        const std::string                  &file,
                        Triangulation<dim>                 &coarse)
    {
      if (loose.empty())
        return 0;
      // The boundary faces by the x of their centres.
      std::vector<std::pair<double, typename Triangulation<dim>::face_iterator>> faces;
      for (const auto &cell : coarse.active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            faces.emplace_back(cell->face(f)->center()[0], cell->face(f));
      std::sort(faces.begin(), faces.end(), [](const auto &a, const auto &b) {
        return a.first < b.first;
      });
      std::set<std::string> elements;
      for (const LooseFacet<dim> &facet : loose)
        {
          Point<dim> centre;
          for (const auto &p : facet.corners)
            centre += p / static_cast<double>(facet.corners.size());
          double size = 0.;
          for (const auto &p : facet.corners)
            size = std::max(size, p.distance(centre));
          const double                                            tolerance = 1e-6 * size;
          std::vector<typename Triangulation<dim>::face_iterator> matches;
          for (auto it = std::lower_bound(faces.begin(), faces.end(), centre[0] - tolerance,
                                          [](const auto &a, const double x) {
                                            return a.first < x;
                                          });
               it != faces.end() && it->first <= centre[0] + tolerance; ++it)
            {
              const auto &face = it->second;
              const bool  same =
                face->n_vertices() == facet.corners.size() &&
                std::all_of(facet.corners.begin(), facet.corners.end(), [&](const Point<dim> &p) {
                  for (const auto v : face->vertex_indices())
                    if (face->vertex(v).distance(p) <= tolerance)
                      return true;
                  return false;
                });
              if (same)
                matches.push_back(face);
            }
          AssertThrow(matches.size() == 1,
                      ExcMessage(mesh_key + ": '" + file + "': " + facet.element +
                                 " is on nodes that no cell uses, and " +
                                 (matches.empty() ?
                                    "no boundary face of the cells lies at its nodes' "
                                    "coordinates" :
                                    "the faces of two bodies lie at its nodes' coordinates") +
                                 "; expected boundary elements on the nodes of the cells "
                                 "(in Gmsh: Coherence, or Geometry.AutoCoherence = 1)."));
          matches[0]->set_boundary_id(static_cast<types::boundary_id>(facet.physical));
          elements.insert(facet.element);
        }
      return elements.size();
    }
  } // namespace

  /**
   * deal.II's "boundary id for an internal face" in the user's words: a
   * face with a physical tag between two cells, mostly two bodies meshed on
   * shared nodes (Gmsh BooleanFragments or Coherence), which contact and
   * tying cannot use. The face's corners, from deal.II's message, are put
   * back into the file's coordinates (the mesh may have been moved).
   */
  std::string
  internal_face_message(const std::string &why, const std::string &file, const Point<3> &origin)
  {
    std::string corners;
    const auto  at = why.find("located at positions");
    if (at != std::string::npos)
      {
        std::istringstream in(why.substr(at + 20));
        char               open = 0;
        while (in >> open && open == '(')
          {
            std::string inside;
            std::getline(in, inside, ')');
            std::istringstream numbers(inside);
            std::string        point;
            double             x = 0.;
            for (unsigned int d = 0; d < 3 && numbers >> x; ++d)
              point += (d > 0 ? ", " : "") + significant(x + origin[d], 12);
            corners += (corners.empty() ? "" : "; ") + ("(" + point + ")");
          }
      }
    return mesh_key + ": '" + file +
           "': a face with a physical tag (boundary id) lies inside the mesh, between two "
           "cells" +
           (corners.empty() ? std::string() : " (its corners: " + corners + ")") +
           ". Most often two bodies share the nodes of the surface between them (in Gmsh: "
           "BooleanFragments, Coherence or Geometry.AutoCoherence fused the volumes): bodies "
           "in contact or tied need their own nodes there, each meshed on its own (no "
           "fragments between them). A surface inside one body cannot carry a boundary id: "
           "remove it from its Physical group.";
  }

  template <int dim>
  MeshFileInfo
  read_gmsh(const std::string &file, Triangulation<dim> &coarse)
  {
    std::error_code error;
    AssertThrow(std::filesystem::is_regular_file(file, error),
                ExcMessage(mesh_key + ": '" + file + "' is " +
                           (std::filesystem::is_directory(file, error) ?
                              "a directory" :
                              "not a regular file (a FIFO, socket or device)") +
                           "; expected a Gmsh .msh file."));
    Contents contents = scan_gmsh(file, dim == 3, false);
    check_contents(contents, file, dim);
    if (dim == 3)
      check_hexahedra(contents, file);
    else
      check_quadrilaterals(contents, file);
    MeshFileInfo info;
    info.physical_names   = contents.physical_names;
    const Point<3> origin = info.frame_origin =
      choose_frame_origin(contents.lower, contents.upper, dim);
    std::string                  split_text; // the split mesh as a file for deal.II's reader
    std::vector<LooseFacet<dim>> loose;
    if (needs_split(contents.elements, dim))
      {
        contents = scan_gmsh(file, false, true);
        const SplitMesh split =
          split_mesh(contents.element_list, contents.node_coordinates, origin, dim);
        check_split_cells(split, contents, file, dim);
        info.first_new_vertex = split.n_file_nodes;
        info.split_note       = split_summary(split, dim);
        split_text            = msh22_text(split);
        loose                 = loose_facets<dim>(split, contents.element_list);
      }
    else
      loose = loose_facets<dim>(contents, origin);
    GridIn<dim> grid_in;
    grid_in.attach_triangulation(coarse);
    try
      {
        if (!split_text.empty())
          {
            std::istringstream in(split_text);
            grid_in.read_msh(in);
          }
        else if (origin.norm_square() > 0.)
          {
            std::istringstream in(moved_copy(file, contents, origin));
            grid_in.read_msh(in);
          }
        else
          {
            std::ifstream in(file);
            grid_in.read_msh(in);
          }
      }
    catch (const std::exception &e)
      {
        const std::string why = user_message(e);
        AssertThrow(why.find("boundary id for an internal face") == std::string::npos,
                    ExcMessage(internal_face_message(why, file, origin)));
        AssertThrow(false,
                    ExcMessage(mesh_key + ": cannot read '" + file + "' as a Gmsh mesh: " + why));
      }
    if (const unsigned int n = assign_loose_facets(loose, file, coarse); n > 0)
      info.orphan_note = std::to_string(n) + (n == 1 ? " boundary element" : " boundary elements") +
                         " on nodes of their own (Gmsh without coherence) took the faces of "
                         "the cells at their coordinates";
    return info;
  }


  namespace
  {
    /// Union-find over vertex indices.
    class Clusters
    {
    public:
      explicit Clusters(const std::size_t n)
        : parent(n)
      {
        std::iota(parent.begin(), parent.end(), 0);
      }
      std::size_t
      root(std::size_t i)
      {
        while (parent[i] != i)
          i = parent[i] = parent[parent[i]];
        return i;
      }
      void
      join(const std::size_t i, const std::size_t j)
      {
        parent[root(i)] = root(j);
      }

    private:
      std::vector<std::size_t> parent;
    };

    /// A boundary face of the coarse mesh, by vertex index.
    template <int dim>
    struct BoundaryFace
    {
      types::material_id                                             body;
      types::boundary_id                                             id;
      std::array<unsigned int, GeometryInfo<dim>::vertices_per_face> vertices;
    };

    /// Groups the vertices of @p faces that lie within a small tolerance of
    /// each other: an R-tree query per vertex, O(n log n).
    template <int dim>
    Clusters
    coincident_vertices(const Triangulation<dim>             &coarse,
                        const std::vector<BoundaryFace<dim>> &faces)
    {
      std::vector<unsigned int> indices;
      double                    shortest = std::numeric_limits<double>::max();
      for (const auto &face : faces)
        for (unsigned int i = 0; i < face.vertices.size(); ++i)
          {
            indices.push_back(face.vertices[i]);
            const double length = coarse.get_vertices()[face.vertices[i]].distance(
              coarse.get_vertices()[face.vertices[(i + 1) % face.vertices.size()]]);
            if (length > 0.)
              shortest = std::min(shortest, length);
          }
      std::sort(indices.begin(), indices.end());
      indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
      std::vector<Point<dim>> points;
      for (const unsigned int v : indices)
        points.push_back(coarse.get_vertices()[v]);
      // Far below any edge of the mesh, far above round-off of coordinates.
      const double             tolerance = 1e-6 * shortest;
      const auto               tree      = pack_rtree_of_indices(points);
      Clusters                 clusters(coarse.n_vertices());
      std::vector<std::size_t> hits;
      for (std::size_t i = 0; i < points.size(); ++i)
        {
          Point<dim> lower = points[i], upper = points[i];
          for (unsigned int d = 0; d < dim; ++d)
            {
              lower[d] -= tolerance;
              upper[d] += tolerance;
            }
          hits.clear();
          tree.query(boost::geometry::index::intersects(BoundingBox<dim>({lower, upper})),
                     std::back_inserter(hits));
          for (const std::size_t j : hits)
            clusters.join(indices[i], indices[j]);
        }
      return clusters;
    }
  } // namespace

  template <int dim>
  void
  check_unmerged_vertices(const Triangulation<dim> &coarse, const std::string &file)
  {
    std::vector<BoundaryFace<dim>> faces;
    for (const auto &cell : coarse.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            BoundaryFace<dim> face{cell->material_id(), cell->face(f)->boundary_id(), {}};
            for (unsigned int v = 0; v < face.vertices.size(); ++v)
              face.vertices[v] = cell->face(f)->vertex_index(v);
            faces.push_back(face);
          }
    if (faces.empty())
      return;
    Clusters clusters = coincident_vertices(coarse, faces);

    // Two boundary faces of one body on the same places are a crack.
    using Key =
      std::pair<types::material_id, std::array<unsigned int, GeometryInfo<dim>::vertices_per_face>>;
    std::vector<std::pair<Key, unsigned int>> keys;
    for (unsigned int i = 0; i < faces.size(); ++i)
      {
        Key key{faces[i].body, faces[i].vertices};
        for (auto &v : key.second)
          v = clusters.root(v);
        std::sort(key.second.begin(), key.second.end());
        keys.emplace_back(key, i);
      }
    std::sort(keys.begin(), keys.end());
    unsigned int n_cracked = 0, first = 0, second = 0;
    for (unsigned int k = 0; k + 1 < keys.size(); ++k)
      if (keys[k].first == keys[k + 1].first &&
          (faces[keys[k].second].id == 0 || faces[keys[k + 1].second].id == 0))
        {
          if (n_cracked++ == 0)
            std::tie(first, second) = std::make_pair(keys[k].second, keys[k + 1].second);
        }
    if (n_cracked == 0)
      return;

    // A node of the first face that the second one does not share.
    const auto  &a = faces[first].vertices, &b = faces[second].vertices;
    unsigned int loose = a[0];
    for (const unsigned int v : a)
      if (std::find(b.begin(), b.end(), v) == b.end())
        loose = v;
    AssertThrow(false,
                ExcMessage(mesh_key + ": '" + file + "': the body of material id " +
                           std::to_string(faces[first].body) +
                           " is cut inside: its cells on "
                           "either side of the node at " +
                           coordinates_text(coarse.get_vertices()[loose]) +
                           " use two coincident copies of it, so " + std::to_string(n_cracked) +
                           " pair(s) of boundary faces without a boundary id lie on top of "
                           "each other (an internal crack). Merge the duplicate nodes: in "
                           "Gmsh, Coherence; (built-in kernel), BooleanFragments "
                           "(OpenCASCADE) or Coherence Mesh; before saving. Bodies in contact "
                           "keep their own nodes: give each body its own material id. An "
                           "intended internal surface of one body needs a physical tag "
                           "(boundary id) on both sides."));
  }

  template <int dim>
  bool
  fit_sphere(const std::vector<Point<dim>> &points,
             Point<dim>                    &centre,
             double                        &radius,
             double                        &max_deviation)
  {
    if (points.size() < dim + 1)
      return false;
    // Relative to the centroid, for the conditioning: 2 c.y + k = |y|^2.
    Point<dim> mean;
    for (const auto &p : points)
      mean += p / static_cast<double>(points.size());
    constexpr unsigned int n           = dim + 1;
    double                 A[n][n + 1] = {};
    for (const auto &p : points)
      {
        const Tensor<1, dim> y = p - mean;
        double               row[n];
        for (unsigned int d = 0; d < dim; ++d)
          row[d] = 2. * y[d];
        row[dim] = 1.;
        for (unsigned int i = 0; i < n; ++i)
          {
            for (unsigned int j = 0; j < n; ++j)
              A[i][j] += row[i] * row[j];
            A[i][n] += row[i] * y.norm_square();
          }
      }
    // Gaussian elimination with partial pivoting; a tiny pivot means the
    // points lie on a line (plane): no circle (sphere).
    double scale = 0.;
    for (unsigned int i = 0; i < n; ++i)
      scale = std::max(scale, std::abs(A[i][i]));
    for (unsigned int i = 0; i < n; ++i)
      {
        unsigned int pivot = i;
        for (unsigned int r = i + 1; r < n; ++r)
          if (std::abs(A[r][i]) > std::abs(A[pivot][i]))
            pivot = r;
        if (!(std::abs(A[pivot][i]) > 1e-12 * scale))
          return false;
        for (unsigned int j = 0; j <= n; ++j)
          std::swap(A[i][j], A[pivot][j]);
        for (unsigned int r = 0; r < n; ++r)
          if (r != i)
            {
              const double factor = A[r][i] / A[i][i];
              for (unsigned int j = i; j <= n; ++j)
                A[r][j] -= factor * A[i][j];
            }
      }
    Tensor<1, dim> c;
    for (unsigned int d = 0; d < dim; ++d)
      c[d] = A[d][n] / A[d][d];
    const double k = A[dim][n] / A[dim][dim];
    if (!(k + c.norm_square() > 0.))
      return false;
    centre        = mean + c;
    radius        = std::sqrt(k + c.norm_square());
    max_deviation = 0.;
    for (const auto &p : points)
      max_deviation = std::max(max_deviation, std::abs(p.distance(centre) - radius));
    return std::isfinite(radius);
  }

  namespace
  {
    /// The joints of a face with its neighbours on the boundary: its
    /// vertices in 2D, its lines in 3D.
    template <int dim>
    std::vector<unsigned int>
    joints_of(const typename Triangulation<dim>::face_iterator &face)
    {
      std::vector<unsigned int> joints;
      if constexpr (dim == 2)
        for (unsigned int v = 0; v < face->n_vertices(); ++v)
          joints.push_back(face->vertex_index(v));
      else
        for (unsigned int l = 0; l < face->n_lines(); ++l)
          joints.push_back(face->line_index(l));
      return joints;
    }
  } // namespace

  namespace
  {
    /**
     * Sets b.fits_cylinder (and its axis and radius) if the faces, whose
     * normals have the moments @p moments (sum of n n^T), are those of an
     * extruded curve - every normal within about 1e-4 rad of perpendicular
     * to the eigenvector of the smallest eigenvalue - and the @p points,
     * projected along it, lie on a circle (within 1e-4 R).
     */
    void
    fit_extruded_cylinder(const SymmetricTensor<2, 3> &moments,
                          const std::vector<Point<3>> &points,
                          PolygonalBoundary<3>        &b)
    {
      const auto eigen = eigenvectors(moments); // descending eigenvalues
      if (!(eigen[2].first <= 1e-8 * trace(moments)))
        return;
      Tensor<1, 3> d       = eigen[2].second / eigen[2].second.norm();
      unsigned int largest = 0;
      for (unsigned int i = 1; i < 3; ++i)
        if (std::abs(d[i]) > std::abs(d[largest]))
          largest = i;
      if (d[largest] < 0.)
        d = -d;
      // An orthonormal basis (e1, e2) of the plane normal to d.
      Tensor<1, 3> e1 =
        cross_product_3d(d, largest == 0 ? Tensor<1, 3>({0., 1., 0.}) : Tensor<1, 3>({1., 0., 0.}));
      e1 /= e1.norm();
      const Tensor<1, 3>    e2 = cross_product_3d(d, e1);
      std::vector<Point<2>> projected;
      for (const Point<3> &p : points)
        projected.emplace_back(p * e1, p * e2);
      Point<2> c;
      double   radius = 0., deviation = 0.;
      if (!fit_sphere(projected, c, radius, deviation) || deviation > 1e-4 * radius)
        return;
      b.fits_cylinder   = true;
      b.axis            = d;
      b.axis_point      = Point<3>(c[0] * e1 + c[1] * e2);
      b.cylinder_radius = radius;
    }
  } // namespace

  template <int dim>
  std::vector<PolygonalBoundary<dim>>
  find_polygonal_boundaries(const Triangulation<dim>              &coarse,
                            const std::vector<types::boundary_id> &skip)
  {
    // A polygonal circle of n sides turns by 2 pi / n at each vertex: 30
    // degrees for n = 12. Below 1e-4 rad (0.006 degrees) the sag of the
    // chords is negligible, and flat faces turn by round-off only.
    constexpr double min_kink = 1e-4, max_kink = numbers::PI / 6.;
    struct Side
    {
      unsigned int       joint;
      types::boundary_id id;
      Tensor<1, dim>     normal;
    };
    std::vector<Side>                                       sides;
    std::map<types::boundary_id, std::vector<unsigned int>> vertices;
    // Per id: the sum of n n^T over its faces, whose smallest eigenvalue
    // vanishes iff every normal is perpendicular to one direction.
    std::map<types::boundary_id, SymmetricTensor<2, dim>> normal_moments;
    for (const auto &cell : coarse.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const types::boundary_id id = cell->face(f)->boundary_id();
            if (std::find(skip.begin(), skip.end(), id) != skip.end())
              continue;
            const Tensor<1, dim> n = outward_normal<dim>(cell, f);
            normal_moments[id] += symmetrize(outer_product(n, n));
            for (const unsigned int joint : joints_of<dim>(cell->face(f)))
              sides.push_back({joint, id, n});
            for (unsigned int v = 0; v < cell->face(f)->n_vertices(); ++v)
              vertices[id].push_back(cell->face(f)->vertex_index(v));
          }
    std::sort(sides.begin(), sides.end(), [](const Side &a, const Side &b) {
      return std::tie(a.joint, a.id) < std::tie(b.joint, b.id);
    });

    std::map<types::boundary_id, PolygonalBoundary<dim>> found;
    for (std::size_t k = 0; k < sides.size();)
      {
        std::size_t end = k;
        while (end < sides.size() && sides[end].joint == sides[k].joint &&
               sides[end].id == sides[k].id)
          ++end;
        // Exactly two faces of one id at a joint: a joint along a surface.
        if (end - k == 2)
          {
            auto &b = found[sides[k].id];
            b.id    = sides[k].id;
            ++b.n_joints;
            const double angle =
              std::acos(std::clamp(sides[k].normal * sides[k + 1].normal, -1., 1.));
            if (angle > min_kink && angle < max_kink)
              {
                b.min_angle = b.n_kinks == 0 ? angle : std::min(b.min_angle, angle);
                b.max_angle = std::max(b.max_angle, angle);
                ++b.n_kinks;
              }
          }
        k = end;
      }

    std::vector<PolygonalBoundary<dim>> result;
    for (auto &[id, b] : found)
      if (b.n_kinks >= 3 && 2 * b.n_kinks > b.n_joints)
        {
          auto &ids = vertices[id];
          std::sort(ids.begin(), ids.end());
          ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
          std::vector<Point<dim>> points;
          for (const unsigned int v : ids)
            points.push_back(coarse.get_vertices()[v]);
          double deviation = 0.;
          b.fits_sphere =
            fit_sphere(points, b.centre, b.radius, deviation) && deviation <= 1e-4 * b.radius;
          if constexpr (dim == 3)
            fit_extruded_cylinder(normal_moments[id], points, b);
          result.push_back(b);
        }
    return result;
  }

  template <int dim>
  void
  check_folded_cells(const Triangulation<dim> &coarse,
                     const std::string        &file,
                     const Point<3>           &origin)
  {
    unsigned int n_folded = 0;
    Point<dim>   first;
    for (const auto &cell : coarse.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        {
          if (cell->at_boundary(f) || cell->neighbor_index(f) < cell->index())
            continue;
          const auto     face = cell->face(f);
          Tensor<1, dim> normal; // from the corners: the sign does not matter here
          if constexpr (dim == 2)
            {
              const Tensor<1, dim> t = face->vertex(1) - face->vertex(0);
              normal[0]              = t[1];
              normal[1]              = -t[0];
            }
          else
            normal = cross_product_3d(face->vertex(3) - face->vertex(0),
                                      face->vertex(2) - face->vertex(1));
          // The centre of a cell with positive corner Jacobians lies on its
          // side of each of its faces: on opposite sides of a shared face.
          const double here  = (cell->center() - face->center()) * normal;
          const double there = (cell->neighbor(f)->center() - face->center()) * normal;
          if (here * there > 0. && n_folded++ == 0)
            first = face->center();
        }
    if (n_folded == 0)
      return;
    Point<dim> in_file;
    for (unsigned int d = 0; d < dim; ++d)
      in_file[d] = first[d] + origin[d];
    AssertThrow(false,
                ExcMessage(mesh_key + ": '" + file +
                           "': the mesh folds over itself: the two cells of the " +
                           (dim == 2 ? "edge" : "face") + " centred at " +
                           coordinates_text(in_file) + " lie on the same side of it" +
                           (n_folded > 1 ? " (and at " + std::to_string(n_folded - 1) +
                                             " more internal " + (dim == 2 ? "edges" : "faces") +
                                             ")" :
                                           std::string()) +
                           ": an element there is inverted (a node lies beyond the opposite " +
                           (dim == 2 ? "edge" : "face") +
                           " of the element), so the cells overlap their neighbours. "
                           "Elements listed in the opposite turn are taken (and reordered), "
                           "a tangled mesh is not: remesh, or fix the node coordinates."));
  }

  template <int dim>
  bool
  is_inverted(const typename Triangulation<dim>::cell_iterator &cell)
  {
    const double h = cell->diameter();
    if (dim == 3)
      return cell->measure() <= 1e-12 * std::pow(h, dim);
    // Corner Jacobians of a valid quadrilateral are all positive.
    static const unsigned int next[4] = {1, 3, 0, 2}, prev[4] = {2, 0, 3, 1};
    for (unsigned int v = 0; v < 4; ++v)
      {
        const Tensor<1, dim> a = cell->vertex(next[v]) - cell->vertex(v);
        const Tensor<1, dim> b = cell->vertex(prev[v]) - cell->vertex(v);
        if (a[0] * b[1] - a[1] * b[0] <= 1e-12 * h * h)
          return true;
      }
    return false;
  }

  template MeshFileInfo
  read_gmsh<2>(const std::string &, Triangulation<2> &);
  template MeshFileInfo
  read_gmsh<3>(const std::string &, Triangulation<3> &);
  template void
  check_folded_cells<2>(const Triangulation<2> &, const std::string &, const Point<3> &);
  template void
  check_folded_cells<3>(const Triangulation<3> &, const std::string &, const Point<3> &);
  template void
  check_unmerged_vertices<2>(const Triangulation<2> &, const std::string &);
  template void
  check_unmerged_vertices<3>(const Triangulation<3> &, const std::string &);
  template std::vector<PolygonalBoundary<2>>
  find_polygonal_boundaries<2>(const Triangulation<2> &, const std::vector<types::boundary_id> &);
  template std::vector<PolygonalBoundary<3>>
  find_polygonal_boundaries<3>(const Triangulation<3> &, const std::vector<types::boundary_id> &);
  template bool
  fit_sphere<2>(const std::vector<Point<2>> &, Point<2> &, double &, double &);
  template bool
  fit_sphere<3>(const std::vector<Point<3>> &, Point<3> &, double &, double &);
  template bool
  is_inverted<2>(const Triangulation<2>::cell_iterator &);
  template bool
  is_inverted<3>(const Triangulation<3>::cell_iterator &);
} // namespace contact_fem
