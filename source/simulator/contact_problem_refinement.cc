#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/error_estimator.h>

#include <contact_fem/postprocess/pressure_profile.h>
#include <contact_fem/simulator/contact_problem.h>
#include <contact_fem/simulator/dof_setup.h>
#include <contact_fem/core/format.h>
#include <contact_fem/adaptivity/marking.h>
#include <contact_fem/contact/mortar.h>
#include <contact_fem/adaptivity/refinement.h>
#include <contact_fem/adaptivity/stress_recovery.h>

#include <map>
#include <set>

namespace contact_fem
{
  namespace
  {
    /// Per slave node of @p interface for which @p wanted (of its node
    /// number) holds: the Gauss points of its slave faces in the reference
    /// configuration, weighted by the node's shape function (weights sum to
    /// int N_j ds; in 3D with hanging vertices, N_j of the constrained
    /// trace, which includes the parent's share of the hanging vertices'
    /// functions). A node's samples come from every slave face around it,
    /// in face order.
    template <int dim, typename Wanted>
    std::map<unsigned int, std::vector<TractionSample<dim>>>
    slave_support_samples(const ContactInterface<dim> &interface, const Wanted &wanted)
    {
      std::map<unsigned int, std::vector<TractionSample<dim>>> samples;
      if constexpr (dim == 2)
        {
          const unsigned int p = interface.degree;
          const QGauss<1>    quadrature(p + 2);
          for (const auto &face : interface.faces)
            if (face.slave)
              {
                const Mortar::LineFace line = interface.face_geometry(face);
                for (unsigned int q = 0; q < quadrature.size(); ++q)
                  {
                    const double       xi = 2. * quadrature.point(q)[0] - 1.;
                    const double       ds = 2. * quadrature.weight(q) * line.tangent(xi).norm();
                    const Tensor<1, 2> n  = Mortar::face_normal(line, xi, face.orientation);
                    for (unsigned int k = 0; k < face.nodes.size(); ++k)
                      if (wanted(face.nodes[k]))
                        samples[face.nodes[k]].push_back(
                          {line.point(xi), n, ds * Mortar::shape_value(p, k, xi)});
                  }
              }
        }
      else
        {
          const unsigned int p = interface.degree;
          const QGauss<2>    quadrature(p + 2);
          for (const auto &face : interface.faces)
            if (face.slave)
              {
                const Mortar::QuadFace quad = interface.face_geometry(face);
                for (unsigned int q = 0; q < quadrature.size(); ++q)
                  {
                    const Point<2> xi(2. * quadrature.point(q)[0] - 1.,
                                      2. * quadrature.point(q)[1] - 1.);
                    const auto     t = quad.tangents(xi);
                    const double   dA =
                      4. * quadrature.weight(q) * cross_product_3d(t[0], t[1]).norm();
                    const Tensor<1, 3> n = Mortar::face_normal(quad, xi, face.orientation);
                    // A hanging vertex carries no multiplier: its shape
                    // function goes to its parents with the hanging-node
                    // weights, so that a node's weights are those of its
                    // function in the constrained trace, N~_j = N_j + sum
                    // w_hj N_h, to which its multiplier (D_j = int N~_j) is
                    // dual.
                    for (unsigned int k = 0; k < face.nodes.size(); ++k)
                      {
                        const double weight  = dA * Mortar::quad_shape_value(p, k, xi);
                        const auto  &parents = interface.nodes[face.nodes[k]].parents;
                        if (parents.empty())
                          {
                            if (wanted(face.nodes[k]))
                              samples[face.nodes[k]].push_back({quad.point(xi), n, weight});
                          }
                        else
                          for (const auto &[parent, w] : parents)
                            if (wanted(parent))
                              samples[parent].push_back({quad.point(xi), n, w * weight});
                      }
                  }
              }
        }
      return samples;
    }
    /// The sums over a slave node's support samples: their weights (int N_j
    /// ds on the reference surface) and their weighted normals.
    template <int dim>
    struct SupportSums
    {
      double         weight = 0.;
      Tensor<1, dim> normal;
    };

    /// The contact tractions that SPR imposes at the paired slave nodes of
    /// @p interface: those of the active nodes of @p contact, and with
    /// @p all_paired (a known pressure is compared) the inactive ones too,
    /// not imposed, in the order recovered_traction_report() expects; in
    /// @p sums, per node listed, the sums over its samples.
    ///
    /// The samples are those of the nodes with a DoF in @p relevant (this
    /// rank's locally relevant DoFs): StressRecovery reads a node's samples
    /// only where it imposes the node's traction, at the support points of
    /// this rank's own cells; the list of other nodes carries none. The sums
    /// come from the rank that owns the node's row (all-gathered, 2 + dim
    /// doubles per listed node), so no rank needs the samples of the whole
    /// surface.
    ///
    /// The traction of a node is imposed as the N_j-weighted mean over the
    /// node's slave faces (which is what a dual multiplier is). The stresses
    /// live on the reference configuration, while the contact force
    /// -lambda_j D_j n_j acts along the normal of the deformed surface and
    /// D_j is measured there: the mean traction is that force over the
    /// reference int N_j ds. (Splitting it along the reference normal
    /// instead would be off by the surface rotation, ~ a / R in Hertz,
    /// which does not shrink under refinement.)
    template <int dim>
    std::vector<ContactNodeTraction<dim>>
    recovery_tractions(const ContactInterface<dim>   &interface,
                       const ContactFormulation<dim> &contact,
                       const bool                     all_paired,
                       const IndexSet                &relevant,
                       std::vector<SupportSums<dim>> &sums)
    {
      const auto support = slave_support_samples(interface, [&](const unsigned int n) {
        return relevant.is_element(interface.nodes[n].dofs[0]);
      });
      const auto listed  = [&](const typename ContactInterface<dim>::SlaveNode &s) {
        return s.paired && (all_paired || contact.is_active(s.node));
      };
      // The owners' sums: (node, weight, normal) per listed node.
      std::vector<double> own;
      for (const auto &s : interface.slave_nodes)
        if (listed(s) && interface.owns_row(s))
          {
            SupportSums<dim> sum;
            for (const auto &q : support.at(s.node))
              {
                sum.weight += q.weight;
                sum.normal += q.weight * q.normal;
              }
            own.push_back(s.node);
            own.push_back(sum.weight);
            for (unsigned int d = 0; d < dim; ++d)
              own.push_back(sum.normal[d]);
          }
      std::map<unsigned int, SupportSums<dim>> sum_of_node;
      for (const auto &chunk : Utilities::MPI::all_gather(interface.communicator(), own))
        for (unsigned int i = 0; i + 2 + dim <= chunk.size(); i += 2 + dim)
          {
            SupportSums<dim> &sum = sum_of_node[static_cast<unsigned int>(chunk[i])];
            sum.weight            = chunk[i + 1];
            for (unsigned int d = 0; d < dim; ++d)
              sum.normal[d] = chunk[i + 2 + d];
          }

      std::vector<ContactNodeTraction<dim>> tractions;
      sums.clear();
      for (const auto &s : interface.slave_nodes)
        if (listed(s))
          {
            const auto   samples   = support.find(s.node);
            const double reference = sum_of_node.at(s.node).weight;
            sums.push_back(sum_of_node.at(s.node));
            const bool active = contact.is_active(s.node);
            // With friction the whole traction vector (normal and
            // tangential) is imposed, not the pressure alone.
            Tensor<1, dim> traction;
            if (active && contact.transmits_shear())
              traction = (s.D / reference) * contact.traction(s);
            else if (active)
              traction = -contact.normal_pressure(s.node) * s.D / reference * s.normal;
            tractions.push_back(
              {interface.nodes[s.node].reference, s.normal, traction,
               samples != support.end() ? samples->second : std::vector<TractionSample<dim>>(),
               active, interface.nodes[s.node].dofs[0]});
          }
      return tractions;
    }

    /// Prints and records the effectivity index eta / error where the
    /// cycle record holds an energy-norm error (and that of plain SPR).
    void
    report_effectivity(const ConditionalOStream &pcout, Json &cycle_record)
    {
      const double energy_error = cycle_record["energy_error"].number_value();
      if (!(energy_error > 0.))
        return;
      const double effectivity = cycle_record["estimated_error"].number_value() / energy_error;
      cycle_record.set("effectivity_index", effectivity);
      pcout << "    effectivity index eta / error: " << std::setprecision(3) << effectivity
            << std::setprecision(6) << std::endl;
      pcout << "    effectivity in [0.8, 1.25]:   "
            << (effectivity >= 0.8 && effectivity <= 1.25 ? "yes" : "no") << std::endl;
      const double plain = cycle_record["plain_spr_estimated_error"].number_value();
      if (std::isfinite(plain))
        {
          cycle_record.set("plain_spr_effectivity_index", plain / energy_error);
          pcout << "    effectivity of plain SPR:     " << std::setprecision(3)
                << plain / energy_error << std::setprecision(6) << std::endl;
        }
    }

    /// The traction of a recovered stress at the paired slave nodes
    /// (@p node_stresses at @p nodes, the paired interface.slave_nodes in
    /// their order), by interface node, in the convention of the imposed
    /// contact condition.
    template <int dim>
    struct RecoveredTractions
    {
      RecoveredTractions(const ContactInterface<dim>                 &interface,
                         const ContactFormulation<dim>               &contact,
                         const std::vector<ContactNodeTraction<dim>> &nodes,
                         const std::vector<SupportSums<dim>>         &sums,
                         const std::vector<SymmetricTensor<2, dim>>  &node_stresses)
      {
        // How well the recovered stress carries the contact traction, in the
        // convention of the imposed condition: the traction sigma* n0 on the
        // reference surface (n0 = the node's N_j-weighted mean reference normal)
        // against -p n (n = the deformed normal the force acts along). Its
        // normal part, scaled from the reference to the deformed surface by
        // int N_j ds / D_j (the mortar pressure is a force per deformed area;
        // the scenes' surface strains reach 1 %), is compared with the exact
        // pressure by the same L2 measure as the mortar pressure; its shear
        // part, which a frictionless contact makes zero, is reported as the
        // largest over the active nodes.
        // With friction the shear part is compared with the mortar tangential
        // traction instead (it is no longer zero), and with Cattaneo.
        const bool with_shear = contact.transmits_shear();
        pressure.assign(interface.nodes.size(), 0.);
        tangential.assign(interface.nodes.size(), 0.);
        std::size_t i = 0; // @p nodes are the paired slave nodes in order
        for (const auto &s : interface.slave_nodes)
          if (s.paired)
            {
              Tensor<1, dim> n0               = sums[i].normal;
              const double   reference_length = sums[i].weight;
              n0 /= n0.norm();
              const Tensor<1, dim> n        = nodes[i].normal / nodes[i].normal.norm();
              const Tensor<1, dim> traction = node_stresses[i] * n0;
              const double         normal   = -(traction * n);
              pressure[s.node]              = s.D > 0. ? normal * reference_length / s.D : normal;
              if (contact.is_active(s.node))
                {
                  Tensor<1, dim> shear = traction + normal * n;
                  if (with_shear && dim == 2)
                    {
                      const Tensor<1, dim> tau =
                        ContactFormulation<dim>::tangent(contact.frame_normal(s));
                      tangential[s.node] =
                        (s.D > 0. ? reference_length / s.D : 1.) * (traction * tau);
                      shear = (tangential[s.node] - contact.traction(s) * tau) * tau;
                    }
                  else if (with_shear)
                    {
                      // 3D: the tangential parts as vectors (frame normal nf).
                      const Tensor<1, dim> nf     = contact.frame_normal(s);
                      const Tensor<1, dim> lambda = contact.traction(s);
                      shear                       = (s.D > 0. ? reference_length / s.D : 1.) *
                                (traction - (traction * nf) * nf) -
                              (lambda - (lambda * nf) * nf);
                    }
                  largest_shear = std::max(largest_shear, shear.norm());
                  p_max         = std::max(p_max, contact.normal_pressure(s.node));
                }
              ++i;
            }
        AssertThrow(i == nodes.size() && i == sums.size() && i == node_stresses.size(),
                    ExcInternalError());
      }

      /// The normal part scaled to the deformed surface, and in 2D with
      /// friction the tangential part.
      std::vector<double> pressure, tangential;
      /// Over the active nodes: the largest shear (or deviation from the
      /// mortar tangential traction) and the largest mortar pressure.
      double largest_shear = 0., p_max = 0.;
    };

    /// The lines of how far the traction of the recovered stress at the
    /// paired slave nodes (@p node_stresses at @p nodes, the paired
    /// interface slave nodes in their order) is from the mortar traction
    /// (or zero shear), from the exact pressure of @p comparison (if any)
    /// and from the reference profile of @p analytical (if any); recorded
    /// in @p cycle_record with keys prefixed with @p prefix.
    template <int dim>
    std::string
    recovered_traction_report(const ContactState<dim>                     &state,
                              const AnalyticalComparison<dim>             *comparison,
                              const AnalyticalSolution                    &analytical,
                              const std::vector<ContactNodeTraction<dim>> &nodes,
                              const std::vector<SupportSums<dim>>         &sums,
                              const std::vector<SymmetricTensor<2, dim>>  &node_stresses,
                              const std::string                           &prefix,
                              Json                                        &cycle_record)
    {
      const RecoveredTractions<dim> recovered(state.interface, state.contact, nodes, sums,
                                              node_stresses);
      const double shear = recovered.p_max > 0. ? recovered.largest_shear / recovered.p_max : 0.;
      const std::string  label = prefix.empty() ? "    recovered" : "    plain SPR recovered";
      std::ostringstream out;
      if (state.contact.transmits_shear())
        {
          cycle_record.set(prefix + "recovered_tangential_traction_deviation_max_relative", shear);
          out << label
              << " tangential traction - mortar one, largest / p_max: " << value_or_ok(shear, 1e-6)
              << std::endl;
        }
      else
        {
          cycle_record.set(prefix + "recovered_shear_traction_max_relative", shear);
          out << label << " shear traction / p_max: " << value_or_ok(shear, 1e-6) << std::endl;
        }
      if (comparison)
        comparison->report_recovered(state, recovered.pressure, recovered.tangential, label, prefix,
                                     cycle_record, out);
      if (!analytical.reference_pressure_profile.empty())
        {
          const double error = reference_pressure_error(analytical, state, recovered.pressure);
          cycle_record.set(prefix + "recovered_pressure_reference_l2_relative_error", error);
          out << label << " pressure, L2 error against the reference: " << value_or_ok(error, 1e-10)
              << std::endl;
        }
      return out.str();
    }
  } // namespace

  template <int dim>
  void
  ContactProblem<dim>::estimate_error(Json &cycle_record)
  {
    TimerOutput::Scope t(*timer, "Estimate");
    const std::string &type = refinement.estimator;
    indicators.reinit(triangulation.n_active_cells());
    typename StressRecovery<dim>::Settings settings;
    settings.contact_terms      = type != "spr";
    settings.penalty_normal     = spr_settings.penalty_normal;
    settings.penalty_tangential = spr_settings.penalty_tangential;
    // The contact tractions (recovery_tractions()); every paired node when
    // the recovered traction is compared with a known pressure.
    const bool pressure_known =
      contact && (comparison || !analytical.reference_pressure_profile.empty());
    std::vector<SupportSums<dim>>               sums;
    const std::vector<ContactNodeTraction<dim>> tractions =
      contact && (settings.contact_terms || pressure_known) ?
        recovery_tractions(*interface, *contact, pressure_known, relevant_dofs, sums) :
        std::vector<ContactNodeTraction<dim>>();
    const auto spr =
      StressRecovery<dim>::estimate(*mapping, dof_handler, ghosted_solution, materials, tractions,
                                    settings, volumetric_projection.get());
    if (type == "kelly")
      KellyErrorEstimator<dim>::estimate(*mapping, dof_handler, QGauss<dim - 1>(degree + 1), {},
                                         ghosted_solution, indicators, ComponentMask(), nullptr,
                                         numbers::invalid_unsigned_int,
                                         triangulation.locally_owned_subdomain());
    else
      indicators = spr.cell_indicators;

    relative_estimate = spr.relative_error;
    cycle_record.set("estimator", type)
      .set("estimated_error", spr.estimated_error)
      .set("relative_estimated_error", spr.relative_error)
      .set("solution_energy_norm", spr.solution_energy_norm);
    pcout << "    estimated error (SPR" << (settings.contact_terms ? " contact" : "")
          << "): eta / |u|_E = " << value_or_ok(spr.relative_error, 1e-10) << std::endl;
    if (pressure_known)
      pcout << recovered_traction_report(contact_state(), comparison.get(), analytical, tractions,
                                         sums, spr.node_stresses, "", cycle_record);

    t.stop();
    if (refinement.compare_plain_spr && settings.contact_terms)
      {
        Timer plain_timer;
        settings.contact_terms = false;
        const auto plain =
          StressRecovery<dim>::estimate(*mapping, dof_handler, ghosted_solution, materials,
                                        tractions, settings, volumetric_projection.get());
        cycle_record.set("plain_spr_estimated_error", plain.estimated_error);
        pcout << "    plain SPR on the same mesh:   eta / |u|_E = "
              << value_or_ok(plain.relative_error, 1e-10) << std::endl;
        if (pressure_known)
          pcout << recovered_traction_report(contact_state(), comparison.get(), analytical,
                                             tractions, sums, plain.node_stresses, "plain_spr_",
                                             cycle_record);
        uncounted_wall_time += plain_timer.wall_time();
      }
    report_effectivity(pcout, cycle_record);
  }

  template <int dim>
  bool
  ContactProblem<dim>::refine_mesh()
  {
    TimerOutput::Scope t(*timer, "Refine");
    if (triangulation.n_global_active_cells() >= refinement.max_cells)
      {
        pcout << "Maximum number of cells reached: mesh kept, remaining cycles skipped."
              << std::endl;
        return false;
      }
    // An estimate at round-off level (an exactly represented solution, as
    // in a patch test) carries no information on where to refine: marking
    // by it would follow the rounding of the solver and the platform.
    if (refinement.estimator != "global" && !(relative_estimate >= 1e-10))
      {
        pcout << "Estimate at round-off level (eta / |u|_E < 1e-10): mesh kept, "
                 "remaining cycles skipped."
              << std::endl;
        return false;
      }
    Marking::flag_cells(triangulation, indicators, refinement);
    if (refinement.estimator != "global")
      {
        // Stick ties the slave to the master's mesh; frictionless contact
        // is left as it was (its meshes and outputs unchanged).
        if (contact && contact->transmits_shear())
          Marking::flag_master_faces_opposite_flagged_slave_faces(dof_handler, *interface);
        std::set<types::boundary_id> contact_ids;
        for (const auto &pair : contact_parameters.pairs)
          contact_ids.insert({pair.slave, pair.master});
        Marking::flag_layers_behind_faces(triangulation, contact_ids, refinement.contact_layers,
                                          refinement.layers_along_surface);
      }
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->level() >= int(refinement.max_level))
        cell->clear_refine_flag();

    // The displacement moves to the new mesh; the active set follows from
    // the transferred gaps at the first step of the next cycle.
    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector> transfer(
      dof_handler);
    triangulation.prepare_coarsening_and_refinement();
    transfer.prepare_for_coarsening_and_refinement(ghosted_solution);
    triangulation.execute_coarsening_and_refinement();
    distribute_dofs(dof_handler, fe, dof_renumbering_seed);
    TrilinosWrappers::MPI::Vector transferred(dof_handler.locally_owned_dofs(), comm);
    transfer.interpolate(transferred);
    transferred_solution = std::make_unique<TrilinosWrappers::MPI::Vector>(transferred);
    return true;
  }

#define INSTANTIATE(dim)                                     \
  template void ContactProblem<dim>::estimate_error(Json &); \
  template bool ContactProblem<dim>::refine_mesh();
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace contact_fem
