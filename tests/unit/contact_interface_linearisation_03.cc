// The interface normal's linearisation (ContactInterface::linearise(true),
// Contact/Kinematics = current): for every paired slave node j, d n_int/du
// of SlaveNode::interface_normal (the modulus-weighted mean of the slave
// nodal normal and the reversed M-weighted master nodal normal, normalised;
// its derivative takes dn_j, dM_jl and the derivatives of the master nodal
// normals), d(-D_j n_int, M_jl n_int)/du (LinearisedNode::interface_force)
// and the force of a held tangential traction kept in the tangent plane of
// n_int (t = tau_k - (tau_k . n_int) n_int, tau_k the frame of n_int at u;
// interface_tangent_force per global component, combined) against central
// differences of ContactInterface::update() at u +- h e_i, along every
// interface DoF. A curved pair: the blocks of contact_interface_linearisation_01
// (E = 100 below, the slave; 200 above), the slave top bent down and the
// master base bent up to parabolas (sag 8 % of the width) plus random
// displacements of up to 1 %; 2D Q1, Q2, Q1 on a quadratic mapping, 3D Q1.
// The difference error falls as h^2 (h = 1e-3 and h/2: ratio near 4 unless
// round-off), at h = 3e-6 it is below 1e-6 of the node's largest
// derivative (at 1e-5 the truncation error of the bent 3D pair is
// 1.2e-6), DoFs outside a node's patch have zero differences, and the face
// pairs are the same at every perturbed configuration. The interface
// normal is off the slave normal by more than 0.05 rad at some node
// (measured 0.26, 0.43, 0.26 and 0.20 rad) and its derivative is not
// small (largest entry above 0.1), so the check is not the slave
// normal's again.

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/friction/stick_slip_sets.h>
#include <contact_fem/material/material.h>

#include "unit_test_blocks.h"
#include "unit_test_materials.h"
#include "unit_test_random.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>

using namespace dealii;
using namespace contact_fem;

namespace
{
  /// (kind, index): 0 the interface normal (index the component), 1 the
  /// force along it, 2 + k the held traction's force along tangent k (index
  /// the row DoF).
  using Key    = std::pair<int, types::global_dof_index>;
  using Values = std::map<unsigned int, std::map<Key, double>>;
  template <int dim>
  using Frames = std::map<unsigned int, std::array<Tensor<1, dim>, dim - 1>>;

  template <int dim>
  Values
  values_of(const ContactInterface<dim> &interface, const Frames<dim> &frames)
  {
    Values result;
    for (const auto &s : interface.slave_nodes)
      if (s.paired)
        {
          auto                 &node = result[s.node];
          const Tensor<1, dim> &n    = s.interface_normal;
          for (unsigned int d = 0; d < dim; ++d)
            {
              node[{0, d}] = n[d];
              node[{1, interface.nodes[s.node].dofs[d]}] += -s.D * n[d];
              for (const auto &[m, value] : s.M)
                node[{1, interface.nodes[m].dofs[d]}] += value * n[d];
            }
          for (unsigned int k = 0; k < dim - 1; ++k)
            {
              const Tensor<1, dim> &tau = frames.at(s.node)[k];
              const Tensor<1, dim>  t   = tau - (tau * n) * n;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  node[{2 + k, interface.nodes[s.node].dofs[d]}] += s.D * t[d];
                  for (const auto &[m, value] : s.M)
                    node[{2 + k, interface.nodes[m].dofs[d]}] += -value * t[d];
                }
            }
        }
    return result;
  }

  template <int dim>
  double
  analytic(const ContactInterface<dim>  &interface,
           const Frames<dim>            &frames,
           const unsigned int            n,
           const Key                    &key,
           const types::global_dof_index dof)
  {
    const auto &node = interface.linearised_nodes.at(n);
    const auto  it   = std::find(node.dofs.begin(), node.dofs.end(), dof);
    if (it == node.dofs.end())
      return 0.;
    const unsigned int i   = it - node.dofs.begin();
    const auto         row = [&](const auto &rows) {
      for (const auto &[r, values] : rows)
        if (r == key.second)
          return values[i];
      return 0.;
    };
    if (key.first == 0)
      return node.interface_normal[key.second][i];
    if (key.first == 1)
      return row(node.interface_force);
    const Tensor<1, dim> &tau    = frames.at(n)[key.first - 2];
    double                result = 0.;
    for (unsigned int c = 0; c < dim; ++c)
      result += tau[c] * row(node.interface_tangent_force[c]);
    return result;
  }

  void
  make_blocks(Triangulation<2> &tria)
  {
    Triangulation<2> lower, upper;
    GridGenerator::subdivided_hyper_rectangle(lower, {3, 1}, Point<2>(0., 0.), Point<2>(1., 1.));
    GridGenerator::subdivided_hyper_rectangle(upper, {2, 1}, Point<2>(0., 1.05),
                                              Point<2>(1., 2.05));
    GridGenerator::merge_triangulations(lower, upper, tria);
  }

  void
  make_blocks(Triangulation<3> &tria)
  {
    make_stacked_blocks_3d(tria);
  }

  template <int dim>
  void
  run(const unsigned int degree, const unsigned int mapping_degree)
  {
    Triangulation<dim> tria;
    make_blocks(tria);
    label_stacked_blocks(tria, 0.05);
    const FESystem<dim> fe(FE_Q<dim>(degree), dim);
    DoFHandler<dim>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const MappingQ<dim>       mapping(mapping_degree);
    const Materials<dim>      materials = make_materials<dim>("1, 2", "100, 200", "0.3, 0.3");
    AffineConstraints<double> none;
    none.close();
    ContactInterface<dim> interface;
    interface.initialize(mapping, dof_handler, {ContactPair{3, 4}}, none, none, materials,
                         MPI_COMM_WORLD);

    // The slave top (y = 1) bent down, the master base bent up, to
    // parabolas of sag 0.08 over the unit width; plus up to 1 % at random.
    Random              random(29);
    std::vector<double> u(interface.dofs().size());
    for (double &value : u)
      value = 0.01 * random.next();
    for (const auto &node : interface.nodes)
      {
        double r2 = 0.;
        for (unsigned int d = 0; d + 1 < dim; ++d)
          r2 += std::pow(2. * node.reference[d] - 1., 2);
        const double sag = 0.08 * r2 / (dim - 1);
        u[interface.position(node.dofs[dim - 1])] += node.slave ? -sag : sag;
      }
    interface.update(u, 3.);
    interface.linearise(true);
    const auto  coupled = interface.coupled_faces;
    const auto &linear  = interface.linearised_nodes;
    Frames<dim> frames;
    double      largest_angle = 0.;
    for (const auto &s : interface.slave_nodes)
      if (s.paired)
        {
          frames[s.node] = tangent_frame(s.interface_normal);
          largest_angle =
            std::max(largest_angle, std::acos(std::min(1., s.normal * s.interface_normal)));
        }

    const auto differences = [&](const double h) {
      std::map<std::pair<unsigned int, Key>, std::map<types::global_dof_index, double>> result;
      bool same_pairs = true;
      for (unsigned int i = 0; i < u.size(); ++i)
        {
          std::array<Values, 2> at;
          for (const int side : {0, 1})
            {
              std::vector<double> v = u;
              v[i] += side == 0 ? h : -h;
              ContactInterface<dim> moved = interface;
              moved.update(v, 3.);
              same_pairs = same_pairs && moved.coupled_faces == coupled;
              at[side]   = values_of(moved, frames);
            }
          for (const auto &[n, entries] : at[0])
            for (const auto &[key, value] : entries)
              result[{n, key}][interface.dofs()[i]] = (value - at[1][n][key]) / (2. * h);
        }
      return std::make_pair(result, same_pairs);
    };
    const auto [coarse, coarse_pairs] = differences(1e-3);
    const auto [fine, fine_pairs]     = differences(5e-4);
    const auto [tight, tight_pairs]   = differences(3e-6);
    bool   small = true, second_order = true, complete = true;
    double worst = 0., largest_normal_derivative = 0.;
    for (const auto &[entry, by_dof] : coarse)
      {
        const auto &node  = linear.at(entry.first);
        double      scale = 0.;
        for (const auto &[dof, value] : by_dof)
          scale =
            std::max(scale, std::abs(analytic(interface, frames, entry.first, entry.second, dof)));
        if (entry.second.first == 0)
          largest_normal_derivative = std::max(largest_normal_derivative, scale);
        for (const auto &[dof, value] : by_dof)
          {
            const double exact = analytic(interface, frames, entry.first, entry.second, dof);
            const double e1    = std::abs(value - exact) / scale;
            const double e2    = std::abs(fine.at(entry).at(dof) - exact) / scale;
            const double e3    = std::abs(tight.at(entry).at(dof) - exact) / scale;
            const bool   inside =
              std::find(node.dofs.begin(), node.dofs.end(), dof) != node.dofs.end();
            complete = complete && (inside || std::abs(value - exact) < 1e-10 * scale);
            small    = small && e3 < 1e-6;
            worst    = std::max(worst, e3);
            if (e1 > 1e-7)
              second_order = second_order && e1 / e2 > 3.5 && e1 / e2 < 4.5;
          }
      }
    std::cout << dim << "D, Q" << degree << " on a mapping of degree " << mapping_degree << ": "
              << linear.size() << " paired slave nodes, " << interface.coupled_faces.size()
              << " coupled face pairs" << std::endl
              << "  largest angle between slave and interface normal above 0.05 rad: "
              << (largest_angle > 0.05 ? "yes" : "no") << std::endl
              << "  d n_int/du not zero (largest above 0.1): "
              << (largest_normal_derivative > 0.1 ? "yes" : "no") << std::endl
              << "  same face pairs at every perturbed configuration: "
              << (coarse_pairs && fine_pairs && tight_pairs ? "yes" : "no") << std::endl
              << "  d n_int/du, d(-D n_int, M n_int)/du and the held traction's force along "
                 "n_int against central differences, error below 1e-6 of the node's largest "
                 "derivative: "
              << (small ? "yes" : "no") << std::endl
              << "  error falling at second order (or round-off): " << (second_order ? "yes" : "no")
              << std::endl
              << "  no coupling outside the node's patch: " << (complete ? "yes" : "no")
              << std::endl;
    if (!small)
      std::cout << "  largest error " << worst << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run<2>(1, 1);
  run<2>(2, 2);
  run<2>(1, 2);
  run<3>(1, 1);
}
