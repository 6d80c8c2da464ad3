// 'cattaneo': the Cattaneo-Mindlin problem of two cylinders (plane strain)
// pressed together by P and sheared by Q at constant P, and its
// Mindlin-Deresiewicz unloading: Hertz' comparison for the normal load P,
// plus the stick zone and the tangential traction (cattaneo_solution.h).
#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/core/format.h>
#include <contact_fem/postprocess/cattaneo_solution.h>
#include <contact_fem/postprocess/hertz_comparison.h>
#include <contact_fem/simulator/scene_parameters.h>

#include <ostream>

namespace contact_fem
{
  namespace
  {
    /**
     * The transmitted normal load P >= 0 and signed tangential load Q of the
     * converged state: the resultant of the contact tractions on the slave
     * (equal to the load applied to a slave body without supports) in the
     * frame of the analytical solution, whose contact plane is normal to y:
     * n0 = (0, +-1) on the side of the mean slave normal, Q along
     * ContactFormulation::tangent(n0) (the nodes' tangential tractions are
     * measured along the same orientation).
     */
    template <int dim>
    std::pair<double, double>
    cattaneo_loads(const ContactInterface<dim> &interface, const ContactFormulation<dim> &contact)
    {
      Tensor<1, dim> force, mean_normal;
      for (const auto &s : interface.slave_nodes)
        if (s.paired && contact.is_active(s.node))
          {
            force += s.D * contact.traction(s);
            mean_normal += s.D * s.normal;
          }
      // The frame of the solution, not the mean normal: an active set one
      // node off the symmetric one tilts that by ~1e-3 rad, which takes 1 %
      // off Q, and a sliding body tilts it to the resultant itself.
      Tensor<1, dim> n0;
      n0[1] = mean_normal[1] < 0. ? -1. : 1.;
      return {-(force * n0), force * ContactFormulation<dim>::tangent(n0)};
    }

    /**
     * The comparison of the converged state: P and Q from cattaneo_loads(),
     * the history of Q along the load path from @p load_path (the Q of every
     * converged load step of the cycle: classify_tangential_path()), E* from
     * the materials of the first pair, R* = Analytical solution/Radius, x of
     * each node in the configuration the mortar operators were built on (the
     * reference one with Contact/Kinematics = small) less Analytical
     * solution/Center. With @p tangential (per interface node) those
     * tangential tractions are compared instead of the formulation's (e.g.
     * the recovered stress's). A path without an analytical solution gives
     * no comparison (the key "no_solution" says why).
     */
    template <int dim>
    Json
    cattaneo_results(const ContactInterface<dim>   &interface,
                     const ContactFormulation<dim> &contact,
                     const AnalyticalSolution      &analytical,
                     const std::vector<double>     &load_path,
                     const std::vector<double>     *tangential = nullptr)
    {
      const double E_star = interface.contact_modulus(0);
      const double mu     = analytical.friction_coefficient; // Tresca: the bound g
      const bool   tresca = analytical.tresca;
      std::vector<CattaneoNode> nodes;
      for (const auto &s : interface.slave_nodes)
        if (s.paired)
          {
            CattaneoNode node;
            const bool   active = contact.is_active(s.node);
            node.x = interface.nodes[s.node].reference[0] +
                     interface.displacement(s.node, interface.search_configuration())[0] -
                     analytical.center;
            node.t = !active ? 0. :
                     tangential ?
                                (*tangential)[s.node] :
                                contact.traction(s) *
                                  ContactFormulation<dim>::tangent(contact.frame_normal(s));
            node.weight = s.D;
            node.active = active;
            node.stick  = contact.held_tangentially(s.node);
            nodes.push_back(node);
          }
      const auto [P, Q] = cattaneo_loads(interface, contact);
      // The same tolerance as for "no tangential load" in the comparison.
      std::vector<double> path = load_path;
      path.push_back(Q);
      const double capacity =
        CattaneoSolution(P, 0., mu, analytical.radius, E_star, tresca).capacity();
      const TangentialPath history = classify_tangential_path(path, 1e-6 * capacity);
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
                                                              analytical.radius, E_star, tresca),
                                             history.direction));
      return to_json(compare_with_cattaneo(
        nodes, CattaneoSolution(P, std::abs(Q), mu, analytical.radius, E_star, tresca)));
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
      }

      void
      record_load_step(const ContactState<dim> &state) override
      {
        load_path.push_back(cattaneo_loads(state.interface, state.contact).second);
      }

      Json
      compare(const ContactState<dim> &state,
              const Json              &contact,
              const Json              &reaction) const override
      {
        Json result = HertzCylinder<dim>::compare(state, contact, reaction);
        result.set("cattaneo",
                   cattaneo_results(state.interface, state.contact, this->analytical, load_path));
        return result;
      }

      void
      print(const Json &record, std::ostream &out) const override
      {
        out << cattaneo_report(record["cattaneo"]);
      }

      void
      report_recovered(const ContactState<dim>   &state,
                       const std::vector<double> &,
                       const std::vector<double> &tangential,
                       const std::string         &label,
                       const std::string         &prefix,
                       Json                      &record,
                       std::ostream              &out) const override
      {
        const Json cattaneo = cattaneo_results(state.interface, state.contact, this->analytical,
                                               load_path, &tangential);
        const double error = cattaneo["tangential_l2_relative_error"].number_value();
        record.set(prefix + "recovered_tangential_l2_relative_error_cattaneo", error);
        out << label << " tangential traction, L2 error against Cattaneo: "
            << value_or_ok(error, 1e-10) << std::endl;
      }

    protected:
      /// The normal load P, not the resultant with Q.
      double
      load(const ContactState<dim> &state) const override
      {
        return cattaneo_loads(state.interface, state.contact).first;
      }

    private:
      /// The signed tangential load of every converged load step of the
      /// cycle so far.
      std::vector<double> load_path;
    };
  } // namespace

  CONTACT_FEM_REGISTER_ANALYTICAL_COMPARISON(CattaneoMindlin, "cattaneo")
} // namespace contact_fem
