// What a scene prescribes beyond geometry, materials and contact: boundary
// conditions, the analytical solution to compare with, and the output.
#ifndef contact_fem_scene_parameters_h
#define contact_fem_scene_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <contact_fem/core/parameters.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  /// A boundary id whose displacement components are prescribed.
  struct DisplacementCondition
  {
    types::boundary_id boundary_id;
    unsigned int       component;
    std::string        expression; ///< function of x, y, (z,) t; "0" for fixed
    std::string        key;        ///< the parameter that set it, for messages

    /// Whether the expression names a coordinate (x, y or z): the value then
    /// may differ along the boundary, which then moves as more than a
    /// rigid translation of its component.
    bool
    varies_in_space() const;
  };

  /// A boundary id loaded by a normal pressure (positive pushes into the body).
  struct PressureCondition
  {
    types::boundary_id boundary_id;
    std::string        expression; ///< function of x, y, (z,) t
  };

  /// A boundary id loaded by a traction vector (force per area, global
  /// components), e.g. a tangential load.
  struct TractionCondition
  {
    types::boundary_id       boundary_id;
    std::vector<std::string> expressions; ///< one per component, of x, y, (z,) t
  };

  /// A displacement component held at zero at one vertex of one body, to
  /// remove a rigid-body mode that the boundary conditions leave free.
  struct PointCondition
  {
    BodyPoint    point;
    unsigned int component;
  };

  struct BoundaryConditions
  {
    std::vector<DisplacementCondition> displacements;
    std::vector<PointCondition>        points;
    std::vector<PressureCondition>     pressures;
    std::vector<TractionCondition>     tractions;
    /// Boundaries whose normal displacement is zero (flat, any orientation).
    std::vector<types::boundary_id> rollers;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm, const unsigned int dim);
  };

  /**
   * Gives the keys of builtin_scene_settings() that the input does not set
   * the values of the built-in scene of Geometry/Type @p type; for a mesh
   * file, which gets no load, support, pair or material it does not ask
   * for, refuses a missing Contact/Pairs or Materials key, naming it.
   * Returns the lines that the run prints at its start: the effective
   * materials, boundary conditions and contact pairs, and which of them
   * came from the built-in scene.
   */
  std::string
  apply_scene_settings(ParameterHandler &prm, const std::string &type);

  struct AnalyticalSolution
  {
    /// "none", "hertz cylinder", "hertz sphere" (3D) or "cattaneo"
    std::string type   = "none";
    double      radius = 8.;
    double      center = 0.; ///< x of the first point of contact
    /// 3D: y of the first point of contact; the Hertz sphere's axis is
    /// parallel to z through (center, center_y).
    double center_y = 0.;
    /// The part of the whole sphere the model holds (0.25 for a quarter
    /// with two symmetry planes): the Hertz load is the model's contact
    /// force over it.
    double symmetry_fraction = 1.;
    /// Coulomb coefficient of the Cattaneo-Mindlin solution (type
    /// "cattaneo"): that of Contact/Friction (NaN otherwise); with tresca
    /// the bound g of a Tresca law.
    double friction_coefficient = std::numeric_limits<double>::quiet_NaN();
    bool   tresca               = false;
    /// Total potential energy of the exact solution, if known (NaN if not):
    /// gives the energy-norm error and the effectivity of the estimate.
    double reference_potential_energy = std::numeric_limits<double>::quiet_NaN();
    /// (x, pressure) of a reference contact pressure, sorted by x; empty if
    /// none was given. In 3D (hertz sphere) x is the distance from the
    /// axis: the reference is taken as axisymmetric.
    std::vector<std::pair<double, double>> reference_pressure_profile;
    /// Type = cattaneo, 3D: bounds of the tangential L2 error at the
    /// compared load steps (one per step, or one for all; empty: no check).
    std::vector<double> tangential_error_bounds;

    /// 3D: the distance of (x, y) from the axis of the Hertz sphere, which
    /// its pressure and the (axisymmetric) reference profile are functions of.
    double
    axis_distance(const double x, const double y) const
    {
      return std::hypot(x - center, y - center_y);
    }

    /// Takes the centre and the 2D reference profile (functions of x) into
    /// the computing frame whose origin lies at (@p x0, @p y0) of the
    /// user's coordinates (ModelFrame); the 3D profile is a function of the
    /// distance from the axis, which does not move.
    void
    move_origin(const double x0, const double y0, const unsigned int dim)
    {
      center -= x0;
      center_y -= y0;
      if (dim == 2)
        for (auto &row : reference_pressure_profile)
          row.first -= x0;
    }

    /// The reference pressure at @p x: linear between the rows, zero
    /// outside their range.
    double
    reference_pressure(const double x) const;

    static void
    declare_parameters(ParameterHandler &prm);
    /// Relative file names are taken relative to @p prm_directory; the
    /// solutions that do not exist in @p dim dimensions are refused.
    void
    parse_parameters(ParameterHandler  &prm,
                     const std::string &prm_directory,
                     const unsigned int dim);
  };

  struct OutputParameters
  {
    std::string directory               = "results";
    bool        print_timing            = true;
    bool        print_newton_iterations = true;
    /// Vertices whose displacement every cycle reports.
    std::vector<BodyPoint> displacement_probes;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm, const unsigned int dim);
  };

  /// The range of small-strain linear elasticity with a contact gap linear
  /// in the displacement. A converged state beyond it (the largest
  /// principal strain, infinitesimal rotation or displacement over the
  /// model size above these limits) is no answer of the bodies: the run
  /// ends with the status "converged outside the model's range" and exit
  /// code 3, unless the input accepts it.
  struct ModelRange
  {
    static constexpr double strain_limit       = 0.05;
    static constexpr double rotation_limit     = 0.1; ///< rad
    static constexpr double displacement_limit = 0.5; ///< of the model size
    bool                    accept_outside     = false;
    /// Skip the interpenetration check (Accept interpenetration).
    bool accept_interpenetration = false;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };
} // namespace contact_fem

#endif
