#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q_cache.h>
#include <deal.II/numerics/rtree.h>

#include <contact_fem/core/format.h>
#include <contact_fem/simulator/interpenetration_check.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace contact_fem
{
  namespace
  {
    /// Distance from @p x to the segment [a, b].
    template <int dim>
    double
    segment_distance(const Point<dim> &x, const Point<dim> &a, const Point<dim> &b)
    {
      const Tensor<1, dim> d  = b - a;
      const double         dd = d * d;
      const double         t  = dd > 0. ? std::clamp((x - a) * d / dd, 0., 1.) : 0.;
      return x.distance(a + t * d);
    }

    /// Distance from @p x to the triangle (a, b, c) (3D).
    template <int dim>
    double
    triangle_distance(const Point<dim> &x,
                      const Point<dim> &a,
                      const Point<dim> &b,
                      const Point<dim> &c)
    {
      // The foot of the perpendicular if it lies inside; else the nearest
      // edge.
      const Tensor<1, dim> ab = b - a, ac = c - a, ax = x - a;
      const double         d00 = ab * ab, d01 = ab * ac, d11 = ac * ac;
      const double         det = d00 * d11 - d01 * d01;
      if (det > 0.)
        {
          const double r0 = ax * ab, r1 = ax * ac;
          const double s = (d11 * r0 - d01 * r1) / det, t = (d00 * r1 - d01 * r0) / det;
          if (s >= 0. && t >= 0. && s + t <= 1.)
            return x.distance(a + s * ab + t * ac);
        }
      return std::min(
        {segment_distance(x, a, b), segment_distance(x, b, c), segment_distance(x, c, a)});
    }

    /// Distance from @p x to a boundary face given by its deformed vertices
    /// (deal.II order): a segment in 2D; in 3D four triangles around the
    /// centre of the bilinear quadrilateral.
    template <int dim>
    double
    face_distance(const Point<dim> &x, const std::vector<Point<dim>> &v)
    {
      if constexpr (dim == 2)
        return segment_distance(x, v[0], v[1]);
      else
        {
          const Point<dim> centre = Point<dim>((v[0] + v[1] + v[2] + v[3]) / 4.);
          // deal.II's quadrilateral order 0 1 3 2 goes round the face.
          const unsigned int ring[4] = {0, 1, 3, 2};
          double             result  = std::numeric_limits<double>::max();
          for (unsigned int k = 0; k < 4; ++k)
            result =
              std::min(result, triangle_distance(x, v[ring[k]], v[ring[(k + 1) % 4]], centre));
          return result;
        }
    }

    template <int dim>
    BoundingBox<dim>
    box_of(const std::vector<Point<dim>> &points, const double margin)
    {
      Point<dim> low = points[0], high = points[0];
      for (const auto &p : points)
        for (unsigned int d = 0; d < dim; ++d)
          {
            low[d]  = std::min(low[d], p[d]);
            high[d] = std::max(high[d], p[d]);
          }
      for (unsigned int d = 0; d < dim; ++d)
        {
          low[d] -= margin;
          high[d] += margin;
        }
      return BoundingBox<dim>(std::make_pair(low, high));
    }
  } // namespace

  template <int dim>
  InterpenetrationCheck<dim>::InterpenetrationCheck(const DoFHandler<dim>          &dof_handler,
                                                    const MappingQ<dim>            &mapping,
                                                    const std::vector<ContactPair> &pairs,
                                                    const double                    tolerance)
    : dof_handler(dof_handler)
    , mapping(mapping)
    , pairs(pairs)
    , tolerance(tolerance)
  {}

  template <int dim>
  typename InterpenetrationCheck<dim>::Finding
  InterpenetrationCheck<dim>::check(
    const TrilinosWrappers::MPI::Vector             &solution,
    const TrilinosWrappers::MPI::Vector             &ghosted_solution,
    const std::map<types::global_dof_index, double> &allowed_by_contact)
  {
    const MPI_Comm comm = dof_handler.get_communicator();
    // The deformed mapping of the cells (of the reference mapping's degree,
    // which follows curved boundaries). From the owned vector: deal.II
    // imports the ghosts itself and refuses a ghosted Trilinos vector.
    const unsigned int degree = mapping.get_degree();
    MappingQCache<dim> deformed(degree);
    deformed.initialize(mapping, dof_handler, solution, true);

    // The deformed boundary faces of this rank's cells, flattened for the
    // exchange: body, boundary id, per vertex its x DoF, reference and
    // deformed position, then the face's points on a grid of degree + 1
    // per direction (a curved face is measured by its chords between
    // them: the sag of a chord is that of the face over 4 degree^2).
    constexpr unsigned int   n_face_vertices = GeometryInfo<dim>::vertices_per_face;
    const QIterated<dim - 1> grid(QTrapezoid<1>(), degree);
    const unsigned int       face_size = 2 + n_face_vertices * (1 + 2 * dim) + grid.size() * dim;
    FEFaceValues<dim>   face_values(deformed, dof_handler.get_fe(), grid, update_quadrature_points);
    std::vector<double> own_faces;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              own_faces.push_back(cell->material_id());
              own_faces.push_back(cell->face(f)->boundary_id());
              for (unsigned int v = 0; v < n_face_vertices; ++v)
                {
                  const auto vertex = cell->face(f)->vertex(v);
                  own_faces.push_back(cell->face(f)->vertex_dof_index(v, 0));
                  for (unsigned int d = 0; d < dim; ++d)
                    own_faces.push_back(vertex[d]);
                  for (unsigned int d = 0; d < dim; ++d)
                    own_faces.push_back(vertex[d] +
                                        ghosted_solution(cell->face(f)->vertex_dof_index(v, d)));
                }
              face_values.reinit(cell, f);
              for (const auto &x : face_values.get_quadrature_points())
                for (unsigned int d = 0; d < dim; ++d)
                  own_faces.push_back(x[d]);
            }

    // A face: its grid of deformed points, split into facets of 2 (2D) or
    // 4 (3D, deal.II's vertex order) points.
    struct Face
    {
      types::material_id                   body;
      types::boundary_id                   boundary;
      std::vector<std::vector<Point<dim>>> facets;
      std::vector<Point<dim>>              points; ///< all points, for the box
      std::vector<types::global_dof_index> dofs;   ///< x DoF of each vertex
    };
    struct Vertex
    {
      Point<dim>                   reference, position;
      double                       size = std::numeric_limits<double>::max();
      std::set<types::material_id> bodies;
      std::set<types::boundary_id> boundaries;
    };
    const unsigned int                        n = degree + 1; // grid points per direction
    std::vector<Face>                         faces;
    std::map<types::global_dof_index, Vertex> vertices; // by x DoF: the same on all ranks
    for (const auto &chunk : Utilities::MPI::all_gather(comm, own_faces))
      for (unsigned int i = 0; i + face_size <= chunk.size(); i += face_size)
        {
          Face face;
          face.body     = static_cast<types::material_id>(chunk[i]);
          face.boundary = static_cast<types::boundary_id>(chunk[i + 1]);
          std::vector<Point<dim>> corners;
          for (unsigned int v = 0; v < n_face_vertices; ++v)
            {
              const double *data = &chunk[i + 2 + v * (1 + 2 * dim)];
              face.dofs.push_back(static_cast<types::global_dof_index>(data[0]));
              Vertex &vertex = vertices[face.dofs.back()];
              for (unsigned int d = 0; d < dim; ++d)
                {
                  vertex.reference[d] = data[1 + d];
                  vertex.position[d]  = data[1 + dim + d];
                }
              vertex.bodies.insert(face.body);
              vertex.boundaries.insert(face.boundary);
              corners.push_back(vertex.position);
            }
          const double *grid_data = &chunk[i + 2 + n_face_vertices * (1 + 2 * dim)];
          for (unsigned int q = 0; q < grid.size(); ++q)
            {
              Point<dim> x;
              for (unsigned int d = 0; d < dim; ++d)
                x[d] = grid_data[q * dim + d];
              face.points.push_back(x);
            }
          if constexpr (dim == 2)
            for (unsigned int k = 0; k + 1 < n; ++k)
              face.facets.push_back({face.points[k], face.points[k + 1]});
          else
            for (unsigned int b = 0; b + 1 < n; ++b)
              for (unsigned int a = 0; a + 1 < n; ++a)
                face.facets.push_back({face.points[b * n + a], face.points[b * n + a + 1],
                                       face.points[(b + 1) * n + a],
                                       face.points[(b + 1) * n + a + 1]});
          // The vertex's element size: the shortest edge of its faces.
          for (unsigned int a = 0; a < n_face_vertices; ++a)
            for (unsigned int b = 0; b < a; ++b)
              if (dim == 2 || (a ^ b) == 1 || (a ^ b) == 2)
                {
                  const double length = corners[a].distance(corners[b]);
                  for (const unsigned int v : {a, b})
                    vertices[face.dofs[v]].size = std::min(vertices[face.dofs[v]].size, length);
                }
          faces.push_back(std::move(face));
        }
    n_vertices = vertices.size();

    // The cells' bounding boxes, enlarged: a curved cell may bulge beyond
    // its support points.
    std::vector<std::pair<BoundingBox<dim>, unsigned int>>      cell_boxes;
    std::vector<typename DoFHandler<dim>::active_cell_iterator> cells;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          BoundingBox<dim> box  = deformed.get_bounding_box(cell);
          double           side = 0.;
          for (unsigned int d = 0; d < dim; ++d)
            side = std::max(side, box.side_length(d));
          box.extend(0.1 * side);
          cell_boxes.emplace_back(box, cells.size());
          cells.push_back(cell);
        }
    const auto                                             cell_tree = pack_rtree(cell_boxes);
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> face_boxes;
    for (unsigned int f = 0; f < faces.size(); ++f)
      face_boxes.emplace_back(box_of(faces[f].points, 0.), f);
    const auto face_tree = pack_rtree(face_boxes);

    // How deep the vertex @p dof at @p x lies below the surface of @p
    // body, up to @p limit (beyond it: limit); the faces of the vertex
    // itself do not count (of its own body: a fold).
    const auto depth_below_surface = [&](const types::global_dof_index dof, const Point<dim> &x,
                                         const types::material_id body, const double limit) {
      std::vector<std::pair<BoundingBox<dim>, unsigned int>> near;
      face_tree.query(boost::geometry::index::intersects(box_of<dim>({x}, limit)),
                      std::back_inserter(near));
      double depth = limit;
      for (const auto &[box, f] : near)
        if (faces[f].body == body &&
            std::find(faces[f].dofs.begin(), faces[f].dofs.end(), dof) == faces[f].dofs.end())
          for (const auto &facet : faces[f].facets)
            depth = std::min(depth, face_distance(x, facet));
      return depth;
    };

    // The partner bodies of the pairs: a slave vertex inside the master
    // body, a master vertex inside the slave body.
    std::map<types::boundary_id, std::set<types::material_id>> body_of_surface;
    for (const auto &face : faces)
      body_of_surface[face.boundary].insert(face.body);
    const auto partner = [&](const Vertex &vertex, const types::material_id body) {
      // 0: not a partner, 1: the vertex is a slave vertex of a pair whose
      // master is @p body, 2: a master vertex of a pair whose slave is it.
      unsigned int result = 0;
      for (const auto &pair : pairs)
        {
          if (vertex.boundaries.count(pair.slave) && body_of_surface[pair.master].count(body))
            result = 1;
          if (result == 0 && vertex.boundaries.count(pair.master) &&
              body_of_surface[pair.slave].count(body))
            result = 2;
        }
      return result;
    };

    n_candidates           = 0;
    n_inside               = 0;
    n_found                = 0;
    const double unbounded = std::numeric_limits<double>::max() / 4.;
    // Per rank its findings: the depth over the vertex size, the x DoF of
    // the vertex, the body of the cell, the depth and the kind.
    std::vector<double>                                    findings;
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
    for (const auto &[dof, vertex] : vertices)
      {
        hits.clear();
        cell_tree.query(boost::geometry::index::intersects(box_of<dim>({vertex.position}, 0.)),
                        std::back_inserter(hits));
        for (const auto &[box, c] : hits)
          {
            const auto &cell = cells[c];
            bool        own  = false;
            for (const auto v : cell->vertex_indices())
              own = own || cell->vertex_dof_index(v, 0) == dof;
            if (own)
              continue;
            ++n_candidates;
            Point<dim> xi;
            try
              {
                xi = deformed.transform_real_to_unit_cell(cell, vertex.position);
              }
            catch (const typename Mapping<dim>::ExcTransformationFailed &)
              {
                continue;
              }
            // Inside the cell: its body's surface is where the depth is
            // measured; a point on the cell's boundary counts (its depth is
            // then small unless the cell is interior).
            if (!GeometryInfo<dim>::is_inside_unit_cell(xi, 1e-10))
              continue;
            ++n_inside;
            const types::material_id body = cell->material_id();
            const unsigned int kind = vertex.bodies.count(body) ? 0u : 1u + partner(vertex, body);
            // 0 fold, 1 unpaired body, 2 slave in master (what the
            // penetration check allows), 3 master in slave (one element).
            double allowed = (kind == 3 ? 1. : tolerance) * vertex.size;
            if (kind == 2)
              if (const auto a = allowed_by_contact.find(dof); a != allowed_by_contact.end())
                allowed = std::max(allowed, a->second);
            if (depth_below_surface(dof, vertex.position, body, 2. * allowed) <= allowed)
              continue;
            // Found (rare): the whole depth.
            const double depth = depth_below_surface(dof, vertex.position, body, unbounded);
            findings.insert(findings.end(),
                            {depth / vertex.size, static_cast<double>(dof),
                             static_cast<double>(body), depth, static_cast<double>(kind)});
          }
      }

    // The deepest over all ranks, the same on every rank. Symmetric
    // vertices lie alike deep: the tie goes to the smaller reference
    // coordinates, not to the last bit of the depth or the DoF numbering.
    Finding                     result;
    std::vector<const double *> all;
    const auto                  gathered = Utilities::MPI::all_gather(comm, findings);
    for (const auto &chunk : gathered)
      for (unsigned int i = 0; i + 5 <= chunk.size(); i += 5)
        all.push_back(&chunk[i]);
    if (all.empty())
      return result;
    const auto reference_of = [&](const double *f) {
      return vertices.at(static_cast<types::global_dof_index>(f[1])).reference;
    };
    const auto precedes = [](const Point<dim> &a, const Point<dim> &b) {
      for (unsigned int d = 0; d < dim; ++d)
        if (a[d] != b[d])
          return a[d] < b[d];
      return false;
    };
    const double *deepest = all[0];
    for (const double *f : all)
      {
        const bool tie = std::abs(f[0] - deepest[0]) <= 1e-9 * deepest[0];
        if (tie ? precedes(reference_of(f), reference_of(deepest)) : f[0] > deepest[0])
          deepest = f;
      }
    n_found = 0;
    {
      std::set<double> flagged;
      for (const double *f : all)
        flagged.insert(f[1]);
      n_found = flagged.size();
    }
    const auto    dof    = static_cast<types::global_dof_index>(deepest[1]);
    const Vertex &vertex = vertices.at(dof);
    result.found         = true;
    result.reference     = vertex.reference;
    result.position      = vertex.position;
    result.size          = vertex.size;
    result.cell_body     = static_cast<unsigned int>(deepest[2]);
    result.vertex_body   = *vertex.bodies.begin();
    for (const auto b : vertex.boundaries)
      result.boundary_ids.push_back(b);
    const unsigned int kind = static_cast<unsigned int>(deepest[4]);
    result.kind             = kind == 0 ? "fold" : kind == 1 ? "unpaired body" : "paired body";
    result.depth            = deepest[3];
    return result;
  }

  template <int dim>
  std::string
  InterpenetrationCheck<dim>::message(const Finding &finding) const
  {
    std::ostringstream text;
    text << "the converged solution interpenetrates: the boundary vertex at (" << finding.reference
         << ") of body " << finding.vertex_body << " (boundary id";
    if (finding.boundary_ids.size() > 1)
      text << "s";
    for (unsigned int i = 0; i < finding.boundary_ids.size(); ++i)
      text << (i == 0 ? " " : ", ") << finding.boundary_ids[i];
    text << "), now at (" << finding.position << "), lies " << scientific(finding.depth, 3)
         << " (h = " << scientific(finding.size, 3) << ") inside ";
    if (finding.kind == "fold")
      text << "its own body: the body folds onto itself, and self-contact is not implemented";
    else if (finding.kind == "unpaired body")
      text << "body " << finding.cell_body
           << ", with which no contact pair pairs that boundary: add the pair "
              "(Contact/Pairs) or keep the bodies apart";
    else
      text << "body " << finding.cell_body
           << ", the slave body of its pair, deeper than one element of the master surface";
    text << "; " << n_found << " boundary vertex(es) lie deeper than the tolerance (" << tolerance
         << " h = Contact/Penetration tolerance; interpenetration check of the "
         << "deformed mesh)";
    return text.str();
  }

  template <int dim>
  Json
  InterpenetrationCheck<dim>::record(const Finding &finding) const
  {
    Json result = Json::object()
                    .set("boundary_vertices", n_vertices)
                    .set("vertex_cell_candidates", n_candidates)
                    .set("vertices_inside_other_cells", n_inside)
                    .set("flagged_vertices", n_found)
                    .set("found", finding.found);
    if (!finding.found)
      return result;
    Json reference = Json::array(), position = Json::array(), ids = Json::array();
    for (unsigned int d = 0; d < dim; ++d)
      {
        reference.push(finding.reference[d]);
        position.push(finding.position[d]);
      }
    for (const unsigned int b : finding.boundary_ids)
      ids.push(b);
    return result.set("kind", finding.kind)
      .set("vertex_body", finding.vertex_body)
      .set("vertex_boundary_ids", ids)
      .set("inside_body", finding.cell_body)
      .set("vertex_reference", reference)
      .set("vertex_position", position)
      .set("depth", finding.depth)
      .set("vertex_size", finding.size);
  }

  template class InterpenetrationCheck<2>;
  template class InterpenetrationCheck<3>;
} // namespace contact_fem
