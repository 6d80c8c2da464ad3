#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/boost_adaptors/bounding_box.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/rtree.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/core/format.h>
#include <contact_fem/contact/mortar.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

namespace contact_fem
{
  template <int dim>
  void
  ContactInterface<dim>::unpack_faces(const std::vector<std::vector<double>> &all,
                                      const unsigned int                      nodes_per_face,
                                      const unsigned int                      n_geometry_points)
  {
    // Nodes shared by faces (of one rank or of several) become one node:
    // they are identified by their first DoF.
    nodes.clear();
    faces.clear();
    slave_faces_per_rank.clear();
    master_faces_per_rank.clear();
    std::map<types::global_dof_index, unsigned int> node_of_dof;
    const unsigned int record = 5 + nodes_per_face * 3 * dim + n_geometry_points * dim;
    for (const auto &chunk : all)
      {
        slave_faces_per_rank.push_back(0);
        master_faces_per_rank.push_back(0);
        for (unsigned int r = 0; r + record <= chunk.size(); r += record)
          {
            Face face;
            face.pair           = static_cast<unsigned int>(chunk[r]);
            face.slave          = chunk[r + 1] > 0.5;
            face.youngs_modulus = chunk[r + 2];
            face.poisson_ratio  = chunk[r + 3];
            face.orientation    = chunk[r + 4];
            for (unsigned int k = 0; k < nodes_per_face; ++k)
              {
                const double *data = &chunk[r + 5 + k * 3 * dim];
                Node          node;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    node.reference[d] = data[d];
                    node.dofs[d] = static_cast<types::global_dof_index>(data[dim + d]);
                    node.fixed[d] = data[2 * dim + d] > 0.5;
                  }
                const auto it = node_of_dof.find(node.dofs[0]);
                unsigned int index;
                if (it == node_of_dof.end())
                  {
                    index                     = nodes.size();
                    node_of_dof[node.dofs[0]] = index;
                    nodes.push_back(node);
                  }
                else
                  index = it->second;
                (face.slave ? nodes[index].slave : nodes[index].master) = true;
                face.nodes.push_back(index);
              }
            for (unsigned int k = 0; k < n_geometry_points; ++k)
              {
                const double *data = &chunk[r + 5 + nodes_per_face * 3 * dim + k * dim];
                Point<dim>    x;
                for (unsigned int d = 0; d < dim; ++d)
                  x[d] = data[d];
                face.geometry_points.push_back(x);
              }
            ++(face.slave ? slave_faces_per_rank.back() : master_faces_per_rank.back());
            faces.push_back(face);
          }
      }
  }

  namespace
  {
    /**
     * Positive if the node polygon of the face of @p fe_face (its support
     * points, in face DoF order) turns its normal (rotated tangent in 2D,
     * t_xi x t_eta in 3D) out of the cell, negative otherwise. The support
     * points are in the face's own orientation (FEFaceValues permutes them
     * like the face DoFs); in 3D their vertices are checked against those
     * of @p face, in case that ever changes.
     */
    template <int dim, typename FaceIterator>
    double
    outward_orientation(const FEFaceValues<dim> &fe_face,
                        const FaceIterator      &face,
                        const unsigned int       nodes_per_face)
    {
      if constexpr (dim == 2)
        {
          Mortar::LineFace line;
          for (unsigned int k = 0; k < nodes_per_face; ++k)
            {
              Point<2> x;
              for (unsigned int d = 0; d < 2; ++d)
                x[d] = fe_face.quadrature_point(k)[d];
              line.nodes.push_back(x);
            }
          const Tensor<1, 2> n_rot = Mortar::face_normal(line, -1., 1.);
          double             dot   = 0.;
          for (unsigned int d = 0; d < 2; ++d)
            dot += n_rot[d] * fe_face.normal_vector(0)[d];
          return dot;
        }
      else
        {
          Mortar::QuadFace quad;
          for (unsigned int k = 0; k < nodes_per_face; ++k)
            quad.nodes.push_back(fe_face.quadrature_point(k));
          for (unsigned int v = 0; v < 4; ++v)
            AssertThrow(quad.nodes[v].distance(face->vertex(v)) <= 1e-10 * face->diameter(),
                        ExcMessage("Contact: the support points of a 3D contact face "
                                   "are not in the order of its vertices."));
          return Mortar::face_normal(quad, Point<2>(-1., -1.), 1.) * fe_face.normal_vector(0);
        }
    }
  } // namespace

  template <int dim>
  void
  ContactInterface<dim>::initialize(const MappingQ<dim>             &mapping,
                                    const DoFHandler<dim>           &dof_handler,
                                    const std::vector<ContactPair>  &contact_pairs,
                                    const AffineConstraints<double> &dirichlet,
                                    const AffineConstraints<double> &hanging,
                                    const Materials<dim>            &materials,
                                    const MPI_Comm                   comm)
  {
    pairs        = contact_pairs;
    communicator = comm;
    owned_dofs   = dof_handler.locally_owned_dofs();
    const FiniteElement<dim> &fe = dof_handler.get_fe();
    degree                       = fe.degree;
    geometry_degree              = std::max(degree, mapping.get_degree());
    // The mortar kernels (mortar.h, mortar_3d.h) take faces of degree 1 or
    // 2, and a geometry above the element degree only as Q1 on a quadratic
    // mapping.
    AssertThrow(geometry_degree == degree || (degree == 1 && geometry_degree == 2),
                ExcMessage("Contact: the geometry of the contact faces (degree " +
                           std::to_string(geometry_degree) + ") may exceed the element "
                           "degree (" + std::to_string(degree) + ") only for degree-1 "
                           "elements on a quadratic mapping (Finite element/Mapping "
                           "degree = 2 or auto)."));
    const unsigned int nodes_per_face = fe.n_dofs_per_face() / dim;
    // Geometry nodes without DoFs of Q1 on a quadratic mapping, whose faces
    // follow the curved boundary: the face midpoint in 2D; the four edge
    // midpoints and the centre in 3D (nodes 4-8 of Mortar::QuadFace).
    const unsigned int n_geometry_points =
      Utilities::fixed_power<dim - 1>(geometry_degree + 1) - nodes_per_face;

    // Support points of the base element on a face, in face DoF order.
    const Quadrature<dim - 1> support(fe.base_element(0).get_unit_face_support_points());
    FEFaceValues<dim>         fe_face(mapping, fe, support,
                              update_quadrature_points | update_normal_vectors);
    // The geometry points in the kernels' node order, in 3D after the
    // vertices, to check that they follow the orientation of the face as
    // its support points do (a midpoint of a line has no orientation).
    const unsigned int          first_geometry_node = dim == 2 ? nodes_per_face : 0;
    std::vector<Point<dim - 1>> geometry_nodes;
    if (n_geometry_points > 0)
      for (unsigned int k = first_geometry_node; k < nodes_per_face + n_geometry_points; ++k)
        {
          Point<dim - 1> x;
          if constexpr (dim == 2)
            x[0] = 0.5 * (Mortar::node_parameter(2, k) + 1.);
          else
            for (unsigned int d = 0; d < 2; ++d)
              x[d] = 0.5 * (Mortar::quad_node_parameter(2, k)[d] + 1.);
          geometry_nodes.push_back(x);
        }
    std::unique_ptr<FEFaceValues<dim>> fe_face_geometry;
    if (n_geometry_points > 0)
      fe_face_geometry = std::make_unique<FEFaceValues<dim>>(
        mapping, fe, Quadrature<dim - 1>(geometry_nodes), update_quadrature_points);

    // Pack the local faces: [pair, slave, E, nu, orientation, then per node:
    // coordinates, dofs, fixed flags].
    std::vector<double>                  packed;
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            for (unsigned int p = 0; p < pairs.size(); ++p)
              for (const bool slave : {true, false})
                {
                  const types::boundary_id id = slave ? pairs[p].slave : pairs[p].master;
                  if (cell->face(f)->boundary_id() != id)
                    continue;
                  fe_face.reinit(cell, f);
                  cell->face(f)->get_dof_indices(face_dofs);
                  std::vector<std::array<types::global_dof_index, dim>> node_dofs(
                    nodes_per_face);
                  for (unsigned int i = 0; i < face_dofs.size(); ++i)
                    {
                      const auto ci = fe.face_system_to_component_index(i, f);
                      node_dofs[ci.second][ci.first] = face_dofs[i];
                    }
                  const double dot = outward_orientation(fe_face, cell->face(f), nodes_per_face);

                  packed.push_back(p);
                  packed.push_back(slave ? 1. : 0.);
                  packed.push_back(materials.constants(cell->material_id()).youngs_modulus);
                  packed.push_back(materials.constants(cell->material_id()).poisson_ratio);
                  packed.push_back(dot > 0 ? 1. : -1.);
                  for (unsigned int k = 0; k < nodes_per_face; ++k)
                    {
                      for (unsigned int d = 0; d < dim; ++d)
                        packed.push_back(fe_face.quadrature_point(k)[d]);
                      for (unsigned int d = 0; d < dim; ++d)
                        packed.push_back(static_cast<double>(node_dofs[k][d]));
                      for (unsigned int d = 0; d < dim; ++d)
                        {
                          const auto dof = node_dofs[k][d];
                          const bool fixed =
                            dirichlet.is_constrained(dof) &&
                            dirichlet.get_constraint_entries(dof)->empty();
                          packed.push_back(fixed ? 1. : 0.);
                        }
                    }
                  if (n_geometry_points > 0)
                    {
                      fe_face_geometry->reinit(cell, f);
                      for (unsigned int k = first_geometry_node; k < nodes_per_face; ++k)
                        AssertThrow(fe_face_geometry->quadrature_point(k).distance(
                                      fe_face.quadrature_point(k)) <=
                                      1e-10 * cell->face(f)->diameter(),
                                    ExcMessage("Contact: the geometry points of a contact "
                                               "face are not in the order of its nodes."));
                      for (unsigned int k = nodes_per_face;
                           k < nodes_per_face + n_geometry_points;
                           ++k)
                        for (unsigned int d = 0; d < dim; ++d)
                          packed.push_back(
                            fe_face_geometry->quadrature_point(k - first_geometry_node)[d]);
                    }
                }

    unpack_faces(Utilities::MPI::all_gather(comm, packed), nodes_per_face, n_geometry_points);

    interface_dofs.clear();
    for (const auto &node : nodes)
      for (unsigned int d = 0; d < dim; ++d)
        interface_dofs.push_back(node.dofs[d]);
    std::sort(interface_dofs.begin(), interface_dofs.end());
    dof_position.clear();
    for (unsigned int i = 0; i < interface_dofs.size(); ++i)
      dof_position[interface_dofs[i]] = i;
    find_hanging_vertices(hanging);
    slave_nodes.clear();
    hanging_slave_vertices.clear();
    coupled_faces.clear();
    face_lengths.clear();
    statistics.assign(pairs.size(), PairStatistics());
  }

  template <int dim>
  void
  ContactInterface<dim>::find_hanging_vertices(const AffineConstraints<double> &hanging)
  {
    // (hanging x DoF, parent x DoF, weight) of the surface nodes this rank
    // sees; a line known on several ranks is the same on each.
    std::vector<double> triples;
    for (const auto &node : nodes)
      if (hanging.can_store_line(node.dofs[0]) && hanging.is_constrained(node.dofs[0]))
        for (const auto &[parent, weight] : *hanging.get_constraint_entries(node.dofs[0]))
          {
            triples.push_back(static_cast<double>(node.dofs[0]));
            triples.push_back(static_cast<double>(parent));
            triples.push_back(weight);
          }
    std::map<types::global_dof_index, unsigned int> node_of_dof;
    for (unsigned int n = 0; n < nodes.size(); ++n)
      node_of_dof[nodes[n].dofs[0]] = n;
    std::map<unsigned int, std::map<unsigned int, double>> parents_of_node;
    for (const auto &chunk : Utilities::MPI::all_gather(communicator, triples))
      for (unsigned int i = 0; i + 3 <= chunk.size(); i += 3)
        {
          const unsigned int n = node_of_dof.at(static_cast<types::global_dof_index>(chunk[i]));
          const auto parent = node_of_dof.find(static_cast<types::global_dof_index>(chunk[i + 1]));
          // With Q2, the hanging vertex at the middle of a coarse edge is
          // tied to that edge's own midpoint DoF, a node of the coarse face
          // only: that face must be part of the same contact surface.
          if (parent == node_of_dof.end())
            {
              std::ostringstream message;
              message << "Contact: a hanging vertex of a contact surface at ("
                      << nodes[n].reference
                      << ") depends on a node that is not on a contact surface: the coarser "
                         "neighbour face lies outside the contact boundary. Refine so that the "
                         "rim of the contact boundary has no hanging vertices, or extend the "
                         "contact boundary.";
              AssertThrow(false, ExcMessage(message.str()));
            }
          parents_of_node[n][parent->second] = chunk[i + 2];
        }
    for (auto &node : nodes)
      node.parents.clear();
    for (const auto &[n, parents] : parents_of_node)
      nodes[n].parents.assign(parents.begin(), parents.end());
  }

  template <int dim>
  void
  ContactInterface<dim>::condense_hanging_vertices(
    std::map<unsigned int, SlaveNode>                      &slave_data,
    std::map<unsigned int, std::map<unsigned int, double>> &M_of_node,
    std::map<unsigned int, Tensor<1, dim>>                 &weighted_gap_of_node) const
  {
    // Master columns first, so the rows moved below are condensed already.
    for (auto &[j, row] : M_of_node)
      {
        std::map<unsigned int, double> condensed;
        for (const auto &[l, value] : row)
          if (nodes[l].parents.empty())
            condensed[l] += value;
          else
            for (const auto &[parent, weight] : nodes[l].parents)
              condensed[parent] += weight * value;
        row = std::move(condensed);
      }
    for (auto it = slave_data.begin(); it != slave_data.end();)
      {
        const unsigned int h = it->first;
        if (nodes[h].parents.empty())
          {
            ++it;
            continue;
          }
        const SlaveNode &hanging = it->second;
        for (const auto &[parent, weight] : nodes[h].parents)
          {
            const auto p = slave_data.find(parent);
            AssertThrow(p != slave_data.end(),
                        ExcMessage("Contact: a hanging vertex of a slave surface depends on "
                                   "a node that is not on that slave surface."));
            p->second.D += weight * hanging.D;
            p->second.full_area += weight * hanging.full_area;
            if (const auto g = weighted_gap_of_node.find(h); g != weighted_gap_of_node.end())
              weighted_gap_of_node[parent] += weight * g->second;
            if (const auto row = M_of_node.find(h); row != M_of_node.end())
              for (const auto &[l, value] : row->second)
                M_of_node[parent][l] += weight * value;
          }
        weighted_gap_of_node.erase(h);
        M_of_node.erase(h);
        it = slave_data.erase(it);
      }
  }

  template <int dim>
  std::vector<double>
  ContactInterface<dim>::gather(const TrilinosWrappers::MPI::Vector &v) const
  {
    return gather([&v](const types::global_dof_index i) { return v(i); });
  }

  template <int dim>
  std::vector<double>
  ContactInterface<dim>::gather(
    const std::function<double(types::global_dof_index)> &value_on_owner) const
  {
    std::vector<double> values(interface_dofs.size(), 0.);
    for (unsigned int i = 0; i < interface_dofs.size(); ++i)
      if (owned_dofs.is_element(interface_dofs[i]))
        values[i] = value_on_owner(interface_dofs[i]);
    // Each value has exactly one owner, so the sum is exact.
    std::vector<double> result(values.size());
    Utilities::MPI::sum(ArrayView<const double>(values), communicator,
                        ArrayView<double>(result));
    return result;
  }

  template <int dim>
  Tensor<1, dim>
  ContactInterface<dim>::displacement(const unsigned int         n,
                                      const std::vector<double> &u) const
  {
    Tensor<1, dim> result;
    for (unsigned int d = 0; d < dim; ++d)
      result[d] = u[dof_position.at(nodes[n].dofs[d])];
    return result;
  }

  template <int dim>
  double
  ContactInterface<dim>::gap(const SlaveNode &s, const std::vector<double> &u) const
  {
    Tensor<1, dim> weighted = -s.D * (nodes[s.node].reference + displacement(s.node, u));
    for (const auto &[m, value] : s.M)
      weighted += value * (nodes[m].reference + displacement(m, u));
    return (s.normal * weighted + s.curvature_gap) / s.D;
  }

  template <int dim>
  Mortar::LineFace
  ContactInterface<dim>::line(const Face &face, const std::vector<Tensor<1, dim>> &u) const
  {
    const auto position = [&](const Point<dim> &X, const Tensor<1, dim> &displacement) {
      Point<2> x;
      for (unsigned int d = 0; d < 2; ++d)
        x[d] = X[d] + displacement[d];
      return x;
    };
    Mortar::LineFace result;
    result.element_degree = degree;
    for (const unsigned int n : face.nodes)
      result.nodes.push_back(position(nodes[n].reference, u.empty() ? Tensor<1, dim>() : u[n]));
    // The geometry midpoint moves with the linear displacement of the face.
    for (const Point<dim> &X : face.geometry_points)
      result.nodes.push_back(
        position(X,
                 u.empty() ? Tensor<1, dim>() : 0.5 * (u[face.nodes[0]] + u[face.nodes[1]])));
    return result;
  }

  namespace
  {
    /// The nodes of @p line (a 2D face) as points of the space.
    template <int dim>
    std::vector<Point<dim>>
    node_points(const Mortar::LineFace &line)
    {
      std::vector<Point<dim>> points;
      for (const auto &x : line.nodes)
        points.push_back(Point<dim>(x[0], x[1]));
      return points;
    }

    /// The box of the nodes of @p line: the search's, whose reach covers
    /// the bulge of a curved quadratic line beyond its nodes.
    template <int dim>
    BoundingBox<dim>
    face_box(const Mortar::LineFace &line)
    {
      return BoundingBox<dim>(node_points<dim>(line));
    }

    /// A box that holds all of @p line, not only its nodes: the
    /// penetration check needs the exact nearest face.
    template <int dim>
    BoundingBox<dim>
    whole_face_box(const Mortar::LineFace &line)
    {
      return Mortar::interpolant_box(node_points<dim>(line),
                                     Mortar::lebesgue_constant(line.degree()));
    }

    double
    face_length(const Mortar::LineFace &line)
    {
      const QGauss<1> q(3);
      double          length = 0.;
      for (unsigned int i = 0; i < q.size(); ++i)
        length += 2. * q.weight(i) * line.tangent(2. * q.point(i)[0] - 1.).norm();
      return length;
    }
  } // namespace

  template <int dim>
  std::map<unsigned int, typename ContactInterface<dim>::SlaveNode>
  ContactInterface<dim>::slave_node_geometry(const std::vector<Mortar::LineFace> &lines,
                                             const std::vector<double>           &lengths) const
  {
    // Nodal normals (length-weighted mean of the face normals), the
    // integral of N_j over the adjacent slave faces, and the nodal sizes.
    std::map<unsigned int, SlaveNode> slave_data;
    for (unsigned int f = 0; f < faces.size(); ++f)
      if (faces[f].slave)
        for (unsigned int k = 0; k < faces[f].nodes.size(); ++k)
          {
            SlaveNode &s = slave_data[faces[f].nodes[k]];
            s.node       = faces[f].nodes[k];
            s.pair       = faces[f].pair;
            const Tensor<1, 2> n =
              Mortar::face_normal(lines[f], Mortar::node_parameter(degree, k),
                                  faces[f].orientation);
            for (unsigned int d = 0; d < 2; ++d)
              s.normal[d] += lengths[f] * n[d];
            const QGauss<1> q(degree + 1);
            for (unsigned int i = 0; i < q.size(); ++i)
              {
                const double xi = 2. * q.point(i)[0] - 1.;
                s.full_area += 2. * q.weight(i) * lines[f].tangent(xi).norm() *
                               Mortar::shape_value(degree, k, xi);
              }
            s.size += lengths[f] / degree;
          }
    std::map<unsigned int, unsigned int> n_adjacent;
    for (const auto &face : faces)
      if (face.slave)
        for (const unsigned int n : face.nodes)
          ++n_adjacent[n];
    for (auto &[n, s] : slave_data)
      {
        s.normal /= s.normal.norm();
        s.size /= n_adjacent[n];
      }
    return slave_data;
  }

  template <int dim>
  double
  ContactInterface<dim>::contact_modulus(const unsigned int pair) const
  {
    double E[2] = {0., 0.}, nu[2] = {0., 0.};
    for (const auto &face : faces)
      if (face.pair == pair)
        {
          E[face.slave]  = face.youngs_modulus;
          nu[face.slave] = face.poisson_ratio;
        }
    return 1. / ((1. - nu[0] * nu[0]) / E[0] + (1. - nu[1] * nu[1]) / E[1]);
  }

  template <int dim>
  std::map<unsigned int, std::pair<Tensor<1, 2>, double>>
  ContactInterface<dim>::surface_node_normals(const std::vector<Mortar::LineFace> &lines,
                                              const std::vector<double>           &lengths,
                                              const bool                           slave) const
  {
    std::map<unsigned int, std::pair<Tensor<1, 2>, double>> result;
    std::map<unsigned int, double>                           length_of_node;
    for (unsigned int f = 0; f < faces.size(); ++f)
      if (faces[f].slave == slave)
        for (unsigned int k = 0; k < faces[f].nodes.size(); ++k)
          {
            auto &[normal, modulus] = result[faces[f].nodes[k]];
            normal += lengths[f] * Mortar::face_normal(lines[f], Mortar::node_parameter(degree, k),
                                                       faces[f].orientation);
            modulus += lengths[f] * faces[f].youngs_modulus /
                       (1. - faces[f].poisson_ratio * faces[f].poisson_ratio);
            length_of_node[faces[f].nodes[k]] += lengths[f];
          }
    for (auto &[n, value] : result)
      {
        value.first /= value.first.norm();
        value.second /= length_of_node[n];
      }
    return result;
  }

  template <int dim>
  template <class SegmentOperators>
  void
  ContactInterface<dim>::add_segment(
    const unsigned int                                      f,
    const unsigned int                                      m,
    const SegmentOperators                                 &ops,
    std::map<unsigned int, SlaveNode>                      &slave_data,
    std::map<unsigned int, std::map<unsigned int, double>> &M_of_node,
    std::map<unsigned int, Tensor<1, dim>>                 &weighted_gap_of_node)
  {
    coupled_faces.emplace_back(f, m);
    for (unsigned int j = 0; j < faces[f].nodes.size(); ++j)
      {
        SlaveNode &s = slave_data[faces[f].nodes[j]];
        s.D += ops.D[j];
        weighted_gap_of_node[s.node] += ops.weighted_gap[j];
        for (unsigned int l = 0; l < faces[m].nodes.size(); ++l)
          M_of_node[s.node][faces[m].nodes[l]] += ops.M(j, l);
      }
  }

  template <int dim>
  void
  ContactInterface<dim>::store_slave_nodes(
    std::map<unsigned int, SlaveNode>                      &slave_data,
    std::map<unsigned int, std::map<unsigned int, double>> &M_of_node,
    std::map<unsigned int, Tensor<1, dim>>                 &weighted_gap_of_node,
    const std::vector<double>                              &u_at_dofs,
    const SurfaceNormals                                   &slave_normals,
    const SurfaceNormals                                   &master_normals)
  {
    // A node counts as paired when the master covers a fair part of its
    // support; tiny or negative dual weights at the rim of the master
    // surface would make its gap ill-defined.
    constexpr double least_covered_fraction = 1e-2;
    hanging_slave_vertices.clear();
    for (const auto &[n, s] : slave_data)
      if (!nodes[n].parents.empty())
        hanging_slave_vertices.push_back(s);
    condense_hanging_vertices(slave_data, M_of_node, weighted_gap_of_node);
    slave_nodes.clear();
    for (auto &[n, s] : slave_data)
      {
        s.paired = s.D > least_covered_fraction * s.full_area;
        if (s.paired)
          {
            for (const auto &[m, value] : M_of_node[n])
              s.M.emplace_back(m, value);
            // gap() is still the nodal form here (curvature_gap = 0).
            s.curvature_gap = s.normal * weighted_gap_of_node[n] - s.D * gap(s, u_at_dofs);

            // The M-weighted master normal and modulus at the projection.
            Tensor<1, dim> master_normal;
            double         master_modulus = 0., weight = 0.;
            for (const auto &[m, value] : s.M)
              if (const auto it = master_normals.find(m); it != master_normals.end())
                {
                  master_normal += value * it->second.first;
                  master_modulus += value * it->second.second;
                  weight += value;
                }
            const double   slave_modulus = slave_normals.at(n).second;
            Tensor<1, dim> shared        = slave_modulus * s.normal;
            if (weight > 0. && master_normal.norm() > 0.)
              shared -= (master_modulus / weight) * master_normal / master_normal.norm();
            // Surfaces that do not face each other (a master normal along
            // the slave's) leave no shared plane: keep the slave normal.
            if (shared * s.normal <= 0.)
              shared = s.normal;
            shared /= shared.norm();
            s.interface_normal = shared;
          }
        else
          s.interface_normal = s.normal;
        slave_nodes.push_back(s);
      }
    for (auto &h : hanging_slave_vertices)
      for (const auto &[parent, weight] : nodes[h.node].parents)
        h.paired = h.paired || slave_data.at(parent).paired;
  }

  template <int dim>
  void
  ContactInterface<dim>::update(const std::vector<double> &u_at_dofs,
                                const double               search_factor,
                                const std::vector<double> &motion_allowance)
  {
    if constexpr (dim == 3)
      update_3d(u_at_dofs, search_factor, motion_allowance);
    else
      {
        search_displacement = u_at_dofs;
        reach_of_search.assign(pairs.size(), std::numeric_limits<double>::max());
        std::vector<Tensor<1, dim>> u(nodes.size());
        for (unsigned int n = 0; n < nodes.size(); ++n)
          u[n] = displacement(n, u_at_dofs);

        std::vector<Mortar::LineFace> lines(faces.size());
        std::vector<double>           lengths(faces.size());
        for (unsigned int f = 0; f < faces.size(); ++f)
          {
            lines[f]   = line(faces[f], u);
            lengths[f] = face_length(lines[f]);
          }

        std::map<unsigned int, SlaveNode> slave_data = slave_node_geometry(lines, lengths);
        face_lengths = lengths;
        coupled_faces.clear();

        // Broad phase: one R-tree of master face boxes per pair.
        statistics.assign(pairs.size(), PairStatistics());
        std::map<unsigned int, std::map<unsigned int, double>> M_of_node;
        std::map<unsigned int, Tensor<1, 2>>                   weighted_gap_of_node;
        std::vector<bool> master_is_candidate(faces.size(), false);
        for (unsigned int p = 0; p < pairs.size(); ++p)
          {
            const double allowance = motion_allowance.empty() ? 0. : motion_allowance[p];
            std::vector<std::pair<BoundingBox<dim>, unsigned int>> master_boxes;
            for (unsigned int f = 0; f < faces.size(); ++f)
              if (!faces[f].slave && faces[f].pair == p)
                {
                  // A margin, so that touching boxes of flat faces meet.
                  constexpr double master_box_margin = 1e-2;
                  BoundingBox<dim> box               = face_box<dim>(lines[f]);
                  box.extend(master_box_margin * lengths[f]);
                  master_boxes.emplace_back(box, f);
                }
            const auto tree = pack_rtree(master_boxes);

            double       slave_length = 0., slave_modulus = 0.;
            unsigned int n_overlapping_faces = 0;
            for (unsigned int f = 0; f < faces.size(); ++f)
              {
                if (!faces[f].slave || faces[f].pair != p)
                  continue;
                BoundingBox<dim> box = face_box<dim>(lines[f]);
                box.extend(search_factor * lengths[f] + allowance);
                reach_of_search[p] =
                  std::min(reach_of_search[p], search_factor * lengths[f] + allowance);

                std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
                tree.query(boost::geometry::index::intersects(box),
                           std::back_inserter(hits));
                std::sort(hits.begin(), hits.end(),
                          [](const auto &a, const auto &b) { return a.second < b.second; });
                if (hits.empty())
                  continue;

                // Narrow phase: opposing normals, then exact segmentation.
                std::vector<Tensor<1, 2>> normals;
                for (const unsigned int n : faces[f].nodes)
                  {
                    Tensor<1, 2> nn;
                    for (unsigned int d = 0; d < 2; ++d)
                      nn[d] = slave_data[n].normal[d];
                    normals.push_back(nn);
                  }
                const Tensor<1, 2> n_slave =
                  Mortar::face_normal(lines[f], 0., faces[f].orientation);
                // Segmentation first: the dual basis is built on the part of
                // the slave face that the masters cover.
                std::vector<unsigned int>               masters, facing;
                std::vector<std::pair<double, double>> intervals;
                std::vector<std::array<int, 2>>         bounding_ends;
                for (const auto &hit : hits)
                  {
                    const unsigned int m = hit.second;
                    const Tensor<1, 2> n_master =
                      Mortar::face_normal(lines[m], 0., faces[m].orientation);
                    if (!(n_slave * n_master < 0.))
                      continue;
                    facing.push_back(m);
                    double             lower, upper;
                    std::array<int, 2> ends;
                    if (Mortar::overlap(lines[f], normals, lines[m], lower, upper, &ends))
                      {
                        masters.push_back(m);
                        intervals.emplace_back(lower, upper);
                        bounding_ends.push_back(ends);
                      }
                  }
                if (masters.empty())
                  continue;
                check_tiling(f, lines, masters, intervals, bounding_ends, facing);
                const FullMatrix<double> A =
                  Mortar::dual_basis_coefficients(lines[f], intervals);
                bool overlapping = false;
                for (const unsigned int m : masters)
                  {
                    Mortar::SegmentOperators ops;
                    if (!Mortar::integrate_pair(lines[f], normals, A, lines[m],
                                                degree + 3, ops))
                      continue;
                    overlapping            = true;
                    master_is_candidate[m] = true;
                    add_segment(f, m, ops, slave_data, M_of_node, weighted_gap_of_node);
                  }
                if (overlapping)
                  {
                    ++n_overlapping_faces;
                    slave_length += lengths[f];
                    slave_modulus += lengths[f] * faces[f].youngs_modulus;
                  }
              }

            double master_length = 0., master_modulus = 0.;
            unsigned int n_master = 0;
            for (unsigned int f = 0; f < faces.size(); ++f)
              if (!faces[f].slave && faces[f].pair == p && master_is_candidate[f])
                {
                  master_length += lengths[f];
                  master_modulus += lengths[f] * faces[f].youngs_modulus;
                  ++n_master;
                }
            // Moduli and sizes of the overlapping faces only: the parts of
            // the surfaces far from contact must not dilute the penalty.
            PairStatistics &stat = statistics[p];
            if (n_overlapping_faces > 0)
              {
                stat.slave_modulus    = slave_modulus / slave_length;
                stat.mean_slave_size  = slave_length / n_overlapping_faces;
                stat.master_modulus   = master_modulus / master_length;
                stat.mean_master_size = master_length / n_master;
              }
          }

        store_slave_nodes(slave_data, M_of_node, weighted_gap_of_node, u_at_dofs,
                          surface_node_normals(lines, lengths, true),
                          surface_node_normals(lines, lengths, false));
      }
  }

  template <int dim>
  void
  ContactInterface<dim>::check_tiling(const unsigned int                            f,
                                      const std::vector<Mortar::LineFace>          &lines,
                                      const std::vector<unsigned int>              &masters,
                                      const std::vector<std::pair<double, double>> &intervals,
                                      const std::vector<std::array<int, 2>> &bounding_ends,
                                      const std::vector<unsigned int>       &facing) const
  {
    // Walk the covered intervals of the slave face in order. Every part
    // left uncovered must end at the rim of the master surface: at a slave
    // end, or at a master node that no other facing master face shares.
    // A shared node there means that a master face which covers the gap was
    // lost by the segmentation, and the dual weights D_j of the slave nodes
    // would shrink (nodal pressures = force / D_j spike): stop instead.
    std::vector<unsigned int> order(masters.size());
    for (unsigned int k = 0; k < order.size(); ++k)
      order[k] = k;
    std::sort(order.begin(), order.end(), [&](const unsigned int a, const unsigned int b) {
      return intervals[a].first < intervals[b].first;
    });
    // Near contact (a master node closer to its slave image than a slave
    // face length) the facing master faces are a graph over the slave face,
    // so their overlaps must join; farther away the normal lines may cross
    // before they reach the master, and a gap is no sign of a lost face.
    // side: 0 for the lower end of interval k, 1 for its upper end.
    const double slave_length = lines[f].nodes[0].distance(lines[f].nodes[1]);
    const auto   check_end    = [&](const unsigned int k, const unsigned int side) {
      const int end = bounding_ends[k][side];
      if (end < 0)
        return;
      const double   xi = side == 0 ? intervals[k].first : intervals[k].second;
      const Point<2> x  = lines[masters[k]].nodes[end];
      if (x.distance(lines[f].point(xi)) > slave_length)
        return;
      const unsigned int node = faces[masters[k]].nodes[end];
      for (const unsigned int m : facing)
        AssertThrow(m == masters[k] ||
                      std::find(faces[m].nodes.begin(), faces[m].nodes.begin() + 2, node) ==
                        faces[m].nodes.begin() + 2,
                    ExcMessage("Contact pair " + std::to_string(faces[f].pair) +
                               ": the master faces leave a hole under the slave face from " +
                               coordinates_text(lines[f].nodes[0]) + " to " +
                               coordinates_text(lines[f].nodes[1]) +
                               " at the master node " + coordinates_text(x) +
                               ", inside the master surface. The mortar segmentation "
                               "lost a face; the contact pressures would be wrong."));
    };
    // Overlaps meet at the slave image of their shared master node up to
    // the precision of that image.
    constexpr double meeting_tolerance = 1e-10;
    double           reach             = -1.;
    int              reach_face        = -1;
    for (const unsigned int k : order)
      {
        if (intervals[k].first > reach + meeting_tolerance)
          {
            if (reach_face >= 0)
              check_end(reach_face, 1);
            check_end(k, 0);
          }
        if (intervals[k].second > reach)
          {
            reach      = intervals[k].second;
            reach_face = k;
          }
      }
    if (reach < 1. - meeting_tolerance)
      check_end(reach_face, 1);
  }

  template <int dim>
  std::vector<double>
  ContactInterface<dim>::relative_motion(const std::vector<double> &from,
                                         const std::vector<double> &to) const
  {
    std::vector<double> slave_motion(pairs.size(), 0.), master_motion(pairs.size(), 0.);
    for (const auto &face : faces)
      for (const unsigned int n : face.nodes)
        {
          const double change =
            (displacement(n, to) - displacement(n, from)).norm();
          double &largest = face.slave ? slave_motion[face.pair] : master_motion[face.pair];
          largest         = std::max(largest, change);
        }
    for (unsigned int p = 0; p < pairs.size(); ++p)
      slave_motion[p] += master_motion[p];
    return slave_motion;
  }

  template <int dim>
  double
  ContactInterface<dim>::nodal_gap(const SlaveNode &s, const std::vector<double> &u) const
  {
    return gap(s, u) - s.curvature_gap / s.D;
  }

  template <int dim>
  double
  ContactInterface<dim>::slip_since_search(const SlaveNode           &s,
                                           const std::vector<double> &u) const
  {
    const auto change = [&](const unsigned int n) {
      return displacement(n, u) - displacement(n, search_displacement);
    };
    Tensor<1, dim> relative = s.D * change(s.node);
    for (const auto &[m, value] : s.M)
      relative -= value * change(m);
    return relative.norm() / s.D;
  }

  namespace
  {
    /// The point of @p face closest to @p x: its parameter in [-1, 1]
    /// (Gauss-Newton from the chord projection, exact for straight faces).
    double
    closest_parameter(const Mortar::LineFace &face, const Point<2> &x)
    {
      const Tensor<1, 2> chord = face.nodes[1] - face.nodes[0];
      double xi = std::clamp(2. * ((x - face.nodes[0]) * chord) / chord.norm_square() - 1.,
                             -1., 1.);
      if (face.degree() == 1)
        return xi;
      for (unsigned int it = 0; it < 20; ++it)
        {
          const Tensor<1, 2> t    = face.tangent(xi);
          const double       step = ((x - face.point(xi)) * t) / t.norm_square();
          const double       next = std::clamp(xi + step, -1., 1.);
          constexpr double   parameter_tolerance = 1e-12;
          const bool         done = std::abs(next - xi) < parameter_tolerance;
          xi                      = next;
          if (done)
            break;
        }
      return xi;
    }
  } // namespace

  template <int dim>
  std::vector<double>
  ContactInterface<dim>::surface_distances(const std::vector<SlaveNode> &points,
                                           const std::vector<double>    &u_at_dofs) const
  {
    std::vector<double> distances(points.size(), std::numeric_limits<double>::infinity());
    if constexpr (dim == 3)
      return surface_distances_3d(points, u_at_dofs);
    else
      {
        std::vector<Tensor<1, dim>> u(nodes.size());
        for (unsigned int n = 0; n < nodes.size(); ++n)
          u[n] = displacement(n, u_at_dofs);
        // Master faces per node, to tell a vertex inside the master surface
        // (two faces: sign by their mean normal) from its rim (one face).
        std::vector<std::vector<unsigned int>> master_faces_of_node(nodes.size());
        std::vector<Mortar::LineFace>          lines(faces.size());
        for (unsigned int f = 0; f < faces.size(); ++f)
          if (!faces[f].slave)
            {
              lines[f] = line(faces[f], u);
              for (const unsigned int n : faces[f].nodes)
                master_faces_of_node[n].push_back(f);
            }
        const auto outward_normal = [&](const unsigned int f, const double xi) {
          return Mortar::face_normal(lines[f], xi, faces[f].orientation);
        };

        for (unsigned int p = 0; p < pairs.size(); ++p)
          {
            std::vector<std::pair<BoundingBox<dim>, unsigned int>> boxes;
            for (unsigned int f = 0; f < faces.size(); ++f)
              if (!faces[f].slave && faces[f].pair == p)
                boxes.emplace_back(whole_face_box<dim>(lines[f]), f);
            if (boxes.empty())
              continue;
            const auto tree = pack_rtree(boxes);

            for (unsigned int i = 0; i < points.size(); ++i)
              {
                const SlaveNode &s = points[i];
                if (s.pair != p)
                  continue;
                const Point<dim> xd = nodes[s.node].reference + u[s.node];
                const Point<2>   x(xd[0], xd[1]);
                // The nearest box bounds the distance from above; every face
                // closer than that has its box within that distance.
                std::vector<std::pair<BoundingBox<dim>, unsigned int>> nearest;
                tree.query(boost::geometry::index::nearest(xd, 1),
                           std::back_inserter(nearest));
                const auto  &first = lines[nearest[0].second];
                const double first_xi = closest_parameter(first, x);
                const double bound    = x.distance(first.point(first_xi));
                BoundingBox<dim> around(std::make_pair(xd, xd));
                around.extend(bound * (1. + 1e-12) + 1e-300);
                std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
                tree.query(boost::geometry::index::intersects(around),
                           std::back_inserter(hits));

                // Seeded with the nearest box's face, so that a closest face
                // is found even if round-off keeps it out of the hits.
                double       best      = bound;
                double       best_xi   = first_xi;
                unsigned int best_face = nearest[0].second;
                for (const auto &hit : hits)
                  {
                    const unsigned int f  = hit.second;
                    const double       xi = closest_parameter(lines[f], x);
                    const double       d  = x.distance(lines[f].point(xi));
                    // Ties (a shared vertex) go to the lower face index, so
                    // the result does not depend on the query order.
                    if (d < best - 1e-14 * bound || (d <= best && f < best_face))
                      {
                        best      = d;
                        best_xi   = xi;
                        best_face = f;
                      }
                  }
                Tensor<1, 2> normal;
                if (std::abs(best_xi) < 1.)
                  normal = outward_normal(best_face, best_xi);
                else
                  {
                    const unsigned int vertex = faces[best_face].nodes[best_xi < 0. ? 0 : 1];
                    if (master_faces_of_node[vertex].size() < 2)
                      continue; // beyond the rim of the master surface
                    for (const unsigned int f : master_faces_of_node[vertex])
                      normal += outward_normal(f, faces[f].nodes[0] == vertex ? -1. : 1.);
                  }
                const double side = (x - lines[best_face].point(best_xi)) * normal;
                distances[i]      = side < 0. ? -best : best;
              }
          }
      }
    return distances;
  }

  template class ContactInterface<2>;
  template class ContactInterface<3>;
  template void
  ContactInterface<2>::add_segment(const unsigned int,
                                   const unsigned int,
                                   const Mortar::SegmentOperators &,
                                   std::map<unsigned int, SlaveNode> &,
                                   std::map<unsigned int, std::map<unsigned int, double>> &,
                                   std::map<unsigned int, Tensor<1, 2>> &);
  template void
  ContactInterface<3>::add_segment(const unsigned int,
                                   const unsigned int,
                                   const Mortar::QuadSegmentOperators &,
                                   std::map<unsigned int, SlaveNode> &,
                                   std::map<unsigned int, std::map<unsigned int, double>> &,
                                   std::map<unsigned int, Tensor<1, 3>> &);
} // namespace contact_fem
