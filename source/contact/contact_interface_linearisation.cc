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
#include <map>
#include <set>

namespace contact_fem
{
  namespace
  {
    using DofMap = std::map<types::global_dof_index, double>;

    /// Sums of one node's derivatives over its face pairs.
    struct NodeSums
    {
      DofMap                                                   gap, D;
      std::map<types::global_dof_index, DofMap>                force;
      std::array<std::map<types::global_dof_index, DofMap>, 3> tangent_force;
      /// The normal's derivatives come whole from any one pair (its patch
      /// holds every slave face at the node); the operators' are summed.
      bool                  has_normal = false;
      std::array<DofMap, 3> normal, operators;
    };

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
                chain.push_back({{n, 1.}});
              }
            result.nodes.push_back(it->second);
          }
        for (unsigned int k = 0; k < face.geometry_points.size(); ++k)
          {
            const auto xi = Mortar::Kernel<dim>::node_parameter(2, face.nodes.size() + k);
            Point<dim> x  = face.geometry_points[k];
            chain.emplace_back();
            for (unsigned int v = 0; v < face.nodes.size(); ++v)
              {
                const double w = Mortar::Kernel<dim>::shape_value(1, v, xi);
                x += w * u[face.nodes[v]];
                chain.back().emplace_back(face.nodes[v], w);
              }
            result.nodes.push_back(patch.points.size());
            patch.points.push_back(x);
          }
        return result;
      }

      /// Adds @p factor times the coordinate derivatives @p derivatives,
      /// taken to the displacement DoFs, to @p sums. Every DoF of the patch
      /// gets an entry, zero or not: the sparsity pattern holds the
      /// couplings of the patch, whatever the configuration.
      void
      add(const std::vector<double> &derivatives, const double factor, DofMap &sums) const
      {
        for (unsigned int i = 0; i < chain.size(); ++i)
          for (const auto &[node, weight] : chain[i])
            for (unsigned int d = 0; d < dim; ++d)
              sums[interface.nodes[node].dofs[d]] += factor * weight * derivatives[dim * i + d];
      }

      typename Linearisation<dim>::Patch patch;

    private:
      const ContactInterface<dim>                              &interface;
      const std::vector<Tensor<1, dim>>                        &u;
      std::map<unsigned int, unsigned int>                      point_of_node;
      std::vector<std::vector<std::pair<unsigned int, double>>> chain;
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
      for (unsigned int d = 0; d < dim; ++d)
        {
          builder.add(result.D[k].derivatives, x(slave_nodes[k])[d], node.operators[d]);
          for (unsigned int l = 0; l < result.M[k].size(); ++l)
            builder.add(result.M[k][l].derivatives, -x(master_nodes[l])[d], node.operators[d]);
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
             std::map<unsigned int, NodeSums>          &sums)
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

    /// The derivatives of the pairs of slave face @p f with its @p masters
    /// added to the sums of its paired nodes. 2D: each pair linearised on
    /// its own patch (the slave face, its @p neighbours, the pair's master
    /// and the others).
    void
    add_slave_face(const ContactInterface<2>        &interface,
                   const std::vector<Tensor<1, 2>>  &u,
                   const unsigned int                f,
                   const std::vector<unsigned int>  &neighbours,
                   const std::vector<unsigned int>  &masters,
                   const bool                        frictional,
                   std::map<unsigned int, NodeSums> &sums)
    {
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
    add_slave_face(const ContactInterface<3>        &interface,
                   const std::vector<Tensor<1, 3>>  &u,
                   const unsigned int                f,
                   const std::vector<unsigned int>  &neighbours,
                   const std::vector<unsigned int>  &masters,
                   const bool                        frictional,
                   std::map<unsigned int, NodeSums> &sums)
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
      for (unsigned int i = 0; i < masters.size(); ++i)
        if (!results[i].D.empty())
          add_pair(interface, u, builder, results[i], f, masters[i], frictional, sums);
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
      typename ContactInterface<dim>::LinearisedNode result;
      result.dofs.assign(dofs.begin(), dofs.end());
      const auto at = [&](const DofMap &values) {
        std::vector<double> dense(result.dofs.size(), 0.);
        for (unsigned int i = 0; i < dense.size(); ++i)
          if (const auto it = values.find(result.dofs[i]); it != values.end())
            dense[i] = it->second;
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
        }
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
      std::map<unsigned int, NodeSums> sums;
      for (const auto &s : slave_nodes)
        if (s.paired)
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
      for (const unsigned int f : slave_faces)
        {
          std::set<unsigned int> neighbours;
          for (const unsigned int n : faces[f].nodes)
            for (const unsigned int g : faces_of_node[n])
              if (g != f)
                neighbours.insert(g);
          add_slave_face(*this, u, f,
                         std::vector<unsigned int>(neighbours.begin(), neighbours.end()),
                         masters_of_face[f], frictional, sums);
        }
      for (const auto &[n, node_sums] : sums)
        linearised_nodes[n] = linearised_node<dim>(node_sums);
    }
  }

  template void
  ContactInterface<2>::linearise(const bool);
  template void
  ContactInterface<3>::linearise(const bool);
} // namespace contact_fem
