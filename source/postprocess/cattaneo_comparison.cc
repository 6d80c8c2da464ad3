// 'cattaneo': the Cattaneo-Mindlin problem of two cylinders (plane strain),
// or in 3D of two spheres (a sphere on a flat, loaded along x; Mindlin),
// pressed together by P and sheared by Q at constant P, and its
// Mindlin-Deresiewicz unloading: Hertz' comparison for the normal load P,
// plus the stick zone and the tangential traction (cattaneo_solution.h).
#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/core/format.h>
#include <contact_fem/postprocess/cattaneo_solution.h>
#include <contact_fem/postprocess/hertz_comparison.h>
#include <contact_fem/postprocess/owned_rows.h>
#include <contact_fem/simulator/scene_parameters.h>

#include <algorithm>
#include <ostream>

namespace contact_fem
{
  namespace
  {
    /// The unit vector along which the tangential load is measured: the
    /// tangent of the 2D frame (ContactFormulation::tangent(n0)), x in 3D
    /// (the load of the spheres is along x).
    template <int dim>
    Tensor<1, dim>
    load_direction(const Tensor<1, dim> &n0)
    {
      if constexpr (dim == 2)
        return ContactFormulation<dim>::tangent(n0);
      Tensor<1, dim> x;
      x[0] = 1.;
      return x;
    }

    /// @p nodes (keyed by @p keys, their indices in slave_nodes) of every
    /// rank, on every rank, in key order. Collective.
    std::vector<CattaneoNode>
    gather_in_node_order(const MPI_Comm                   comm,
                         const std::vector<CattaneoNode> &nodes,
                         const std::vector<unsigned int> &keys)
    {
      std::vector<std::vector<double>> rows;
      for (unsigned int i = 0; i < nodes.size(); ++i)
        {
          const CattaneoNode &n = nodes[i];
          rows.push_back({double(keys[i]), n.x, n.t, n.weight, n.active ? 1. : 0.,
                          n.stick ? 1. : 0., n.t_across, n.along, n.size});
        }
      rows = gather_rows(comm, rows, true);
      std::sort(rows.begin(), rows.end(), [](const auto &a, const auto &b) {
        return a[0] < b[0];
      });
      std::vector<CattaneoNode> all(rows.size());
      for (unsigned int i = 0; i < rows.size(); ++i)
        {
          const auto &r   = rows[i];
          all[i].x        = r[1];
          all[i].t        = r[2];
          all[i].weight   = r[3];
          all[i].active   = r[4] != 0.;
          all[i].stick    = r[5] != 0.;
          all[i].t_across = r[6];
          all[i].along    = r[7];
          all[i].size     = r[8];
        }
      return all;
    }

    /**
     * The transmitted normal load P >= 0 and signed tangential load Q of the
     * converged state: the resultant of the contact tractions on the slave
     * (equal to the load applied to a slave body without supports) in the
     * frame of the analytical solution, whose contact plane is normal to y
     * (z in 3D): n0 = +-e_y (e_z) on the side of the mean slave normal, Q
     * along load_direction(n0) (the nodes' tangential tractions are
     * measured along the same orientation). Both for the whole model: over
     * Analytical solution/Symmetry fraction.
     */
    template <int dim>
    std::pair<double, double>
    cattaneo_loads(const ContactInterface<dim>   &interface,
                   const ContactFormulation<dim> &contact,
                   const double                   symmetry_fraction)
    {
      // Each rank the nodes whose rows it owns, summed in node order.
      std::vector<std::pair<unsigned int, Tensor<1, dim>>> forces, normals;
      for (unsigned int k = 0; k < interface.slave_nodes.size(); ++k)
        if (const auto &s = interface.slave_nodes[k];
            s.paired && interface.owns_row(s) && contact.is_active(s.node))
          {
            forces.emplace_back(k, s.D * contact.traction(s));
            normals.emplace_back(k, s.D * s.normal);
          }
      const Tensor<1, dim> force       = sum_in_node_order(interface, forces);
      const Tensor<1, dim> mean_normal = sum_in_node_order(interface, normals);
      // The frame of the solution, not the mean normal: an active set one
      // node off the symmetric one tilts that by ~1e-3 rad, which takes 1 %
      // off Q, and a sliding body tilts it to the resultant itself.
      Tensor<1, dim> n0;
      n0[dim - 1] = mean_normal[dim - 1] < 0. ? -1. : 1.;
      return {-(force * n0) / symmetry_fraction, force * load_direction(n0) / symmetry_fraction};
    }

    /**
     * The comparison of the converged state: P and Q from cattaneo_loads(),
     * the history of Q along the load path from @p load_path (the Q of every
     * converged load step of the cycle: classify_tangential_path()), E* from
     * the materials of the first pair, R* = Analytical solution/Radius, x of
     * each node in the configuration the mortar operators were built on (the
     * reference one with Contact/Kinematics = small) less Analytical
     * solution/Center (in 3D its distance from the axis, Analytical
     * solution/Center, Center y). With @p tangential (per interface node, 2D)
     * those tangential tractions are compared instead of the formulation's
     * (e.g. the recovered stress's). A path without an analytical solution
     * gives no comparison (the key "no_solution" says why).
     */
    template <int dim>
    Json
    cattaneo_results(const ContactInterface<dim>   &interface,
                     const ContactFormulation<dim> &contact,
                     const AnalyticalSolution      &analytical,
                     const std::vector<double>     &load_path,
                     const std::vector<double>     *tangential = nullptr)
    {
      const double          E_star  = interface.contact_modulus(0);
      const double          mu      = analytical.friction_coefficient; // Tresca: the bound g
      const CattaneoProblem problem = dim == 3          ? CattaneoProblem::spheres :
                                      analytical.tresca ? CattaneoProblem::cylinders_tresca :
                                                          CattaneoProblem::cylinders;
      // Each rank the nodes whose rows it owns, gathered to every rank in
      // node order (the comparison sorts them by x, ties in node order).
      std::vector<CattaneoNode> nodes;
      std::vector<unsigned int> keys;
      for (unsigned int k = 0; k < interface.slave_nodes.size(); ++k)
        if (const auto &s = interface.slave_nodes[k]; s.paired && interface.owns_row(s))
          {
            CattaneoNode     node;
            const bool       active = contact.is_active(s.node);
            const Point<dim> x      = interface.nodes[s.node].reference +
                                 interface.displacement(s.node, interface.search_configuration());
            node.weight = s.D;
            node.active = active;
            node.stick  = contact.held_tangentially(s.node);
            node.size   = s.size;
            if constexpr (dim == 2)
              {
                node.x = x[0] - analytical.center;
                node.t = !active    ? 0. :
                         tangential ? (*tangential)[s.node] :
                                      contact.traction(s) *
                                        ContactFormulation<dim>::tangent(contact.frame_normal(s));
              }
            else
              {
                // The tangential traction in the node's frame, its
                // components along the load (x) and across it (y).
                node.x                 = analytical.axis_distance(x[0], x[1]);
                node.along             = x[0] - analytical.center;
                const Tensor<1, dim> n = contact.frame_normal(s);
                Tensor<1, dim>       t = contact.traction(s);
                t -= (t * n) * n;
                node.t        = active ? t[0] : 0.;
                node.t_across = active ? t[1] : 0.;
              }
            nodes.push_back(node);
            keys.push_back(k);
          }
      nodes                 = gather_in_node_order(interface.communicator(), nodes, keys);
      const double fraction = analytical.symmetry_fraction;
      const auto [P, Q]     = cattaneo_loads(interface, contact, fraction);
      // The same tolerance as for "no tangential load" in the comparison.
      std::vector<double> path = load_path;
      path.push_back(Q);
      const double capacity =
        CattaneoSolution(P, 0., mu, analytical.radius, E_star, problem).capacity();
      const TangentialPath history =
        classify_tangential_path(path, CattaneoSolution::no_tangential_load * capacity);
      if (history.kind == TangentialPath::Kind::none)
        return Json::object()
          .set("mu", mu)
          .set("P", P)
          .set("Q", std::abs(Q))
          .set("no_solution", "the tangential load turned back twice: no analytical "
                              "solution (Cattaneo for monotone loading, "
                              "Mindlin-Deresiewicz for one unloading)");
      if (history.kind == TangentialPath::Kind::unloading)
        return to_json(compare_with_cattaneo(nodes,
                                             CattaneoSolution(P, history.Q, history.Q_star, mu,
                                                              analytical.radius, E_star, problem),
                                             history.direction, fraction));
      return to_json(compare_with_cattaneo(nodes,
                                           CattaneoSolution(P, std::abs(Q), mu, analytical.radius,
                                                            E_star, problem),
                                           0., fraction));
    }

    template <int dim>
    class CattaneoMindlin : public HertzCylinder<dim>
    {
    public:
      using HertzCylinder<dim>::HertzCylinder;

      void
      start_load_path() override
      {
        load_path.clear();
        steps = Json::array();
      }

      /// Q of the step for the load path, and the comparison of the step
      /// (the tests check c/a at several Q of one run).
      void
      record_load_step(const ContactState<dim> &state) override
      {
        const Json step =
          cattaneo_results(state.interface, state.contact, this->analytical, load_path);
        steps.push(step);
        load_path.push_back(
          cattaneo_loads(state.interface, state.contact, this->analytical.symmetry_fraction)
            .second);
      }

      Json
      compare(const ContactState<dim> &state,
              const Json              &contact,
              const Json              &reaction) const override
      {
        Json result = HertzCylinder<dim>::compare(state, contact, reaction);
        Json cattaneo =
          cattaneo_results(state.interface, state.contact, this->analytical, load_path);
        cattaneo.set("load_steps", steps);
        result.set("cattaneo", cattaneo);
        return result;
      }

      void
      print(const Json &record, std::ostream &out) const override
      {
        const Json &cattaneo = record["cattaneo"];
        if (dim == 3)
          out << cattaneo_steps_report(cattaneo["load_steps"],
                                       this->analytical.tangential_error_bounds);
        out << cattaneo_report(cattaneo);
      }

      void
      report_recovered(const ContactState<dim> &state,
                       const std::vector<double> &,
                       const std::vector<double> &tangential,
                       const std::string         &label,
                       const std::string         &prefix,
                       Json                      &record,
                       std::ostream              &out) const override
      {
        // In 3D the recovered shear is compared with the mortar traction
        // only (report_recovered_tractions()).
        if (dim == 3)
          return;
        const Json   cattaneo = cattaneo_results(state.interface, state.contact, this->analytical,
                                                 load_path, &tangential);
        const double error    = cattaneo["tangential_l2_relative_error"].number_value();
        record.set(prefix + "recovered_tangential_l2_relative_error_cattaneo", error);
        out << label
            << " tangential traction, L2 error against Cattaneo: " << value_or_ok(error, 1e-10)
            << std::endl;
      }

    protected:
      /// The normal load P (of the whole sphere in 3D), not the resultant
      /// with Q.
      double
      load(const ContactState<dim> &state) const override
      {
        return cattaneo_loads(state.interface, state.contact, this->analytical.symmetry_fraction)
          .first;
      }

      HertzContact
      solution(const ContactState<dim> &state) const override
      {
        if (dim == 3)
          return HertzContact::sphere(load(state), this->analytical.radius,
                                      state.interface.contact_modulus(0));
        return HertzCylinder<dim>::solution(state);
      }

      /// In 3D the distance from the axis.
      double
      coordinate(const Point<dim> &x) const override
      {
        if (dim == 3)
          return this->analytical.axis_distance(x[0], x[1]);
        return HertzCylinder<dim>::coordinate(x);
      }

    private:
      /// The signed tangential load of every converged load step of the
      /// cycle so far.
      std::vector<double> load_path;
      /// The comparison of every converged load step of the cycle so far.
      Json steps = Json::array();
    };
  } // namespace

  CONTACT_FEM_REGISTER_ANALYTICAL_COMPARISON(CattaneoMindlin, "cattaneo")
} // namespace contact_fem
