#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <contact_fem/solvers/rigid_body_modes.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace contact_fem
{
  template <int dim>
  std::vector<std::vector<double>>
  rigid_body_modes(const Mapping<dim> &mapping, const DoFHandler<dim> &dof_handler)
  {
    const IndexSet                               &owned = dof_handler.locally_owned_dofs();
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

    const unsigned int               n_rotations = dim == 2 ? 1 : 3;
    std::vector<std::vector<double>> modes(dim + n_rotations,
                                           std::vector<double>(owned.n_elements(), 0.));
    unsigned int                     k = 0;
    for (const auto i : owned)
      {
        unsigned int d = 0;
        while (!component_dofs[d].is_element(i))
          ++d;
        const Tensor<1, dim> x = points.at(i) - centre;
        modes[d][k]            = 1.;
        for (unsigned int r = 0; r < n_rotations; ++r)
          modes[dim + r][k] = rotation_displacement<dim>(r, d, x);
        ++k;
      }
    return modes;
  }

  namespace
  {
    /// The row of a fixed DoF in the map from a rigid motion (t / size,
    /// omega) to the DoF's displacement over size.
    template <int dim>
    Vector<double>
    motion_row(const FixedDof<dim> &fixed, const Point<dim> &centre, const double size)
    {
      const unsigned int n_rotations = dim == 2 ? 1 : 3;
      Vector<double>     row(dim + n_rotations);
      row[fixed.component] = 1.;
      for (unsigned int r = 0; r < n_rotations; ++r)
        row[dim + r] =
          rotation_displacement<dim>(r, fixed.component, (fixed.point - centre) / size);
      return row;
    }
  } // namespace

  template <int dim>
  std::vector<double>
  support_lever_arms(const std::vector<FixedDof<dim>> &fixed,
                     const Point<dim>                 &centre,
                     const double                      size,
                     const MPI_Comm                    comm)
  {
    const unsigned int n_rotations = dim == 2 ? 1 : 3, n = dim + n_rotations;
    // The normal matrix A^T A of the rows of all fixed DoFs (of every rank).
    std::vector<double> normal(n * n, 0.);
    for (const auto &dof : fixed)
      {
        const Vector<double> row = motion_row(dof, centre, size);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            normal[i * n + j] += row[i] * row[j];
      }
    Utilities::MPI::sum(normal, comm, normal);

    std::vector<double> lever_arms(n_rotations, 0.);
    for (unsigned int r = 0; r < n_rotations; ++r)
      {
        // With omega_r = 1, the other components m minimise |A m|^2:
        // N_oo m = -N_or, N_oo the normal matrix of the others. Directions
        // that no fixed DoF sees (singular values below 1e-12 of the
        // largest: round-off) are left out; they move nothing.
        const unsigned int k    = dim + r;
        const auto         skip = [k](const unsigned int i) {
          return i < k ? i : i + 1;
        };
        LAPACKFullMatrix<double> others(n - 1, n - 1);
        Vector<double>           coupling(n - 1), rest(n - 1);
        for (unsigned int i = 0; i + 1 < n; ++i)
          {
            coupling[i] = -normal[skip(i) * n + k];
            for (unsigned int j = 0; j + 1 < n; ++j)
              others(i, j) = normal[skip(i) * n + skip(j)];
          }
        others.compute_inverse_svd(1e-12);
        others.vmult(rest, coupling);
        Vector<double> motion(n);
        motion[k] = 1.;
        for (unsigned int i = 0; i + 1 < n; ++i)
          motion[skip(i)] = rest[i];
        for (const auto &dof : fixed)
          lever_arms[r] = std::max(lever_arms[r], std::abs(motion_row(dof, centre, size) * motion));
      }
    // A maximum is exact: every rank gets the same values.
    Utilities::MPI::max(lever_arms, comm, lever_arms);
    return lever_arms;
  }

  template std::vector<std::vector<double>>
  rigid_body_modes(const Mapping<2> &, const DoFHandler<2> &);
  template std::vector<std::vector<double>>
  rigid_body_modes(const Mapping<3> &, const DoFHandler<3> &);
  template std::vector<double>
  support_lever_arms(const std::vector<FixedDof<2>> &,
                     const Point<2> &,
                     const double,
                     const MPI_Comm);
  template std::vector<double>
  support_lever_arms(const std::vector<FixedDof<3>> &,
                     const Point<3> &,
                     const double,
                     const MPI_Comm);
} // namespace contact_fem
