// The split of triangles, tetrahedra and prisms on reading a Gmsh file
// (source/geometry/mesh_split.cc through read_gmsh()), on small meshes
// written here, each with the answer known by construction:
//  - 2D: a triangle beside a quadrilateral (a mixed mesh) gives 3 + 4
//    quadrilaterals covering the same area; the boundary lines keep their
//    physical tags (each split in two: same length per id), the cells their
//    material ids; the shared edge is split once (7 cells, 13 vertices);
//  - 3D: a tetrahedron, a prism on a face of it and a hexahedron beside the
//    prism give 4 + 6 + 8 hexahedra of the same volume; boundary triangles
//    and quadrilaterals keep their ids and areas; the mesh is conforming
//    (deal.II refuses it otherwise), every cell positive;
//  - the same 3D mesh with its nodes renumbered, its elements listed in
//    another order and each element's nodes rotated gives the same cells,
//    bit for bit (the split does not depend on the numbering);
//  - MSH 4.1: the physical tags come from $Entities.
#include <deal.II/grid/tria.h>

#include <contact_fem/geometry/mesh_file.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <vector>

using namespace dealii;
using namespace contact_fem;

namespace
{
  template <int dim>
  Triangulation<dim>
  read(const std::string &name, const std::string &text, MeshFileInfo &info)
  {
    std::ofstream(name) << text;
    Triangulation<dim> tria;
    info = read_gmsh(name, tria);
    return tria;
  }

  template <int dim>
  void
  report(const Triangulation<dim> &tria, const MeshFileInfo &info)
  {
    double                           measure = 0.;
    std::map<unsigned int, double>   boundary;
    std::map<unsigned int, unsigned> materials;
    unsigned int                     n_inverted = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        measure += cell->measure();
        ++materials[cell->material_id()];
        n_inverted += is_inverted<dim>(cell) ? 1 : 0;
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            boundary[cell->face(f)->boundary_id()] += cell->face(f)->measure();
      }
    std::cout << "  " << info.split_note << "; " << tria.n_active_cells() << " cells, "
              << tria.n_vertices() << " vertices (the file's: " << info.first_new_vertex
              << "), measure " << measure << ", inverted cells " << n_inverted << std::endl;
    std::cout << "  material ids:";
    for (const auto &[id, n] : materials)
      std::cout << " " << id << " (" << n << " cells)";
    std::cout << std::endl << "  boundary ids:";
    for (const auto &[id, size] : boundary)
      std::cout << " " << id << " (" << size << ")";
    std::cout << std::endl;
  }

  /// Each cell as its sorted vertex coordinates, sorted: the mesh up to
  /// the numbering of vertices and cells.
  std::vector<std::vector<std::array<double, 3>>>
  cells_of(const Triangulation<3> &tria)
  {
    std::vector<std::vector<std::array<double, 3>>> cells;
    for (const auto &cell : tria.active_cell_iterators())
      {
        std::vector<std::array<double, 3>> x;
        for (const unsigned int v : cell->vertex_indices())
          x.push_back({{cell->vertex(v)[0], cell->vertex(v)[1], cell->vertex(v)[2]}});
        std::sort(x.begin(), x.end());
        cells.push_back(x);
      }
    std::sort(cells.begin(), cells.end());
    return cells;
  }

  const std::string mixed_2d = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$Nodes
5
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
5 2 0.5 0
$EndNodes
$Elements
7
1 1 2 1 1 1 2
2 1 2 2 2 3 4
3 1 2 3 3 2 5
4 1 2 3 3 5 3
5 1 2 4 4 4 1
6 3 2 10 10 1 2 3 4
7 2 2 20 20 2 5 3
$EndElements
)";

  /// Nodes 1-4 the base square, 5-8 the top of the hexahedron [0,1]^3,
  /// 9-10 the ridge of the prism on the hexahedron's face x = 1 (its
  /// triangles y = 0 and y = 1), 11 the apex of the tetrahedron on the
  /// prism's face y = 0.
  std::string
  mixed_3d(const std::vector<int> &tag, const bool reordered)
  {
    const std::array<Point<3>, 11> x = {{{0, 0, 0},
                                                      {1, 0, 0},
                                                      {1, 1, 0},
                                                      {0, 1, 0},
                                                      {0, 0, 1},
                                                      {1, 0, 1},
                                                      {1, 1, 1},
                                                      {0, 1, 1},
                                                      {2, 0, 0.5},
                                                      {2, 1, 0.5},
                                                      {1.5, -1, 0.5}}};
    std::ostringstream                          out;
    out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n11\n";
    for (unsigned int i = 0; i < 11; ++i)
      out << tag[i] << " " << x[i][0] << " " << x[i][1] << " " << x[i][2] << "\n";
    const auto n = [&](const std::vector<int> &local) {
      std::string s;
      for (const int i : local)
        s += " " + std::to_string(tag[i - 1]);
      return s;
    };
    // 'type 2 physical elementary nodes'; the second listing rotates each
    // element's nodes (the same cell, the same turn).
    std::vector<std::string> elements = {
      "3 2 2 2" + (reordered ? n({3, 2, 1, 4}) : n({1, 4, 3, 2})) + "\n", // base z = 0
      "2 2 1 1" + (reordered ? n({9, 11, 2}) : n({2, 9, 11})) + "\n", // a face of the tetrahedron
      "2 2 3 3" + (reordered ? n({10, 7, 3}) : n({3, 10, 7})) + "\n", // the prism's end y = 1
      "5 2 1 1" + (reordered ? n({4, 3, 2, 1, 8, 7, 6, 5}) : n({1, 2, 3, 4, 5, 6, 7, 8})) + "\n",
      "6 2 1 1" + (reordered ? n({6, 9, 2, 7, 10, 3}) : n({2, 6, 9, 3, 7, 10})) + "\n",
      "4 2 2 2" + (reordered ? n({9, 6, 2, 11}) : n({2, 9, 6, 11})) + "\n"};
    if (reordered)
      std::reverse(elements.begin(), elements.end());
    out << "$EndNodes\n$Elements\n" << elements.size() << "\n";
    for (unsigned int i = 0; i < elements.size(); ++i)
      out << i + 1 << " " << elements[i];
    out << "$EndElements\n";
    return out.str();
  }

  const std::string msh41 = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$Entities
0 1 1 0
1 0 0 0 1 0 0 1 7 0
1 0 0 0 1 1 0 1 3 0
$EndEntities
$Nodes
1 4 1 4
2 1 0 4
1
2
3
4
0 0 0
1 0 0
1 1 0
0 1 0
$EndNodes
$Elements
2 3 1 3
1 1 1 1
1 1 2
2 1 2 2
2 1 2 3
3 1 3 4
$EndElements
)";
} // namespace

int
main()
{
  MeshFileInfo info;
  std::cout << "2D: a triangle beside a quadrilateral" << std::endl;
  report(read<2>("mixed_2d.msh", mixed_2d, info), info);

  std::cout << "3D: a tetrahedron, a prism and a hexahedron" << std::endl;
  const std::vector<int> tags = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  const auto             a    = read<3>("mixed_3d.msh", mixed_3d(tags, false), info);
  report(a, info);

  const std::vector<int> renumbered = {40, 7, 33, 2, 91, 15, 8, 60, 3, 12, 5};
  const auto             b = read<3>("mixed_3d_renumbered.msh", mixed_3d(renumbered, true), info);
  std::cout << "  renumbered and reordered: the same cells bit for bit: "
            << (cells_of(a) == cells_of(b) ? "yes" : "no") << std::endl;

  std::cout << "MSH 4.1 with $Entities" << std::endl;
  report(read<2>("msh41.msh", msh41, info), info);
}
