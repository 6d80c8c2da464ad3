#include <deal.II/base/exceptions.h>

#include <contact_fem/material/material.h>
#include <contact_fem/core/parameters.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace contact_fem
{
  namespace
  {
    std::string
    format(const double x)
    {
      std::ostringstream s;
      s << x;
      return s.str();
    }

    /// Refuses a Poisson's ratio whose lambda / mu exceeds
    /// max_lambda_over_mu(): see there.
    void
    check_bulk_to_shear_ratio(const double nu, const unsigned int entry, const std::string &text)
    {
      const double       ratio = lambda_over_mu(nu);
      std::ostringstream message;
      message << "Materials/Poisson's ratios: entry " << entry + 1 << " is " << text
              << ": lambda/mu = 2 nu / (1 - 2 nu) = " << std::setprecision(2) << ratio
              << " exceeds " << max_lambda_over_mu()
              << " = 1 / (10 eps): where the stiffness matrix adds lambda and mu, double "
                 "precision keeps no digit of the shear stiffness (the factorisation "
                 "finds hundreds of zero pivots). Nearly incompressible bodies keep "
                 "their balance to about 1e-14 lambda/mu (nu = 0.49999999 with B-bar: "
                 "lambda/mu = 5e7, imbalance 2e-7).";
      AssertThrow(!(ratio > max_lambda_over_mu()), ExcMessage(message.str()));
    }
  } // namespace

  double
  lambda_over_mu(const double nu)
  {
    // 1 - 2 nu is exact near nu = 0.5 (Sterbenz), so the ratio is accurate.
    return 2. * nu / (1. - 2. * nu);
  }

  double
  shear_over_bulk(const double nu)
  {
    return 3. * (1. - 2. * nu) / (2. * (1. + nu));
  }

  double
  ElasticConstants::lambda() const
  {
    return youngs_modulus * poisson_ratio / ((1. + poisson_ratio) * (1. - 2. * poisson_ratio));
  }

  double
  ElasticConstants::mu() const
  {
    return youngs_modulus / (2. * (1. + poisson_ratio));
  }

  template <int dim>
  void
  Materials<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    prm.declare_entry(
      "Material ids", "", Patterns::Anything(),
      "Material ids of the bodies (cell material ids of the mesh, "
      "or their Gmsh physical names), one entry per body. The lists below give the constants in "
      "the same order." +
        not_set_help(true),
      true);
    prm.declare_entry("Young's moduli", "", Patterns::List(Patterns::Double()),
                      "Young's modulus of each body, a positive normal double "
                      "(2.2e-308 to 1.8e308). Units: stress." +
                        not_set_help(true),
                      true);
    prm.declare_entry("Poisson's ratios", "", Patterns::List(Patterns::Double()),
                      "Poisson's ratio of each body, in (-1, 0.5). 2D bodies are "
                      "in plane strain. Ratios whose lambda/mu = 2 nu / (1 - 2 "
                      "nu) exceeds 4.5e14 (nu > 0.499999999999999) are refused: "
                      "double precision then keeps no digit of the shear "
                      "stiffness; beyond 1e8 (nu > 0.499999995) the set-up "
                      "warns, since the reactions balance the load only to "
                      "about 1e-14 lambda/mu. Near -1 the bulk modulus vanishes "
                      "next to the shear modulus: 1 + nu below 1e-14 is refused, "
                      "below 1.5e-8 (mu/K > 1e8) the set-up warns." +
                        not_set_help(true),
                      true);
    prm.declare_entry("Models", "", Patterns::Anything(),
                      "The elastic law of each body, in the order of Material ids: "
                      "'linear' (small strain, sigma = C : eps), 'neo-hookean' "
                      "(compressible, W = mu/2 (tr C - 3) - mu ln J + lambda/2 "
                      "(ln J)^2) or 'saint-venant-kirchhoff' (W = lambda/2 "
                      "(tr E)^2 + mu E : E), the finite-strain laws solved "
                      "total-Lagrangian with the Lame constants of the body's "
                      "Young's modulus and Poisson's ratio (their small-strain "
                      "limit is the linear law). The contact operators follow "
                      "Contact/Kinematics (the reference configuration by "
                      "default). Empty: every body linear.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  Materials<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    std::vector<int> ids;
    for (const std::string &entry : Utilities::split_string_list(prm.get("Material ids")))
      {
        std::size_t end = 0;
        int         id  = -1;
        try
          {
            id = std::stoi(entry, &end);
          }
        catch (...)
          {}
        AssertThrow(end == entry.size() && id >= 0 && id <= 255,
                    ExcMessage("Materials/Material ids: '" + entry +
                               "' is not a material id "
                               "(an integer from 0 to 255) nor a physical name of the bodies "
                               "of a mesh file."));
        ids.push_back(id);
      }
    const std::string E_text = prm.get("Young's moduli"), nu_text = prm.get("Poisson's ratios");
    const auto        model_names = Utilities::split_string_list(prm.get("Models"));
    prm.leave_subsection();
    AssertThrow(!ids.empty(),
                ExcMessage("Materials/Material ids: empty; expected the material id of "
                           "every body (and its constants in Young's moduli and "
                           "Poisson's ratios)."));
    const auto E = parse_number_list(E_text, "Materials/Young's moduli",
                                     "a positive normal double (2.2e-308 to 1.8e308)");
    const auto nu =
      parse_number_list(nu_text, "Materials/Poisson's ratios", "a value in (-1, 0.5)");
    const auto nu_entries = Utilities::split_string_list(nu_text, ',');

    AssertThrow(E.size() == ids.size() && nu.size() == ids.size(),
                ExcMessage("Materials: 'Material ids', 'Young's moduli' and "
                           "'Poisson's ratios' must have the same number of "
                           "entries (got " +
                           std::to_string(ids.size()) + ", " + std::to_string(E.size()) + ", " +
                           std::to_string(nu.size()) + ")."));
    AssertThrow(model_names.empty() || model_names.size() == ids.size(),
                ExcMessage("Materials/Models: lists " + std::to_string(model_names.size()) +
                           " model(s) for " + std::to_string(ids.size()) +
                           " material ids; expected one model per body (or none: "
                           "every body linear)."));
    bodies.clear();
    for (unsigned int i = 0; i < ids.size(); ++i)
      {
        AssertThrow(std::isfinite(E[i]) && E[i] > 0.,
                    ExcMessage("Materials/Young's moduli: entry " + std::to_string(i + 1) + " is " +
                               format(E[i]) + "; expected a finite value > 0."));
        AssertThrow(nu[i] > -1. && nu[i] < 0.5,
                    ExcMessage("Materials/Poisson's ratios: entry " + std::to_string(i + 1) +
                               " is " + format(nu[i]) + "; expected a value in (-1, 0.5)."));
        check_bulk_to_shear_ratio(nu[i], i, nu_entries[i]);
        AssertThrow(!(shear_over_bulk(nu[i]) > max_shear_over_bulk()),
                    ExcMessage("Materials/Poisson's ratios: entry " + std::to_string(i + 1) +
                               " is " + nu_entries[i] +
                               ": 1 + nu is within ten units of round-off of 0, so the "
                               "ratio of the shear to the bulk modulus, mu/K = 3 (1 - 2 "
                               "nu) / (2 (1 + nu)) = " +
                               format(shear_over_bulk(nu[i])) +
                               ", keeps at most one correct digit (as nu -> -1 the bulk "
                               "modulus vanishes next to the shear modulus); expected 1 + "
                               "nu of at least about 1e-14 (nu >= -0.99999999999999)."));
        AssertThrow(bodies.count(ids[i]) == 0,
                    ExcMessage("Materials/Material ids: id " + std::to_string(ids[i]) +
                               " is listed twice."));
        bodies[ids[i]] =
          ElasticConstants{E[i], nu[i],
                           model_names.empty() ? ElasticModel::linear :
                                                 parse_elastic_model(model_names[i], i)};
      }
  }

  template <int dim>
  const ElasticConstants &
  Materials<dim>::constants(const types::material_id id) const
  {
    const auto it = bodies.find(id);
    AssertThrow(it != bodies.end(),
                ExcMessage("Materials: the mesh has cells with material id " + std::to_string(id) +
                           ", which 'Materials/Material ids' does not list."));
    return it->second;
  }

  template <int dim>
  bool
  Materials<dim>::finite_strain() const
  {
    for (const auto &[id, constants] : bodies)
      if (constants.model != ElasticModel::linear)
        return true;
    return false;
  }

  template <int dim>
  std::pair<double, double>
  Materials<dim>::youngs_modulus_range() const
  {
    std::pair<double, double> range(std::numeric_limits<double>::max(), 0.);
    for (const auto &[id, constants] : bodies)
      {
        range.first  = std::min(range.first, constants.youngs_modulus);
        range.second = std::max(range.second, constants.youngs_modulus);
      }
    return range;
  }

  template <int dim>
  SymmetricTensor<4, dim>
  Materials<dim>::stiffness_tensor(const types::material_id id) const
  {
    const ElasticConstants &c      = constants(id);
    const double            lambda = c.lambda(), mu = c.mu();
    SymmetricTensor<4, dim> C;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = 0; l < dim; ++l)
            C[i][j][k][l] = ((i == k && j == l ? mu : 0.) + (i == l && j == k ? mu : 0.) +
                             (i == j && k == l ? lambda : 0.));
    return C;
  }

  template <int dim>
  SymmetricTensor<2, dim>
  Materials<dim>::stress(const types::material_id id, const SymmetricTensor<2, dim> &strain) const
  {
    const ElasticConstants &c = constants(id);
    return c.lambda() * trace(strain) * unit_symmetric_tensor<dim>() + 2. * c.mu() * strain;
  }

  template <int dim>
  SymmetricTensor<2, dim>
  Materials<dim>::stress(const types::material_id       id,
                         const SymmetricTensor<2, dim> &strain,
                         const double                   volumetric_strain) const
  {
    const ElasticConstants &c = constants(id);
    return c.lambda() * volumetric_strain * unit_symmetric_tensor<dim>() + 2. * c.mu() * strain;
  }

  template <int dim>
  SymmetricTensor<2, dim>
  Materials<dim>::compliance(const types::material_id       id,
                             const SymmetricTensor<2, dim> &sigma) const
  {
    // Inverse of the (plane strain) law: eps = (sigma - lambda/(2 mu + dim
    // lambda) tr(sigma) I) / (2 mu).
    const ElasticConstants &c      = constants(id);
    const double            lambda = c.lambda(), mu = c.mu();
    return (sigma -
            lambda / (2. * mu + dim * lambda) * trace(sigma) * unit_symmetric_tensor<dim>()) /
           (2. * mu);
  }

  template <int dim>
  SymmetricTensor<2, 3>
  Materials<dim>::finite_strain_stress(const types::material_id id,
                                       const Tensor<2, dim>    &grad_u) const
  {
    const ElasticConstants &c   = constants(id);
    const auto              law = HyperelasticLaw<3>::create(c.model, c);
    AssertThrow(law, ExcMessage("Materials: body " + std::to_string(id) + " is linear."));
    Tensor<2, 3> H;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        H[i][j] = grad_u[i][j];
    return law->cauchy_stress(H);
  }

  template <int dim>
  double
  Materials<dim>::von_mises(const types::material_id id, const SymmetricTensor<2, dim> &sigma) const
  {
    if (dim == 3)
      return std::sqrt(1.5) * deviator(sigma).norm();
    // Plane strain: sigma_zz = nu (sigma_xx + sigma_yy).
    const double nu  = constants(id).poisson_ratio;
    const double sxx = sigma[0][0], syy = sigma[1][1], sxy = sigma[0][1];
    const double szz = nu * (sxx + syy);
    return std::sqrt(
      0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx)) +
      3. * sxy * sxy);
  }

  template class Materials<2>;
  template class Materials<3>;
} // namespace contact_fem
