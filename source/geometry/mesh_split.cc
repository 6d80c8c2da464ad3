#include <deal.II/base/tensor.h>

#include <contact_fem/geometry/mesh_split.h>

#include <algorithm>
#include <array>
#include <iomanip>
#include <set>
#include <sstream>
#include <utility>

namespace contact_fem
{
  namespace
  {
    /// An element shape on its reference cell: the corners (positively
    /// turned) and the faces as cycles of corners (2D shapes: the polygon
    /// itself; a line: its two ends).
    struct Shape
    {
      int                                    gmsh_type;
      unsigned int                           dim;
      const char                            *singular;
      const char                            *plural;
      std::vector<Point<3>>                  corners;
      std::vector<std::vector<unsigned int>> faces;
    };

    const std::vector<Shape> &
    shapes()
    {
      static const std::vector<Shape> list = {
        {1, 1, "line", "lines", {{0, 0, 0}, {1, 0, 0}}, {{0, 1}}},
        {2, 2, "triangle", "triangles", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}},
        {3,
         2,
         "quadrilateral",
         "quadrilaterals",
         {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
         {{0, 1, 2, 3}}},
        {4,
         3,
         "tetrahedron",
         "tetrahedra",
         {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
         {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}},
        {5,
         3,
         "hexahedron",
         "hexahedra",
         {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
         {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}},
        {6,
         3,
         "prism",
         "prisms",
         {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}},
         {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}}}};
      return list;
    }

    const Shape *
    find_shape(const int gmsh_type)
    {
      for (const Shape &s : shapes())
        if (s.gmsh_type == gmsh_type)
          return &s;
      return nullptr;
    }

    /// The corners joined to corner @p v by an edge, turned positively on
    /// the reference cell (2D: counterclockwise; 3D: right-handed).
    std::vector<unsigned int>
    neighbours(const Shape &shape, const unsigned int v)
    {
      std::set<unsigned int> found;
      for (const auto &face : shape.faces)
        for (unsigned int i = 0; i < face.size(); ++i)
          if (face[i] == v && face.size() > 1)
            {
              found.insert(face[(i + 1) % face.size()]);
              found.insert(face[(i + face.size() - 1) % face.size()]);
            }
      std::vector<unsigned int> n(found.begin(), found.end());
      const auto                edge = [&](const unsigned int k) {
        return shape.corners[n[k]] - shape.corners[v];
      };
      if (n.size() == 2 && cross_product_3d(edge(0), edge(1))[2] < 0.)
        std::swap(n[0], n[1]);
      if (n.size() == 3 && cross_product_3d(edge(0), edge(1)) * edge(2) < 0.)
        std::swap(n[1], n[2]);
      return n;
    }

    /// The local corners of the face of @p shape holding corners a, b, c.
    const std::vector<unsigned int> &
    face_with(const Shape &shape, const unsigned int a, const unsigned int b, const unsigned int c)
    {
      for (const auto &face : shape.faces)
        if (std::count(face.begin(), face.end(), a) + std::count(face.begin(), face.end(), b) +
              std::count(face.begin(), face.end(), c) ==
            3)
          return face;
      AssertThrow(false, ExcInternalError());
      return shape.faces[0];
    }

    /// Makes the points of the split mesh: each shared edge midpoint and
    /// face centre once, whichever element asks first.
    class PointMaker
    {
    public:
      PointMaker(SplitMesh &mesh, std::map<long, unsigned int> file_index)
        : mesh(mesh)
        , file_index(std::move(file_index))
      {}

      unsigned int
      node(const long tag) const
      {
        return file_index.at(tag);
      }

      unsigned int
      midpoint(long a, long b)
      {
        if (b < a)
          std::swap(a, b);
        const auto [entry, is_new] = edges.emplace(std::make_pair(a, b), 0u);
        if (is_new)
          entry->second = add(mean({a, b}));
        return entry->second;
      }

      /// The centre of the face (2D element) with the corners @p tags.
      unsigned int
      face_centre(std::vector<long> tags)
      {
        std::sort(tags.begin(), tags.end());
        const auto [entry, is_new] = faces.emplace(tags, 0u);
        if (is_new)
          entry->second = add(mean(tags));
        return entry->second;
      }

      unsigned int
      cell_centre(const std::vector<long> &tags)
      {
        return add(mean(tags));
      }

    private:
      /// The mean of the nodes @p tags, summed in the order of their
      /// coordinates: the same bits for any numbering of the nodes.
      Point<3>
      mean(const std::vector<long> &tags) const
      {
        std::vector<Point<3>> x;
        for (const long t : tags)
          x.push_back(mesh.points[node(t)]);
        std::sort(x.begin(), x.end(), [](const Point<3> &p, const Point<3> &q) {
          return std::make_tuple(p[0], p[1], p[2]) < std::make_tuple(q[0], q[1], q[2]);
        });
        Point<3> sum;
        for (const Point<3> &p : x)
          sum += p;
        return sum / static_cast<double>(x.size());
      }

      unsigned int
      add(const Point<3> &p)
      {
        mesh.points.push_back(p);
        return mesh.points.size() - 1;
      }

      SplitMesh                                    &mesh;
      const std::map<long, unsigned int>            file_index;
      std::map<std::pair<long, long>, unsigned int> edges;
      std::map<std::vector<long>, unsigned int>     faces;
    };

    /// The pieces of @p element (of @p shape), one per corner.
    std::vector<SplitMesh::Piece>
    split_element(const GmshElement &element,
                  const Shape       &shape,
                  const std::size_t  parent,
                  PointMaker        &points)
    {
      const auto &t     = element.nodes;
      const auto  nodes = [&](const std::vector<unsigned int> &local) {
        std::vector<long> tags;
        for (const unsigned int i : local)
          tags.push_back(t[i]);
        return tags;
      };
      std::vector<unsigned int> all(t.size());
      for (unsigned int i = 0; i < all.size(); ++i)
        all[i] = i;
      const unsigned int            centre = shape.dim == 3 ? points.cell_centre(t) :
                                             shape.dim == 2 ? points.face_centre(t) :
                                                              0;
      std::vector<SplitMesh::Piece> pieces;
      for (unsigned int v = 0; v < t.size(); ++v)
        {
          const auto n = neighbours(shape, v);
          const auto m = [&](const unsigned int k) {
            return points.midpoint(t[v], t[n[k]]);
          };
          const auto f = [&](const unsigned int j, const unsigned int k) {
            return points.face_centre(nodes(face_with(shape, v, n[j], n[k])));
          };
          SplitMesh::Piece piece;
          piece.physical       = element.physical;
          piece.parent         = parent;
          piece.corner         = v;
          piece.type           = shape.dim == 1 ? 1 : shape.dim == 2 ? 3 : 5;
          const unsigned int x = points.node(t[v]);
          if (shape.dim == 1)
            piece.vertices = {x, m(0)};
          else if (shape.dim == 2)
            piece.vertices = {x, m(0), centre, m(1)};
          else
            piece.vertices = {x, m(0), f(0, 1), m(1), m(2), f(0, 2), centre, f(1, 2)};
          pieces.push_back(piece);
        }
      return pieces;
    }
  } // namespace

  bool
  needs_split(const std::map<int, std::size_t> &element_counts, const unsigned int dim)
  {
    for (const auto &[type, count] : element_counts)
      if (const Shape *s = find_shape(type);
          s && s->dim == dim && count > 0 && (type == 2 || type == 4 || type == 6))
        return true;
    return false;
  }

  SplitMesh
  split_mesh(const std::vector<GmshElement>           &elements,
             const std::unordered_map<long, Point<3>> &coordinates,
             const Point<3>                           &origin,
             const unsigned int                        dim)
  {
    SplitMesh      mesh;
    std::set<long> used;
    for (const GmshElement &e : elements)
      if (const Shape *s = find_shape(e.type); s && s->dim <= dim)
        used.insert(e.nodes.begin(), e.nodes.end());
    std::map<long, unsigned int> file_index;
    for (const long tag : used)
      {
        file_index[tag] = mesh.points.size();
        mesh.node_tags.push_back(tag);
        mesh.points.push_back(Point<3>(coordinates.at(tag) - origin));
      }
    mesh.n_file_nodes = mesh.points.size();

    PointMaker points(mesh, std::move(file_index));
    for (std::size_t i = 0; i < elements.size(); ++i)
      {
        const Shape *s = find_shape(elements[i].type);
        if (s == nullptr || s->dim > dim)
          continue;
        auto  pieces = split_element(elements[i], *s, i, points);
        auto &target = s->dim == dim ? mesh.cells : mesh.boundary;
        target.insert(target.end(), pieces.begin(), pieces.end());
        if (s->dim == dim)
          ++mesh.n_split[s->gmsh_type];
      }
    return mesh;
  }

  std::string
  msh22_text(const SplitMesh &mesh)
  {
    std::ostringstream out;
    out << std::setprecision(17) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n"
        << mesh.points.size() << '\n';
    for (std::size_t i = 0; i < mesh.points.size(); ++i)
      out << i + 1 << ' ' << mesh.points[i][0] << ' ' << mesh.points[i][1] << ' '
          << mesh.points[i][2] << '\n';
    out << "$EndNodes\n$Elements\n" << mesh.boundary.size() + mesh.cells.size() << '\n';
    std::size_t k = 0;
    for (const auto *list : {&mesh.boundary, &mesh.cells})
      for (const auto &piece : *list)
        {
          out << ++k << ' ' << piece.type << " 1 " << piece.physical;
          for (const unsigned int v : piece.vertices)
            out << ' ' << v + 1;
          out << '\n';
        }
    out << "$EndElements\n";
    return out.str();
  }

  std::string
  split_summary(const SplitMesh &mesh, const unsigned int dim)
  {
    std::string text;
    for (const auto &[type, count] : mesh.n_split)
      {
        const Shape *s = find_shape(type);
        text +=
          (text.empty() ? "" : ", ") + std::to_string(count) + " " +
          (count == 1 ? s->singular : s->plural) + (text.empty() ? " split into " : " into ") +
          std::to_string(count * s->corners.size()) + (dim == 2 ? " quadrilaterals" : " hexahedra");
      }
    return text;
  }
} // namespace contact_fem
