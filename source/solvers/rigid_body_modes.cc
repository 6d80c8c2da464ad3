#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>

#include <contact_fem/solvers/rigid_body_modes.h>

#include <map>

namespace contact_fem
{
  template <int dim>
  std::vector<std::vector<double>>
  rigid_body_modes(const Mapping<dim> &mapping, const DoFHandler<dim> &dof_handler)
  {
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    std::map<types::global_dof_index, Point<dim>> points;
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
    std::vector<IndexSet> component_dofs;
    for (unsigned int d = 0; d < dim; ++d)
      {
        std::vector<bool> selected(dim, false);
        selected[d] = true;
        component_dofs.push_back(DoFTools::extract_dofs(dof_handler, ComponentMask(selected)));
      }

    Point<dim> centre;
    for (const auto i : owned)
      centre += points.at(i);
    if (owned.n_elements() > 0)
      centre /= owned.n_elements();

    const unsigned int n_rotations = dim == 2 ? 1 : 3;
    std::vector<std::vector<double>> modes(dim + n_rotations,
                                           std::vector<double>(owned.n_elements(), 0.));
    unsigned int k = 0;
    for (const auto i : owned)
      {
        unsigned int d = 0;
        while (!component_dofs[d].is_element(i))
          ++d;
        const Tensor<1, dim> x = points.at(i) - centre;
        modes[d][k] = 1.;
        // Rotation about axis a moves component d by (e_a x x)_d.
        for (unsigned int r = 0; r < n_rotations; ++r)
          {
            const unsigned int axis = dim == 2 ? 2 : r;
            const unsigned int i1 = (axis + 1) % 3, i2 = (axis + 2) % 3;
            if (d == i1 && i2 < dim)
              modes[dim + r][k] = -x[i2];
            else if (d == i2 && i1 < dim)
              modes[dim + r][k] = x[i1];
          }
        ++k;
      }
    return modes;
  }

  template std::vector<std::vector<double>>
  rigid_body_modes(const Mapping<2> &, const DoFHandler<2> &);
  template std::vector<std::vector<double>>
  rigid_body_modes(const Mapping<3> &, const DoFHandler<3> &);
} // namespace contact_fem
