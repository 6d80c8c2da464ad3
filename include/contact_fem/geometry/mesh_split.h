// Meshes as users make them: a Gmsh mesh with triangles (2D), tetrahedra or
// prisms (3D) is split on reading into quadrilaterals or hexahedra, so that
// p4est and the mortar code see the cells they know.
#ifndef contact_fem_mesh_split_h
#define contact_fem_mesh_split_h

#include <deal.II/base/point.h>

#include <cstddef>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /// One element of a Gmsh file, as the scan found it.
  struct GmshElement
  {
    int               type     = 0; ///< Gmsh element type (2 triangle, 4 tetrahedron, ...)
    long              tag      = 0;
    unsigned int      line     = 0; ///< of the file, for messages
    int               physical = 0; ///< physical tag (0: none)
    std::vector<long> nodes;
  };

  /**
   * The mesh after the split: every cell into one quadrilateral (2D) or
   * hexahedron (3D) per corner, bounded by the corner, the midpoints of its
   * edges, the centres of its faces and the centre of the cell:
   * triangle -> 3 quadrilaterals, quadrilateral -> 4; tetrahedron -> 4
   * hexahedra, prism -> 6, hexahedron -> 8. A face is split alike from
   * either side (triangle -> 3, quadrilateral -> 4), so the mesh stays
   * conforming; boundary lines and faces are split with it and keep their
   * physical tags.
   */
  struct SplitMesh
  {
    /// Coordinates in the computing frame: the file's nodes used by an
    /// element (by increasing node tag), then the new points.
    std::vector<Point<3>> points;
    std::size_t           n_file_nodes = 0;
    std::vector<long>     node_tags; ///< Gmsh tags of the first n_file_nodes points

    /// A piece of an element: its points (Gmsh order: quadrilateral,
    /// hexahedron or line), the index of the element it comes from and the
    /// corner of that element it holds.
    struct Piece
    {
      int                       type     = 0; ///< Gmsh type of the piece (1, 3 or 5)
      int                       physical = 0;
      std::vector<unsigned int> vertices;
      std::size_t               parent = 0;
      unsigned int              corner = 0;
    };
    std::vector<Piece> cells;    ///< of dimension dim
    std::vector<Piece> boundary; ///< lines (and quadrilaterals in 3D)

    /// Gmsh type of the split cells -> their number.
    std::map<int, std::size_t> n_split;
  };

  /// Whether the @p dim D mesh with these element counts (Gmsh type ->
  /// number) holds cells that must be split: triangles, tetrahedra, prisms.
  bool
  needs_split(const std::map<int, std::size_t> &element_counts, unsigned int dim);

  /**
   * Splits @p elements (nodes at @p coordinates, moved by -@p origin into
   * the computing frame). New points lie on the straight element; a centre
   * is the mean of the corners summed in the order of their coordinates,
   * so that it does not depend on the numbering of the nodes. Points
   * (Gmsh type 15) are dropped: deal.II does not use them beyond 1D.
   */
  SplitMesh
  split_mesh(const std::vector<GmshElement>           &elements,
             const std::unordered_map<long, Point<3>> &coordinates,
             const Point<3>                           &origin,
             unsigned int                              dim);

  /// @p mesh as the text of an ASCII MSH 2.2 file (coordinates to 17
  /// digits: read back exactly), for deal.II's reader.
  std::string
  msh22_text(const SplitMesh &mesh);

  /// "24 tetrahedra split into 96 hexahedra, 3 prisms into 18 hexahedra".
  std::string
  split_summary(const SplitMesh &mesh, unsigned int dim);
} // namespace contact_fem

#endif
