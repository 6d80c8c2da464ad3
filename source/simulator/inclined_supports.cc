// Rollers on flat boundaries of any orientation. The normal of a boundary is
// taken once from the coarse mesh (identical on every rank, so that the
// constraints of a node shared by ranks are identical); each node then
// satisfies n . u = 0 through an affine constraint among its own components,
// which AffineConstraints merges with the supports, hanging nodes and
// contact like any other line.
#include <deal.II/base/exceptions.h>

#include <contact_fem/core/format.h>
#include <contact_fem/simulator/inclined_supports.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace contact_fem
{
  namespace
  {
    const std::string key = "Boundary conditions/Rollers";

    /// A normal of the straight coarse face @p face, of length its measure
    /// (2D) or twice its area (3D, planar quadrilateral).
    template <typename Face>
    Tensor<1, 2>
    scaled_normal(const Face &face, std::integral_constant<int, 2>)
    {
      const Tensor<1, 2> t = face->vertex(1) - face->vertex(0);
      return Tensor<1, 2>({t[1], -t[0]});
    }

    template <typename Face>
    Tensor<1, 3>
    scaled_normal(const Face &face, std::integral_constant<int, 3>)
    {
      return cross_product_3d(face->vertex(3) - face->vertex(0), face->vertex(2) - face->vertex(1));
    }

    std::string
    name(const types::boundary_id id)
    {
      return "boundary " + std::to_string(static_cast<unsigned int>(id));
    }
  } // namespace

  template <int dim>
  void
  InclinedSupports<dim>::initialize(const Triangulation<dim>              &coarse,
                                    const std::vector<types::boundary_id> &ids,
                                    const std::vector<ContactPair>        &pairs)
  {
    normals.clear();
    std::set<types::boundary_id> contact_ids;
    for (const auto &pair : pairs)
      contact_ids.insert({pair.slave, pair.master});
    std::map<types::boundary_id, std::vector<Tensor<1, dim>>> face_normals;
    std::map<types::boundary_id, std::set<unsigned int>>      vertices;
    std::set<unsigned int>                                    contact_vertices;
    for (const auto &cell : coarse.cell_iterators_on_level(0))
      for (const auto f : cell->face_indices())
        {
          const auto face = cell->face(f);
          if (!face->at_boundary())
            continue;
          const types::boundary_id id = face->boundary_id();
          if (contact_ids.count(id))
            for (const auto v : face->vertex_indices())
              contact_vertices.insert(face->vertex_index(v));
          if (std::find(ids.begin(), ids.end(), id) == ids.end())
            continue;
          Tensor<1, dim> n = scaled_normal(face, std::integral_constant<int, dim>());
          AssertThrow(n.norm() > 0.,
                      ExcMessage(key + ": " + name(id) + " has a face of zero size."));
          const double size = face->diameter();
          // Its corners, and the point its manifold puts at its middle when
          // refining (a circle of Geometry/Manifolds bulges), on its plane.
          for (const auto v : face->vertex_indices())
            AssertThrow(std::abs((face->vertex(v) - face->vertex(0)) * n) <= 1e-6 * size * n.norm(),
                        ExcMessage(key + ": " + name(id) + " has a warped face at " +
                                   coordinates_text(face->center()) +
                                   "; a roller needs a flat boundary."));
          AssertThrow(std::abs((face->center(true) - face->vertex(0)) * n) <=
                        1e-6 * size * n.norm(),
                      ExcMessage(key + ": " + name(id) + " carries a curved manifold (at " +
                                 coordinates_text(face->center()) +
                                 "); a roller holds a flat boundary only: split a curved "
                                 "one into flat pieces, or hold it by Fixed components."));
          face_normals[id].push_back(n);
          for (const auto v : face->vertex_indices())
            vertices[id].insert(face->vertex_index(v));
        }
    for (const types::boundary_id id : ids)
      {
        // Signs aligned with the first face: a roller does not care which
        // side the normal points to.
        Tensor<1, dim> sum;
        for (const auto &n : face_normals[id])
          sum += (n * face_normals[id].front() < 0. ? -1. : 1.) * n;
        const Tensor<1, dim> normal = sum / sum.norm();
        for (const auto &n : face_normals[id])
          {
            const double sine = (n / n.norm() - (n / n.norm() * normal) * normal).norm();
            AssertThrow(sine <= 1e-6,
                        ExcMessage(key + ": " + name(id) +
                                   " is not flat: its face normals differ by up to " +
                                   significant(std::asin(std::min(sine, 1.)), 2) +
                                   " rad (at most 1e-6); a roller holds a flat boundary "
                                   "only: split a curved or kinked one into flat pieces, "
                                   "each with its own id."));
          }
        for (const auto v : vertices[id])
          AssertThrow(contact_vertices.count(v) == 0,
                      ExcMessage(key + ": " + name(id) + " touches a contact surface (at " +
                                 coordinates_text(coarse.get_vertices()[v]) +
                                 "); rollers on or beside contact surfaces are not "
                                 "supported yet: hold such a boundary by Fixed components "
                                 "(in the axes) or end it away from the contact pair."));
        normals[id] = normal;
      }
  }

  template <int dim>
  std::map<types::global_dof_index,
           std::pair<std::vector<types::global_dof_index>, std::set<types::boundary_id>>>
  InclinedSupports<dim>::roller_nodes(const DoFHandler<dim> &dof_handler) const
  {
    // Keyed by the node's x DoF; its DoFs by component, and its boundaries.
    const auto &fe = dof_handler.get_fe();
    std::map<types::global_dof_index,
             std::pair<std::vector<types::global_dof_index>, std::set<types::boundary_id>>>
                                         nodes;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && normals.count(cell->face(f)->boundary_id()))
            {
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < dofs.size(); ++i)
                if (fe.has_support_on_face(i, f) && fe.system_to_component_index(i).first == 0)
                  {
                    auto &node = nodes[dofs[i]];
                    node.first.assign(dim, 0);
                    for (unsigned int j = 0; j < dofs.size(); ++j)
                      if (fe.system_to_component_index(j).second ==
                          fe.system_to_component_index(i).second)
                        node.first[fe.system_to_component_index(j).first] = dofs[j];
                    node.second.insert(cell->face(f)->boundary_id());
                  }
            }
    return nodes;
  }

  template <int dim>
  void
  InclinedSupports<dim>::constrain_node(const std::vector<types::global_dof_index> &dofs,
                                        std::vector<Tensor<1, dim>>                 rows,
                                        const std::vector<bool>                    &fixed,
                                        AffineConstraints<double>                  &dirichlet) const
  {
    // Reduced row echelon form of the rows n^T on the free components: each
    // independent row expresses its pivot component by the others (fixed
    // ones enter through their own lines when the set is closed).
    std::vector<bool> pivot_column(dim, false);
    std::vector<int>  pivot(rows.size(), -1);
    for (unsigned int r = 0; r < rows.size(); ++r)
      {
        int best = -1;
        for (unsigned int d = 0; d < dim; ++d)
          if (!fixed[d] && !pivot_column[d] &&
              (best < 0 || std::abs(rows[r][d]) > std::abs(rows[r][best])))
            best = d;
        if (best < 0 || std::abs(rows[r][best]) < 1e-8)
          continue;
        pivot[r]           = best;
        pivot_column[best] = true;
        rows[r] /= rows[r][best];
        for (unsigned int s = 0; s < rows.size(); ++s)
          if (s != r)
            {
              rows[s] -= rows[s][best] * rows[r];
              rows[s][best] = 0.;
            }
      }
    for (unsigned int r = 0; r < rows.size(); ++r)
      if (pivot[r] >= 0)
        {
          dirichlet.add_line(dofs[pivot[r]]);
          for (unsigned int d = 0; d < dim; ++d)
            if (static_cast<int>(d) != pivot[r] && std::abs(rows[r][d]) > 1e-13)
              dirichlet.add_entry(dofs[pivot[r]], dofs[d], -rows[r][d]);
        }
  }

  template <int dim>
  void
  InclinedSupports<dim>::add_constraints(const DoFHandler<dim>           &dof_handler,
                                         const AffineConstraints<double> &hanging,
                                         AffineConstraints<double>       &dirichlet)
  {
    owned_nodes.clear();
    held.clear();
    if (normals.empty())
      return;
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    for (const auto &[first, node] : roller_nodes(dof_handler))
      {
        const auto &[node_dofs, ids] = node;
        if (hanging.is_constrained(first))
          continue;
        std::vector<Tensor<1, dim>> directions;
        for (const auto id : ids)
          directions.push_back(normals.at(id));
        std::vector<bool> fixed(dim);
        for (unsigned int d = 0; d < dim; ++d)
          fixed[d] = dirichlet.is_constrained(node_dofs[d]);
        constrain_node(node_dofs, directions, fixed, dirichlet);
        if (!owned.is_element(first))
          continue;
        // The directions whose residual is a reaction: the normals and the
        // fixed axes, orthonormalised.
        for (unsigned int d = 0; d < dim; ++d)
          if (fixed[d])
            {
              Tensor<1, dim> axis;
              axis[d] = 1.;
              directions.push_back(axis);
            }
        Node held_node{node_dofs, {}};
        for (auto v : directions)
          {
            for (const auto &b : held_node.held_directions)
              v -= (v * b) * b;
            if (v.norm() > 1e-8)
              held_node.held_directions.push_back(v / v.norm());
          }
        for (const auto dof : node_dofs)
          held[dof] = owned_nodes.size();
        owned_nodes.push_back(held_node);
      }
  }

  template <int dim>
  double
  InclinedSupports<dim>::free_residual_squared(const TrilinosWrappers::MPI::Vector &residual) const
  {
    double sum = 0.;
    for (const auto &node : owned_nodes)
      {
        Tensor<1, dim> r;
        for (unsigned int d = 0; d < dim; ++d)
          r[d] = residual(node.dofs[d]);
        for (const auto &b : node.held_directions)
          r -= (r * b) * b;
        sum += r.norm_square();
      }
    return sum;
  }

  template class InclinedSupports<2>;
  template class InclinedSupports<3>;
} // namespace contact_fem
