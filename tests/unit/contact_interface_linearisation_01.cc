// ContactInterface::linearise() (Contact/Kinematics = current) against
// central differences of the interface's own operators: for every paired
// slave node j, dG_j/du (G_j = D_j g_j, the weighted normal gap), dD_j/du
// and df_j/du (f_j = -D_j n_j on the slave node, +M_jl n_j on master l) with
// respect to every interface DoF, from ContactInterface::update() at u +-
// h e_i. Two stacked blocks (the lower one's top the slave, 3 cells; the
// upper one's base the master, 2 cells: non-matching; 5 % of the width
// apart), every interface DoF displaced at random by up to 2 % of the
// width (deterministic generator); Q1, Q2, and Q1 on a quadratic mapping.
// The difference error falls as h^2 (h = 1e-3 and h/2: ratio near 4,
// unless it is round-off already), at h = 1e-5 it is below 1e-6 of the
// node's largest derivative, and DoFs outside a node's patch have zero
// differences (the linearisation misses no coupling). The coupled face
// pairs are the same at every perturbed configuration (no branch switch
// inside a difference). The frictional quantities likewise (alm frictional
// with current kinematics): dh_j/du (h_j = D_j t on the slave node, -M_jl t
// on master l, for t = tau_k, each tangent of the node's frame at u, held
// in the tangent plane as n_j turns: t(v) = tau_k - (tau_k . n_j(v))
// n_j(v); the linearisation's per global component, combined), dn_j/du,
// and d(D_j x_j - sum_l M_jl x_l)/du (the linearisation's part at held
// positions plus D_j and -M_jl on the node's own coordinates). In 3D
// (Q1, bilinear faces: the lower block 3 x 3 cells on its top, the upper
// 2 x 2, overhanging it by 0.1: no coincident rims) the same checks.

#include <deal.II/base/mpi.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/friction/stick_slip_sets.h>

#include "unit_test_linearisation.h"
#include "unit_test_random.h"
#include "unit_test_stacked_interface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <numeric>

using namespace dealii;
using namespace contact_fem;
using namespace unit_test_linearisation;

namespace
{
  /// The analytic derivative of entry @p key of node @p n along DoF @p dof
  /// (0 outside the node's patch).
  template <int dim>
  double
  analytic(const ContactInterface<dim>  &interface,
           const Frames<dim>            &frames,
           const unsigned int            n,
           const Key                    &key,
           const types::global_dof_index dof)
  {
    const auto &node = interface.linearised_nodes.at(n);
    double      held = 0.;
    if (key.first == operators)
      for (const auto &s : interface.slave_nodes)
        if (s.node == n)
          held = direct_part(interface, s, key.second, dof);
    const auto it = std::find(node.dofs.begin(), node.dofs.end(), dof);
    if (it == node.dofs.end())
      return held;
    const unsigned int i   = it - node.dofs.begin();
    const auto         row = [&](const auto &rows) {
      for (const auto &[r, values] : rows)
        if (r == key.second)
          return values[i];
      return 0.;
    };
    switch (key.first)
      {
        case gap:
          return node.gap[i];
        case weight:
          return node.D[i];
        case normal:
          return node.normal[key.second][i];
        case operators:
          return held + node.operators[key.second][i];
        case force:
          return row(node.force);
        default:
          {
            // Per global component c of the held traction, combined.
            const Tensor<1, dim> &tau    = frames.at(n)[key.first - tangent_force];
            double                result = 0.;
            for (unsigned int c = 0; c < dim; ++c)
              result += tau[c] * row(node.tangent_force[c]);
            return result;
          }
      }
  }

  template <int dim>
  void
  run(const unsigned int degree, const unsigned int mapping_degree)
  {
    StackedInterface<dim> blocks(degree, mapping_degree);
    auto                 &interface = blocks.interface;

    Random              random(29);
    std::vector<double> u(interface.dofs().size());
    for (double &value : u)
      value = 0.02 * random.next();
    interface.update(u, 3.);
    interface.linearise(true);
    const auto  coupled = interface.coupled_faces;
    const auto &linear  = interface.linearised_nodes;
    Frames<dim> frames;
    for (const auto &s : interface.slave_nodes)
      if (s.paired)
        frames[s.node] = tangent_frame(s.normal);

    // Differences at h and h / 2 of every entry along every DoF.
    std::vector<unsigned int> every_dof(u.size());
    std::iota(every_dof.begin(), every_dof.end(), 0u);
    const auto differences = [&](const double h) {
      return central_differences(interface, u, every_dof, frames, coupled, h,
                                 [](std::vector<double> &) {});
    };
    // The order from h = 1e-3 and h / 2 (above the noise of the double
    // path's iterative roots), the accuracy at h = 1e-5.
    const auto [coarse, coarse_pairs] = differences(1e-3);
    const auto [fine, fine_pairs]     = differences(5e-4);
    const auto [tight, tight_pairs]   = differences(1e-5);
    const Verdict verdict =
      judge(interface, coarse, fine, tight,
            [&](const unsigned int n, const Key &key, const types::global_dof_index dof) {
              return analytic(interface, frames, n, key, dof);
            });
    std::cout << dim << "D, Q" << degree << " on a mapping of degree " << mapping_degree << ": "
              << linear.size() << " paired slave nodes, " << interface.coupled_faces.size()
              << " coupled face pairs" << std::endl;
    verdict.print(coarse_pairs && fine_pairs && tight_pairs,
                  "dG/du, dD/du, df/du, dh/du, dn/du and d(D x - M x)/du");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run<2>(1, 1);
  run<2>(2, 2);
  // Q1 faces with a geometry point (moving with the vertices).
  run<2>(1, 2);
  // 3D: bilinear faces only.
  run<3>(1, 1);
}
