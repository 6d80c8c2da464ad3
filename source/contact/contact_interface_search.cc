// The search of ContactInterface, written once over the dimension: the
// nodal normals of the surfaces, the broad phase (R-tree of the master
// faces), the narrow phase and the mortar integration of every slave face
// against its masters, and the independent surface distances.
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/boost_adaptors/bounding_box.h>
#include <deal.II/numerics/rtree.h>

#include <deal.II/base/mpi.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/faces_in_reach.h>
#include <contact_fem/core/parameters.h>

#include <algorithm>
#include <cfenv>
#include <cstdint>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

namespace contact_fem
{
  template <int dim>
  typename ContactInterface<dim>::SurfaceNormals
  ContactInterface<dim>::surface_node_normals(const std::vector<FaceGeometry>   &geometries,
                                              const std::vector<double>         &measures,
                                              const bool                         slave,
                                              std::map<unsigned int, SlaveNode> *slave_data) const
  {
    using Kernel = Mortar::Kernel<dim>;
    SurfaceNormals                       result;
    std::map<unsigned int, double>       measure_of_node;
    std::map<unsigned int, unsigned int> n_adjacent;
    // The full area: exact for flat faces; in 3D the curved geometry of Q1
    // on a quadratic mapping takes the points of its degree, 2D keeps the
    // element's (its outputs were made so).
    const QGauss<dim - 1> q(dim == 2 ? degree + 1 : geometry_degree + 1);
    for (unsigned int f = 0; f < faces.size(); ++f)
      if (faces[f].slave == slave)
        for (unsigned int k = 0; k < faces[f].nodes.size(); ++k)
          {
            const unsigned int n    = faces[f].nodes[k];
            auto &[normal, modulus] = result[n];
            normal +=
              measures[f] * Mortar::face_normal(geometries[f], Kernel::node_parameter(degree, k),
                                                faces[f].orientation);
            modulus += measures[f] * faces[f].youngs_modulus /
                       (1. - faces[f].poisson_ratio * faces[f].poisson_ratio);
            measure_of_node[n] += measures[f];
            ++n_adjacent[n];
            if (slave_data == nullptr)
              continue;
            SlaveNode &s = (*slave_data)[n];
            s.node       = n;
            s.pair       = faces[f].pair;
            for (unsigned int i = 0; i < q.size(); ++i)
              {
                const auto xi = Kernel::parameter(q.point(i));
                s.full_area += Kernel::reference_measure * q.weight(i) *
                               Kernel::area_element(geometries[f], xi) *
                               Kernel::shape_value(degree, k, xi);
              }
            // The nodal size h_j: the face's side (the side of a square of
            // its area in 3D).
            s.size += Kernel::side(measures[f]) / degree;
          }
    for (auto &[n, value] : result)
      {
        // On a symmetry plane: the axis across it removed, the normal of
        // the whole, mirror-symmetric surface (the faces at the node lie
        // on one side of the plane only).
        for (unsigned int d = 0; d < dim; ++d)
          if (nodes[n].symmetry_plane[d])
            value.first[d] = 0.;
        value.first /= value.first.norm();
        value.second /= measure_of_node[n];
        if (slave_data != nullptr)
          {
            SlaveNode &s = slave_data->at(n);
            s.normal     = value.first;
            s.size /= n_adjacent[n];
          }
      }
    return result;
  }

  namespace
  {
    /// The length (2D) or area (3D) of @p face.
    template <int dim>
    double
    face_measure(const typename Mortar::Kernel<dim>::Face &face)
    {
      using Kernel = Mortar::Kernel<dim>;
      const QGauss<dim - 1> q(3);
      double                measure = 0.;
      for (unsigned int i = 0; i < q.size(); ++i)
        measure += Kernel::reference_measure * q.weight(i) *
                   Kernel::area_element(face, Kernel::parameter(q.point(i)));
      return measure;
    }
  } // namespace

  template <int dim>
  void
  ContactInterface<dim>::update(const std::vector<double> &u_at_dofs,
                                const double               search_factor,
                                const std::vector<double> &motion_allowance)
  {
    search_displacement = u_at_dofs;
    reach_of_search.assign(pairs.size(), std::numeric_limits<double>::max());
    std::vector<Tensor<1, dim>> u(nodes.size());
    for (unsigned int n = 0; n < nodes.size(); ++n)
      u[n] = displacement(n, u_at_dofs);
    // Lengths of the faces (2D) or areas (3D), and their sides.
    std::vector<FaceGeometry> geometries(faces.size());
    std::vector<double>       measures(faces.size());
    face_lengths.resize(faces.size());
    for (unsigned int f = 0; f < faces.size(); ++f)
      {
        geometries[f]   = face_geometry(faces[f], u);
        measures[f]     = face_measure<dim>(geometries[f]);
        face_lengths[f] = Mortar::Kernel<dim>::side(measures[f]);
      }
    std::map<unsigned int, SlaveNode> slave_data;
    slave_surface_normals = surface_node_normals(geometries, measures, true, &slave_data);
    coupled_faces.clear();

    statistics.assign(pairs.size(), PairStatistics());
    within_reach.assign(faces.size(), 0);
    std::map<unsigned int, std::map<unsigned int, double>> M_of_node;
    std::map<unsigned int, Tensor<1, dim>>                 weighted_gap_of_node;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      search_pair(p, geometries, measures, search_factor,
                  motion_allowance.empty() ? 0. : motion_allowance[p], slave_data, M_of_node,
                  weighted_gap_of_node);
    // The faces within reach (search_pair() marked the own slave faces and
    // their candidate masters) and those sharing a node with them.
    {
      std::vector<char> node_within(nodes.size(), 0);
      for (unsigned int f = 0; f < faces.size(); ++f)
        if (within_reach[f])
          for (const unsigned int n : faces[f].nodes)
            node_within[n] = 1;
      for (unsigned int f = 0; f < faces.size(); ++f)
        within_reach[f] =
          within_reach[f] ||
          std::any_of(faces[f].nodes.begin(), faces[f].nodes.end(), [&](const unsigned int n) {
            return node_within[n] != 0;
          });
      // checking_held_surface(): the nodes a rank will hold, those of the
      // faces within reach and of the faces at a node with a locally
      // relevant DoF (the faces of its own and ghost cells: their nodes
      // carry the constraint lines its cells distribute through).
      node_within_reach.clear();
      if (checking_held_surface())
        {
          const auto relevant = [&](const unsigned int n) {
            return std::any_of(nodes[n].dofs.begin(), nodes[n].dofs.end(), [&](const auto dof) {
              return relevant_dofs.is_element(dof);
            });
          };
          node_within_reach.assign(nodes.size(), 0);
          for (unsigned int f = 0; f < faces.size(); ++f)
            if (within_reach[f] ||
                std::any_of(faces[f].nodes.begin(), faces[f].nodes.end(), relevant))
              for (const unsigned int n : faces[f].nodes)
                node_within_reach[n] = 1;
        }
    }
    if (checking_held_state())
      check_faces_within_reach(geometries, search_factor, motion_allowance);
    master_surface_normals = surface_node_normals(geometries, measures, false);
    store_slave_nodes(slave_data, M_of_node, weighted_gap_of_node, u_at_dofs, slave_surface_normals,
                      master_surface_normals);
    close_ghosts();
    close_lines();
    if (checking_held_surface() && Utilities::MPI::n_mpi_processes(mpi_communicator) > 1)
      poison_nodes_beyond_reach();
  }

  template <int dim>
  void
  ContactInterface<dim>::poison_nodes_beyond_reach()
  {
    // A signalling NaN traps at its first arithmetic use when
    // CONTACT_FEM_TRAP_POISON is set (then run under a debugger).
    static const bool trap = std::getenv("CONTACT_FEM_TRAP_POISON") != nullptr;
    if (trap)
      feenableexcept(FE_INVALID);
    const double nan    = trap ? std::numeric_limits<double>::signaling_NaN() :
                                 std::numeric_limits<double>::quiet_NaN();
    const auto   poison = [&](SlaveNode &s) {
      for (unsigned int d = 0; d < dim; ++d)
        s.normal[d] = s.interface_normal[d] = nan;
      s.D = s.full_area = s.size = s.curvature_gap = nan;
      for (auto &entry : s.M)
        entry.second = nan;
    };
    for (auto *list : {&slave_nodes, &hanging_slave_vertices})
      for (SlaveNode &s : *list)
        if (node_within_reach[s.node] == 0)
          poison(s);
  }

  template <int dim>
  void
  ContactInterface<dim>::check_faces_within_reach(const std::vector<FaceGeometry> &geometries,
                                                  const double                     search_factor,
                                                  const std::vector<double> &motion_allowance) const
  {
    // This rank's faces as their owner sees them, with the boxes and reach
    // of search_pair()'s broad phase.
    std::vector<ReachFace<dim>> own;
    for (unsigned int f = own_faces.first; f < own_faces.second; ++f)
      {
        ReachFace<dim> face;
        face.face   = f;
        face.pair   = faces[f].pair;
        face.slave  = faces[f].slave;
        face.box    = BoundingBox<dim>(geometries[f].nodes);
        face.nodes  = faces[f].nodes;
        face.record = face_record(f);
        if (face.slave)
          face.reach = search_factor * face_lengths[f] +
                       (motion_allowance.empty() ? 0. : motion_allowance[face.pair]);
        else
          face.box.extend(master_box_margin * face_lengths[f]);
        own.push_back(std::move(face));
      }
    std::string               error;
    std::vector<unsigned int> exchanged;
    unsigned int              n_wrong_records = 0;
    try
      {
        for (const auto &face : faces_within_reach(own, mpi_communicator))
          {
            exchanged.push_back(face.face);
            if (face.nodes != faces[face.face].nodes || face.record != face_record(face.face))
              ++n_wrong_records;
          }
      }
    catch (const std::exception &e)
      {
        error = user_message(e);
      }
    std::vector<unsigned int> projected;
    for (unsigned int f = 0; f < within_reach.size(); ++f)
      if (within_reach[f])
        projected.push_back(f);
    if (error.empty() && (exchanged != projected || n_wrong_records > 0))
      {
        std::vector<unsigned int> missing, extra;
        std::set_difference(projected.begin(), projected.end(), exchanged.begin(), exchanged.end(),
                            std::back_inserter(missing));
        std::set_difference(exchanged.begin(), exchanged.end(), projected.begin(), projected.end(),
                            std::back_inserter(extra));
        error = "Contact (check of CONTACT_FEM_CHECK_HELD_STATE): on rank " +
                std::to_string(Utilities::MPI::this_mpi_process(mpi_communicator)) +
                ", the faces within reach found by the exchange of boxes "
                "(faces_within_reach()) differ from those of the gathered surface: " +
                std::to_string(exchanged.size()) + " against " + std::to_string(projected.size()) +
                ", " + std::to_string(missing.size()) + " missing" +
                (missing.empty() ? "" : " (face " + std::to_string(missing[0]) + ")") + ", " +
                std::to_string(extra.size()) + " extra" +
                (extra.empty() ? "" : " (face " + std::to_string(extra[0]) + ")") + ", " +
                std::to_string(n_wrong_records) + " with other nodes or another record.";
      }
    stop_on_every_rank(error);
  }

  template <int dim>
  std::vector<double>
  ContactInterface<dim>::face_record(const unsigned int f) const
  {
    const Face         &face = faces[f];
    std::vector<double> record{static_cast<double>(face.pair), face.slave ? 1. : 0.,
                               face.youngs_modulus, face.poisson_ratio, face.orientation};
    for (const unsigned int n : face.nodes)
      {
        for (unsigned int d = 0; d < dim; ++d)
          record.push_back(nodes[n].reference[d]);
        for (unsigned int d = 0; d < dim; ++d)
          record.push_back(static_cast<double>(nodes[n].dofs[d]));
        for (unsigned int d = 0; d < dim; ++d)
          record.push_back(nodes[n].fixed[d] ? 1. : 0.);
      }
    for (const auto &x : face.geometry_points)
      for (unsigned int d = 0; d < dim; ++d)
        record.push_back(x[d]);
    return record;
  }

  namespace
  {
    /// The master faces in @p tree whose boxes meet @p box, by face index.
    template <int dim, class Tree>
    std::vector<unsigned int>
    candidate_masters(const Tree &tree, const BoundingBox<dim> &box)
    {
      std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
      tree.query(boost::geometry::index::intersects(box), std::back_inserter(hits));
      std::vector<unsigned int> masters;
      for (const auto &hit : hits)
        masters.push_back(hit.second);
      std::sort(masters.begin(), masters.end());
      return masters;
    }

    /// The box of the slave face of @p nodes enlarged by @p reach.
    template <int dim>
    BoundingBox<dim>
    slave_box(const std::vector<Point<dim>> &nodes, const double reach)
    {
      BoundingBox<dim> box(nodes);
      box.extend(reach);
      return box;
    }

    /**
     * The faces of @p costs (face, cost of its narrow phase and
     * integration: the number of its candidate masters; in face order)
     * that rank @p rank of @p n_ranks integrates: contiguous runs in face
     * order of about equal cost. Every rank computes the same split.
     */
    std::vector<unsigned int>
    share_of_faces(const std::vector<std::pair<unsigned int, unsigned int>> &costs,
                   const unsigned int                                        rank,
                   const unsigned int                                        n_ranks)
    {
      std::uint64_t total = 0;
      for (const auto &entry : costs)
        total += entry.second;
      std::vector<unsigned int> share;
      std::uint64_t             before = 0;
      for (const auto &[f, cost] : costs)
        {
          // The rank whose part holds the middle of the face's cost
          // (integers: the same on every rank).
          if ((2 * before + cost) * n_ranks / (2 * total) == rank)
            share.push_back(f);
          before += cost;
        }
      return share;
    }
  } // namespace

  template <int dim>
  template <class Tree>
  std::vector<double>
  ContactInterface<dim>::integrate_faces(const std::vector<unsigned int>         &share,
                                         const std::vector<FaceGeometry>         &geometries,
                                         const Tree                              &tree,
                                         const std::vector<double>               &reach,
                                         const std::map<unsigned int, SlaveNode> &slave_data,
                                         std::string                             &error) const
  {
    using Kernel = Mortar::Kernel<dim>;
    std::vector<double> packed;
    try
      {
        for (const unsigned int f : share)
          {
            // Narrow phase: opposing normals, then the overlaps, on which
            // the dual basis of the slave face is built (the part the
            // masters cover).
            std::vector<Tensor<1, dim>> normals;
            for (const unsigned int n : faces[f].nodes)
              normals.push_back(slave_data.at(n).normal);
            const Tensor<1, dim> n_slave =
              Mortar::face_normal(geometries[f], Kernel::centre(), faces[f].orientation);
            std::vector<unsigned int> masters, facing;
            typename Kernel::Overlaps overlaps;
            for (const unsigned int m :
                 candidate_masters<dim>(tree, slave_box(geometries[f].nodes, reach[f])))
              {
                if (!(n_slave *
                        Mortar::face_normal(geometries[m], Kernel::centre(), faces[m].orientation) <
                      0.))
                  continue;
                facing.push_back(m);
                if (Kernel::add_overlap(geometries[f], normals, geometries[m], overlaps))
                  masters.push_back(m);
              }
            if (masters.empty())
              continue;
            check_tiling(f, geometries, normals, masters, overlaps, facing);
            const FullMatrix<double> A = Kernel::dual_basis(geometries[f], normals, overlaps);
            const std::size_t        count_at = packed.size() + 1;
            packed.push_back(f);
            packed.push_back(0.);
            for (const unsigned int m : masters)
              {
                typename Kernel::Operators ops;
                if (!Mortar::integrate_pair(geometries[f], normals, A, geometries[m],
                                            Mortar::n_quadrature_points(geometries[f],
                                                                        geometries[m]),
                                            ops))
                  continue;
                AssertDimension(ops.D.size(), faces[f].nodes.size());
                AssertDimension(ops.M.n(), faces[m].nodes.size());
                packed[count_at] += 1.;
                packed.push_back(m);
                packed.insert(packed.end(), ops.D.begin(), ops.D.end());
                for (unsigned int j = 0; j < ops.M.m(); ++j)
                  for (unsigned int l = 0; l < ops.M.n(); ++l)
                    packed.push_back(ops.M(j, l));
                for (const auto &g : ops.weighted_gap)
                  for (unsigned int d = 0; d < dim; ++d)
                    packed.push_back(g[d]);
              }
          }
      }
    catch (const std::exception &e)
      {
        error = user_message(e);
      }
    return packed;
  }

  template <int dim>
  std::map<unsigned int, typename ContactInterface<dim>::Segments>
  ContactInterface<dim>::unpack_segments(const std::vector<std::vector<double>> &packed) const
  {
    std::map<unsigned int, Segments> segments_of_face;
    for (const auto &chunk : packed)
      for (std::size_t i = 0; i < chunk.size();)
        {
          const auto         f          = static_cast<unsigned int>(chunk[i]);
          const auto         n_segments = static_cast<unsigned int>(chunk[i + 1]);
          const unsigned int n          = faces[f].nodes.size();
          Segments          &segments   = segments_of_face[f];
          i += 2;
          for (unsigned int k = 0; k < n_segments; ++k)
            {
              const auto                              m = static_cast<unsigned int>(chunk[i++]);
              typename Mortar::Kernel<dim>::Operators ops;
              ops.D.assign(chunk.begin() + i, chunk.begin() + i + n);
              i += n;
              ops.M.reinit(n, faces[m].nodes.size());
              for (unsigned int j = 0; j < ops.M.m(); ++j)
                for (unsigned int l = 0; l < ops.M.n(); ++l)
                  ops.M(j, l) = chunk[i++];
              ops.weighted_gap.resize(n);
              for (auto &g : ops.weighted_gap)
                for (unsigned int d = 0; d < dim; ++d)
                  g[d] = chunk[i++];
              segments.emplace_back(m, std::move(ops));
            }
        }
    return segments_of_face;
  }

  template <int dim>
  void
  ContactInterface<dim>::search_pair(
    const unsigned int                                      p,
    const std::vector<FaceGeometry>                        &geometries,
    const std::vector<double>                              &measures,
    const double                                            search_factor,
    const double                                            allowance,
    std::map<unsigned int, SlaveNode>                      &slave_data,
    std::map<unsigned int, std::map<unsigned int, double>> &M_of_node,
    std::map<unsigned int, Tensor<1, dim>>                 &weighted_gap_of_node)
  {
    using Kernel = Mortar::Kernel<dim>;
    // Broad phase: an R-tree of the master face boxes, with a margin so
    // that touching boxes of flat faces meet.
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> master_boxes;
    std::vector<double>                                    reach(faces.size(), 0.);
    for (unsigned int f = 0; f < faces.size(); ++f)
      if (faces[f].pair == p && !faces[f].slave)
        {
          BoundingBox<dim> box(geometries[f].nodes);
          box.extend(master_box_margin * face_lengths[f]);
          master_boxes.emplace_back(box, f);
        }
      else if (faces[f].pair == p)
        {
          reach[f]           = search_factor * face_lengths[f] + allowance;
          reach_of_search[p] = std::min(reach_of_search[p], reach[f]);
        }
    const auto tree = pack_rtree(master_boxes);

    // The broad phase of this rank's own slave faces gives their costs
    // (the number of candidate masters); the faces with candidates are
    // then shared out over the ranks by cost, since the contact zone need
    // not follow the partition of the cells. The narrow phase and the
    // integration run on the shared-out faces; a failed tiling check stops
    // every rank with the same message.
    std::vector<unsigned int> own_costs;
    for (unsigned int f = own_faces.first; f < own_faces.second; ++f)
      if (faces[f].slave && faces[f].pair == p)
        {
          const auto candidates =
            candidate_masters<dim>(tree, slave_box(geometries[f].nodes, reach[f]));
          within_reach[f] = 1;
          for (const unsigned int m : candidates)
            within_reach[m] = 1;
          if (const auto n = candidates.size())
            own_costs.insert(own_costs.end(), {f, static_cast<unsigned int>(n)});
        }
    std::vector<std::pair<unsigned int, unsigned int>> costs;
    for (const auto &chunk : Utilities::MPI::all_gather(mpi_communicator, own_costs))
      for (unsigned int i = 0; i + 1 < chunk.size(); i += 2)
        costs.emplace_back(chunk[i], chunk[i + 1]);
    std::string error;
    const auto  share = share_of_faces(costs, Utilities::MPI::this_mpi_process(mpi_communicator),
                                       Utilities::MPI::n_mpi_processes(mpi_communicator));
    const auto  mine  = integrate_faces(share, geometries, tree, reach, slave_data, error);
    stop_on_every_rank(error);
    const auto segments_of_face =
      unpack_segments(Utilities::MPI::all_gather(mpi_communicator, mine));

    for (const auto &[f, segments] : segments_of_face)
      if (!add_constrained_face(f, segments, slave_data, M_of_node, weighted_gap_of_node))
        for (const auto &[m, ops] : segments)
          add_segment(f, m, ops, slave_data, M_of_node, weighted_gap_of_node);

    statistics[p] = statistics_of_segments(share, segments_of_face, measures, search_factor);
  }

  template <int dim>
  typename ContactInterface<dim>::PairStatistics
  ContactInterface<dim>::statistics_of_segments(
    const std::vector<unsigned int>        &share,
    const std::map<unsigned int, Segments> &segments_of_face,
    const std::vector<double>              &measures,
    const double                            search_factor) const
  {
    // The statistics weigh each face by its share in the contact zone, so
    // that they are continuous in the geometry (the same for the scene
    // turned, moved or rescaled): a segment weighs its overlap measure
    // (sum_j D_j: the dual functions sum to one), in full up to a mean
    // separation over the overlap of half the search distance (the search
    // factor times the slave face's side: the reach without the motion
    // allowance, which varies with the step and the axes of the prescribed
    // displacements), then less, linearly to nothing at that distance,
    // beyond which the broad phase's axis-aligned boxes may or may not find
    // the pair, depending on the orientation. A sliver weighs nearly
    // nothing.
    //
    // Each rank weighs the segments of its own share; per segment: the
    // slave and the master face, the weight tapered and in full, and each
    // face's measure and modulus.
    constexpr unsigned int n_terms = 8;
    std::vector<double>    terms;
    for (const unsigned int f : share)
      if (const auto found = segments_of_face.find(f); found != segments_of_face.end())
        for (const auto &[m, ops] : found->second)
          {
            double         overlap = 0.;
            Tensor<1, dim> separation;
            for (unsigned int j = 0; j < ops.D.size(); ++j)
              {
                overlap += ops.D[j];
                separation += ops.weighted_gap[j];
              }
            if (!(overlap > 0.))
              continue;
            const double support = search_factor * face_lengths[f];
            const double tapered =
              overlap * std::clamp(2. - 2. * separation.norm() / (overlap * support), 0., 1.);
            terms.insert(terms.end(),
                         {static_cast<double>(f), static_cast<double>(m), tapered, overlap,
                          measures[f], faces[f].youngs_modulus, measures[m],
                          faces[m].youngs_modulus});
          }
    // The shares are contiguous runs in face order, so the terms gathered
    // in rank order are in face order: every rank adds them as one rank
    // holding every segment would, bit for bit. Per face: the weight w,
    // w / measure (its overlapped fraction, which counts a fully overlapped
    // face as one) and w E.
    const auto all = Utilities::MPI::all_gather(mpi_communicator, terms);
    struct Weights
    {
      double overlap = 0., fraction = 0., modulus = 0.;
    };
    std::map<unsigned int, Weights> slave_weights, master_weights;
    for (const unsigned int weight_at : {2u, 3u})
      {
        for (const auto &chunk : all)
          for (std::size_t i = 0; i < chunk.size(); i += n_terms)
            {
              const double w = chunk[i + weight_at];
              for (const unsigned int side : {0u, 1u})
                {
                  Weights &sum = (side == 0 ? slave_weights : master_weights)[static_cast<
                    unsigned int>(chunk[i + side])];
                  sum.overlap += w;
                  sum.fraction += w / chunk[i + 4 + 2 * side];
                  sum.modulus += w * chunk[i + 5 + 2 * side];
                }
            }
        // Every segment beyond the search distance (pairs the boxes found
        // all the same): the overlaps in full, rather than no statistics.
        double total = 0.;
        for (const auto &[f, sum] : slave_weights)
          total += sum.overlap;
        if (total > 0.)
          break;
        slave_weights.clear();
        master_weights.clear();
      }

    // The mean face measure counts each face by its overlapped fraction
    // (every face of a fully tied interface as one); the moduli are
    // overlap-weighted means.
    const auto mean = [](const std::map<unsigned int, Weights> &weights) {
      Weights total;
      for (const auto &[f, sum] : weights)
        {
          total.overlap += sum.overlap;
          total.fraction += sum.fraction;
          total.modulus += sum.modulus;
        }
      return std::make_pair(Mortar::Kernel<dim>::side(total.overlap / total.fraction),
                            total.modulus / total.overlap);
    };
    PairStatistics stat;
    if (!slave_weights.empty())
      {
        std::tie(stat.mean_slave_size, stat.slave_modulus)   = mean(slave_weights);
        std::tie(stat.mean_master_size, stat.master_modulus) = mean(master_weights);
      }
    return stat;
  }

  namespace
  {
    /**
     * The point of the faces in @p tree (boxes that hold the whole faces
     * @p geometries) closest to @p x: its face, parameter and distance.
     * The nearest box bounds the distance from above; every face closer
     * than that has its box within that distance. Ties (a shared edge or
     * vertex) go to the lower face index, so the result does not depend on
     * the query order.
     */
    template <int dim, class Tree>
    std::tuple<unsigned int, typename Mortar::Kernel<dim>::Parameter, double>
    closest_point(const Tree                                            &tree,
                  const std::vector<typename Mortar::Kernel<dim>::Face> &geometries,
                  const Point<dim>                                      &x)
    {
      std::vector<std::pair<BoundingBox<dim>, unsigned int>> nearest;
      tree.query(boost::geometry::index::nearest(x, 1), std::back_inserter(nearest));
      const auto      &first    = geometries[nearest[0].second];
      const auto       first_xi = Mortar::closest_parameter(first, x);
      const double     bound    = x.distance(first.point(first_xi));
      BoundingBox<dim> around(std::make_pair(x, x));
      around.extend(bound * (1. + 1e-12) + 1e-300);
      std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
      tree.query(boost::geometry::index::intersects(around), std::back_inserter(hits));

      // Seeded with the nearest box's face, so that a closest face is found
      // even if round-off keeps it out of the hits.
      double       best      = bound;
      auto         best_xi   = first_xi;
      unsigned int best_face = nearest[0].second;
      for (const auto &hit : hits)
        {
          const unsigned int f  = hit.second;
          const auto         xi = Mortar::closest_parameter(geometries[f], x);
          const double       d  = x.distance(geometries[f].point(xi));
          if (d < best - 1e-14 * bound || (d <= best && f < best_face))
            {
              best      = d;
              best_xi   = xi;
              best_face = f;
            }
        }
      return {best_face, best_xi, best};
    }
  } // namespace

  template <int dim>
  std::vector<double>
  ContactInterface<dim>::surface_distances(const std::vector<SlaveNode> &points,
                                           const std::vector<double>    &u_at_dofs) const
  {
    std::vector<unsigned int> all(points.size());
    std::iota(all.begin(), all.end(), 0u);
    return surface_distances(points, all, u_at_dofs);
  }

  template <int dim>
  std::vector<double>
  ContactInterface<dim>::surface_distances(const std::vector<SlaveNode>    &points,
                                           const std::vector<unsigned int> &which,
                                           const std::vector<double>       &u_at_dofs) const
  {
    using Kernel = Mortar::Kernel<dim>;
    std::vector<double>         distances(which.size(), std::numeric_limits<double>::infinity());
    std::vector<Tensor<1, dim>> u(nodes.size());
    for (unsigned int n = 0; n < nodes.size(); ++n)
      u[n] = displacement(n, u_at_dofs);
    // Master faces per vertex node and per edge (by its sorted vertex
    // nodes; in 2D an edge is a vertex): a closest point on an edge with
    // one face, or on a vertex of such an edge, lies on the rim of the
    // master surface.
    std::vector<std::vector<unsigned int>> master_faces_of_node(nodes.size());
    std::map<std::pair<unsigned int, unsigned int>, unsigned int> faces_of_edge;
    std::vector<FaceGeometry>                                     geometries(faces.size());
    for (unsigned int f = 0; f < faces.size(); ++f)
      if (!faces[f].slave)
        {
          geometries[f] = face_geometry(faces[f], u);
          const auto &v = faces[f].nodes;
          for (unsigned int k = 0; k < Kernel::n_vertices; ++k)
            master_faces_of_node[v[k]].push_back(f);
          for (const auto &[a, b] : Kernel::edges)
            ++faces_of_edge[std::minmax(v[a], v[b])];
        }
    std::set<unsigned int> rim_vertices;
    for (const auto &[edge, count] : faces_of_edge)
      if (count < 2)
        rim_vertices.insert({edge.first, edge.second});

    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        if (std::none_of(which.begin(), which.end(), [&](const unsigned int i) {
              return points[i].pair == p;
            }))
          continue;
        std::vector<std::pair<BoundingBox<dim>, unsigned int>> boxes;
        for (unsigned int f = 0; f < faces.size(); ++f)
          if (!faces[f].slave && faces[f].pair == p)
            boxes.emplace_back(Mortar::whole_face_box(geometries[f]), f);
        if (boxes.empty())
          continue;
        const auto tree = pack_rtree(boxes);
        for (unsigned int i = 0; i < which.size(); ++i)
          {
            const SlaveNode &s = points[which[i]];
            if (s.pair != p)
              continue;
            const Point<dim> x                    = nodes[s.node].reference + u[s.node];
            const auto [best_face, best_xi, best] = closest_point<dim>(tree, geometries, x);
            const FaceGeometry  &face             = geometries[best_face];
            const Tensor<1, dim> r                = x - face.point(best_xi);
            Tensor<1, dim>       normal;
            if (Kernel::inside(best_xi))
              normal = Mortar::face_normal(face, best_xi, faces[best_face].orientation);
            else
              {
                // On an edge or a vertex: the mean normal of the faces there.
                std::vector<unsigned int> vertices;
                for (const unsigned int k : Kernel::boundary_vertices(best_xi))
                  vertices.push_back(faces[best_face].nodes[k]);
                if (std::any_of(vertices.begin(), vertices.end(), [&](const unsigned int v) {
                      return rim_vertices.count(v);
                    }))
                  {
                    // On the rim of the master surface: beyond it in 2D (a
                    // rim vertex); in 3D a distance only if the node lies
                    // straight over the rim edge (along the face normal).
                    if constexpr (dim == 2)
                      continue;
                    const Tensor<1, dim> n =
                      Mortar::face_normal(face, best_xi, faces[best_face].orientation);
                    if ((r - (r * n) * n).norm() > 1e-8 * s.size)
                      continue;
                    distances[i] = r * n < 0. ? -best : best;
                    continue;
                  }
                for (const unsigned int f : master_faces_of_node[vertices[0]])
                  {
                    const auto &v    = faces[f].nodes;
                    const auto  last = v.begin() + Kernel::n_vertices;
                    if (vertices.size() == 2 && std::find(v.begin(), last, vertices[1]) == last)
                      continue;
                    const unsigned int k = std::find(v.begin(), last, vertices[0]) - v.begin();
                    normal += Mortar::face_normal(geometries[f], Kernel::node_parameter(1, k),
                                                  faces[f].orientation);
                  }
              }
            const double side = r * normal;
            distances[i]      = side < 0. ? -best : best;
          }
      }
    return distances;
  }

  // The members defined here, for both dimensions; the class itself is
  // instantiated in contact_interface.cc.
  template void
  ContactInterface<2>::update(const std::vector<double> &,
                              const double,
                              const std::vector<double> &);
  template std::vector<double>
  ContactInterface<2>::surface_distances(const std::vector<SlaveNode> &,
                                         const std::vector<double> &) const;
  template std::vector<double>
  ContactInterface<2>::surface_distances(const std::vector<SlaveNode> &,
                                         const std::vector<unsigned int> &,
                                         const std::vector<double> &) const;
  template void
  ContactInterface<3>::update(const std::vector<double> &,
                              const double,
                              const std::vector<double> &);
  template std::vector<double>
  ContactInterface<3>::surface_distances(const std::vector<SlaveNode> &,
                                         const std::vector<double> &) const;
  template std::vector<double>
  ContactInterface<3>::surface_distances(const std::vector<SlaveNode> &,
                                         const std::vector<unsigned int> &,
                                         const std::vector<double> &) const;
} // namespace contact_fem
