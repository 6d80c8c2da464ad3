// ContactInterface::linearise(): the derivatives of the weighted gaps and
// contact forces of the paired slave nodes with respect to the
// displacement DoFs, at the configuration of the last search, from
// Mortar::linearise_pair() on every coupled face pair (2D) or
// Mortar::linearise_slave_face() on every slave face with its masters (3D). For
// Contact/Kinematics = current (doc/finite_strain.md).
#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/mortar_3d_linearisation.h>
#include <contact_fem/contact/mortar_linearisation.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <memory_resource>
#include <new>
#include <set>

namespace contact_fem
{
  namespace
  {
    // The sums are polymorphic-allocator maps: linearise() builds them in
    // one arena per call and frees them with it (ordered maps as before, so
    // every sum is formed by the same operations in the same order). A
    // malloc per entry and the walk of every tree to free it took a fifth
    // of a frictional 3D run (doc/performance.md, "Session 38").
    using DofMap = std::pmr::map<types::global_dof_index, double>;
    using RowMap = std::pmr::map<types::global_dof_index, DofMap>;

    /// Sums of one node's derivatives over its face pairs.
    struct NodeSums
    {
      using allocator_type = std::pmr::polymorphic_allocator<std::byte>;

      /// Every map of the node in @p arena's memory.
      explicit NodeSums(const allocator_type &arena)
        : gap(arena)
        , D(arena)
        , force(arena)
        , tangent_force{{RowMap(arena), RowMap(arena), RowMap(arena)}}
        , normal{{DofMap(arena), DofMap(arena), DofMap(arena)}}
        , operators{{DofMap(arena), DofMap(arena), DofMap(arena)}}
        , dM(arena)
        , interface_normal{{DofMap(arena), DofMap(arena), DofMap(arena)}}
        , interface_force(arena)
        , interface_tangent_force{{RowMap(arena), RowMap(arena), RowMap(arena)}}
        , owned(arena)
      {}

      DofMap                gap, D;
      RowMap                force;
      std::array<RowMap, 3> tangent_force;
      /// The normal's derivatives come whole from any one pair (its patch
      /// holds every slave face at the node); the operators' are summed.
      bool                  has_normal = false;
      std::array<DofMap, 3> normal, operators;
      /// Frictional: d M_jl per master node l (hanging master vertices
      /// condensed to their parents, as SlaveNode::M), and the derivatives
      /// of the interface normal and of the forces along it (add_interface_frame()).
      std::pmr::map<unsigned int, DofMap> dM;
      std::array<DofMap, 3>               interface_normal;
      RowMap                              interface_force;
      std::array<RowMap, 3>               interface_tangent_force;

      /// The parts from slave faces with hanging vertices, which go to the
      /// owners of the face's trace (ContactInterface::face_trace(); the
      /// node need not be on the face): D, M by master node and the
      /// weighted gap vector with their derivatives, the node's normal
      /// applied at the end (add_owner_parts()).
      struct OwnerParts
      {
        explicit OwnerParts(const allocator_type &arena)
          : dD(arena)
          , M(arena)
          , dM(arena)
          , d_weighted_gap{{DofMap(arena), DofMap(arena), DofMap(arena)}}
        {}

        bool                                any = false;
        double                              D   = 0.;
        DofMap                              dD;
        std::pmr::map<unsigned int, double> M;
        std::pmr::map<unsigned int, DofMap> dM;
        std::array<double, 3>               weighted_gap = {{0., 0., 0.}};
        std::array<DofMap, 3>               d_weighted_gap;
      } owned;
    };

    /// The sums of the paired nodes, by node.
    using Sums = std::pmr::map<unsigned int, NodeSums>;

    /// @p to += @p factor * @p from (every entry of @p from, zero or not).
    void
    add_to(DofMap &to, const DofMap &from, const double factor)
    {
      for (const auto &[dof, value] : from)
        to[dof] += factor * value;
    }

    /// The position of interface node @p l at @p u, for a hanging vertex
    /// the interpolation of its parents': the operators' columns of hanging
    /// master vertices are those of their parents (condensed at update()).
    template <int dim>
    Point<dim>
    column_position(const ContactInterface<dim>       &interface,
                    const std::vector<Tensor<1, dim>> &u,
                    const unsigned int                 l)
    {
      const auto &parents = interface.nodes[l].parents;
      if (parents.empty())
        return interface.nodes[l].reference + u[l];
      Point<dim> x;
      for (const auto &[parent, weight] : parents)
        x += weight * (interface.nodes[parent].reference + u[parent]);
      return x;
    }

    /// The face-pair patch and its linearised operators of each dimension.
    template <int dim>
    struct Linearisation
    {
      using Patch  = Mortar::PairPatch;
      using Result = Mortar::LinearisedPair;
    };
    template <>
    struct Linearisation<3>
    {
      using Patch  = Mortar::QuadFacePatch;
      using Result = Mortar::LinearisedQuadPair;
    };

    /// A PairPatch of interface faces, with the chain from its points to
    /// the interface nodes (a geometry point of Q1 on a quadratic mapping
    /// moves with the linear interpolation of its face's vertices).
    template <int dim>
    class PatchBuilder
    {
    public:
      PatchBuilder(const ContactInterface<dim> &interface, const std::vector<Tensor<1, dim>> &u)
        : interface(interface)
        , u(u)
      {}

      Mortar::PairPatch::Face
      add_face(const unsigned int f)
      {
        const auto             &face = interface.faces[f];
        Mortar::PairPatch::Face result;
        result.orientation    = face.orientation;
        result.element_degree = interface.degree;
        for (const unsigned int n : face.nodes)
          {
            const auto [it, inserted] = point_of_node.emplace(n, patch.points.size());
            if (inserted)
              {
                patch.points.push_back(interface.nodes[n].reference + u[n]);
                patch.symmetry_planes.push_back(interface.nodes[n].symmetry_plane);
                add_terms(it->second, {{n, 1.}});
              }
            result.nodes.push_back(it->second);
          }
        for (unsigned int k = 0; k < face.geometry_points.size(); ++k)
          {
            const auto xi = Mortar::Kernel<dim>::node_parameter(2, face.nodes.size() + k);
            Point<dim> x  = face.geometry_points[k];
            std::vector<std::pair<unsigned int, double>> weights;
            for (unsigned int v = 0; v < face.nodes.size(); ++v)
              {
                const double w = Mortar::Kernel<dim>::shape_value(1, v, xi);
                x += w * u[face.nodes[v]];
                weights.emplace_back(face.nodes[v], w);
              }
            result.nodes.push_back(patch.points.size());
            patch.points.push_back(x);
            patch.symmetry_planes.emplace_back();
            add_terms(result.nodes.back(), weights);
          }
        return result;
      }

      /// Adds @p factor times the coordinate derivatives @p derivatives,
      /// taken to the displacement DoFs, to @p sums. Every DoF of the patch
      /// gets an entry, zero or not: the sparsity pattern holds the
      /// couplings of the patch, whatever the configuration. Each DoF's
      /// entry is looked up once per call, then the terms are added in
      /// chain order (the same sums, operation by operation, as looking
      /// each term up).
      void
      add(const std::vector<double> &derivatives, const double factor, DofMap &sums) const
      {
        for (const auto &[node, point] : point_of_node)
          for (unsigned int d = 0; d < dim; ++d)
            entries[dim * point + d] = &sums[interface.nodes[node].dofs[d]];
        for (const Term &t : terms)
          *entries[t.entry] += factor * t.weight * derivatives[t.coordinate];
      }

      typename Linearisation<dim>::Patch patch;

    private:
      /// A point's coordinate d moves with weight times node's
      /// displacement component d: the term weight * derivative
      /// (coordinate) of the DoF at entry.
      struct Term
      {
        unsigned int coordinate, entry;
        double       weight;
      };

      /// Adds the terms of point @p point, moving with @p weights of nodes.
      void
      add_terms(const unsigned int                                  point,
                const std::vector<std::pair<unsigned int, double>> &weights)
      {
        for (const auto &[node, weight] : weights)
          for (unsigned int d = 0; d < dim; ++d)
            terms.push_back({dim * point + d, dim * point_of_node.at(node) + d, weight});
        entries.resize(dim * patch.points.size());
      }

      const ContactInterface<dim>         &interface;
      const std::vector<Tensor<1, dim>>   &u;
      std::map<unsigned int, unsigned int> point_of_node;
      /// The chain from the points to the nodes, point by point.
      std::vector<Term> terms;
      /// The sums' entry of each node point's DoFs (add()).
      mutable std::vector<double *> entries;
    };

    /// The frictional derivatives of slave node @p k of a pair (@p result)
    /// added to @p node: per global component c of a held tangential
    /// traction t = e_c, kept in the tangent plane as n_j turns (dt = -(t .
    /// dn) n), the force h_j = D_j t on the slave and -M_jl t on master l;
    /// n_j; D_j x_j - sum_l M_jl x_l at held x.
    template <int dim>
    void
    add_frictional(const ContactInterface<dim>               &interface,
                   const std::vector<Tensor<1, dim>>         &u,
                   const PatchBuilder<dim>                   &builder,
                   const typename Linearisation<dim>::Result &result,
                   const unsigned int                         k,
                   const std::vector<unsigned int>           &slave_nodes,
                   const std::vector<unsigned int>           &master_nodes,
                   NodeSums                                  &node)
    {
      const auto &n = result.normals[k];
      const auto  x = [&](const unsigned int node_index) {
        return interface.nodes[node_index].reference + u[node_index];
      };
      for (unsigned int c = 0; c < dim; ++c)
        for (unsigned int d = 0; d < dim; ++d)
          {
            DofMap &row = node.tangent_force[c][interface.nodes[slave_nodes[k]].dofs[d]];
            if (c == d)
              builder.add(result.D[k].derivatives, 1., row);
            builder.add(n[c].derivatives, -result.D[k].value * n[d].value, row);
            for (unsigned int l = 0; l < result.M[k].size(); ++l)
              {
                DofMap &master_row =
                  node.tangent_force[c][interface.nodes[master_nodes[l]].dofs[d]];
                if (c == d)
                  builder.add(result.M[k][l].derivatives, -1., master_row);
                builder.add(n[c].derivatives, result.M[k][l].value * n[d].value, master_row);
              }
          }
      for (unsigned int l = 0; l < result.M[k].size(); ++l)
        {
          const auto &parents = interface.nodes[master_nodes[l]].parents;
          if (parents.empty())
            builder.add(result.M[k][l].derivatives, 1., node.dM[master_nodes[l]]);
          for (const auto &[parent, weight] : parents)
            builder.add(result.M[k][l].derivatives, weight, node.dM[parent]);
        }
      for (unsigned int d = 0; d < dim; ++d)
        {
          builder.add(result.D[k].derivatives, x(slave_nodes[k])[d], node.operators[d]);
          for (unsigned int l = 0; l < result.M[k].size(); ++l)
            builder.add(result.M[k][l].derivatives,
                        -column_position(interface, u, master_nodes[l])[d], node.operators[d]);
          if (!node.has_normal)
            builder.add(n[d].derivatives, 1., node.normal[d]);
        }
      node.has_normal = true;
    }

    /// The derivatives of pair (@p f, @p m), linearised in @p result on
    /// the patch of @p builder, added to the sums of the paired nodes of
    /// slave face @p f.
    template <int dim>
    void
    add_pair(const ContactInterface<dim>               &interface,
             const std::vector<Tensor<1, dim>>         &u,
             const PatchBuilder<dim>                   &builder,
             const typename Linearisation<dim>::Result &result,
             const unsigned int                         f,
             const unsigned int                         m,
             const bool                                 frictional,
             Sums                                      &sums)
    {
      const auto &slave_nodes  = interface.faces[f].nodes;
      const auto &master_nodes = interface.faces[m].nodes;
      for (unsigned int k = 0; k < result.D.size(); ++k)
        {
          const auto it = sums.find(slave_nodes[k]);
          if (it == sums.end())
            continue;
          NodeSums &node = it->second;
          builder.add(result.normal_gap[k].derivatives, 1., node.gap);
          builder.add(result.D[k].derivatives, 1., node.D);
          const auto &n = result.normals[k];
          // f_j = -D_j n_j on the slave node, +M_jl n_j on master l.
          for (unsigned int d = 0; d < dim; ++d)
            {
              DofMap &row = node.force[interface.nodes[slave_nodes[k]].dofs[d]];
              builder.add(result.D[k].derivatives, -n[d].value, row);
              builder.add(n[d].derivatives, -result.D[k].value, row);
              for (unsigned int l = 0; l < result.M[k].size(); ++l)
                {
                  DofMap &master_row = node.force[interface.nodes[master_nodes[l]].dofs[d]];
                  builder.add(result.M[k][l].derivatives, n[d].value, master_row);
                  builder.add(n[d].derivatives, result.M[k][l].value, master_row);
                }
            }
          if (frictional)
            add_frictional(interface, u, builder, result, k, slave_nodes, master_nodes, node);
        }
    }

    /**
     * The derivatives of the operators of slave face @p f with hanging
     * vertices (its pairs @p results with @p masters, linearised on the
     * patch of @p builder) in the basis of its owners (@p trace), as
     * ContactInterface::add_constrained_face() builds them, or lumped onto
     * them as condense_hanging_vertices() does, added to the OwnerParts of
     * the paired owners: D_q = sum_a T(q, a) D_a, M_ql = sum_a S(q, a)
     * M_al and the weighted gap likewise, with S = D~ T^-T D^-1 (D~ = T D,
     * D summed over the masters) for the owners' dual basis and S = T
     * lumped. S depends on the configuration through D: dS(q, a) =
     * T^-T(q, a) (dD~_q / D_a - D~_q dD_a / D_a^2).
     */
    void
    add_owner_face(const ContactInterface<3>                     &interface,
                   const PatchBuilder<3>                         &builder,
                   const std::vector<Mortar::LinearisedQuadPair> &results,
                   const std::vector<unsigned int>               &masters,
                   const unsigned int                             f,
                   const ContactInterface<3>::FaceTrace          &trace,
                   Sums                                          &sums)
    {
      const unsigned int        n           = interface.faces[f].nodes.size();
      const unsigned int        n_owners    = trace.owners.size();
      const unsigned int        n_variables = 3 * builder.patch.points.size();
      const FullMatrix<double> &T           = trace.T;
      const auto                zero        = [&]() {
        return Mortar::Linearised{0., std::vector<double>(n_variables, 0.)};
      };
      std::vector<Mortar::Linearised> D(n, zero());
      for (const auto &result : results)
        for (unsigned int a = 0; a < result.D.size(); ++a)
          {
            D[a].value += result.D[a].value;
            for (unsigned int v = 0; v < n_variables; ++v)
              D[a].derivatives[v] += result.D[a].derivatives[v];
          }
      std::vector<double> D_values(n);
      for (unsigned int a = 0; a < n; ++a)
        D_values[a] = D[a].value;
      std::vector<std::vector<Mortar::Linearised>> S(n_owners, std::vector<Mortar::Linearised>(n));
      if (ContactInterface<3>::has_owner_duals(trace, D_values))
        {
          FullMatrix<double> T_inverse_transpose(n, n);
          T_inverse_transpose.copy_transposed(T);
          T_inverse_transpose.gauss_jordan();
          for (unsigned int q = 0; q < n; ++q)
            {
              Mortar::Linearised D_owner = zero();
              for (unsigned int a = 0; a < n; ++a)
                {
                  D_owner.value += T(q, a) * D[a].value;
                  for (unsigned int v = 0; v < n_variables; ++v)
                    D_owner.derivatives[v] += T(q, a) * D[a].derivatives[v];
                }
              for (unsigned int a = 0; a < n; ++a)
                {
                  const double t  = T_inverse_transpose(q, a);
                  const double Da = D[a].value;
                  S[q][a]         = zero();
                  S[q][a].value   = D_owner.value * t / Da;
                  for (unsigned int v = 0; v < n_variables; ++v)
                    S[q][a].derivatives[v] =
                      t * (D_owner.derivatives[v] - D_owner.value * D[a].derivatives[v] / Da) / Da;
                }
            }
        }
      else
        for (unsigned int q = 0; q < n_owners; ++q)
          for (unsigned int a = 0; a < n; ++a)
            {
              S[q][a]       = zero();
              S[q][a].value = T(q, a);
            }

      for (unsigned int i = 0; i < masters.size(); ++i)
        {
          const Mortar::LinearisedQuadPair &result = results[i];
          if (result.D.empty())
            continue;
          const auto &master_nodes = interface.faces[masters[i]].nodes;
          for (unsigned int q = 0; q < n_owners; ++q)
            {
              const auto it = sums.find(trace.owners[q]);
              if (it == sums.end())
                continue;
              NodeSums::OwnerParts &owned = it->second.owned;
              owned.any                   = true;
              for (unsigned int a = 0; a < n; ++a)
                {
                  owned.D += T(q, a) * result.D[a].value;
                  builder.add(result.D[a].derivatives, T(q, a), owned.dD);
                  for (unsigned int l = 0; l < master_nodes.size(); ++l)
                    {
                      const Mortar::Linearised &M = result.M[a][l];
                      owned.M[master_nodes[l]] += S[q][a].value * M.value;
                      DofMap &dM = owned.dM[master_nodes[l]];
                      builder.add(M.derivatives, S[q][a].value, dM);
                      builder.add(S[q][a].derivatives, M.value, dM);
                    }
                  for (unsigned int d = 0; d < 3; ++d)
                    {
                      const Mortar::Linearised &g = result.weighted_gap[a][d];
                      owned.weighted_gap[d] += S[q][a].value * g.value;
                      builder.add(g.derivatives, S[q][a].value, owned.d_weighted_gap[d]);
                      builder.add(S[q][a].derivatives, g.value, owned.d_weighted_gap[d]);
                    }
                }
            }
        }
    }

    /**
     * The OwnerParts of paired slave node @p q added to its sums, with its
     * unit normal n_q and dn_q from the slave faces at it (@p faces_at_q),
     * as add_pair() and add_frictional() add those of a face node: G_q =
     * n_q . weighted gap, f_q = -D_q n_q on the node and M_ql n_q on master
     * l, the held tangential traction's force, D_q x_q - sum_l M_ql x_l.
     */
    template <int dim>
    void
    add_owner_parts(const ContactInterface<dim>       &interface,
                    const std::vector<Tensor<1, dim>> &u,
                    const unsigned int                 q,
                    const std::vector<unsigned int>   &faces_at_q,
                    const bool                         frictional,
                    NodeSums                          &node)
    {
      PatchBuilder<dim> builder(interface, u);
      for (const unsigned int g : faces_at_q)
        builder.patch.slave_faces.push_back(builder.add_face(g));
      const auto     normals = Mortar::linearise_nodal_normals(builder.patch);
      const auto    &first   = interface.faces[faces_at_q[0]].nodes;
      const auto    &n_q     = normals[std::find(first.begin(), first.end(), q) - first.begin()];
      Tensor<1, dim> n;
      std::array<DofMap, dim> dn;
      for (unsigned int d = 0; d < dim; ++d)
        {
          n[d] = n_q[d].value;
          builder.add(n_q[d].derivatives, 1., dn[d]);
        }
      const NodeSums::OwnerParts &o    = node.owned;
      const auto                 &dofs = interface.nodes[q].dofs;
      add_to(node.D, o.dD, 1.);
      for (unsigned int d = 0; d < dim; ++d)
        {
          add_to(node.gap, o.d_weighted_gap[d], n[d]);
          add_to(node.gap, dn[d], o.weighted_gap[d]);
          DofMap &row = node.force[dofs[d]];
          add_to(row, o.dD, -n[d]);
          add_to(row, dn[d], -o.D);
          for (const auto &[l, dM] : o.dM)
            {
              DofMap &master_row = node.force[interface.nodes[l].dofs[d]];
              add_to(master_row, dM, n[d]);
              add_to(master_row, dn[d], o.M.at(l));
            }
        }
      if (!frictional)
        return;
      const Point<dim> x = interface.nodes[q].reference + u[q];
      for (unsigned int c = 0; c < dim; ++c)
        for (unsigned int d = 0; d < dim; ++d)
          {
            DofMap &row = node.tangent_force[c][dofs[d]];
            if (c == d)
              add_to(row, o.dD, 1.);
            add_to(row, dn[c], -o.D * n[d]);
            for (const auto &[l, dM] : o.dM)
              {
                DofMap &master_row = node.tangent_force[c][interface.nodes[l].dofs[d]];
                if (c == d)
                  add_to(master_row, dM, -1.);
                add_to(master_row, dn[c], o.M.at(l) * n[d]);
              }
          }
      for (const auto &[l, dM] : o.dM)
        {
          const auto &parents = interface.nodes[l].parents;
          if (parents.empty())
            add_to(node.dM[l], dM, 1.);
          for (const auto &[parent, weight] : parents)
            add_to(node.dM[parent], dM, weight);
        }
      for (unsigned int d = 0; d < dim; ++d)
        {
          add_to(node.operators[d], o.dD, x[d]);
          for (const auto &[l, dM] : o.dM)
            add_to(node.operators[d], dM, -column_position(interface, u, l)[d]);
          if (!node.has_normal)
            add_to(node.normal[d], dn[d], 1.);
        }
      node.has_normal = true;
    }

    /// The derivatives of the pairs of slave face @p f with its @p masters
    /// added to the sums of its paired nodes. 2D: each pair linearised on
    /// its own patch (the slave face, its @p neighbours, the pair's master
    /// and the others).
    void
    add_slave_face(const ContactInterface<2>       &interface,
                   const std::vector<Tensor<1, 2>> &u,
                   const unsigned int               f,
                   const std::vector<unsigned int> &neighbours,
                   const std::vector<unsigned int> &masters,
                   const bool                       frictional,
                   Sums                            &sums)
    {
      // A 2D contact surface has no hanging vertices (they lie inside the
      // body, on the edges between cells of different levels).
      AssertThrow(interface.face_trace(f).owners.empty(), ExcInternalError());
      for (const unsigned int m : masters)
        {
          PatchBuilder<2> builder(interface, u);
          builder.patch.slave_faces.push_back(builder.add_face(f));
          for (const unsigned int g : neighbours)
            builder.patch.slave_faces.push_back(builder.add_face(g));
          builder.patch.master = builder.add_face(m);
          for (const unsigned int other : masters)
            if (other != m)
              builder.patch.other_masters.push_back(builder.add_face(other));
          Mortar::LinearisedPair result;
          if (Mortar::linearise_pair(builder.patch, true, result))
            add_pair(interface, u, builder, result, f, m, frictional, sums);
        }
    }

    /// 3D: the slave face linearised once with all its masters (the nodal
    /// normals and the dual basis are shared).
    void
    add_slave_face(const ContactInterface<3>       &interface,
                   const std::vector<Tensor<1, 3>> &u,
                   const unsigned int               f,
                   const std::vector<unsigned int> &neighbours,
                   const std::vector<unsigned int> &masters,
                   const bool                       frictional,
                   Sums                            &sums)
    {
      PatchBuilder<3> builder(interface, u);
      builder.patch.slave_faces.push_back(builder.add_face(f));
      for (const unsigned int g : neighbours)
        builder.patch.slave_faces.push_back(builder.add_face(g));
      for (const unsigned int m : masters)
        builder.patch.masters.push_back(builder.add_face(m));
      std::vector<Mortar::LinearisedQuadPair> results;
      if (!Mortar::linearise_slave_face(builder.patch, true, results))
        return;
      if (const auto trace = interface.face_trace(f); !trace.owners.empty())
        {
          add_owner_face(interface, builder, results, masters, f, trace, sums);
          return;
        }
      for (unsigned int i = 0; i < masters.size(); ++i)
        if (!results[i].D.empty())
          add_pair(interface, u, builder, results[i], f, masters[i], frictional, sums);
    }

    /// d n_l / du of the averaged unit normal of master node @p l (over
    /// the master faces @p faces_at_l, as ContactInterface averages the
    /// slave's), per component.
    template <int dim>
    std::array<DofMap, 3>
    master_normal_derivative(const ContactInterface<dim>       &interface,
                             const std::vector<Tensor<1, dim>> &u,
                             const unsigned int                 l,
                             const std::vector<unsigned int>   &faces_at_l)
    {
      PatchBuilder<dim> builder(interface, u);
      for (const unsigned int f : faces_at_l)
        builder.patch.slave_faces.push_back(builder.add_face(f));
      const auto            normals = Mortar::linearise_nodal_normals(builder.patch);
      const auto           &first   = interface.faces[faces_at_l[0]].nodes;
      const auto           &n_l = normals[std::find(first.begin(), first.end(), l) - first.begin()];
      std::array<DofMap, 3> result;
      for (unsigned int d = 0; d < dim; ++d)
        builder.add(n_l[d].derivatives, 1., result[d]);
      return result;
    }

    /**
     * The derivatives of the interface normal of slave node @p s
     * (store_slave_nodes(): n_int = a / |a|, a = E_s n_j - E_m m / |m|, m =
     * sum_l M_jl n_l, E_m = sum_l M_jl E_l / sum_l M_jl), of its force per
     * unit pressure (-D_j n_int, M_jl n_int) and of the force of a held unit
     * tangential traction kept in its tangent plane, into @p node. The
     * moduli E_s, E_l of the nodes are held (a face's measure weights them
     * within one body, where they are equal). @p master_normals: the
     * master nodal normals' derivatives, filled as needed.
     */
    template <int dim>
    void
    add_interface_frame(const ContactInterface<dim>                             &interface,
                        const std::vector<Tensor<1, dim>>                       &u,
                        const typename ContactInterface<dim>::SlaveNode         &s,
                        const std::map<unsigned int, std::vector<unsigned int>> &master_faces,
                        std::map<unsigned int, std::array<DofMap, 3>>           &master_normals,
                        NodeSums                                                &node)
    {
      const auto    &slave_dofs = interface.nodes[s.node].dofs;
      Tensor<1, dim> m;
      double         E_m = 0., weight = 0.;
      for (const auto &[l, value] : s.M)
        if (const auto it = interface.master_surface_normals.find(l);
            it != interface.master_surface_normals.end())
          {
            m += value * it->second.first;
            E_m += value * it->second.second;
            weight += value;
          }
      const double   E_s = interface.slave_surface_normals.at(s.node).second;
      Tensor<1, dim> a   = E_s * s.normal;
      const bool     shared =
        weight > 0. && m.norm() > 0. && (a - (E_m / weight) * m / m.norm()) * s.normal > 0.;
      std::array<DofMap, 3> &dn = node.interface_normal;
      if (!shared)
        // The interface normal is the slave normal (store_slave_nodes()).
        for (unsigned int d = 0; d < dim; ++d)
          add_to(dn[d], node.normal[d], 1.);
      else
        {
          E_m /= weight;
          const double         m_norm = m.norm();
          const Tensor<1, dim> m_unit = m / m_norm;
          a -= E_m * m_unit;
          const Tensor<1, dim> n_int = a / a.norm();
          // dm = sum_l (dM_jl n_l + M_jl dn_l), dE_m = sum_l dM_jl (E_l -
          // E_m) / sum_l M_jl.
          std::array<DofMap, 3> dm;
          DofMap                dE;
          for (const auto &[l, value] : s.M)
            {
              const auto it = interface.master_surface_normals.find(l);
              if (it == interface.master_surface_normals.end())
                continue;
              auto found = master_normals.find(l);
              if (found == master_normals.end())
                found = master_normals
                          .emplace(l, master_normal_derivative(interface, u, l, master_faces.at(l)))
                          .first;
              const DofMap &dM = node.dM[l];
              add_to(dE, dM, (it->second.second - E_m) / weight);
              for (unsigned int d = 0; d < dim; ++d)
                {
                  add_to(dm[d], dM, it->second.first[d]);
                  add_to(dm[d], found->second[d], value);
                }
            }
          // da = E_s dn_j - dE_m m_unit - E_m (I - m_unit m_unit^T) dm / |m|.
          std::array<DofMap, 3> da;
          for (unsigned int d = 0; d < dim; ++d)
            {
              add_to(da[d], node.normal[d], E_s);
              add_to(da[d], dE, -m_unit[d]);
              add_to(da[d], dm[d], -E_m / m_norm);
              for (unsigned int e = 0; e < dim; ++e)
                add_to(da[d], dm[e], E_m * m_unit[d] * m_unit[e] / m_norm);
            }
          // dn_int = (I - n_int n_int^T) da / |a|.
          const double a_norm = a.norm();
          for (unsigned int d = 0; d < dim; ++d)
            {
              add_to(dn[d], da[d], 1. / a_norm);
              for (unsigned int e = 0; e < dim; ++e)
                add_to(dn[d], da[e], -n_int[d] * n_int[e] / a_norm);
            }
        }
      // The forces along n_int: -D_j n_int on the slave, M_jl n_int on
      // master l; a held unit traction e_c turning with n_int: D_j e_c and
      // -M_jl e_c, d e_c = -(e_c . dn_int) n_int.
      const Tensor<1, dim> &n = s.interface_normal;
      for (unsigned int d = 0; d < dim; ++d)
        {
          DofMap &row = node.interface_force[slave_dofs[d]];
          add_to(row, node.D, -n[d]);
          add_to(row, dn[d], -s.D);
          for (unsigned int c = 0; c < dim; ++c)
            {
              DofMap &tangent_row = node.interface_tangent_force[c][slave_dofs[d]];
              if (c == d)
                add_to(tangent_row, node.D, 1.);
              add_to(tangent_row, dn[c], -s.D * n[d]);
            }
          for (const auto &[l, value] : s.M)
            {
              const auto &master_dofs = interface.nodes[l].dofs;
              const auto &dM          = node.dM[l];
              DofMap     &master_row  = node.interface_force[master_dofs[d]];
              add_to(master_row, dM, n[d]);
              add_to(master_row, dn[d], value);
              for (unsigned int c = 0; c < dim; ++c)
                {
                  DofMap &tangent_row = node.interface_tangent_force[c][master_dofs[d]];
                  if (c == d)
                    add_to(tangent_row, dM, -1.);
                  add_to(tangent_row, dn[c], value * n[d]);
                }
            }
        }
    }

    /// The sums of one node as a LinearisedNode over the union of its DoFs.
    template <int dim>
    typename ContactInterface<dim>::LinearisedNode
    linearised_node(const NodeSums &sums)
    {
      std::set<types::global_dof_index> dofs;
      for (const auto &[dof, value] : sums.gap)
        dofs.insert(dof);
      for (const auto &[row, values] : sums.force)
        for (const auto &[dof, value] : values)
          dofs.insert(dof);
      for (const auto &[row, values] : sums.interface_force)
        for (const auto &[dof, value] : values)
          dofs.insert(dof);
      typename ContactInterface<dim>::LinearisedNode result;
      result.dofs.assign(dofs.begin(), dofs.end());
      // Both sorted by DoF: one walk along both (an entry of @p values
      // outside dofs is left out, as the look-up per DoF left it).
      const auto at = [&](const DofMap &values) {
        std::vector<double> dense(result.dofs.size(), 0.);
        auto                it = values.begin();
        for (unsigned int i = 0; i < dense.size() && it != values.end(); ++i)
          {
            while (it != values.end() && it->first < result.dofs[i])
              ++it;
            if (it != values.end() && it->first == result.dofs[i])
              dense[i] = it->second;
          }
        return dense;
      };
      result.gap = at(sums.gap);
      result.D   = at(sums.D);
      for (const auto &[row, values] : sums.force)
        result.force.emplace_back(row, at(values));
      for (unsigned int d = 0; d < dim; ++d)
        {
          for (const auto &[row, values] : sums.tangent_force[d])
            result.tangent_force[d].emplace_back(row, at(values));
          result.normal[d]    = at(sums.normal[d]);
          result.operators[d] = at(sums.operators[d]);
          if (sums.interface_force.empty())
            continue;
          result.interface_normal[d] = at(sums.interface_normal[d]);
          for (const auto &[row, values] : sums.interface_tangent_force[d])
            result.interface_tangent_force[d].emplace_back(row, at(values));
        }
      for (const auto &[row, values] : sums.interface_force)
        result.interface_force.emplace_back(row, at(values));
      return result;
    }
  } // namespace

  template <int dim>
  void
  ContactInterface<dim>::linearise(const bool frictional)
  {
    linearised_nodes.clear();
    {
      std::vector<Tensor<1, dim>> u(nodes.size());
      for (unsigned int n = 0; n < nodes.size(); ++n)
        u[n] = displacement(n, search_displacement);
      // Only the nodes whose rows this rank assembles (x DoF owned, as the
      // formulations test): a node's sums are those of its own slave faces
      // in face order, whichever other nodes are left out, so they are the
      // serial ones bit for bit.
      // The sums, every map in them included, live in the arena and go
      // with it at the end of the block, without a destructor: those would
      // only walk the trees to hand each entry back to an arena that frees
      // nothing (10 % of a frictional 3D run). Nothing in them holds other
      // memory (NodeSums passes the arena to every map it holds).
      std::pmr::monotonic_buffer_resource arena;
      Sums &sums = *new (arena.allocate(sizeof(Sums), alignof(Sums))) Sums(&arena);
      for (const auto &s : slave_nodes)
        if (s.paired && owned_dofs.is_element(nodes[s.node].dofs[0]))
          sums[s.node];
      // The slave faces at every node, and the masters of every slave face.
      std::map<unsigned int, std::vector<unsigned int>> faces_of_node, masters_of_face;
      for (unsigned int f = 0; f < faces.size(); ++f)
        if (faces[f].slave)
          for (const unsigned int n : faces[f].nodes)
            faces_of_node[n].push_back(f);
      // Each slave face with its masters, in the order of the pairs.
      std::vector<unsigned int> slave_faces;
      for (const auto &[f, m] : coupled_faces)
        {
          if (masters_of_face[f].empty())
            slave_faces.push_back(f);
          masters_of_face[f].push_back(m);
        }
      // A face adds to its nodes and to the owners of its trace (the
      // parents of its hanging vertices); one adding to none of the sums
      // is skipped.
      const auto adds_to_sums = [&](const unsigned int f) {
        for (const unsigned int n : faces[f].nodes)
          {
            if (sums.count(n) > 0)
              return true;
            for (const auto &[parent, weight] : nodes[n].parents)
              if (sums.count(parent) > 0)
                return true;
          }
        return false;
      };
      for (const unsigned int f : slave_faces)
        {
          if (!adds_to_sums(f))
            continue;
          std::set<unsigned int> neighbours;
          for (const unsigned int n : faces[f].nodes)
            for (const unsigned int g : faces_of_node[n])
              if (g != f)
                neighbours.insert(g);
          add_slave_face(*this, u, f,
                         std::vector<unsigned int>(neighbours.begin(), neighbours.end()),
                         masters_of_face[f], frictional, sums);
        }
      for (auto &[n, node_sums] : sums)
        if (node_sums.owned.any)
          add_owner_parts(*this, u, n, faces_of_node.at(n), frictional, node_sums);
      if (frictional)
        {
          std::map<unsigned int, std::vector<unsigned int>> master_faces_of_node;
          for (unsigned int f = 0; f < faces.size(); ++f)
            if (!faces[f].slave)
              for (const unsigned int n : faces[f].nodes)
                master_faces_of_node[n].push_back(f);
          std::map<unsigned int, std::array<DofMap, 3>> master_normals;
          for (const auto &s : slave_nodes)
            if (const auto it = sums.find(s.node); it != sums.end())
              add_interface_frame(*this, u, s, master_faces_of_node, master_normals, it->second);
        }
      for (const auto &[n, node_sums] : sums)
        linearised_nodes[n] = linearised_node<dim>(node_sums);
    }
    // The patches reach beyond the relevant DoFs.
    close_lines();
  }

  template void
  ContactInterface<2>::linearise(const bool);
  template void
  ContactInterface<3>::linearise(const bool);
} // namespace contact_fem
