#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/core/format.h>
#include <contact_fem/postprocess/hertz_comparison.h>
#include <contact_fem/simulator/scene_parameters.h>

#include <iomanip>
#include <ostream>

namespace contact_fem
{
  template <int dim>
  double
  HertzCylinder<dim>::load(const ContactState<dim> &state) const
  {
    return state.contact_force().norm();
  }

  template <int dim>
  HertzContact
  HertzCylinder<dim>::solution(const ContactState<dim> &state) const
  {
    return HertzContact::cylinder(load(state), this->analytical.radius,
                                  state.interface.contact_modulus(0));
  }

  template <int dim>
  double
  HertzCylinder<dim>::coordinate(const Point<dim> &x) const
  {
    return x[0] - this->analytical.center;
  }

  template <int dim>
  double
  HertzCylinder<dim>::measured_size(const ContactState<dim> &, const Json &contact) const
  {
    return contact["contact_half_width"].number_value();
  }

  template <int dim>
  std::function<double(const Point<dim> &)>
  HertzCylinder<dim>::exact_pressure(const ContactState<dim> &state) const
  {
    const HertzContact h = solution(state);
    return [this, h](const Point<dim> &x) {
      return h.pressure(coordinate(x));
    };
  }

  template <int dim>
  Json
  HertzCylinder<dim>::compare(const ContactState<dim> &state,
                              const Json              &contact,
                              const Json &) const
  {
    const HertzContact h      = solution(state);
    const double       p_num  = contact["max_contact_pressure"].number_value();
    const double       a_num  = measured_size(state, contact);
    const double       size   = contact["slave_element_size"].number_value();
    Json               result = Json::object();
    result.set("type", this->analytical.type)
      .set("load", load(state))
      .set("a", h.a)
      .set("p_max", h.p_max)
      .set("a_error", std::abs(a_num - h.a))
      .set("a_error_in_slave_elements", size > 0. ? std::abs(a_num - h.a) / size : 0.)
      .set("p_max_relative_error", (p_num - h.p_max) / h.p_max)
      .set("pressure_l2_relative_error",
           pressure_l2_relative_error(state, state.contact.pressures(state.interface),
                                      exact_pressure(state)));
    // A degree-1 geometry (Q1 on a linear mapping, e.g. with Finite
    // element/Mapping degree = 1) replaces the arc by its chords, which lie
    // inside the circle by h^2 t (1 - t) / (2 R) along a chord of length h:
    // the discrete cylinder is shorter where it touches, and the contact
    // force does the extra work W = sum_faces (lambda_a + lambda_b) h^3 /
    // (24 R) (linear pressure interpolation), which lowers Pi_h by about W.
    // On adaptive Q1 meshes W is as large as the squared energy error itself
    // (see doc/convergence.md), so the driver's energy error adds it back.
    // Quadratic arcs (Q2, or Q1 on a quadratic mapping) deviate by
    // O(h^4 / R^3): no term. (2D only: the chords of 3D faces are not summed.)
    if (dim == 2 && state.interface.geometry_degree == 1)
      {
        // Each rank its own slave faces (the pressures at their nodes are
        // held), summed in face order.
        const ContactInterface<dim>                 &interface = state.interface;
        std::vector<std::pair<unsigned int, double>> work;
        for (unsigned int f = interface.own_faces.first; f < interface.own_faces.second; ++f)
          if (const auto &face = interface.faces[f]; face.slave)
            {
              const unsigned int a = face.nodes[0], b = face.nodes[1];
              const double       h_face =
                interface.nodes[a].reference.distance(interface.nodes[b].reference);
              work.emplace_back(f, (state.contact.normal_pressure(a) +
                                    state.contact.normal_pressure(b)) *
                                     h_face * h_face * h_face / (24. * this->analytical.radius));
            }
        result.set("chord_gap_work", interface.sum_in_node_order(work));
      }
    return result;
  }

  template <int dim>
  void
  HertzCylinder<dim>::print(const Json &hertz, std::ostream &out) const
  {
    out << std::setprecision(6) << "    Hertz a:                      " << hertz["a"].number_value()
        << std::endl
        << "    Hertz p_max:                  " << hertz["p_max"].number_value() << std::endl
        << "    p_max relative error:         " << std::setprecision(3)
        << hertz["p_max_relative_error"].number_value() << std::endl
        << "    |a - a_Hertz| / slave h:      " << hertz["a_error_in_slave_elements"].number_value()
        << std::endl
        << "    p_max within 2 % of Hertz:    "
        << (std::abs(hertz["p_max_relative_error"].number_value()) < 0.02 ? "yes" : "no")
        << std::endl
        << "    a within one slave element:   "
        << (hertz["a_error_in_slave_elements"].number_value() <= 1. ? "yes" : "no") << std::endl
        << std::setprecision(6);
  }

  template <int dim>
  void
  HertzCylinder<dim>::report_recovered(const ContactState<dim>   &state,
                                       const std::vector<double> &pressure,
                                       const std::vector<double> &,
                                       const std::string &label,
                                       const std::string &prefix,
                                       Json              &record,
                                       std::ostream      &out) const
  {
    const double error = pressure_l2_relative_error(state, pressure, exact_pressure(state));
    record.set(prefix + "recovered_pressure_l2_relative_error", error);
    out << label << " pressure, L2 error against Hertz: " << value_or_ok(error, 1e-10) << std::endl;
  }

  template class HertzCylinder<2>;
  template class HertzCylinder<3>;

  CONTACT_FEM_REGISTER_ANALYTICAL_COMPARISON(HertzCylinder, "hertz cylinder")
} // namespace contact_fem
