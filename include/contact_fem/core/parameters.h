// The run parameters of a scene that are not owned by a component class:
// boundary conditions, load stepping, contact, Newton and output settings.
#ifndef contact_fem_parameters_h
#define contact_fem_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <limits>
#include <string>
#include <utility>
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
  };

  /// A boundary id loaded by a normal pressure (positive pushes into the body).
  struct PressureCondition
  {
    types::boundary_id boundary_id;
    std::string        expression; ///< function of x, y, (z,) t
  };

  /// A mesh vertex of one body, written 'material id @ x, y(, z)'.
  struct BodyPoint
  {
    types::material_id  material_id = 0;
    std::vector<double> coordinates;
  };

  /// Parses 'material id @ x, y(, z)'; throws naming @p key otherwise.
  BodyPoint
  parse_body_point(const std::string &text, const unsigned int dim, const std::string &key);

  /// The text 'material id @ x, y(, z)' of @p point (for messages and output).
  std::string
  to_string(const BodyPoint &point);

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

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm, const unsigned int dim);
  };

  struct LoadStepping
  {
    double       end_time = 1.;
    unsigned int n_steps  = 1;
    unsigned int max_splits   = 4;  ///< times a failing step may be split
    unsigned int split_factor = 2;  ///< sub-steps a failing step is split into

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /// One contact pair: the slave and master surfaces by boundary id.
  struct ContactPair
  {
    types::boundary_id slave;
    types::boundary_id master;
  };

  struct ContactParameters
  {
    std::vector<ContactPair> pairs; ///< empty: no contact code runs
    double search_factor       = 3.;
    /// Mortar operators rebuilt at every load step (else once, on the
    /// reference configuration).
    bool   updated_kinematics    = false;
    /// Unexplained penetration allowed after convergence, over the element size.
    double penetration_tolerance = 0.05;
    bool   allow_loss_of_contact = false;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  struct NewtonParameters
  {
    unsigned int max_iterations                  = 20;
    double       displacement_relative_tolerance = 1e-4;
    double       displacement_absolute_tolerance = 1e-9;
    double       multiplier_relative_tolerance   = 1e-4;
    double       multiplier_absolute_tolerance   = 1e-9;
    double       damping                         = 1.; ///< step length of every update

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  struct AnalyticalSolution
  {
    std::string type   = "none"; ///< "none" or "hertz cylinder"
    double      radius = 8.;
    double      center = 0.; ///< x of the first point of contact
    /// Total potential energy of the exact solution, if known (NaN if not):
    /// gives the energy-norm error and the effectivity of the estimate.
    double reference_potential_energy = std::numeric_limits<double>::quiet_NaN();
    /// (x, pressure) of a reference contact pressure, sorted by x; empty if
    /// none was given.
    std::vector<std::pair<double, double>> reference_pressure_profile;

    /// The reference pressure at @p x: linear between the rows, zero
    /// outside their range.
    double
    reference_pressure(const double x) const;

    static void
    declare_parameters(ParameterHandler &prm);
    /// Relative file names are taken relative to @p prm_directory.
    void
    parse_parameters(ParameterHandler &prm, const std::string &prm_directory);
  };

  struct OutputParameters
  {
    std::string directory = "results";
    bool        write_vtu              = true;
    bool        write_pressure_profile = true;
    bool        print_timing           = true;
    /// Vertices whose displacement every cycle reports.
    std::vector<BodyPoint> displacement_probes;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm, const unsigned int dim);
  };

  /// Why @p text is not a usable double, or an empty string if it is one
  /// (then stored in @p value): not a number, not finite, or outside the
  /// normal range of double precision. strtod() turns '1e-320' into a
  /// subnormal that keeps only a few digits, and deal.II's conversion then
  /// fails with a message that names neither key nor entry.
  std::string
  number_problem(const std::string &text, double &value);

  /// The comma-separated numbers of @p text; throws naming @p key, the
  /// entry and what was expected (@p expected, e.g. "a positive normal
  /// double") if one is not a usable double (number_problem()).
  std::vector<double>
  parse_number_list(const std::string &text, const std::string &key, const std::string &expected);

  /// Parses "a: b; c: d" style lists; throws naming @p key on malformed input.
  std::vector<std::pair<std::string, std::string>>
  split_key_value_list(const std::string &text, const std::string &key);

  /// Parses a boundary id; throws naming @p key if it is not in 0..254.
  types::boundary_id
  parse_boundary_id(const std::string &text, const std::string &key);
} // namespace contact_fem

#endif
