#include <deal.II/base/numbers.h>

#include <contact_fem/simulator/cattaneo.h>
#include <contact_fem/core/format.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace contact_fem
{
  CattaneoSolution::CattaneoSolution(const double P,
                                     const double Q,
                                     const double mu,
                                     const double radius,
                                     const double E_star)
    : P(P)
    , Q(Q)
    , mu(mu)
  {
    a     = std::sqrt(4. * P * radius / (numbers::PI * E_star));
    p_max = 2. * P / (numbers::PI * a);
    c     = Q < mu * P ? a * std::sqrt(1. - Q / (mu * P)) : 0.;
  }

  double
  CattaneoSolution::pressure(const double x) const
  {
    return std::abs(x) < a ? p_max * std::sqrt(1. - x * x / (a * a)) : 0.;
  }

  double
  CattaneoSolution::tangential(const double x) const
  {
    if (std::abs(x) >= a)
      return 0.;
    double q = mu * pressure(x);
    if (std::abs(x) < c)
      q -= mu * p_max * (c / a) * std::sqrt(1. - x * x / (c * c));
    return q;
  }

  CattaneoComparison
  compare_with_cattaneo(std::vector<CattaneoNode> nodes, const CattaneoSolution &exact)
  {
    CattaneoComparison result;
    result.exact = exact;
    std::sort(nodes.begin(), nodes.end(),
              [](const CattaneoNode &m, const CattaneoNode &n) { return m.x < n.x; });
    const unsigned int n     = nodes.size();
    unsigned int       first = n, last = n;
    for (unsigned int i = 0; i < n; ++i)
      {
        result.n_stick += nodes[i].stick;
        result.n_slip += nodes[i].active && !nodes[i].stick;
        if (nodes[i].stick)
          {
            if (first == n)
              first = i;
            last = i;
          }
      }
    if (first < n)
      {
        for (unsigned int i = first; i <= last; ++i)
          if (!nodes[i].stick)
            result.stick_contiguous = false;
        // Each end halfway to the next node outward; a stick node with no
        // outer neighbour ends the zone at itself.
        const double left  = first > 0 ? 0.5 * (nodes[first].x + nodes[first - 1].x) :
                                         nodes[first].x;
        const double right = last + 1 < n ? 0.5 * (nodes[last].x + nodes[last + 1].x) :
                                            nodes[last].x;
        result.c_h          = 0.5 * (right - left);
        result.stick_center = 0.5 * (right + left);
        const double left_spacing  = first > 0 ? nodes[first].x - nodes[first - 1].x : 0.;
        const double right_spacing = last + 1 < n ? nodes[last + 1].x - nodes[last].x : 0.;
        result.end_spacing         = 0.5 * (left_spacing + right_spacing);
      }
    result.c_error_in_slave_elements =
      result.end_spacing > 0. ? std::abs(result.c_h - exact.c) / result.end_spacing : 0.;

    double resultant = 0.;
    for (const auto &node : nodes)
      resultant += node.weight * node.t;
    const double sign = resultant < 0. ? -1. : 1.;
    double       error = 0., norm = 0., weights = 0.;
    for (const auto &node : nodes)
      {
        const double t = sign * exact.tangential(node.x);
        error += node.weight * (node.t - t) * (node.t - t);
        norm += node.weight * t * t;
        weights += node.weight;
      }
    // Without a tangential load (Q = 0 up to the round-off of an
    // antisymmetric sum, the normal phase) q vanishes: the error is then
    // relative to the slip bound mu p_max instead.
    constexpr double no_tangential_load = 1e-6;
    const double bound = exact.mu * exact.p_max;
    if (exact.Q <= no_tangential_load * exact.mu * exact.P)
      norm = bound * bound * weights;
    result.tangential_l2_relative_error = norm > 0. ? std::sqrt(error / norm) : 0.;
    return result;
  }

  Json
  to_json(const CattaneoComparison &comparison)
  {
    const CattaneoSolution &exact = comparison.exact;
    const double            a     = exact.a;
    Json                    result = Json::object();
    result.set("mu", exact.mu)
      .set("P", exact.P)
      .set("Q", exact.Q)
      .set("Q_over_mu_P", exact.mu * exact.P > 0. ? exact.Q / (exact.mu * exact.P) : 0.)
      .set("a", a)
      .set("p_max", exact.p_max)
      .set("c", exact.c)
      .set("c_over_a", a > 0. ? exact.c / a : 0.)
      .set("stick_nodes", comparison.n_stick)
      .set("slip_nodes", comparison.n_slip)
      .set("stick_zone_contiguous", comparison.stick_contiguous)
      .set("c_h", comparison.c_h)
      .set("c_h_over_a", a > 0. ? comparison.c_h / a : 0.)
      .set("stick_zone_center", comparison.stick_center)
      .set("stick_end_spacing", comparison.end_spacing)
      .set("c_error_in_slave_elements", comparison.c_error_in_slave_elements)
      .set("tangential_l2_relative_error", comparison.tangential_l2_relative_error);
    return result;
  }

  std::string
  cattaneo_report(const Json &cattaneo)
  {
    const auto value = [&](const char *key) { return cattaneo[key].number_value(); };
    std::ostringstream out;
    out << std::setprecision(6)
        << "    Cattaneo mu, P, Q:            " << value("mu") << ", " << value("P") << ", "
        << value("Q") << std::endl
        << "    Cattaneo Q/(mu P):            " << value_or_ok(value("Q_over_mu_P"), 1e-6)
        << std::endl
        << std::setprecision(4)
        << "    stick zone c_h/a vs c/a:      " << value("c_h_over_a") << " vs "
        << value("c_over_a") << std::endl
        << std::setprecision(3)
        << "    stick zone centre / a:        "
        // A centred zone leaves round-off here: not printed as a number.
        << value_or_ok(value("stick_zone_center") / value("a"), 1e-6) << std::endl
        << "    |c_h - c| / slave h:          " << value("c_error_in_slave_elements")
        << std::endl
        << "    c within one slave element:   "
        << (value("stick_nodes") > 0 && value("c_error_in_slave_elements") <= 1. ? "yes" :
                                                                                   "no")
        << std::endl
        << "    tangential traction, L2 relative error against Cattaneo: "
        << value("tangential_l2_relative_error") << std::endl;
    return out.str();
  }

  template <int dim>
  Json
  cattaneo_results(const ContactInterface<dim>   &interface,
                   const ContactFormulation<dim> &contact,
                   const AnalyticalSolution      &analytical,
                   const std::vector<double>     *tangential)
  {
    const double E_star = interface.contact_modulus(0);

    // P and Q: the resultant of the contact tractions on the slave along
    // the mean slave normal and its tangent (the nodal normals tilt by
    // x / R_slave across the zone; the resultant does not).
    std::vector<CattaneoNode> nodes;
    Tensor<1, dim>            force, mean_normal;
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
          node.stick  = contact.sticks(s.node);
          if (active)
            {
              force += s.D * contact.traction(s);
              mean_normal += s.D * s.normal;
            }
          nodes.push_back(node);
        }
    if (mean_normal.norm() > 0.)
      mean_normal /= mean_normal.norm();
    const double P = -(force * mean_normal);
    const double Q = std::abs(force * ContactFormulation<dim>::tangent(mean_normal));
    const CattaneoSolution exact(P, Q, analytical.friction_coefficient, analytical.radius,
                                 E_star);
    return to_json(compare_with_cattaneo(nodes, exact));
  }

  template Json
  cattaneo_results(const ContactInterface<2> &, const ContactFormulation<2> &,
                   const AnalyticalSolution &, const std::vector<double> *);
  template Json
  cattaneo_results(const ContactInterface<3> &, const ContactFormulation<3> &,
                   const AnalyticalSolution &, const std::vector<double> *);
} // namespace contact_fem
