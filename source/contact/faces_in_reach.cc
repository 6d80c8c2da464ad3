// The contact faces a rank needs at a search, by an exchange of bounding
// boxes (faces_in_reach.h).
#include <deal.II/boost_adaptors/bounding_box.h>
#include <deal.II/numerics/rtree.h>

#include <contact_fem/contact/faces_in_reach.h>

#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <utility>

namespace contact_fem
{
  namespace
  {
    /// Appends @p face to @p out: number, pair, slave, the box's corners,
    /// reach, the number of nodes and the nodes.
    template <int dim>
    void
    append_face(std::vector<double> &out, const ReachFace<dim> &face)
    {
      out.insert(out.end(), {static_cast<double>(face.face), static_cast<double>(face.pair),
                             face.slave ? 1. : 0.});
      const auto &corners = face.box.get_boundary_points();
      for (unsigned int d = 0; d < dim; ++d)
        out.push_back(corners.first[d]);
      for (unsigned int d = 0; d < dim; ++d)
        out.push_back(corners.second[d]);
      out.push_back(face.reach);
      out.push_back(face.nodes.size());
      for (const unsigned int n : face.nodes)
        out.push_back(n);
      out.push_back(face.record.size());
      out.insert(out.end(), face.record.begin(), face.record.end());
    }

    /// The faces append_face() wrote into @p in.
    template <int dim>
    std::vector<ReachFace<dim>>
    read_faces(const std::vector<double> &in)
    {
      std::vector<ReachFace<dim>> faces;
      for (std::size_t i = 0; i < in.size();)
        {
          ReachFace<dim> face;
          face.face  = static_cast<unsigned int>(in[i++]);
          face.pair  = static_cast<unsigned int>(in[i++]);
          face.slave = in[i++] > 0.5;
          Point<dim> low, high;
          for (unsigned int d = 0; d < dim; ++d)
            low[d] = in[i++];
          for (unsigned int d = 0; d < dim; ++d)
            high[d] = in[i++];
          face.box           = BoundingBox<dim>(std::make_pair(low, high));
          face.reach         = in[i++];
          const auto n_nodes = static_cast<unsigned int>(in[i++]);
          for (unsigned int k = 0; k < n_nodes; ++k)
            face.nodes.push_back(static_cast<unsigned int>(in[i++]));
          const auto n_record = static_cast<std::size_t>(in[i++]);
          face.record.assign(in.begin() + i, in.begin() + i + n_record);
          i += n_record;
          faces.push_back(std::move(face));
        }
      return faces;
    }

    /**
     * Sends each face of @p offered to the other ranks whose boxes @p asked
     * (all-gathered as a level of their R-tree, which contains them) its box
     * meets, each (face, rank) at most once over the calls sharing @p sent
     * (which records them); returns the faces sent to this rank. A superset
     * of what the receiver selects, never less: an R-tree's node boxes
     * contain its entries.
     */
    template <int dim>
    std::vector<ReachFace<dim>>
    exchange(const std::vector<BoundingBox<dim>>             &asked,
             const std::vector<const ReachFace<dim> *>       &offered,
             std::set<std::pair<unsigned int, unsigned int>> &sent,
             const MPI_Comm                                   comm)
    {
      std::vector<double> coarse;
      if (!asked.empty())
        for (const auto &box : extract_rtree_level(pack_rtree(asked), 1))
          for (const auto &corner :
               {box.get_boundary_points().first, box.get_boundary_points().second})
            for (unsigned int d = 0; d < dim; ++d)
              coarse.push_back(corner[d]);

      const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
      std::vector<std::pair<BoundingBox<dim>, unsigned int>> boxes_of_ranks;
      const auto all = Utilities::MPI::all_gather(comm, coarse);
      for (unsigned int r = 0; r < all.size(); ++r)
        if (r != rank)
          for (std::size_t i = 0; i + 2 * dim <= all[r].size(); i += 2 * dim)
            {
              Point<dim> low, high;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  low[d]  = all[r][i + d];
                  high[d] = all[r][i + dim + d];
                }
              boxes_of_ranks.emplace_back(BoundingBox<dim>(std::make_pair(low, high)), r);
            }

      std::map<unsigned int, std::vector<double>> outgoing;
      if (!boxes_of_ranks.empty())
        {
          const auto tree = pack_rtree(boxes_of_ranks);
          for (const ReachFace<dim> *face : offered)
            {
              std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
              tree.query(boost::geometry::index::intersects(face->box), std::back_inserter(hits));
              std::set<unsigned int> to;
              for (const auto &hit : hits)
                to.insert(hit.second);
              for (const unsigned int r : to)
                if (sent.emplace(face->face, r).second)
                  append_face(outgoing[r], *face);
            }
        }
      std::vector<ReachFace<dim>> received;
      for (const auto &[source, data] : Utilities::MPI::some_to_some(comm, outgoing))
        for (auto &face : read_faces<dim>(data))
          received.push_back(std::move(face));
      return received;
    }
  } // namespace

  template <int dim>
  std::vector<ReachFace<dim>>
  faces_within_reach(const std::vector<ReachFace<dim>> &own, const MPI_Comm comm)
  {
    // Round 1: the master faces that may be candidates of the own slave
    // faces; then the candidates exactly, by the broad phase's test.
    std::vector<BoundingBox<dim>>       reach_boxes;
    std::vector<const ReachFace<dim> *> own_slaves, own_masters, own_all;
    for (const auto &face : own)
      {
        own_all.push_back(&face);
        if (face.slave)
          {
            own_slaves.push_back(&face);
            BoundingBox<dim> box = face.box;
            box.extend(face.reach);
            reach_boxes.push_back(box);
          }
        else
          own_masters.push_back(&face);
      }
    std::set<std::pair<unsigned int, unsigned int>> sent; // (face, rank)
    // Every face this rank has: its own and those sent to it, by number.
    std::map<unsigned int, const ReachFace<dim> *> known;
    for (const auto &face : own)
      known[face.face] = &face;
    const std::vector<ReachFace<dim>> sent_masters = exchange(reach_boxes, own_masters, sent, comm);
    for (const auto &face : sent_masters)
      known[face.face] = &face;

    std::set<unsigned int> core; // face numbers
    {
      std::vector<const ReachFace<dim> *> masters = own_masters;
      for (const auto &face : sent_masters)
        masters.push_back(&face);
      std::vector<std::pair<BoundingBox<dim>, unsigned int>> master_boxes;
      for (unsigned int i = 0; i < masters.size(); ++i)
        master_boxes.emplace_back(masters[i]->box, i);
      const auto tree = pack_rtree(master_boxes);
      for (unsigned int s = 0; s < own_slaves.size(); ++s)
        {
          core.insert(own_slaves[s]->face);
          std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
          tree.query(boost::geometry::index::intersects(reach_boxes[s]), std::back_inserter(hits));
          for (const auto &hit : hits)
            if (masters[hit.second]->pair == own_slaves[s]->pair)
              core.insert(masters[hit.second]->face);
        }
    }

    // Round 2: the faces sharing a node with the core. A shared node lies
    // in both faces' boxes; the boxes asked about are enlarged by a part of
    // their size in case the two faces' copies of the node differ by
    // round-off.
    std::vector<BoundingBox<dim>> core_boxes;
    std::set<unsigned int>        core_nodes;
    for (const unsigned int f : core)
      {
        BoundingBox<dim> box = known.at(f)->box;
        const auto      &c   = box.get_boundary_points();
        box.extend(1e-10 * c.first.distance(c.second));
        core_boxes.push_back(box);
        core_nodes.insert(known.at(f)->nodes.begin(), known.at(f)->nodes.end());
      }
    const std::vector<ReachFace<dim>> sent_ring = exchange(core_boxes, own_all, sent, comm);
    for (const auto &face : sent_ring)
      known[face.face] = &face;

    std::vector<ReachFace<dim>> held;
    for (const auto &[f, face] : known)
      if (core.count(f) > 0 ||
          std::any_of(face->nodes.begin(), face->nodes.end(), [&](const unsigned int n) {
            return core_nodes.count(n) > 0;
          }))
        held.push_back(*face);
    return held;
  }

  template std::vector<ReachFace<2>>
  faces_within_reach(const std::vector<ReachFace<2>> &, const MPI_Comm);
  template std::vector<ReachFace<3>>
  faces_within_reach(const std::vector<ReachFace<3>> &, const MPI_Comm);
} // namespace contact_fem
