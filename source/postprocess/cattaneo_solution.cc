#include <deal.II/base/numbers.h>

#include <contact_fem/postprocess/cattaneo_solution.h>
#include <contact_fem/postprocess/cattaneo_tresca.h>
#include <contact_fem/core/format.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace contact_fem
{
  CattaneoSolution::CattaneoSolution(const double          P,
                                     const double          Q,
                                     const double          mu,
                                     const double          radius,
                                     const double          E_star,
                                     const CattaneoProblem problem)
    : P(P)
    , Q(Q)
    , mu(problem == CattaneoProblem::cylinders_tresca ? 0. : mu)
    , g(problem == CattaneoProblem::cylinders_tresca ? mu : 0.)
    , sphere(problem == CattaneoProblem::spheres)
  {
    constexpr double pi = dealii::numbers::PI;
    a                   = sphere ? std::cbrt(3. * P * radius / (4. * E_star)) :
                                   std::sqrt(4. * P * radius / (pi * E_star));
    p_max               = sphere ? 3. * P / (2. * pi * a * a) : 2. * P / (pi * a);
    c                   = stick_size(Q);
  }

  double
  CattaneoSolution::stick_size(const double load) const
  {
    if (g > 0.)
      return tresca_stick_half_width(a, load, g);
    if (load >= mu * P)
      return 0.;
    const double ratio = 1. - load / (mu * P);
    return a * (sphere ? std::cbrt(ratio) : std::sqrt(ratio));
  }

  CattaneoSolution::CattaneoSolution(const double          P,
                                     const double          Q,
                                     const double          Q_star,
                                     const double          mu,
                                     const double          radius,
                                     const double          E_star,
                                     const CattaneoProblem problem)
    : CattaneoSolution(P, Q_star, mu, radius, E_star, problem)
  {
    this->Q      = Q;
    unloading    = true;
    this->Q_star = Q_star;
    c_star       = c;
    // The second term is a monotone solution for (Q_star - Q) / 2.
    c = stick_size(0.5 * (Q_star - Q));
  }

  double
  CattaneoSolution::pressure(const double x) const
  {
    return std::abs(x) < a ? p_max * std::sqrt(1. - x * x / (a * a)) : 0.;
  }

  double
  CattaneoSolution::monotone_traction(const double x, const double stick) const
  {
    if (g > 0.)
      return tresca_traction(x, a, stick, g);
    if (std::abs(x) >= a)
      return 0.;
    double q = mu * pressure(x);
    if (std::abs(x) < stick)
      q -= mu * p_max * (stick / a) * std::sqrt(1. - x * x / (stick * stick));
    return q;
  }

  double
  CattaneoSolution::tangential(const double x) const
  {
    return unloading ? monotone_traction(x, c_star) - 2. * monotone_traction(x, c) :
                       monotone_traction(x, c);
  }

  TangentialPath
  classify_tangential_path(const std::vector<double> &loads, const double tolerance)
  {
    using Kind = TangentialPath::Kind;
    TangentialPath path;
    double         previous = 0.;
    for (const double q : loads)
      {
        if (path.direction == 0. && std::abs(q) > tolerance)
          path.direction = q > 0. ? 1. : -1.;
        const double along = path.direction * q, before = path.direction * previous;
        if (path.kind == Kind::monotone && along < before - tolerance)
          {
            path.kind   = Kind::unloading;
            path.Q_star = before;
          }
        else if (path.kind == Kind::unloading && along < -path.Q_star - tolerance)
          {
            // Past the reversed peak every point slips again: the memory
            // of the peak is gone, a monotone load the other way.
            path.kind      = Kind::monotone;
            path.direction = -path.direction;
          }
        else if (path.kind == Kind::unloading && along > before + tolerance)
          path.kind = Kind::none;
        previous = q;
      }
    path.Q = path.direction * previous;
    return path;
  }

  namespace
  {
    /// The stick zone of Mindlin's spheres: the radius of the stick nodes'
    /// area, and its centre along the load.
    void
    measure_stick_disc(const std::vector<CattaneoNode> &nodes,
                       const double                     symmetry_fraction,
                       CattaneoComparison              &result)
    {
      double       area = 0., moment = 0., size = 0.;
      unsigned int n_active = 0;
      for (const auto &node : nodes)
        {
          if (node.stick)
            {
              area += node.weight;
              moment += node.weight * node.along;
            }
          if (node.active)
            {
              size += node.size;
              ++n_active;
            }
        }
      result.c_h          = std::sqrt(area / (dealii::numbers::PI * symmetry_fraction));
      result.stick_center = area > 0. ? moment / area : 0.;
      result.end_spacing  = n_active > 0 ? size / n_active : 0.;
    }
  } // namespace

  CattaneoComparison
  compare_with_cattaneo(std::vector<CattaneoNode> nodes,
                        const CattaneoSolution   &exact,
                        const double              direction,
                        const double              symmetry_fraction)
  {
    CattaneoComparison result;
    result.exact = exact;
    std::sort(nodes.begin(), nodes.end(), [](const CattaneoNode &m, const CattaneoNode &n) {
      return m.x < n.x;
    });
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
    if (exact.sphere)
      measure_stick_disc(nodes, symmetry_fraction, result);
    else if (first < n)
      {
        for (unsigned int i = first; i <= last; ++i)
          if (!nodes[i].stick)
            result.stick_contiguous = false;
        // Each end halfway to the next node outward; a stick node with no
        // outer neighbour ends the zone at itself.
        const double left =
          first > 0 ? 0.5 * (nodes[first].x + nodes[first - 1].x) : nodes[first].x;
        const double right =
          last + 1 < n ? 0.5 * (nodes[last].x + nodes[last + 1].x) : nodes[last].x;
        result.c_h                 = 0.5 * (right - left);
        result.stick_center        = 0.5 * (right + left);
        const double left_spacing  = first > 0 ? nodes[first].x - nodes[first - 1].x : 0.;
        const double right_spacing = last + 1 < n ? nodes[last + 1].x - nodes[last].x : 0.;
        result.end_spacing         = 0.5 * (left_spacing + right_spacing);
      }
    result.c_error_in_slave_elements =
      result.end_spacing > 0. ? std::abs(result.c_h - exact.c) / result.end_spacing : 0.;

    double resultant = 0.;
    for (const auto &node : nodes)
      resultant += node.weight * node.t;
    const double sign  = direction != 0. ? direction : resultant < 0. ? -1. : 1.;
    double       error = 0., norm = 0., weights = 0.;
    for (const auto &node : nodes)
      {
        const double t = sign * exact.tangential(node.x);
        error += node.weight * ((node.t - t) * (node.t - t) + node.t_across * node.t_across);
        norm += node.weight * t * t;
        weights += node.weight;
      }
    // Without a tangential load (the normal phase: zero up to the round-off
    // of an antisymmetric sum in 2D, up to the Newton tolerance in 3D) q
    // vanishes: the error is then relative to the largest slip bound instead.
    const double bound = exact.largest_bound();
    if (!exact.unloading && exact.Q <= CattaneoSolution::no_tangential_load * exact.capacity())
      norm = bound * bound * weights;
    result.tangential_l2_relative_error = norm > 0. ? std::sqrt(error / norm) : 0.;
    return result;
  }

  Json
  to_json(const CattaneoComparison &comparison)
  {
    const CattaneoSolution &exact  = comparison.exact;
    const double            a      = exact.a;
    Json                    result = Json::object();
    // Under Tresca the bound g and Q over the capacity 2 a g instead.
    const bool tresca = exact.g > 0.;
    result.set(tresca ? "g" : "mu", tresca ? exact.g : exact.mu)
      .set("P", exact.P)
      .set("Q", exact.Q)
      .set("load_path", exact.unloading ? "unloading" : "monotone");
    if (exact.unloading)
      result.set("Q_star", exact.Q_star).set("c_star", exact.c_star);
    result
      .set(tresca ? "Q_over_2_a_g" : "Q_over_mu_P",
           exact.capacity() > 0. ? exact.Q / exact.capacity() : 0.)
      .set("a", a)
      .set("p_max", exact.p_max)
      .set("c", exact.c)
      .set("c_over_a", a > 0. ? exact.c / a : 0.)
      .set("stick_nodes", comparison.n_stick)
      .set("slip_nodes", comparison.n_slip)
      .set("geometry", exact.sphere ? "spheres" : "cylinders");
    if (!exact.sphere)
      result.set("stick_zone_contiguous", comparison.stick_contiguous);
    result.set("c_h", comparison.c_h)
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
    const auto value = [&](const char *key) {
      return cattaneo[key].number_value();
    };
    std::ostringstream out;
    const bool         tresca = !std::isnan(value("g"));
    out << std::setprecision(6)
        << (tresca ? "    Cattaneo Tresca g, P, Q:      " : "    Cattaneo mu, P, Q:            ")
        << value(tresca ? "g" : "mu") << ", " << value("P") << ", " << value("Q") << std::endl;
    // cattaneo_results() gives no c for a path without a solution.
    if (std::isnan(value("c")))
      {
        out << "    Cattaneo: the tangential load turned back twice, no analytical "
               "solution; no comparison."
            << std::endl;
        return out.str();
      }
    if (!std::isnan(value("Q_star")))
      out << "    unloaded from the peak Q*:    " << value("Q_star")
          << " (Mindlin-Deresiewicz; c is the stick half-width b)" << std::endl;
    out << (tresca ? "    Cattaneo Q/(2 a g):           " : "    Cattaneo Q/(mu P):            ")
        << value_or_ok(value(tresca ? "Q_over_2_a_g" : "Q_over_mu_P"), 1e-6) << std::endl
        << std::setprecision(4) << "    stick zone c_h/a vs c/a:      " << value("c_h_over_a")
        << " vs " << value("c_over_a") << std::endl
        << std::setprecision(3)
        << "    stick zone centre / a:        "
        // A centred zone leaves round-off here: not printed as a number.
        << value_or_ok(value("stick_zone_center") / value("a"), 1e-6) << std::endl
        << "    |c_h - c| / slave h:          " << value("c_error_in_slave_elements") << std::endl
        << "    c within one slave element:   "
        << (value("stick_nodes") > 0 && value("c_error_in_slave_elements") <= 1. ? "yes" : "no")
        << std::endl
        << "    tangential traction, L2 relative error against Cattaneo: "
        << value("tangential_l2_relative_error") << std::endl;
    return out.str();
  }

  std::string
  cattaneo_steps_report(const Json &steps, const std::vector<double> &bounds)
  {
    std::ostringstream out;
    out << "    load steps: Q/(mu P), c/a, c_h/a, |c_h - c| / slave h, tangential L2 error"
        << std::endl;
    std::vector<std::size_t> compared;
    for (std::size_t k = 0; k < steps.size(); ++k)
      {
        const auto value = [&](const char *key) {
          return steps[k][key].number_value();
        };
        // Steps without a tangential load or a solution compare nothing.
        if (std::isnan(value("c")) || value("Q_over_mu_P") < CattaneoSolution::no_tangential_load)
          continue;
        compared.push_back(k);
        out << std::fixed << std::setprecision(4) << "      step " << std::setw(2) << k + 1 << ":  "
            << value("Q_over_mu_P") << "  " << value("c_over_a") << "  " << value("c_h_over_a")
            << "  " << std::setprecision(3) << value("c_error_in_slave_elements") << "  "
            << value("tangential_l2_relative_error") << std::endl;
      }
    if (bounds.empty())
      return out.str();
    out << "    every step within its bounds: ";
    if (bounds.size() != 1 && bounds.size() != compared.size())
      {
        out << "no (" << compared.size() << " steps compared, " << bounds.size() << " bounds)"
            << std::endl;
        return out.str();
      }
    std::ostringstream failures;
    failures << std::setprecision(3);
    for (std::size_t i = 0; i < compared.size(); ++i)
      {
        const Json  &step  = steps[compared[i]];
        const double c     = step["c_error_in_slave_elements"].number_value();
        const double error = step["tangential_l2_relative_error"].number_value();
        const double bound = bounds[bounds.size() == 1 ? 0 : i];
        // As "c within one slave element": a stick zone, c_h within h of c.
        if (!(step["stick_nodes"].number_value() > 0 && c <= 1.))
          failures << "; step " << compared[i] + 1 << ": |c_h - c| / h = " << c;
        if (!(error <= bound))
          failures << "; step " << compared[i] + 1 << ": L2 error " << error << " > " << bound;
      }
    std::ostringstream list;
    list << std::setprecision(3);
    for (std::size_t i = 0; i < bounds.size(); ++i)
      list << (i > 0 ? ", " : "") << bounds[i];
    if (failures.str().empty())
      out << "yes (c within one slave h, L2 error <= " << list.str() << ")" << std::endl;
    else
      out << "no (" << failures.str().substr(2) << ")" << std::endl;
    return out.str();
  }
} // namespace contact_fem
