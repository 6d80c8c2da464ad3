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

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/friction/stick_slip_sets.h>

#include "unit_test_linearisation.h"
#include "unit_test_random.h"
#include "unit_test_stacked_interface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <numeric>

using namespace dealii;
using namespace contact_fem;
using namespace unit_test_linearisation;

namespace
{
  // The entries' keys (kind, index): 0 the interface normal (index the
  // component), 1 the force along it, 2 + k the held traction's force along
  // tangent k (index the row DoF).

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

  template <int dim>
  void
  run(const unsigned int degree, const unsigned int mapping_degree)
  {
    StackedInterface<dim> blocks(degree, mapping_degree);
    auto                 &interface = blocks.interface;

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

    std::vector<unsigned int> every_dof(u.size());
    std::iota(every_dof.begin(), every_dof.end(), 0u);
    const auto differences = [&](const double h) {
      return central_differences(
        interface, u, every_dof, coupled, h, [](std::vector<double> &) {},
        [&](const ContactInterface<dim> &moved, const std::vector<double> &) {
          return values_of(moved, frames);
        });
    };
    const auto [coarse, coarse_pairs] = differences(1e-3);
    const auto [fine, fine_pairs]     = differences(5e-4);
    const auto [tight, tight_pairs]   = differences(3e-6);
    const Verdict verdict =
      judge(interface, coarse, fine, tight,
            [&](const unsigned int n, const Key &key, const types::global_dof_index dof) {
              return analytic(interface, frames, n, key, dof);
            });
    const double largest_normal_derivative = verdict.largest.count(0) ? verdict.largest.at(0) : 0.;
    std::cout << dim << "D, Q" << degree << " on a mapping of degree " << mapping_degree << ": "
              << linear.size() << " paired slave nodes, " << interface.coupled_faces.size()
              << " coupled face pairs" << std::endl
              << "  largest angle between slave and interface normal above 0.05 rad: "
              << (largest_angle > 0.05 ? "yes" : "no") << std::endl
              << "  d n_int/du not zero (largest above 0.1): "
              << (largest_normal_derivative > 0.1 ? "yes" : "no") << std::endl;
    verdict.print(coarse_pairs && fine_pairs && tight_pairs,
                  "d n_int/du, d(-D n_int, M n_int)/du and the held traction's force along n_int");
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
