// The 3D part of ContactInterface: quadrilateral faces, nodal normals, the
// search and the mortar integration with the kernel of mortar_3d.h, and the
// independent surface distances.
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/boost_adaptors/bounding_box.h>
#include <deal.II/numerics/rtree.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/core/format.h>
#include <contact_fem/contact/mortar_3d.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace contact_fem
{
  namespace
  {
    /// A box that holds all of @p quad, not only its nodes (a biquadratic
    /// face bulges beyond them): the penetration check needs the exact
    /// nearest face. The search works on the nodes' boxes, whose reach
    /// (a fraction of the face size) covers that bulge.
    BoundingBox<3>
    whole_face_box(const Mortar::QuadFace &quad)
    {
      const double lebesgue_1d = Mortar::lebesgue_constant(quad.degree());
      return Mortar::interpolant_box(quad.nodes, lebesgue_1d * lebesgue_1d);
    }

    double
    face_area(const Mortar::QuadFace &quad)
    {
      const QGauss<2> q(3);
      double          area = 0.;
      for (unsigned int i = 0; i < q.size(); ++i)
        {
          const Point<2> xi(2. * q.point(i)[0] - 1., 2. * q.point(i)[1] - 1.);
          const auto     t = quad.tangents(xi);
          area += 4. * q.weight(i) * cross_product_3d(t[0], t[1]).norm();
        }
      return area;
    }

    /// The point of @p quad closest to @p x, as parameters in [-1, 1]^2:
    /// Gauss-Newton from the centre; a coordinate that leaves the face is
    /// held on its bound and the other one minimised along that edge (exact
    /// after one step for flat parallelograms).
    Point<2>
    closest_parameter(const Mortar::QuadFace &quad, const Point<3> &x)
    {
      constexpr double parameter_tolerance = 1e-13;
      Point<2>         xi;
      for (unsigned int it = 0; it < 30; ++it)
        {
          const auto         t = quad.tangents(xi);
          const Tensor<1, 3> r = x - quad.point(xi);
          const double       a = t[0] * t[0], b = t[0] * t[1], c = t[1] * t[1];
          const double       det = a * c - b * b;
          Point<2>           next(xi[0] + (c * (r * t[0]) - b * (r * t[1])) / det,
                        xi[1] + (a * (r * t[1]) - b * (r * t[0])) / det);
          for (unsigned int held = 0; held < 2; ++held)
            if (std::abs(next[held]) > 1.)
              {
                next[held]               = next[held] > 0. ? 1. : -1.;
                const unsigned int along = 1 - held;
                next[along]              = std::clamp(next[along], -1., 1.);
                for (unsigned int k = 0; k < 20; ++k)
                  {
                    const Tensor<1, 3> tangent = quad.tangents(next)[along];
                    const double       step =
                      ((x - quad.point(next)) * tangent) / tangent.norm_square();
                    next[along] = std::clamp(next[along] + step, -1., 1.);
                    if (std::abs(step) < parameter_tolerance)
                      break;
                  }
                break;
              }
          const bool done = next.distance(xi) < parameter_tolerance;
          xi              = next;
          if (done)
            break;
        }
      return xi;
    }

    /// Distance in the plane from the segment [a, b] to the convex polygon
    /// @p ring (counterclockwise or clockwise): 0 where they meet.
    double
    planar_distance(const Point<2> &a, const Point<2> &b, const std::vector<Point<2>> &ring)
    {
      const auto cross = [](const Tensor<1, 2> &u, const Tensor<1, 2> &v) {
        return u[0] * v[1] - u[1] * v[0];
      };
      const auto point_to_segment = [](const Point<2> &x, const Point<2> &p, const Point<2> &q) {
        const Tensor<1, 2> d = q - p;
        const double t = d.norm_square() > 0. ? std::clamp((x - p) * d / d.norm_square(), 0., 1.) : 0.;
        return x.distance(p + t * d);
      };
      // Inside: on the same side of every edge.
      bool positive = true, negative = true;
      for (std::size_t k = 0; k < ring.size(); ++k)
        {
          const double side = cross(ring[(k + 1) % ring.size()] - ring[k], a - ring[k]);
          positive          = positive && side >= 0.;
          negative          = negative && side <= 0.;
        }
      if (positive || negative)
        return 0.;
      double distance = std::numeric_limits<double>::max();
      for (std::size_t k = 0; k < ring.size(); ++k)
        {
          const Point<2> &p = ring[k], &q = ring[(k + 1) % ring.size()];
          const double    s1 = cross(q - p, a - p), s2 = cross(q - p, b - p);
          const double    s3 = cross(b - a, p - a), s4 = cross(b - a, q - a);
          if (((s1 < 0.) != (s2 < 0.)) && ((s3 < 0.) != (s4 < 0.)))
            return 0.;
          distance = std::min({distance, point_to_segment(a, p, q), point_to_segment(b, p, q),
                               point_to_segment(p, a, b), point_to_segment(q, a, b)});
        }
      return distance;
    }

    /// Whether @p quad is a flat parallelogram with its nodes where the
    /// bilinear map of its vertices puts them.
    bool
    is_parallelogram(const Mortar::QuadFace &quad)
    {
      const auto  &x         = quad.nodes;
      const double tolerance = 1e-12 * x[0].distance(x[3]);
      // Differences first: the round-off is then that of the face's size,
      // not of its distance from the origin.
      if (((x[3] - x[1]) - (x[2] - x[0])).norm() > tolerance)
        return false;
      for (unsigned int k = 4; k < x.size(); ++k)
        {
          const Point<2> xi = Mortar::quad_node_parameter(2, k);
          Tensor<1, 3>   bilinear;
          for (unsigned int v = 1; v < 4; ++v)
            bilinear += Mortar::quad_shape_value(1, v, xi) * (x[v] - x[0]);
          if (((x[k] - x[0]) - bilinear).norm() > tolerance)
            return false;
        }
      return true;
    }

    /// Gauss points per direction of the mortar integration of a pair:
    /// 2 p + 1 is exact for flat parallelograms (polynomial integrands); on
    /// other faces the master parameter and the rim dual basis are not
    /// polynomial. Measured on the patch test against an unstructured
    /// master mesh (contact_patch_3d_04), the spread of the pressure with
    /// Q1: 1.2e-6 with 3 points, 2.2e-8 with 4, 5e-10 with 5, below the 10
    /// printed digits with 6.
    unsigned int
    n_quadrature_points(const Mortar::QuadFace &slave, const Mortar::QuadFace &master)
    {
      const unsigned int exact = 2 * slave.shape_degree() + 1;
      return is_parallelogram(slave) && is_parallelogram(master) ? exact : exact + 2;
    }

    /// The vertex nodes (positions in Face::nodes) of the edge of a face
    /// on which the parameter @p xi lies, or of the vertex.
    std::vector<unsigned int>
    boundary_vertices(const Point<2> &xi)
    {
      const bool on_xi = std::abs(xi[0]) == 1., on_eta = std::abs(xi[1]) == 1.;
      const unsigned int i = xi[0] > 0. ? 1 : 0, j = xi[1] > 0. ? 2 : 0;
      if (on_xi && on_eta)
        return {i + j};
      if (on_xi)
        return {i, i + 2};
      return {j, j + 1};
    }
  } // namespace

  template <>
  Mortar::QuadFace
  ContactInterface<3>::quad(const Face &face, const std::vector<Tensor<1, 3>> &u) const
  {
    Mortar::QuadFace result;
    result.element_degree = degree;
    for (const unsigned int n : face.nodes)
      result.nodes.push_back(nodes[n].reference + (u.empty() ? Tensor<1, 3>() : u[n]));
    // The edge midpoints and the centre of Q1 on a quadratic mapping move
    // with the bilinear displacement of the face, as the midpoint in 2D.
    for (unsigned int k = 0; k < face.geometry_points.size(); ++k)
      {
        Tensor<1, 3> displacement;
        if (!u.empty())
          {
            const Point<2> xi = Mortar::quad_node_parameter(2, face.nodes.size() + k);
            for (unsigned int v = 0; v < face.nodes.size(); ++v)
              displacement += Mortar::quad_shape_value(1, v, xi) * u[face.nodes[v]];
          }
        result.nodes.push_back(face.geometry_points[k] + displacement);
      }
    return result;
  }

  template <>
  std::map<unsigned int, std::pair<Tensor<1, 3>, double>>
  ContactInterface<3>::surface_node_normals_3d(const std::vector<Mortar::QuadFace> &quads,
                                               const std::vector<double>           &areas,
                                               const bool                           slave,
                                               std::map<unsigned int, SlaveNode> *slave_data) const
  {
    std::map<unsigned int, std::pair<Tensor<1, 3>, double>> result;
    std::map<unsigned int, double>                           area_of_node;
    std::map<unsigned int, unsigned int>                     n_adjacent;
    // Exact for the full area of flat faces; the curved geometry of Q1 on
    // a quadratic mapping needs the points of its degree.
    const QGauss<2>                                          q(geometry_degree + 1);
    for (unsigned int f = 0; f < faces.size(); ++f)
      if (faces[f].slave == slave)
        for (unsigned int k = 0; k < faces[f].nodes.size(); ++k)
          {
            const unsigned int n        = faces[f].nodes[k];
            auto &[normal, modulus]     = result[n];
            normal += areas[f] * Mortar::face_normal(quads[f],
                                                     Mortar::quad_node_parameter(degree, k),
                                                     faces[f].orientation);
            modulus += areas[f] * faces[f].youngs_modulus /
                       (1. - faces[f].poisson_ratio * faces[f].poisson_ratio);
            area_of_node[n] += areas[f];
            ++n_adjacent[n];
            if (slave_data == nullptr)
              continue;
            SlaveNode &s = (*slave_data)[n];
            s.node       = n;
            s.pair       = faces[f].pair;
            for (unsigned int i = 0; i < q.size(); ++i)
              {
                const Point<2> xi(2. * q.point(i)[0] - 1., 2. * q.point(i)[1] - 1.);
                const auto     t = quads[f].tangents(xi);
                s.full_area += 4. * q.weight(i) * cross_product_3d(t[0], t[1]).norm() *
                               Mortar::quad_shape_value(degree, k, xi);
              }
            // The nodal size h_j: the side of a square of the face's area.
            s.size += std::sqrt(areas[f]) / degree;
          }
    for (auto &[n, value] : result)
      {
        value.first /= value.first.norm();
        value.second /= area_of_node[n];
        if (slave_data != nullptr)
          {
            SlaveNode &s = slave_data->at(n);
            s.normal     = value.first;
            s.size /= n_adjacent[n];
          }
      }
    return result;
  }

  template <>
  bool
  ContactInterface<3>::add_constrained_face(
    const unsigned int                                                        f,
    const std::vector<std::pair<unsigned int, Mortar::QuadSegmentOperators>> &segments,
    std::map<unsigned int, SlaveNode>                                        &slave_data,
    std::map<unsigned int, std::map<unsigned int, double>>                   &M_of_node,
    std::map<unsigned int, Tensor<1, 3>> &weighted_gap_of_node)
  {
    const std::vector<unsigned int> &local = faces[f].nodes;
    const bool has_hanging_vertex          = std::any_of(local.begin(), local.end(), [&](auto n) {
      return !nodes[n].parents.empty();
    });
    if (segments.empty() || !has_hanging_vertex)
      return false;

    // The owners of the face's trace: its regular nodes and the parents of
    // its hanging vertices; T(q, a) is the weight of owner q in node a.
    std::vector<unsigned int>            owners;
    std::map<unsigned int, unsigned int> owner_index;
    const auto                           owner = [&](const unsigned int n) {
      const auto [it, inserted] = owner_index.emplace(n, owners.size());
      if (inserted)
        owners.push_back(n);
      return it->second;
    };
    std::vector<std::vector<std::pair<unsigned int, double>>> weights(local.size());
    for (unsigned int a = 0; a < local.size(); ++a)
      if (nodes[local[a]].parents.empty())
        weights[a].emplace_back(owner(local[a]), 1.);
      else
        for (const auto &[parent, weight] : nodes[local[a]].parents)
          weights[a].emplace_back(owner(parent), weight);
    const unsigned int n = local.size();
    // A face whose owners outnumber its nodes has a dependent trace basis
    // and no dual basis of its own: its hanging rows are lumped instead.
    if (owners.size() != n)
      return false;
    FullMatrix<double> T(n, n);
    for (unsigned int a = 0; a < n; ++a)
      for (const auto &[q, weight] : weights[a])
        T(q, a) += weight;

    std::vector<double> D(n, 0.);
    double              D_sum = 0.;
    for (const auto &segment : segments)
      for (unsigned int a = 0; a < n; ++a)
        D[a] += segment.second.D[a];
    for (const double d : D)
      D_sum += std::abs(d);
    constexpr double least_nodal_weight = 1e-12;
    if (std::any_of(D.begin(), D.end(),
                    [&](const double d) { return std::abs(d) <= least_nodal_weight * D_sum; }))
      return false;

    // The dual functions of the owners, Psi~_q = sum_a S(q, a) Psi_a, are
    // biorthogonal to the owners' trace functions N~_q = sum_a T(q, a) N_a
    // on this face: S D T^T = D~ with D~ = T D, so S = D~ T^-T D^-1. They sum
    // to one, as the Psi_a do, since the columns of T sum to one.
    FullMatrix<double> T_inverse_transpose(n, n);
    T_inverse_transpose.copy_transposed(T);
    T_inverse_transpose.gauss_jordan();
    Vector<double> D_owner(n);
    for (unsigned int q = 0; q < n; ++q)
      for (unsigned int a = 0; a < n; ++a)
        D_owner[q] += T(q, a) * D[a];
    FullMatrix<double> S(n, n);
    for (unsigned int q = 0; q < n; ++q)
      for (unsigned int a = 0; a < n; ++a)
        S(q, a) = D_owner[q] * T_inverse_transpose(q, a) / D[a];

    for (const auto &[m, ops] : segments)
      {
        coupled_faces.emplace_back(f, m);
        for (unsigned int q = 0; q < n; ++q)
          {
            SlaveNode &s = slave_data[owners[q]];
            for (unsigned int a = 0; a < n; ++a)
              {
                s.D += T(q, a) * ops.D[a];
                weighted_gap_of_node[owners[q]] += S(q, a) * ops.weighted_gap[a];
                for (unsigned int l = 0; l < faces[m].nodes.size(); ++l)
                  M_of_node[owners[q]][faces[m].nodes[l]] += S(q, a) * ops.M(a, l);
              }
          }
      }
    return true;
  }

  template <>
  void
  ContactInterface<3>::check_tiling(const unsigned int                           f,
                                    const std::vector<Mortar::QuadFace>         &quads,
                                    const std::vector<unsigned int>             &masters,
                                    const std::vector<unsigned int>             &facing,
                                    const std::vector<Mortar::ParameterPolygon> &polygons) const
  {
    // Neighbouring overlap polygons share their vertices (the slave images
    // of the same clipped points), so where the facing master faces cover
    // the slave face they tile its parameter square [-1, 1]^2: area 4.
    // That is expected where the slave face is near the master (closer
    // than its diameter: the master is a graph over it) and no rim edge of
    // the facing master faces (an edge only one of them has; also where
    // they meet a hanging vertex) comes within its diameter.
    const Mortar::QuadFace &slave    = quads[f];
    const Point<2>          centre;
    const Point<3>          middle   = slave.point(centre);
    const double            diameter = std::max(slave.nodes[0].distance(slave.nodes[3]),
                                     slave.nodes[1].distance(slave.nodes[2]));
    bool near = false;
    for (const unsigned int m : masters)
      {
        Point<2> eta;
        near = near || (Mortar::project_along(quads[m], middle,
                                              Mortar::face_normal(slave, centre, faces[f].orientation),
                                              eta) &&
                        std::abs(eta[0]) <= 1. && std::abs(eta[1]) <= 1. &&
                        quads[m].point(eta).distance(middle) < diameter);
      }
    if (!near)
      return;
    // The slave face and the rim edges seen along its normal, in the
    // tangent plane at its centre.
    const Tensor<1, 3> n  = Mortar::face_normal(slave, centre, 1.);
    Tensor<1, 3>       e1 = slave.tangents(centre)[0];
    e1 -= (e1 * n) * n;
    e1 /= e1.norm();
    const Tensor<1, 3> e2 = cross_product_3d(n, e1);
    const auto in_plane = [&](const Point<3> &x) {
      return Point<2>((x - middle) * e1, (x - middle) * e2);
    };
    std::vector<Point<2>> ring;
    for (const unsigned int v : {0, 1, 3, 2})
      ring.push_back(in_plane(slave.nodes[v]));
    // Per vertex edge of the facing faces: how many of them have it.
    std::map<std::pair<unsigned int, unsigned int>, std::pair<unsigned int, std::array<Point<3>, 2>>>
      edges;
    for (const unsigned int m : facing)
      for (const auto &[a, b] : {std::pair(0, 1), std::pair(2, 3), std::pair(0, 2), std::pair(1, 3)})
        {
          auto &edge = edges[std::minmax(faces[m].nodes[a], faces[m].nodes[b])];
          ++edge.first;
          edge.second = {{quads[m].nodes[a], quads[m].nodes[b]}};
        }
    // A rim edge that comes within a tenth of the diameter of the slave
    // face (curved faces bulge beyond their vertices) may bound a part that
    // is rightly uncovered.
    for (const auto &[key, edge] : edges)
      if (edge.first == 1 &&
          planar_distance(in_plane(edge.second[0]), in_plane(edge.second[1]), ring) <
            0.1 * diameter)
        return;

    double area = 0.;
    for (const auto &polygon : polygons)
      for (std::size_t v = 0; v < polygon.size(); ++v)
        area += 0.5 * (polygon[v][0] * polygon[(v + 1) % polygon.size()][1] -
                       polygon[v][1] * polygon[(v + 1) % polygon.size()][0]);
    constexpr double tiling_tolerance = 1e-8;
    AssertThrow(std::abs(area - 4.) <= 4. * tiling_tolerance,
                ExcMessage("Contact pair " + std::to_string(faces[f].pair) +
                           ": the master faces cover " + std::to_string(area / 4.) +
                           " of the slave face centred at " + coordinates_text(middle) +
                           ", which lies inside the master surface. The mortar "
                           "segmentation lost or doubled a part; the contact pressures "
                           "would be wrong."));
  }

  template <>
  void
  ContactInterface<3>::search_pair_3d(
    const unsigned int                                      p,
    const std::vector<Mortar::QuadFace>                    &quads,
    const std::vector<double>                              &areas,
    const double                                            search_factor,
    const double                                            allowance,
    std::map<unsigned int, SlaveNode>                      &slave_data,
    std::map<unsigned int, std::map<unsigned int, double>> &M_of_node,
    std::map<unsigned int, Tensor<1, 3>>                   &weighted_gap_of_node)
  {
    // Broad phase: an R-tree of the master face boxes, with a margin so
    // that touching boxes of flat faces meet.
    constexpr double master_box_margin = 1e-2;
    std::vector<std::pair<BoundingBox<3>, unsigned int>> master_boxes;
    for (unsigned int f = 0; f < faces.size(); ++f)
      if (!faces[f].slave && faces[f].pair == p)
        {
          BoundingBox<3> box(quads[f].nodes);
          box.extend(master_box_margin * std::sqrt(areas[f]));
          master_boxes.emplace_back(box, f);
        }
    const auto tree = pack_rtree(master_boxes);

    const Point<2>    centre;
    std::vector<bool> master_is_candidate(faces.size(), false);
    double            slave_area = 0., slave_modulus = 0.;
    unsigned int      n_overlapping_faces = 0;
    for (unsigned int f = 0; f < faces.size(); ++f)
      {
        if (!faces[f].slave || faces[f].pair != p)
          continue;
        const double reach = search_factor * std::sqrt(areas[f]) + allowance;
        BoundingBox<3> box(quads[f].nodes);
        box.extend(reach);
        reach_of_search[p] = std::min(reach_of_search[p], reach);
        std::vector<std::pair<BoundingBox<3>, unsigned int>> hits;
        tree.query(boost::geometry::index::intersects(box), std::back_inserter(hits));
        std::sort(hits.begin(), hits.end(),
                  [](const auto &a, const auto &b) { return a.second < b.second; });

        // Narrow phase: opposing normals, then the overlap polygons, whose
        // union carries the dual basis of the slave face.
        std::vector<Tensor<1, 3>> normals;
        for (const unsigned int n : faces[f].nodes)
          normals.push_back(slave_data.at(n).normal);
        const Tensor<1, 3> n_slave = Mortar::face_normal(quads[f], centre, faces[f].orientation);
        std::vector<unsigned int>               masters, facing;
        std::vector<Mortar::ParameterPolygon>   all_polygons;
        for (const auto &hit : hits)
          {
            const unsigned int m = hit.second;
            if (!(n_slave * Mortar::face_normal(quads[m], centre, faces[m].orientation) < 0.))
              continue;
            facing.push_back(m);
            std::vector<Mortar::ParameterPolygon> polygons;
            if (Mortar::overlap(quads[f], normals, quads[m], polygons))
              {
                masters.push_back(m);
                all_polygons.insert(all_polygons.end(), polygons.begin(), polygons.end());
              }
          }
        if (masters.empty())
          continue;
        check_tiling(f, quads, masters, facing, all_polygons);
        const FullMatrix<double> A =
          Mortar::dual_basis_coefficients(quads[f], normals, all_polygons);
        std::vector<std::pair<unsigned int, Mortar::QuadSegmentOperators>> segments;
        for (const unsigned int m : masters)
          {
            Mortar::QuadSegmentOperators ops;
            if (!Mortar::integrate_pair(quads[f], normals, A, quads[m],
                                        n_quadrature_points(quads[f], quads[m]), ops))
              continue;
            master_is_candidate[m] = true;
            segments.emplace_back(m, std::move(ops));
          }
        if (!add_constrained_face(f, segments, slave_data, M_of_node, weighted_gap_of_node))
          for (const auto &[m, ops] : segments)
            add_segment(f, m, ops, slave_data, M_of_node, weighted_gap_of_node);
        if (!segments.empty())
          {
            ++n_overlapping_faces;
            slave_area += areas[f];
            slave_modulus += areas[f] * faces[f].youngs_modulus;
          }
      }

    // Moduli and sizes of the overlapping faces only, as in 2D.
    double       master_area = 0., master_modulus = 0.;
    unsigned int n_master = 0;
    for (unsigned int f = 0; f < faces.size(); ++f)
      if (master_is_candidate[f])
        {
          master_area += areas[f];
          master_modulus += areas[f] * faces[f].youngs_modulus;
          ++n_master;
        }
    PairStatistics &stat = statistics[p];
    if (n_overlapping_faces > 0)
      {
        stat.slave_modulus    = slave_modulus / slave_area;
        stat.mean_slave_size  = std::sqrt(slave_area / n_overlapping_faces);
        stat.master_modulus   = master_modulus / master_area;
        stat.mean_master_size = std::sqrt(master_area / n_master);
      }
  }

  template <>
  void
  ContactInterface<3>::update_3d(const std::vector<double> &u_at_dofs,
                                 const double               search_factor,
                                 const std::vector<double> &motion_allowance)
  {
    search_displacement = u_at_dofs;
    reach_of_search.assign(pairs.size(), std::numeric_limits<double>::max());
    std::vector<Tensor<1, 3>> u(nodes.size());
    for (unsigned int n = 0; n < nodes.size(); ++n)
      u[n] = displacement(n, u_at_dofs);
    std::vector<Mortar::QuadFace> quads(faces.size());
    std::vector<double>           areas(faces.size());
    for (unsigned int f = 0; f < faces.size(); ++f)
      {
        quads[f] = quad(faces[f], u);
        areas[f] = face_area(quads[f]);
      }
    std::map<unsigned int, SlaveNode> slave_data;
    surface_node_normals_3d(quads, areas, true, &slave_data);
    // The "length" of a face in 3D: the side of a square of its area.
    face_lengths.resize(faces.size());
    for (unsigned int f = 0; f < faces.size(); ++f)
      face_lengths[f] = std::sqrt(areas[f]);
    coupled_faces.clear();

    statistics.assign(pairs.size(), PairStatistics());
    std::map<unsigned int, std::map<unsigned int, double>> M_of_node;
    std::map<unsigned int, Tensor<1, 3>>                   weighted_gap_of_node;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      search_pair_3d(p, quads, areas, search_factor,
                     motion_allowance.empty() ? 0. : motion_allowance[p], slave_data,
                     M_of_node, weighted_gap_of_node);
    store_slave_nodes(slave_data, M_of_node, weighted_gap_of_node, u_at_dofs,
                      surface_node_normals_3d(quads, areas, true),
                      surface_node_normals_3d(quads, areas, false));
  }

  template <>
  std::vector<double>
  ContactInterface<3>::surface_distances_3d(const std::vector<SlaveNode> &points,
                                            const std::vector<double>    &u_at_dofs) const
  {
    std::vector<double> distances(points.size(), std::numeric_limits<double>::infinity());
    std::vector<Tensor<1, 3>> u(nodes.size());
    for (unsigned int n = 0; n < nodes.size(); ++n)
      u[n] = displacement(n, u_at_dofs);
    // Master faces per vertex node and per edge (by its sorted vertex
    // nodes): a closest point on an edge with one face, or on a vertex of
    // such an edge, lies on the rim of the master surface.
    std::vector<std::vector<unsigned int>>                    master_faces_of_node(nodes.size());
    std::map<std::pair<unsigned int, unsigned int>, unsigned int> faces_of_edge;
    std::vector<Mortar::QuadFace>                             quads(faces.size());
    const auto edge_key = [](const unsigned int a, const unsigned int b) {
      return std::make_pair(std::min(a, b), std::max(a, b));
    };
    for (unsigned int f = 0; f < faces.size(); ++f)
      if (!faces[f].slave)
        {
          quads[f]      = quad(faces[f], u);
          const auto &v = faces[f].nodes;
          for (unsigned int k = 0; k < 4; ++k)
            master_faces_of_node[v[k]].push_back(f);
          static const unsigned int edges[4][2] = {{0, 1}, {1, 3}, {3, 2}, {2, 0}};
          for (const auto &edge : edges)
            ++faces_of_edge[edge_key(v[edge[0]], v[edge[1]])];
        }
    std::set<unsigned int> rim_vertices;
    for (const auto &[edge, count] : faces_of_edge)
      if (count < 2)
        rim_vertices.insert({edge.first, edge.second});

    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        std::vector<std::pair<BoundingBox<3>, unsigned int>> boxes;
        for (unsigned int f = 0; f < faces.size(); ++f)
          if (!faces[f].slave && faces[f].pair == p)
            boxes.emplace_back(whole_face_box(quads[f]), f);
        if (boxes.empty())
          continue;
        const auto tree = pack_rtree(boxes);
        for (unsigned int i = 0; i < points.size(); ++i)
          {
            const SlaveNode &s = points[i];
            if (s.pair != p)
              continue;
            const Point<3> x = nodes[s.node].reference + u[s.node];
            // The nearest box bounds the distance from above; every face
            // closer than that has its box within that distance.
            std::vector<std::pair<BoundingBox<3>, unsigned int>> nearest;
            tree.query(boost::geometry::index::nearest(x, 1), std::back_inserter(nearest));
            const auto  &first = quads[nearest[0].second];
            const Point<2> first_xi = closest_parameter(first, x);
            const double   bound    = x.distance(first.point(first_xi));
            BoundingBox<3> around(std::make_pair(x, x));
            around.extend(bound * (1. + 1e-12) + 1e-300);
            std::vector<std::pair<BoundingBox<3>, unsigned int>> hits;
            tree.query(boost::geometry::index::intersects(around), std::back_inserter(hits));

            // Seeded with the nearest box's face, so that a closest face is
            // found even if round-off keeps it out of the hits.
            double       best      = bound;
            Point<2>     best_xi   = first_xi;
            unsigned int best_face = nearest[0].second;
            for (const auto &hit : hits)
              {
                const unsigned int f  = hit.second;
                const Point<2>     xi = closest_parameter(quads[f], x);
                const double       d  = x.distance(quads[f].point(xi));
                // Ties (a shared edge or vertex) go to the lower face index.
                if (d < best - 1e-14 * bound || (d <= best && f < best_face))
                  {
                    best      = d;
                    best_xi   = xi;
                    best_face = f;
                  }
              }
            Tensor<1, 3> normal;
            if (std::abs(best_xi[0]) < 1. && std::abs(best_xi[1]) < 1.)
              normal = Mortar::face_normal(quads[best_face], best_xi, faces[best_face].orientation);
            else
              {
                // On an edge or a vertex: the mean normal of the faces there.
                std::vector<unsigned int> vertices;
                for (const unsigned int k : boundary_vertices(best_xi))
                  vertices.push_back(faces[best_face].nodes[k]);
                if (std::any_of(vertices.begin(), vertices.end(),
                                [&](const unsigned int v) { return rim_vertices.count(v); }))
                  {
                    // On the rim of the master surface: a distance only if
                    // the node lies straight over it (along the face
                    // normal), not beyond it.
                    const Tensor<1, 3> n = Mortar::face_normal(quads[best_face], best_xi,
                                                               faces[best_face].orientation);
                    const Tensor<1, 3> r = x - quads[best_face].point(best_xi);
                    if ((r - (r * n) * n).norm() > 1e-8 * s.size)
                      continue;
                    distances[i] = r * n < 0. ? -best : best;
                    continue;
                  }
                for (const unsigned int f : master_faces_of_node[vertices[0]])
                  {
                    const auto &v = faces[f].nodes;
                    if (vertices.size() == 2 &&
                        std::find(v.begin(), v.begin() + 4, vertices[1]) == v.begin() + 4)
                      continue;
                    const unsigned int k = std::find(v.begin(), v.begin() + 4, vertices[0]) -
                                           v.begin();
                    normal += Mortar::face_normal(quads[f], Mortar::quad_node_parameter(1, k),
                                                  faces[f].orientation);
                  }
              }
            const double side = (x - quads[best_face].point(best_xi)) * normal;
            distances[i]      = side < 0. ? -best : best;
          }
      }
    return distances;
  }
} // namespace contact_fem
