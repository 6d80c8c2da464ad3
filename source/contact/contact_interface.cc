// ContactInterface: the surfaces gathered from every rank, their hanging
// vertices, the mortar sums of the slave nodes and the gaps. The search is in
// contact_interface_search.cc, the tiling checks in
// contact_interface_tiling.cc.
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/surface_numbering.h>
#include <contact_fem/core/format.h>
#include <contact_fem/core/parameters.h>
#include <contact_fem/contact/mortar_kernel.h>

#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <tuple>

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
    const unsigned int record = face_record_size(nodes_per_face, n_geometry_points);
    const unsigned int rank   = Utilities::MPI::this_mpi_process(mpi_communicator);
    for (const auto &chunk : all)
      {
        if (slave_faces_per_rank.size() == rank)
          own_faces.first = faces.size();
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
                    node.dofs[d]      = static_cast<types::global_dof_index>(data[dim + d]);
                    node.fixed[d]     = data[2 * dim + d] > 0.5;
                  }
                const auto   it = node_of_dof.find(node.dofs[0]);
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
        if (slave_faces_per_rank.size() == rank + 1)
          own_faces.second = faces.size();
      }
  }

  namespace
  {
    /**
     * Positive if the node polygon of the face of @p fe_face (its support
     * points, in face DoF order) turns its normal (rotated tangent in 2D,
     * t_xi x t_eta in 3D) out of the cell, negative otherwise. The support
     * points are in the face's own orientation (FEFaceValues permutes them
     * like the face DoFs); their vertices are checked against those of
     * @p face, in case that ever changes.
     */
    template <int dim, typename FaceIterator>
    double
    outward_orientation(const FEFaceValues<dim> &fe_face,
                        const FaceIterator      &face,
                        const unsigned int       nodes_per_face)
    {
      using Kernel = Mortar::Kernel<dim>;
      typename Kernel::Face geometry;
      for (unsigned int k = 0; k < nodes_per_face; ++k)
        geometry.nodes.push_back(fe_face.quadrature_point(k));
      for (unsigned int v = 0; v < Kernel::n_vertices; ++v)
        AssertThrow(geometry.nodes[v].distance(face->vertex(v)) <= 1e-10 * face->diameter(),
                    ExcMessage("Contact: the support points of a contact face are not in "
                               "the order of its vertices."));
      return Mortar::face_normal(geometry, Kernel::node_parameter(1, 0), 1.) *
             fe_face.normal_vector(0);
    }
  } // namespace

  namespace
  {
    /**
     * A cycle of pairs through shared nodes in @p interface, or "": pair A
     * leads to pair B where a node is on A's slave and B's master surface,
     * and the pairs lead back to A (two corners pressed into each other,
     * each on the other's pair). The multipliers of a chain are recovered
     * link by link from its outer end
     * (ContactFormulation::recover_through_chains()), and a cycle has none:
     * the message names the pairs and nodes (an input error).
     */
    template <int dim>
    std::string
    chain_cycle(const ContactInterface<dim> &interface)
    {
      const auto &pairs = interface.pairs;
      const auto &nodes = interface.nodes;
      const auto &faces = interface.faces;
      if (!interface.has_chained_nodes())
        return "";
      // The links: pair a leads to pair b through node link_node[a][b].
      const unsigned int                     n_pairs = pairs.size();
      const unsigned int                     none    = numbers::invalid_unsigned_int;
      std::vector<std::vector<unsigned int>> link_node(n_pairs,
                                                       std::vector<unsigned int>(n_pairs, none));
      std::vector<std::set<unsigned int>>    master_of(nodes.size());
      for (const auto &face : faces)
        if (!face.slave)
          for (const unsigned int n : face.nodes)
            master_of[n].insert(face.pair);
      for (const auto &face : faces)
        if (face.slave)
          for (const unsigned int n : face.nodes)
            for (const unsigned int b : master_of[n])
              if (b != face.pair && link_node[face.pair][b] == none)
                link_node[face.pair][b] = n;
      // Which pairs each leads to through any number of links (few pairs).
      std::vector<std::vector<bool>> reach(n_pairs, std::vector<bool>(n_pairs));
      for (unsigned int a = 0; a < n_pairs; ++a)
        for (unsigned int b = 0; b < n_pairs; ++b)
          reach[a][b] = link_node[a][b] != none;
      for (unsigned int k = 0; k < n_pairs; ++k)
        for (unsigned int a = 0; a < n_pairs; ++a)
          for (unsigned int b = 0; b < n_pairs; ++b)
            reach[a][b] = reach[a][b] || (reach[a][k] && reach[k][b]);
      const auto name = [&](const unsigned int p) {
        return "'" + std::to_string(pairs[p].slave) + ": " + std::to_string(pairs[p].master) + "'";
      };
      for (unsigned int a = 0; a < n_pairs; ++a)
        for (unsigned int b = 0; b < n_pairs; ++b)
          if (link_node[a][b] != none && reach[b][a])
            return "Contact/Pairs: the pairs form a cycle through shared nodes: the node at " +
                   coordinates_text(nodes[link_node[a][b]].reference) +
                   " is on the slave surface of pair " + name(a) +
                   " and on the master surface of pair " + name(b) + ", and pair " + name(b) +
                   (link_node[b][a] != none ?
                      " leads back to " + name(a) + " at the node at " +
                        coordinates_text(nodes[link_node[b][a]].reference) :
                      " leads back to " + name(a) + " through other pairs") +
                   ". The contact forces of a chain of pairs are recovered link by link from its "
                   "outer end, and a cycle has none. Let one surface of such a link end an "
                   "element before the other (share no node), or make the other surface of a "
                   "pair its slave.";
      return "";
    }
  } // namespace

  template <int dim>
  void
  ContactInterface<dim>::initialize(const MappingQ<dim>                &mapping,
                                    const DoFHandler<dim>              &dof_handler,
                                    const std::vector<ContactPair>     &contact_pairs,
                                    const AffineConstraints<double>    &dirichlet,
                                    const AffineConstraints<double>    &hanging,
                                    const Materials<dim>               &materials,
                                    const MPI_Comm                      comm,
                                    const std::set<types::boundary_id> &moving_supports)
  {
    pairs                        = contact_pairs;
    mpi_communicator             = comm;
    owned_dofs                   = dof_handler.locally_owned_dofs();
    const FiniteElement<dim> &fe = dof_handler.get_fe();
    degree                       = fe.degree;
    geometry_degree              = std::max(degree, mapping.get_degree());
    // The mortar kernels (mortar.h, mortar_3d.h) take faces of degree 1 or
    // 2, and a geometry above the element degree only as Q1 on a quadratic
    // mapping.
    AssertThrow(geometry_degree == degree || (degree == 1 && geometry_degree == 2),
                ExcMessage("Contact: the geometry of the contact faces (degree " +
                           std::to_string(geometry_degree) +
                           ") may exceed the element "
                           "degree (" +
                           std::to_string(degree) +
                           ") only for degree-1 "
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
          geometry_nodes.push_back(
            Mortar::Kernel<dim>::unit(Mortar::Kernel<dim>::node_parameter(2, k)));
        }
    std::unique_ptr<FEFaceValues<dim>> fe_face_geometry;
    if (n_geometry_points > 0)
      fe_face_geometry =
        std::make_unique<FEFaceValues<dim>>(mapping, fe, Quadrature<dim - 1>(geometry_nodes),
                                            update_quadrature_points);

    // Pack the local faces: [pair, slave, E, nu, orientation, then per node:
    // coordinates, dofs, fixed flags].
    std::vector<double>                  packed;
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    // A failed check of a face stops every rank (stop_on_every_rank()).
    std::string error;
    try
      {
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
                          const auto ci                  = fe.face_system_to_component_index(i, f);
                          node_dofs[ci.second][ci.first] = face_dofs[i];
                        }
                      const double dot =
                        outward_orientation(fe_face, cell->face(f), nodes_per_face);

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
                              const auto dof   = node_dofs[k][d];
                              const bool fixed = dirichlet.is_constrained(dof) &&
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
                               k < nodes_per_face + n_geometry_points; ++k)
                            for (unsigned int d = 0; d < dim; ++d)
                              packed.push_back(
                                fe_face_geometry->quadrature_point(k - first_geometry_node)[d]);
                        }
                    }
      }
    catch (const std::exception &e)
      {
        error = user_message(e);
      }
    stop_on_every_rank(error);
    unpack_faces(Utilities::MPI::all_gather(comm, packed), nodes_per_face, n_geometry_points);
    if (checking_held_state())
      check_own_numbering(packed, nodes_per_face, n_geometry_points);
    // Every rank holds the same faces: the same verdict everywhere.
    stop_on_every_rank(chain_cycle(*this));

    interface_dofs.clear();
    for (const auto &node : nodes)
      for (unsigned int d = 0; d < dim; ++d)
        interface_dofs.push_back(node.dofs[d]);
    std::sort(interface_dofs.begin(), interface_dofs.end());
    dof_position.clear();
    for (unsigned int i = 0; i < interface_dofs.size(); ++i)
      dof_position[interface_dofs[i]] = i;
    owned_interface_dofs = IndexSet(owned_dofs.size());
    ghost_interface_dofs = IndexSet(owned_dofs.size());
    for (const auto dof : interface_dofs)
      (owned_dofs.is_element(dof) ? owned_interface_dofs : ghost_interface_dofs).add_index(dof);
    owned_interface_dofs.compress();
    ghost_interface_dofs.compress();
    ghost_import =
      std::make_shared<const Utilities::MPI::NoncontiguousPartitioner>(owned_interface_dofs,
                                                                       ghost_interface_dofs, comm);
    {
      IndexSet all_interface_dofs(owned_dofs.size());
      all_interface_dofs.add_indices(interface_dofs.begin(), interface_dofs.end());
      owner_of_position = Utilities::MPI::compute_index_owner(owned_dofs, all_interface_dofs, comm);
    }
    fixed_positions.assign(interface_dofs.size(), false);
    for (const auto &node : nodes)
      for (unsigned int d = 0; d < dim; ++d)
        if (node.fixed[d])
          fixed_positions[dof_position[node.dofs[d]]] = true;
    find_symmetry_planes(dof_handler, dirichlet, moving_supports);
    find_hanging_vertices(hanging);
    {
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      find_row_holders(relevant);
    }
    find_pair_materials();
    count_own_slave_nodes();
    slave_nodes.clear();
    hanging_slave_vertices.clear();
    coupled_faces.clear();
    within_reach.clear();
    face_lengths.clear();
    statistics.assign(pairs.size(), PairStatistics());
  }

  template <int dim>
  void
  ContactInterface<dim>::check_own_numbering(const std::vector<double> &packed,
                                             const unsigned int         nodes_per_face,
                                             const unsigned int         n_geometry_points) const
  {
    // The first DoF of every node of the own faces, as unpack_faces() reads
    // them.
    const unsigned int record = face_record_size(nodes_per_face, n_geometry_points);
    std::vector<types::global_dof_index> node_dofs;
    for (unsigned int r = 0; r + record <= packed.size(); r += record)
      for (unsigned int k = 0; k < nodes_per_face; ++k)
        node_dofs.push_back(
          static_cast<types::global_dof_index>(packed[r + 5 + k * 3 * dim + dim]));
    OwnSurfaceNumbers numbers;
    std::string       error;
    try
      {
        numbers = number_own_faces(node_dofs, nodes_per_face, owned_dofs, mpi_communicator);
      }
    catch (const std::exception &e)
      {
        error = user_message(e);
      }
    const unsigned int n_own   = node_dofs.size() / nodes_per_face;
    unsigned int       n_wrong = 0, first_wrong = numbers::invalid_unsigned_int;
    if (error.empty() && own_faces.second - own_faces.first == n_own)
      for (unsigned int i = 0; i < n_own; ++i)
        for (unsigned int k = 0; k < nodes_per_face; ++k)
          if (numbers.nodes[i * nodes_per_face + k] != faces[own_faces.first + i].nodes[k])
            {
              if (n_wrong++ == 0)
                first_wrong = i;
            }
    if (error.empty() &&
        (numbers.first_face != own_faces.first || own_faces.second - own_faces.first != n_own ||
         numbers.n_faces != faces.size() || numbers.n_nodes != nodes.size() || n_wrong > 0))
      {
        std::ostringstream message;
        message << "Contact (check of CONTACT_FEM_CHECK_HELD_STATE): on rank "
                << Utilities::MPI::this_mpi_process(mpi_communicator)
                << ", the numbers of the own contact faces and their nodes computed from this "
                   "rank's faces alone (number_own_faces()) differ from those of the gathered "
                   "surface: first own face "
                << numbers.first_face << " against " << own_faces.first << ", own faces " << n_own
                << " against " << own_faces.second - own_faces.first << ", faces in all "
                << numbers.n_faces << " against " << faces.size() << ", nodes in all "
                << numbers.n_nodes << " against " << nodes.size() << ", " << n_wrong
                << " node numbers differ";
        if (n_wrong > 0)
          message << " (the first on own face " << first_wrong << ")";
        message << ".";
        error = message.str();
      }
    stop_on_every_rank(error);
  }

  template <int dim>
  void
  ContactInterface<dim>::stop_on_every_rank(const std::string &error) const
  {
    for (const std::string &message : Utilities::MPI::all_gather(mpi_communicator, error))
      if (!message.empty())
        throw GeometryFailure(message);
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
    for (const auto &chunk : Utilities::MPI::all_gather(mpi_communicator, triples))
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
              message << "Contact: a hanging vertex of a contact surface at (" << nodes[n].reference
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
  void
  ContactInterface<dim>::find_row_holders(const IndexSet &relevant)
  {
    // The regular slave nodes by x DoF: the import's order.
    std::map<types::global_dof_index, unsigned int> node_of_row;
    for (unsigned int n = 0; n < nodes.size(); ++n)
      if (nodes[n].slave && nodes[n].parents.empty())
        node_of_row[nodes[n].dofs[0]] = n;
    owned_row_nodes.clear();
    ghost_row_nodes.clear();
    row_holder.assign(nodes.size(), 0);
    for (const auto &[row, n] : node_of_row)
      if (owned_dofs.is_element(row))
        {
          owned_row_nodes.push_back(n);
          row_holder[n] = 1;
        }
      else if (std::any_of(nodes[n].dofs.begin(), nodes[n].dofs.end(), [&](const auto dof) {
                 return relevant.is_element(dof);
               }))
        {
          ghost_row_nodes.push_back(n);
          row_holder[n] = 2;
        }
    row_imports = std::make_shared<
      std::map<unsigned int, std::shared_ptr<const Utilities::MPI::NoncontiguousPartitioner>>>();
    zone_nodes_received = std::make_shared<unsigned int>(0);
    relevant_dofs       = relevant;
    state_held.assign(nodes.size(), 0);
    held_check_counts = std::make_shared<std::pair<unsigned int, unsigned int>>(0, 0);
    line_check_counts = std::make_shared<std::pair<unsigned int, unsigned int>>(0, 0);
    // Until the first search, every line (as before the lines were held).
    line_held.assign(nodes.size(), 1);
    held_line_dofs = relevant;
    held_line_dofs.add_indices(owned_interface_dofs);
    held_line_dofs.add_indices(ghost_interface_dofs);
  }

  template <int dim>
  void
  ContactInterface<dim>::close_ghosts()
  {
    // The force at a DoF of node l sums -lambda_j D_j n_j (j = l) and
    // lambda_j M_jl n_j over the slave nodes j whose M reaches l: a node
    // is held if it or one of its masters has a relevant DoF.
    const auto relevant_node = [&](const unsigned int n) {
      return std::any_of(nodes[n].dofs.begin(), nodes[n].dofs.end(), [&](const auto dof) {
        return relevant_dofs.is_element(dof);
      });
    };
    state_held.assign(nodes.size(), 0);
    for (const SlaveNode &s : slave_nodes)
      state_held[s.node] = row_holder[s.node] != 0 || relevant_node(s.node) ||
                           std::any_of(s.M.begin(), s.M.end(), [&](const auto &entry) {
                             return relevant_node(entry.first);
                           });
  }

  template <int dim>
  void
  ContactInterface<dim>::close_lines()
  {
    // The lines a rank's constraints need: those at its relevant DoFs (its
    // cells distribute through them) and at the DoFs of the linearised
    // patches of its rows (add_sparsity() closes them over the candidates),
    // and, since close() resolves a line through the lines at its
    // masters, those of the masters of every node held, repeatedly.
    std::vector<char> seed(nodes.size(), 0);
    for (unsigned int n = 0; n < nodes.size(); ++n)
      seed[n] = std::any_of(nodes[n].dofs.begin(), nodes[n].dofs.end(), [&](const auto dof) {
        return relevant_dofs.is_element(dof);
      });
    if (!linearised_nodes.empty())
      {
        std::map<types::global_dof_index, unsigned int> node_of_dof;
        for (unsigned int n = 0; n < nodes.size(); ++n)
          for (const auto dof : nodes[n].dofs)
            node_of_dof[dof] = n;
        for (const auto &[n, linearised] : linearised_nodes)
          for (const auto dof : linearised.dofs)
            if (const auto it = node_of_dof.find(dof); it != node_of_dof.end())
              seed[it->second] = 1;
      }
    std::vector<const SlaveNode *> slave_of_node(nodes.size(), nullptr);
    for (const SlaveNode &s : slave_nodes)
      slave_of_node[s.node] = &s;
    line_held.assign(nodes.size(), 0);
    std::vector<unsigned int> pending;
    for (unsigned int n = 0; n < nodes.size(); ++n)
      if (seed[n])
        {
          line_held[n] = 1;
          pending.push_back(n);
        }
    // Every node enters once, so the walk ends (cycles of pairs too).
    while (!pending.empty())
      {
        const unsigned int n = pending.back();
        pending.pop_back();
        if (slave_of_node[n] != nullptr)
          for (const auto &[m, value] : slave_of_node[n]->M)
            if (!line_held[m])
              {
                line_held[m] = 1;
                pending.push_back(m);
              }
      }
    held_line_dofs = relevant_dofs;
    std::vector<types::global_dof_index> dofs;
    for (unsigned int n = 0; n < nodes.size(); ++n)
      if (line_held[n])
        dofs.insert(dofs.end(), nodes[n].dofs.begin(), nodes[n].dofs.end());
    std::sort(dofs.begin(), dofs.end());
    held_line_dofs.add_indices(dofs.begin(), dofs.end());
    held_line_dofs.compress();
  }

  template <int dim>
  void
  ContactInterface<dim>::close_line_dofs(IndexSet                                         &lines,
                                         const std::vector<const ContactInterface<dim> *> &surfaces)
  {
    const auto in_lines = [&](const Node &node) {
      return std::any_of(node.dofs.begin(), node.dofs.end(), [&](const auto dof) {
        return lines.is_element(dof);
      });
    };
    for (bool grew = true; grew;)
      {
        grew = false;
        std::vector<types::global_dof_index> added;
        for (const auto *surface : surfaces)
          {
            if (surface == nullptr)
              continue;
            const auto add_node = [&](const unsigned int n) {
              for (const auto dof : surface->nodes[n].dofs)
                if (!lines.is_element(dof))
                  added.push_back(dof);
            };
            for (const auto &s : surface->slave_nodes)
              if (in_lines(surface->nodes[s.node]))
                for (const auto &[m, value] : s.M)
                  add_node(m);
            for (const auto &node : surface->nodes)
              if (!node.parents.empty() && in_lines(node))
                for (const auto &[parent, weight] : node.parents)
                  add_node(parent);
            // The next surface sees what this one added.
            if (!added.empty())
              {
                std::sort(added.begin(), added.end());
                added.erase(std::unique(added.begin(), added.end()), added.end());
                lines.add_indices(added.begin(), added.end());
                lines.compress();
                grew = true;
                added.clear();
              }
          }
      }
  }

  unsigned int
  count_differing_lines(const AffineConstraints<double>            &held,
                        const AffineConstraints<double>            &full,
                        const std::vector<types::global_dof_index> &dofs,
                        const MPI_Comm                              comm)
  {
    const auto same_bits = [](const double a, const double b) {
      return std::memcmp(&a, &b, sizeof(double)) == 0;
    };
    const auto constrained_in = [](const AffineConstraints<double> &c,
                                   const types::global_dof_index    dof) {
      return c.can_store_line(dof) && c.is_constrained(dof);
    };
    unsigned int wrong = 0;
    for (const auto dof : dofs)
      {
        const bool constrained = constrained_in(full, dof);
        if (constrained_in(held, dof) != constrained)
          {
            ++wrong;
            continue;
          }
        if (!constrained)
          continue;
        const auto &a    = *held.get_constraint_entries(dof);
        const auto &b    = *full.get_constraint_entries(dof);
        bool        same = a.size() == b.size() &&
                    same_bits(held.get_inhomogeneity(dof), full.get_inhomogeneity(dof));
        for (unsigned int k = 0; same && k < a.size(); ++k)
          same = a[k].first == b[k].first && same_bits(a[k].second, b[k].second);
        wrong += !same;
      }
    return Utilities::MPI::sum(wrong, comm);
  }

  template <int dim>
  void
  ContactInterface<dim>::check_held_lines(const AffineConstraints<double> &held,
                                          const AffineConstraints<double> &full) const
  {
    std::vector<types::global_dof_index> dofs;
    relevant_dofs.fill_index_vector(dofs);
    const unsigned int compared = dofs.size();
    // Every rank stops (one rank alone would leave the others waiting).
    const unsigned int wrong = count_differing_lines(held, full, dofs, mpi_communicator);
    AssertThrow(wrong == 0,
                ExcMessage("The constraint lines of the held slave nodes differ from those of "
                           "every slave node at " +
                           std::to_string(wrong) + " locally relevant DoFs."));
    const unsigned int left_out =
      full.n_constraints() > held.n_constraints() ? full.n_constraints() - held.n_constraints() : 0;
    line_check_counts->first  = std::max(line_check_counts->first, compared);
    line_check_counts->second = std::max(line_check_counts->second, left_out);
  }

  template <int dim>
  bool
  ContactInterface<dim>::checking_held_state()
  {
    static const bool checking = std::getenv("CONTACT_FEM_CHECK_HELD_STATE") != nullptr;
    return checking;
  }

  template <int dim>
  bool
  ContactInterface<dim>::checking_held_surface()
  {
    static const bool checking = std::getenv("CONTACT_FEM_CHECK_HELD_SURFACE") != nullptr;
    return checking;
  }

  template <int dim>
  void
  ContactInterface<dim>::check_held_forces(const std::vector<double> &held,
                                           const std::vector<double> &full) const
  {
    AssertDimension(held.size(), interface_dofs.size());
    AssertDimension(full.size(), interface_dofs.size());
    // Bit for bit (a -0 against a +0 counts as a difference), at every
    // interface DoF: the owners' sums reach every rank (sum_forces()).
    unsigned int compared = 0, left_out = 0, wrong = 0;
    for (unsigned int k = 0; k < interface_dofs.size(); ++k)
      {
        const bool same = std::memcmp(&held[k], &full[k], sizeof(double)) == 0;
        if (relevant_dofs.is_element(interface_dofs[k]))
          ++compared;
        else
          left_out += !same;
        wrong += !same;
      }
    AssertThrow(wrong == 0,
                ExcMessage("The contact force summed by the owners of the DoFs differs from the "
                           "one from every slave node at " +
                           std::to_string(wrong) + " interface DoFs."));
    held_check_counts->first  = std::max(held_check_counts->first, compared);
    held_check_counts->second = std::max(held_check_counts->second, left_out);
  }

  template <int dim>
  typename ContactInterface<dim>::HeldCounts
  ContactInterface<dim>::count_held() const
  {
    HeldCounts held;
    held.faces                = faces.size();
    held.slave_nodes          = slave_nodes.size();
    held.rows_owned           = owned_row_nodes.size();
    held.row_ghosts           = ghost_row_nodes.size();
    held.interface_dofs       = interface_dofs.size();
    held.interface_dofs_owned = owned_interface_dofs.n_elements();
    held.zone_nodes_received  = zone_nodes_received ? *zone_nodes_received : 0;
    for (const SlaveNode &s : slave_nodes)
      held.closed_ghosts += state_held[s.node] && row_holder[s.node] != 1;
    if (held_check_counts)
      std::tie(held.check_dofs_compared, held.check_dofs_left_out) = *held_check_counts;
    for (const SlaveNode &s : slave_nodes)
      held.line_nodes += line_held[s.node] != 0;
    held.line_dofs = held_line_dofs.n_elements();
    {
      std::set<unsigned int> reach_nodes;
      for (unsigned int f = 0; f < within_reach.size(); ++f)
        if (within_reach[f])
          {
            ++held.faces_within_reach;
            reach_nodes.insert(faces[f].nodes.begin(), faces[f].nodes.end());
          }
      held.dofs_within_reach = dim * reach_nodes.size();
    }
    if (line_check_counts)
      std::tie(held.check_lines_compared, held.check_lines_left_out) = *line_check_counts;
    // A std::map entry: the key and value plus about 32 bytes of tree node.
    const double map_entry = 32. + sizeof(types::global_dof_index) + sizeof(unsigned int);
    double       bytes     = 0.;
    for (const Face &face : faces)
      bytes += sizeof(Face) + face.nodes.capacity() * sizeof(unsigned int) +
               face.geometry_points.capacity() * sizeof(Point<dim>);
    for (const Node &node : nodes)
      bytes += sizeof(Node) + node.parents.capacity() * sizeof(node.parents[0]);
    for (const auto *list : {&slave_nodes, &hanging_slave_vertices})
      for (const SlaveNode &s : *list)
        bytes += sizeof(SlaveNode) + s.M.capacity() * sizeof(s.M[0]);
    bytes += interface_dofs.capacity() * sizeof(types::global_dof_index) +
             dof_position.size() * map_entry + fixed_positions.size() / 8. +
             coupled_faces.capacity() * sizeof(coupled_faces[0]) +
             face_lengths.capacity() * sizeof(double) +
             search_displacement.capacity() * sizeof(double) +
             (slave_surface_normals.size() + master_surface_normals.size()) *
               (32. + sizeof(unsigned int) + sizeof(Tensor<1, dim>) + sizeof(double));
    held.bytes = bytes;
    return held;
  }

  template <int dim>
  void
  ContactInterface<dim>::share_node_values(const std::vector<std::vector<double> *> &fields,
                                           const unsigned int                        n_key) const
  {
    if (Utilities::MPI::n_mpi_processes(mpi_communicator) == 1)
      return;
    // The ghosts: from their owners, point to point, all fields at once
    // (index K x DoF + k of field k of K), so the ranks meet once.
    const unsigned int K      = fields.size();
    auto              &import = (*row_imports)[K];
    if (!import)
      {
        // The K x DoF numbering must fit the index type.
        AssertThrow(owned_dofs.size() <= std::numeric_limits<types::global_dof_index>::max() / K,
                    ExcMessage("The contact interface's node-state exchange numbers " +
                               std::to_string(K) + " fields per DoF; " +
                               std::to_string(owned_dofs.size()) +
                               " DoFs exceed the DoF index type (build deal.II with "
                               "64-bit indices)."));
        IndexSet own_rows(owned_dofs.size() * K), ghost_rows(owned_dofs.size() * K);
        for (const auto *held : {&owned_row_nodes, &ghost_row_nodes})
          for (const unsigned int n : *held)
            for (unsigned int k = 0; k < K; ++k)
              (held == &owned_row_nodes ? own_rows : ghost_rows)
                .add_index(nodes[n].dofs[0] * K + k);
        own_rows.compress();
        ghost_rows.compress();
        import =
          std::make_shared<const Utilities::MPI::NoncontiguousPartitioner>(own_rows, ghost_rows,
                                                                           mpi_communicator);
      }
    std::vector<double> own(owned_row_nodes.size() * K), ghosts(ghost_row_nodes.size() * K);
    for (unsigned int i = 0; i < owned_row_nodes.size(); ++i)
      for (unsigned int k = 0; k < K; ++k)
        own[i * K + k] = (*fields[k])[owned_row_nodes[i]];
    import->export_to_ghosted_array(ArrayView<const double>(own), ArrayView<double>(ghosts));
    for (unsigned int i = 0; i < ghost_row_nodes.size(); ++i)
      for (unsigned int k = 0; k < K; ++k)
        (*fields[k])[ghost_row_nodes[i]] = ghosts[i * K + k];
    // The rest: the owned nodes with a key value other than +0 (a -0 too,
    // so the copies are exact), all-gathered; every other node gets +0.
    const auto is_set = [](const double v) {
      return v != 0. || std::signbit(v);
    };
    std::vector<double> zone;
    for (const unsigned int n : owned_row_nodes)
      if (std::any_of(fields.begin(), fields.begin() + n_key, [&](const auto *field) {
            return is_set((*field)[n]);
          }))
        {
          zone.push_back(n);
          for (const auto *field : fields)
            zone.push_back((*field)[n]);
        }
    for (unsigned int n = 0; n < nodes.size(); ++n)
      if (row_holder[n] == 0 && nodes[n].slave && nodes[n].parents.empty())
        for (auto *field : fields)
          (*field)[n] = 0.;
    unsigned int received = 0;
    for (const auto &chunk : Utilities::MPI::all_gather(mpi_communicator, zone))
      for (unsigned int i = 0; i < chunk.size(); i += 1 + K)
        {
          const auto n = static_cast<unsigned int>(chunk[i]);
          if (row_holder[n] == 0)
            {
              ++received;
              for (unsigned int k = 0; k < K; ++k)
                (*fields[k])[n] = chunk[i + 1 + k];
            }
        }
    *zone_nodes_received = std::max(*zone_nodes_received, received);
    if (checking_held_surface() && !node_within_reach.empty())
      for (unsigned int n = 0; n < nodes.size(); ++n)
        if (row_holder[n] == 0 && node_within_reach[n] == 0)
          for (auto *field : fields)
            (*field)[n] = std::numeric_limits<double>::quiet_NaN();
  }

  template <int dim>
  double
  ContactInterface<dim>::sum_in_node_order(
    const std::vector<std::pair<unsigned int, double>> &terms,
    const double                                        start) const
  {
    double sum = start;
    if (Utilities::MPI::n_mpi_processes(mpi_communicator) == 1)
      {
        for (const auto &term : terms)
          sum += term.second;
        return sum;
      }
    // (index, term) flat, as doubles (an index below 2^53 is exact).
    std::vector<double> own;
    for (const auto &[k, term] : terms)
      if (term != 0. || std::signbit(term))
        {
          own.push_back(k);
          own.push_back(term);
        }
    std::vector<std::pair<unsigned int, double>> all;
    for (const auto &chunk : Utilities::MPI::all_gather(mpi_communicator, own))
      for (unsigned int i = 0; i < chunk.size(); i += 2)
        all.emplace_back(static_cast<unsigned int>(chunk[i]), chunk[i + 1]);
    // A node's terms come from its owner, in its order: a stable sort by
    // node keeps them so.
    std::stable_sort(all.begin(), all.end(), [](const auto &a, const auto &b) {
      return a.first < b.first;
    });
    for (const auto &term : all)
      sum += term.second;
    return sum;
  }

  template <int dim>
  std::vector<double>
  ContactInterface<dim>::sum_forces(const std::vector<ForceTerm> &terms,
                                    const bool                    every_node_here) const
  {
    std::vector<double> force(interface_dofs.size(), 0.);
    if (every_node_here || Utilities::MPI::n_mpi_processes(mpi_communicator) == 1)
      {
        for (const auto &term : terms)
          force[term.position] += term.value;
        return force;
      }
    // (key, DoF, value) flat, as doubles (keys and DoFs below 2^53 are
    // exact), to the owner of the DoF.
    const unsigned int me = Utilities::MPI::this_mpi_process(mpi_communicator);
    std::map<unsigned int, std::vector<double>>                     outgoing;
    std::vector<std::pair<double, std::pair<unsigned int, double>>> mine;
    for (const auto &term : terms)
      if (const unsigned int owner = owner_of_position[term.position]; owner == me)
        mine.push_back({term.key, {term.position, term.value}});
      else
        outgoing[owner].insert(outgoing[owner].end(),
                               {term.key, static_cast<double>(interface_dofs[term.position]),
                                term.value});
    for (const auto &[rank, flat] : Utilities::MPI::some_to_some(mpi_communicator, outgoing))
      for (unsigned int i = 0; i + 2 < flat.size(); i += 3)
        mine.push_back(
          {flat[i], {position(static_cast<types::global_dof_index>(flat[i + 1])), flat[i + 2]}});
    // A node's terms come from one rank in its order: a stable sort by
    // key gives the serial loop's order at every DoF.
    std::stable_sort(mine.begin(), mine.end(), [](const auto &a, const auto &b) {
      return a.first < b.first;
    });
    for (const auto &[key, term] : mine)
      force[term.first] += term.second;
    return gather([&](const types::global_dof_index dof) {
      return force[position(dof)];
    });
  }

  template <int dim>
  std::vector<double>
  ContactInterface<dim>::gather(const TrilinosWrappers::MPI::Vector &v) const
  {
    return gather([&v](const types::global_dof_index i) {
      return v(i);
    });
  }

  template <int dim>
  std::vector<double>
  ContactInterface<dim>::gather(
    const std::function<double(types::global_dof_index)> &value_on_owner) const
  {
    // The owned values, then the ghosts' from their owners: copies, so
    // every rank has the owners' values exactly.
    std::vector<double> own, ghosts(ghost_interface_dofs.n_elements());
    own.reserve(owned_interface_dofs.n_elements());
    for (const auto dof : owned_interface_dofs)
      own.push_back(value_on_owner(dof));
    ghost_import->export_to_ghosted_array(ArrayView<const double>(own), ArrayView<double>(ghosts));
    // Both sets are sorted, as dofs() is: merge them.
    std::vector<double> result(interface_dofs.size());
    unsigned int        next_own = 0, next_ghost = 0;
    for (unsigned int i = 0; i < interface_dofs.size(); ++i)
      result[i] =
        owned_interface_dofs.is_element(interface_dofs[i]) ? own[next_own++] : ghosts[next_ghost++];
    return result;
  }

  template <int dim>
  Tensor<1, dim>
  ContactInterface<dim>::displacement(const unsigned int n, const std::vector<double> &u) const
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
  typename ContactInterface<dim>::FaceGeometry
  ContactInterface<dim>::face_geometry(const Face &face, const std::vector<Tensor<1, dim>> &u) const
  {
    using Kernel = Mortar::Kernel<dim>;
    FaceGeometry result;
    result.element_degree = degree;
    for (const unsigned int n : face.nodes)
      result.nodes.push_back(nodes[n].reference + (u.empty() ? Tensor<1, dim>() : u[n]));
    // The geometry points of Q1 on a quadratic mapping (the midpoint in 2D;
    // the edge midpoints and the centre in 3D) move with the (bi)linear
    // displacement of the face.
    for (unsigned int k = 0; k < face.geometry_points.size(); ++k)
      {
        Tensor<1, dim> displacement;
        if (!u.empty())
          {
            const auto xi = Kernel::node_parameter(2, face.nodes.size() + k);
            for (unsigned int v = 0; v < face.nodes.size(); ++v)
              displacement += Kernel::shape_value(1, v, xi) * u[face.nodes[v]];
          }
        result.nodes.push_back(face.geometry_points[k] + displacement);
      }
    return result;
  }

  template <int dim>
  double
  ContactInterface<dim>::contact_modulus(const unsigned int pair) const
  {
    const auto &E  = pair_materials.at(pair).youngs_modulus;
    const auto &nu = pair_materials.at(pair).poisson_ratio;
    return 1. / ((1. - nu[0] * nu[0]) / E[0] + (1. - nu[1] * nu[1]) / E[1]);
  }

  template <int dim>
  void
  ContactInterface<dim>::count_own_slave_nodes()
  {
    // A node belongs to the first face holding it, which a rank that holds
    // the faces sharing a node with its own can also tell.
    std::vector<unsigned int> first_face(nodes.size(), numbers::invalid_unsigned_int);
    for (unsigned int f = 0; f < faces.size(); ++f)
      for (const unsigned int n : faces[f].nodes)
        if (first_face[n] == numbers::invalid_unsigned_int)
          first_face[n] = f;
    own_nodes.assign(nodes.size(), false);
    std::array<unsigned int, 2> counts = {{0, 0}};
    for (unsigned int f = own_faces.first; f < own_faces.second; ++f)
      for (const unsigned int n : faces[f].nodes)
        if (first_face[n] == f)
          {
            own_nodes[n] = true;
            if (nodes[n].slave)
              ++counts[nodes[n].parents.empty() ? 0 : 1];
          }
    slave_node_counts = {Utilities::MPI::sum(counts[0], mpi_communicator),
                         Utilities::MPI::sum(counts[1], mpi_communicator)};
  }

  template <int dim>
  void
  ContactInterface<dim>::find_symmetry_planes(const DoFHandler<dim>              &dof_handler,
                                              const AffineConstraints<double>    &dirichlet,
                                              const std::set<types::boundary_id> &moving_supports)
  {
    const auto &fe    = dof_handler.get_fe();
    const auto  fixed = [&](const types::global_dof_index dof) {
      return dirichlet.is_constrained(dof) && dirichlet.get_constraint_entries(dof)->empty();
    };
    // The component-d DoFs of the interface nodes on a roller face normal
    // to e_d. A roller, not a clamp: d fixed at every node of the face,
    // and no other component at every node (a node where two symmetry
    // planes meet fixes both, the face's other nodes one). Flat and
    // normal to e_d: its vertices' coordinate d agree to a fraction of
    // its diameter (an inclined support or a face oblique to the axis is
    // not a symmetry plane of the axis; a fixed point is not a face).
    // A contact surface is never the plane: a surface that slides on a
    // support (Fixed 4: y on the master's top) is held, not mirrored, and
    // its normal is e_d itself. Nor is a support whose prescribed value
    // varies along it (a face turned or bent by the input): it is flat and
    // normal to e_d only in the reference configuration.
    std::set<types::boundary_id> not_planes(moving_supports);
    for (const auto &pair : pairs)
      not_planes.insert({pair.slave, pair.master});
    std::vector<types::global_dof_index> on_plane;
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && not_planes.count(cell->face(f)->boundary_id()) == 0)
            {
              const auto face = cell->face(f);
              face->get_dof_indices(face_dofs);
              std::array<bool, dim> all_fixed;
              all_fixed.fill(true);
              for (unsigned int i = 0; i < face_dofs.size(); ++i)
                if (!fixed(face_dofs[i]))
                  all_fixed[fe.face_system_to_component_index(i, f).first] = false;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  bool roller = all_fixed[d];
                  for (unsigned int c = 0; c < dim; ++c)
                    roller = roller && (c == d || !all_fixed[c]);
                  for (const unsigned int v : face->vertex_indices())
                    roller = roller && std::abs(face->vertex(v)[d] - face->vertex(0)[d]) <=
                                         1e-8 * face->diameter();
                  if (!roller)
                    continue;
                  for (unsigned int i = 0; i < face_dofs.size(); ++i)
                    if (fe.face_system_to_component_index(i, f).first == d &&
                        dof_position.count(face_dofs[i]) > 0)
                      on_plane.push_back(face_dofs[i]);
                }
            }
    std::set<types::global_dof_index> all;
    for (const auto &chunk : Utilities::MPI::all_gather(mpi_communicator, on_plane))
      all.insert(chunk.begin(), chunk.end());
    for (Node &node : nodes)
      for (unsigned int d = 0; d < dim; ++d)
        node.symmetry_plane[d] = all.count(node.dofs[d]) > 0;
  }

  template <int dim>
  void
  ContactInterface<dim>::find_pair_materials()
  {
    // Per pair and side (0 master, 1 slave) of this rank's faces: E and nu
    // of the last face, whether there is one, the largest E. The last face
    // in face order decides E and nu, as a loop over the whole surface
    // would (faces are in rank order).
    constexpr unsigned int n_values = 4;
    std::vector<double>    own(pairs.size() * 2 * n_values, 0.);
    for (unsigned int f = own_faces.first; f < own_faces.second; ++f)
      {
        const Face   &face  = faces[f];
        double *const entry = &own[(face.pair * 2 + face.slave) * n_values];
        entry[0]            = face.youngs_modulus;
        entry[1]            = face.poisson_ratio;
        entry[2]            = 1.;
        entry[3]            = std::max(entry[3], face.youngs_modulus);
      }
    pair_materials.assign(pairs.size(), PairMaterials());
    for (const auto &rank : Utilities::MPI::all_gather(mpi_communicator, own))
      for (unsigned int p = 0; p < pairs.size(); ++p)
        for (unsigned int side = 0; side < 2; ++side)
          {
            const double *const entry = &rank[(p * 2 + side) * n_values];
            PairMaterials      &m     = pair_materials[p];
            if (entry[2] > 0.5)
              {
                m.youngs_modulus[side] = entry[0];
                m.poisson_ratio[side]  = entry[1];
              }
            m.largest_youngs_modulus[side] = std::max(m.largest_youngs_modulus[side], entry[3]);
          }
  }

  template <int dim>
  void
  ContactInterface<dim>::add_segment(
    const unsigned int                                      f,
    const unsigned int                                      m,
    const typename Mortar::Kernel<dim>::Operators          &ops,
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
  typename ContactInterface<dim>::FaceTrace
  ContactInterface<dim>::face_trace(const unsigned int f) const
  {
    const std::vector<unsigned int> &local = faces[f].nodes;
    FaceTrace                        trace;
    if (std::all_of(local.begin(), local.end(), [&](auto n) {
          return nodes[n].parents.empty();
        }))
      return trace;
    std::map<unsigned int, unsigned int> owner_index;
    const auto                           owner = [&](const unsigned int n) {
      const auto [it, inserted] = owner_index.emplace(n, trace.owners.size());
      if (inserted)
        trace.owners.push_back(n);
      return it->second;
    };
    std::vector<std::vector<std::pair<unsigned int, double>>> weights(local.size());
    for (unsigned int a = 0; a < local.size(); ++a)
      if (nodes[local[a]].parents.empty())
        weights[a].emplace_back(owner(local[a]), 1.);
      else
        for (const auto &[parent, weight] : nodes[local[a]].parents)
          weights[a].emplace_back(owner(parent), weight);
    trace.T.reinit(trace.owners.size(), local.size());
    for (unsigned int a = 0; a < local.size(); ++a)
      for (const auto &[q, weight] : weights[a])
        trace.T(q, a) += weight;
    return trace;
  }

  template <int dim>
  bool
  ContactInterface<dim>::has_owner_duals(const FaceTrace &trace, const std::vector<double> &D)
  {
    // A face whose owners outnumber its nodes has a dependent trace basis
    // and no dual basis of its own.
    if (trace.owners.size() != D.size())
      return false;
    double D_sum = 0.;
    for (const double d : D)
      D_sum += std::abs(d);
    constexpr double least_nodal_weight = 1e-12;
    return std::none_of(D.begin(), D.end(), [&](const double d) {
      return std::abs(d) <= least_nodal_weight * D_sum;
    });
  }

  template <int dim>
  bool
  ContactInterface<dim>::add_constrained_face(
    const unsigned int                                                                   f,
    const std::vector<std::pair<unsigned int, typename Mortar::Kernel<dim>::Operators>> &segments,
    std::map<unsigned int, SlaveNode>                                                   &slave_data,
    std::map<unsigned int, std::map<unsigned int, double>>                              &M_of_node,
    std::map<unsigned int, Tensor<1, dim>> &weighted_gap_of_node)
  {
    // The owners of the face's trace: its regular nodes and the parents of
    // its hanging vertices; T(q, a) is the weight of owner q in node a.
    const FaceTrace trace = face_trace(f);
    if (segments.empty() || trace.owners.empty())
      return false;
    const std::vector<unsigned int> &owners = trace.owners;
    const FullMatrix<double>        &T      = trace.T;
    const unsigned int               n      = faces[f].nodes.size();
    std::vector<double>              D(n, 0.);
    for (const auto &segment : segments)
      for (unsigned int a = 0; a < n; ++a)
        D[a] += segment.second.D[a];
    if (!has_owner_duals(trace, D))
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
    // support (least_covered_fraction).
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
  std::vector<double>
  ContactInterface<dim>::relative_motion(const std::vector<double> &from,
                                         const std::vector<double> &to) const
  {
    // Over the faces of this rank, then the largest over the ranks (exact).
    std::vector<double> slave_motion(pairs.size(), 0.), master_motion(pairs.size(), 0.);
    for (unsigned int f = own_faces.first; f < own_faces.second; ++f)
      for (const unsigned int n : faces[f].nodes)
        {
          const double change = (displacement(n, to) - displacement(n, from)).norm();
          double      &largest =
            faces[f].slave ? slave_motion[faces[f].pair] : master_motion[faces[f].pair];
          largest = std::max(largest, change);
        }
    Utilities::MPI::max(slave_motion, mpi_communicator, slave_motion);
    Utilities::MPI::max(master_motion, mpi_communicator, master_motion);
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
  ContactInterface<dim>::slip_since_search(const SlaveNode &s, const std::vector<double> &u) const
  {
    const auto change = [&](const unsigned int n) {
      return displacement(n, u) - displacement(n, search_displacement);
    };
    Tensor<1, dim> relative = s.D * change(s.node);
    for (const auto &[m, value] : s.M)
      relative -= value * change(m);
    return relative.norm() / s.D;
  }


  template class ContactInterface<2>;
  template class ContactInterface<3>;
} // namespace contact_fem
