#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <contact_fem/contact/friction/frictional_law.h>
#include <contact_fem/geometry/scene.h>
#include <contact_fem/simulator/scene_parameters.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>

namespace contact_fem
{
  namespace
  {
    /// Component indices of letters like "xy" (spaces ignored); @p what
    /// names the entry in the message.
    std::vector<unsigned int>
    parse_components(const std::string &letters,
                     const std::string &axes,
                     const std::string &key,
                     const std::string &what)
    {
      std::vector<unsigned int> result;
      for (const char c : letters)
        {
          if (c == ' ')
            continue;
          const auto d = axes.find(c);
          AssertThrow(d != std::string::npos,
                      ExcMessage(key + ": '" + std::string(1, c) +
                                 "' is not a component; expected letters from '" + axes + "'."));
          result.push_back(static_cast<unsigned int>(d));
        }
      AssertThrow(!result.empty(), ExcMessage(key + ": " + what + " lists no components."));
      return result;
    }

    /// @p text split at the commas outside parentheses (muparser's
    /// min(t, 1) stays one piece), trimmed; throws naming @p key on
    /// unbalanced parentheses.
    std::vector<std::string>
    split_top_level_commas(const std::string &text, const std::string &key)
    {
      std::vector<std::string> pieces(1);
      int                      depth = 0;
      for (const char c : text)
        {
          depth += c == '(' ? 1 : c == ')' ? -1 : 0;
          AssertThrow(depth >= 0, ExcMessage(key + ": '" + text + "' has a ')' without its '('."));
          if (c == ',' && depth == 0)
            pieces.emplace_back();
          else
            pieces.back() += c;
        }
      AssertThrow(depth == 0, ExcMessage(key + ": '" + text + "' has a '(' without its ')'."));
      for (auto &piece : pieces)
        piece = Utilities::trim(piece);
      return pieces;
    }
  } // namespace

  bool
  DisplacementCondition::varies_in_space() const
  {
    // The identifiers of the expression, against the coordinate names
    // (muparser's names are letters, digits and '_', from a letter or '_').
    std::string name;
    for (const char c : expression + ' ')
      if (std::isalnum(static_cast<unsigned char>(c)) || c == '_')
        name += c;
      else
        {
          if (name == "x" || name == "y" || name == "z")
            return true;
          name.clear();
        }
    return false;
  }

  void
  BoundaryConditions::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    prm.declare_entry("Fixed", "", Patterns::Anything(),
                      "Boundaries whose displacement components are zero, as "
                      "'id: components; ...' with components from x, y, z, e.g. "
                      "'2: xy; 1: x'." +
                        not_set_help(false),
                      true);
    prm.declare_entry("Fixed points", "", Patterns::Anything(),
                      "Mesh vertices whose displacement components are zero, as "
                      "'material id @ x, y: components; ...', e.g. '1 @ 0, 1: x' "
                      "(the vertex of body 1 at (0, 1)). For rigid-body modes that "
                      "the boundary conditions leave free; the vertex must exist.");
    prm.declare_entry("Rollers", "", Patterns::Anything(),
                      "Flat boundaries of any orientation whose displacement normal to "
                      "the boundary is zero (a roller or sliding support on a tilted "
                      "plane, a symmetry plane of a turned model), as 'id; id; ...'. "
                      "Curved or kinked boundaries and boundaries that touch a contact "
                      "surface are refused.");
    prm.declare_entry("Prescribed displacement", "", Patterns::Anything(),
                      "Boundaries with a prescribed displacement component, as "
                      "'id: component = expression; ...' with an expression of x, "
                      "y, (z,) t, e.g. '1: y = -0.01*t'.");
    prm.declare_entry("Pressure", "", Patterns::Anything(),
                      "Boundaries loaded by a normal pressure (positive pushes "
                      "into the body), as 'id: expression; ...' with an "
                      "expression of x, y, (z,) t. Units: stress." +
                        not_set_help(false),
                      true);
    prm.declare_entry("Traction", "", Patterns::Anything(),
                      "Boundaries loaded by a traction vector (force per area, in "
                      "global components, e.g. a tangential load), as 'id: fx, fy; "
                      "...' ('id: fx, fy, fz' in 3D) with expressions of x, y, (z,) "
                      "t, e.g. '1: 0.05*max(t-1, 0), 0'. Adds to a Pressure on the "
                      "same boundary. Units: stress.");
    prm.leave_subsection();
  }

  void
  BoundaryConditions::parse_parameters(ParameterHandler &prm, const unsigned int dim)
  {
    const std::string axes = dim == 2 ? "xy" : "xyz";
    prm.enter_subsection("Boundary conditions");
    displacements.clear();
    pressures.clear();
    const std::string fixed_key = "Boundary conditions/Fixed";
    for (const auto &[id, components] : split_key_value_list(prm.get("Fixed"), fixed_key))
      {
        const types::boundary_id b = parse_boundary_id(id, fixed_key);
        for (const unsigned int d : parse_components(components, axes, fixed_key, "boundary " + id))
          displacements.push_back({b, d, "0", fixed_key});
      }
    const std::string points_key = "Boundary conditions/Fixed points";
    points.clear();
    for (const auto &[location, components] :
         split_key_value_list(prm.get("Fixed points"), points_key))
      {
        PointCondition condition;
        condition.point = parse_body_point(location, dim, points_key);
        for (const unsigned int d :
             parse_components(components, axes, points_key, "point '" + location + "'"))
          {
            condition.component = d;
            points.push_back(condition);
          }
      }
    const std::string rollers_key = "Boundary conditions/Rollers";
    rollers.clear();
    for (const auto &entry : Utilities::split_string_list(prm.get("Rollers"), ';'))
      {
        AssertThrow(entry.find(':') == std::string::npos,
                    ExcMessage(rollers_key + ": entry '" + excerpt(entry) +
                               "' names components; a roller takes boundary ids only "
                               "('id; id; ...'): the held direction is the boundary's "
                               "normal."));
        const types::boundary_id b = parse_boundary_id(entry, rollers_key);
        AssertThrow(std::find(rollers.begin(), rollers.end(), b) == rollers.end(),
                    ExcMessage(rollers_key + ": boundary " + entry + " is given twice."));
        rollers.push_back(b);
      }
    const std::string disp_key = "Boundary conditions/Prescribed displacement";
    for (const auto &[id, rhs] : split_key_value_list(prm.get("Prescribed displacement"), disp_key))
      {
        const types::boundary_id b   = parse_boundary_id(id, disp_key);
        const auto               eq  = rhs.find('=');
        const std::string        cmp = Utilities::trim(rhs.substr(0, eq));
        AssertThrow(eq != std::string::npos && cmp.size() == 1 &&
                      axes.find(cmp[0]) != std::string::npos,
                    ExcMessage(disp_key + ": entry '" + id + ": " + rhs +
                               "' is not of the form 'id: component = expression' "
                               "with a component from '" +
                               axes + "'."));
        const std::string expression = Utilities::trim(rhs.substr(eq + 1));
        check_expression(expression, dim, disp_key);
        displacements.push_back(
          {b, static_cast<unsigned int>(axes.find(cmp[0])), expression, disp_key});
      }
    const std::string pressure_key = "Boundary conditions/Pressure";
    for (const auto &[id, expression] : split_key_value_list(prm.get("Pressure"), pressure_key))
      {
        check_expression(expression, dim, pressure_key);
        const types::boundary_id b = parse_boundary_id(id, pressure_key);
        for (const auto &other : pressures)
          AssertThrow(other.boundary_id != b,
                      ExcMessage(pressure_key + ": boundary " + id + " is given twice."));
        pressures.push_back({b, expression});
      }
    const std::string traction_key = "Boundary conditions/Traction";
    tractions.clear();
    for (const auto &[id, components] : split_key_value_list(prm.get("Traction"), traction_key))
      {
        const types::boundary_id       b = parse_boundary_id(id, traction_key);
        const std::vector<std::string> expressions =
          split_top_level_commas(components, traction_key);
        AssertThrow(expressions.size() == dim &&
                      std::none_of(expressions.begin(), expressions.end(),
                                   [](const std::string &e) {
                                     return e.empty();
                                   }),
                    ExcMessage(traction_key + ": entry '" + id + ": " + components +
                               "' is not of the form 'id: " +
                               (dim == 2 ? std::string("fx, fy") : std::string("fx, fy, fz")) +
                               "' (" + std::to_string(dim) + " comma-separated expressions of " +
                               (dim == 2 ? "x, y, t" : "x, y, z, t") + ")."));
        for (const auto &expression : expressions)
          check_expression(expression, dim, traction_key);
        for (const auto &other : tractions)
          AssertThrow(other.boundary_id != b,
                      ExcMessage(traction_key + ": boundary " + id + " is given twice."));
        tractions.push_back({b, expressions});
      }
    prm.leave_subsection();

    for (unsigned int i = 0; i < displacements.size(); ++i)
      for (unsigned int j = 0; j < i; ++j)
        AssertThrow(displacements[i].boundary_id != displacements[j].boundary_id ||
                      displacements[i].component != displacements[j].component,
                    ExcMessage("Boundary conditions: component " +
                               std::string(1, axes[displacements[i].component]) + " of boundary " +
                               std::to_string(displacements[i].boundary_id) +
                               " is prescribed twice."));
  }

  namespace
  {
    /// The lines of apply_scene_settings() that tell the bodies, the
    /// boundary conditions and the pairs as the run takes them.
    std::string
    effective_input(ParameterHandler &prm)
    {
      prm.enter_subsection("Materials");
      std::string text = "Bodies (Materials): ids " + prm.get("Material ids") +
                         "; Young's moduli " + prm.get("Young's moduli") + "; Poisson's ratios " +
                         prm.get("Poisson's ratios");
      // Only when set: the outputs of linear scenes stay as they were.
      if (const std::string models = Utilities::trim(prm.get("Models")); !models.empty())
        text += "; Models " + models;
      text += "\n";
      prm.leave_subsection();
      std::string conditions;
      prm.enter_subsection("Boundary conditions");
      for (const char *key :
           {"Fixed", "Fixed points", "Rollers", "Prescribed displacement", "Pressure", "Traction"})
        if (const std::string value = Utilities::trim(prm.get(key)); !value.empty())
          conditions += (conditions.empty() ? "" : " | ") + std::string(key) + " = " + value;
      prm.leave_subsection();
      text += "Supports and loads (Boundary conditions): " +
              (conditions.empty() ? std::string("none") : conditions) + "\n";
      prm.enter_subsection("Contact");
      const std::string pairs   = Utilities::trim(prm.get("Pairs"));
      const std::string tied    = Utilities::trim(prm.get("Tied pairs"));
      const std::string release = prm.get_bool("Tied release in tension") ?
                                    "; released in tension beyond " +
                                      prm.get("Tied release threshold") +
                                      " of the pair's largest traction" :
                                    "";
      prm.leave_subsection();
      return text + "Contact pairs (slave: master): " +
             (pairs.empty() ? std::string("none (no contact)") : pairs) + "\n" +
             (tied.empty() ? std::string() :
                             "Tied pairs (slave: master): " + tied + release + "\n");
    }
  } // namespace

  std::string
  apply_scene_settings(ParameterHandler &prm, const std::string &type)
  {
    std::string from_scene;
    for (const auto &[path, required] : builtin_scene_keys())
      AssertThrow(is_set(prm, path) || !required || type != "mesh file",
                  ExcMessage(path +
                             ": not set. A scene read from a mesh file (Geometry/"
                             "Type = mesh file) gets no contact pair or material it does "
                             "not ask for: give " +
                             (path == "Contact/Pairs" ?
                                std::string("the pairs as 'slave id: master id; ...' (set "
                                            "it empty for a scene without contact).") :
                                std::string("Material ids, Young's moduli and Poisson's "
                                            "ratios of every body."))));
    for (const auto &setting : builtin_scene_settings(type))
      if (!is_set(prm, setting.path))
        {
          const auto slash = setting.path.find('/');
          prm.enter_subsection(setting.path.substr(0, slash));
          prm.set(setting.path.substr(slash + 1), setting.value);
          prm.leave_subsection();
          from_scene += (from_scene.empty() ? "" : ", ") + setting.path;
        }
    return effective_input(prm) +
           (from_scene.empty() ?
              std::string() :
              "  (not set in the input, the built-in scene's values: " + from_scene + ")\n");
  }

  void
  AnalyticalSolution::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Analytical solution");
    prm.declare_entry("Type", "none",
                      Patterns::Selection("none|hertz cylinder|hertz sphere|cattaneo"),
                      "Reference solution to compare with: 'hertz cylinder' = 2D "
                      "plane-strain Hertz contact of a cylinder of radius R on a "
                      "plane, with the load per unit thickness taken from the "
                      "transmitted contact force (so displacement-driven scenes "
                      "compare too) and E* from the materials of the contact "
                      "pair. 'cattaneo' = the same Hertz contact, then a "
                      "tangential load Q < mu P at constant P (Cattaneo-Mindlin, "
                      "plane strain, equal materials): stick zone |x| < c, c/a = "
                      "sqrt(1 - Q/(mu P)), with P and Q the transmitted normal "
                      "and tangential contact forces and mu the Coulomb "
                      "coefficient of Contact/Friction (which must then be one "
                      "'coulomb MU' law, or give the first pair such a law; "
                      "under a 'tresca G' law instead (2D only), c/a = sqrt(1 - "
                      "(Q/(2 a G))^2) and the slip zones carry G); "
                      "compares the stick zone and the tangential traction. In "
                      "3D (Mindlin): a sphere on a flat loaded along x, axis and "
                      "Symmetry fraction as for 'hertz sphere', c/a = (1 - Q/(mu "
                      "P))^(1/3), compared at every load step. "
                      "'hertz sphere' = 3D Hertz contact of a sphere of radius R "
                      "on a half-space, axis parallel to z through (Center, "
                      "Center y): a = (3 F R / (4 E*))^(1/3), p0 = 3 F / (2 pi "
                      "a^2), p(r) = p0 sqrt(1 - r^2 / a^2), with F the z "
                      "component of the transmitted contact force over "
                      "Symmetry fraction and E* from the materials of the "
                      "contact pair; compares p_max, the contact radius (the "
                      "farthest active slave node from the axis) and the "
                      "pressure profile.");
    prm.declare_entry("Radius", "8", Patterns::Double(0.), "Cylinder (sphere) radius R.");
    prm.declare_entry("Center", "0", Patterns::Double(),
                      "x coordinate of the centre of the contact zone.");
    prm.declare_entry("Center y", "0", Patterns::Double(),
                      "Type = hertz sphere, cattaneo (3D): y coordinate of the centre of the "
                      "contact zone (the axis is parallel to z).");
    prm.declare_entry("Symmetry fraction", "1", Patterns::Double(0., 1.),
                      "Type = hertz sphere, cattaneo (3D): the part of the whole sphere and "
                      "plate that the model holds, e.g. 0.25 for a quarter cut "
                      "by two symmetry planes through the axis. The Hertz load F "
                      "of the whole sphere is the model's contact force over "
                      "this fraction. Other types: 1.");
    prm.declare_entry("Reference potential energy", "", Patterns::Anything(),
                      "Total potential energy 1/2 u.K u - f.u of the exact solution, "
                      "if known (e.g. from an overkill or extrapolated run: "
                      "summary.json, cycles[].potential_energy); empty if not. "
                      "Then every cycle reports the energy-norm error "
                      "sqrt(2 |Pi_h - Pi_ref|) and the effectivity index eta / "
                      "error of the estimate. Without contact this is the "
                      "energy-norm error; with contact it exceeds it by the work "
                      "of the exact pressure on the discrete gap. With degree 1 "
                      "and Type = hertz cylinder the chords of the polygonal arc "
                      "lie inside the circle: the work W of the contact force on "
                      "that chord gap (summary.json: analytical.chord_gap_work) "
                      "is added to Pi_h, sqrt(2 |Pi_h + W - Pi_ref|), since it is "
                      "a geometry error the estimate does not measure. Pi_h < "
                      "Pi_ref (a discretisation softer than the exact problem, "
                      "or an inaccurate reference) is warned about.");
    prm.declare_entry("Reference pressure profile", "", Patterns::Anything(),
                      "CSV file with the columns 'x' and 'pressure' (any others "
                      "are ignored; in 3D, with Type = hertz sphere, 'x', 'y' and "
                      "'pressure', and the profile is taken as axisymmetric, a "
                      "function of the distance from the axis), e.g. the "
                      "pressure_profile.csv of an overkill "
                      "run; a relative name is taken relative to the .prm file; "
                      "empty if none. Then every cycle also measures the contact "
                      "pressure against it (interpolated linearly in x, zero "
                      "outside its range): the mortar pressure, and the normal "
                      "traction of the recovered stress of the SPR estimators "
                      "(summary.json: *_reference_l2_relative_error). Unlike the "
                      "Hertz half-space pressure, an overkill run of the same "
                      "finite bodies has no modelling error.");
    prm.declare_entry("Tangential error bounds", "", Patterns::Anything(),
                      "Type = cattaneo, 3D: upper bounds of the tangential "
                      "traction's L2 relative error at the load steps that are "
                      "compared (those with a tangential load), one per step "
                      "or one for all, e.g. '0.8, 0.35, 0.25, 0.2'; empty for "
                      "none. Then the run prints whether every step is within "
                      "its bound with its stick radius within one slave nodal "
                      "spacing of Mindlin's (a check for tests: a step out of "
                      "bounds prints 'no' and the step).");
    prm.leave_subsection();
  }

  namespace
  {
    /// The (x, pressure) rows of a CSV file with a header line naming the
    /// columns, sorted by x.
    /// In 3D (@p axis_distance given) the rows also need a column y, and x
    /// is replaced by the distance from the axis.
    std::vector<std::pair<double, double>>
    read_pressure_profile(const std::string                           &file_name,
                          const std::function<double(double, double)> &axis_distance)
    {
      const std::string key = "Analytical solution/Reference pressure profile: ";
      std::ifstream     in(file_name);
      AssertThrow(in, ExcMessage(key + "cannot open '" + file_name + "'."));
      std::string line;
      AssertThrow(static_cast<bool>(std::getline(in, line)),
                  ExcMessage(key + "'" + file_name +
                             "' is empty (expected a header line "
                             "naming the columns x and pressure)."));
      const std::vector<std::string> header = Utilities::split_string_list(line, ',');
      const auto                     column = [&](const std::string &name) {
        const auto found = std::find(header.begin(), header.end(), name);
        AssertThrow(found != header.end(),
                                        ExcMessage(key + "'" + file_name + "', line 1: no column '" + name +
                                                   "' (expected a header line naming the columns " +
                                                   (axis_distance ? "x, y and pressure" : "x and pressure") + ")."));
        return static_cast<std::size_t>(found - header.begin());
      };
      const std::size_t x_column = column("x"), p_column = column("pressure");
      const std::size_t y_column = axis_distance ? column("y") : x_column;

      std::vector<std::pair<double, double>> rows;
      for (unsigned int line_number = 2; std::getline(in, line); ++line_number)
        {
          if (Utilities::trim(line).empty())
            continue;
          const std::vector<std::string> fields = Utilities::split_string_list(line, ',');
          double                         values[3];
          const std::size_t              columns[3] = {x_column, p_column, y_column};
          for (unsigned int i = 0; i < 3; ++i)
            {
              const std::string field = columns[i] < fields.size() ? fields[columns[i]] : "";
              char             *end   = nullptr;
              values[i]               = std::strtod(field.c_str(), &end);
              AssertThrow(!field.empty() && *end == '\0' && std::isfinite(values[i]),
                          ExcMessage(key + "'" + file_name + "', line " +
                                     std::to_string(line_number) + ": column '" +
                                     header[columns[i]] + "' is '" + field +
                                     "', expected a number."));
            }
          rows.emplace_back(axis_distance ? axis_distance(values[0], values[2]) : values[0],
                            values[1]);
        }
      AssertThrow(rows.size() >= 2,
                  ExcMessage(key + "'" + file_name + "' has " + std::to_string(rows.size()) +
                             " data rows, expected at least 2."));
      std::sort(rows.begin(), rows.end());
      return rows;
    }
  } // namespace

  double
  AnalyticalSolution::reference_pressure(const double x) const
  {
    const auto &rows = reference_pressure_profile;
    if (rows.empty() || x < rows.front().first || x > rows.back().first)
      return 0.;
    const auto upper = std::lower_bound(rows.begin(), rows.end(), std::make_pair(x, -HUGE_VAL));
    if (upper == rows.begin())
      return upper->second;
    const auto   lower = upper - 1;
    const double width = upper->first - lower->first;
    if (width <= 0.)
      return upper->second;
    const double t = (x - lower->first) / width;
    return (1. - t) * lower->second + t * upper->second;
  }

  void
  AnalyticalSolution::parse_parameters(ParameterHandler  &prm,
                                       const std::string &prm_directory,
                                       const unsigned int dim)
  {
    prm.enter_subsection("Analytical solution");
    type                        = prm.get("Type");
    radius                      = prm.get_double("Radius");
    center                      = prm.get_double("Center");
    center_y                    = prm.get_double("Center y");
    symmetry_fraction           = prm.get_double("Symmetry fraction");
    const std::string reference = Utilities::trim(prm.get("Reference potential energy"));
    std::string       profile   = Utilities::trim(prm.get("Reference pressure profile"));
    const std::string bounds    = prm.get("Tangential error bounds");
    prm.leave_subsection();
    tangential_error_bounds.clear();
    for (const std::string &bound : Utilities::split_string_list(bounds, ','))
      {
        char        *end   = nullptr;
        const double value = std::strtod(bound.c_str(), &end);
        AssertThrow(end != bound.c_str() && *end == '\0' && std::isfinite(value) && value > 0.,
                    ExcMessage("Analytical solution/Tangential error bounds: '" + bound +
                               "' is not a positive number (expected a comma-separated "
                               "list of bounds, or empty)."));
        tangential_error_bounds.push_back(value);
      }
    AssertThrow(tangential_error_bounds.empty() || (dim == 3 && type == "cattaneo"),
                ExcMessage("Analytical solution/Tangential error bounds: only with Type = "
                           "cattaneo in 3D, whose load steps are compared (leave it empty)."));
    // The cylinder solutions are functions of x (2D), the sphere's of the
    // distance from its axis (3D).
    AssertThrow(dim == 3 || type != "hertz sphere",
                ExcMessage("Analytical solution/Type = hertz sphere: a 3D solution (set "
                           "Dimension = 3; in 2D, 'hertz cylinder')."));
    AssertThrow(dim == 2 || type == "none" || type == "hertz sphere" || type == "cattaneo",
                ExcMessage("Analytical solution/Type = " + type +
                           ": a 2D solution (of x); in 3D, use 'hertz sphere', 'cattaneo' "
                           "or 'none'."));
    AssertThrow(dim == 2 || profile.empty() || type == "hertz sphere",
                ExcMessage("Analytical solution/Reference pressure profile: in 3D only "
                           "with Type = hertz sphere (the profile is then taken as "
                           "axisymmetric about its axis); set Type = hertz sphere or "
                           "leave the profile empty."));
    std::ostringstream fraction_text;
    fraction_text << symmetry_fraction;
    AssertThrow(symmetry_fraction > 0. && (symmetry_fraction == 1. || type == "hertz sphere" ||
                                           (dim == 3 && type == "cattaneo")),
                ExcMessage("Analytical solution/Symmetry fraction: expected a value in "
                           "(0, 1], and 1 unless Type = hertz sphere or (3D) cattaneo (got " +
                           fraction_text.str() + ")."));
    reference_pressure_profile.clear();
    if (!profile.empty())
      {
        if (profile[0] != '/' && !prm_directory.empty())
          profile = prm_directory + "/" + profile;
        std::function<double(double, double)> distance;
        if (dim == 3)
          distance = [this](const double x, const double y) {
            return axis_distance(x, y);
          };
        reference_pressure_profile = read_pressure_profile(profile, distance);
      }
    reference_potential_energy = std::numeric_limits<double>::quiet_NaN();
    if (!reference.empty())
      {
        char *end                  = nullptr;
        reference_potential_energy = std::strtod(reference.c_str(), &end);
        AssertThrow(end != reference.c_str() && *end == '\0' &&
                      std::isfinite(reference_potential_energy),
                    ExcMessage("Analytical solution/Reference potential energy: '" + reference +
                               "' is not a number (leave it empty if unknown)."));
      }
    AssertThrow(radius > 0., ExcMessage("Analytical solution/Radius: expected > 0."));
    friction_coefficient = std::numeric_limits<double>::quiet_NaN();
    tresca               = false;
    if (type == "cattaneo")
      {
        // mu of the law the run uses: one source, no second key to keep
        // consistent with it. The comparison is of the first pair.
        const auto laws     = FrictionParameters::parse_laws(prm);
        const bool friction = !laws.empty() && laws.front()->parameter() > 0.;
        AssertThrow(friction,
                    ExcMessage("Analytical solution/Type = cattaneo: needs a Coulomb law "
                               "with mu > 0 or a Tresca law with g > 0 in Contact/Friction "
                               "(e.g. 'coulomb 0.2') for the first contact pair, " +
                               (laws.empty() ? std::string("found none (the key is empty)") :
                                               "found '" + laws.front()->description() + "'") +
                               "."));
        friction_coefficient = laws.front()->parameter();
        tresca               = laws.front()->kind() == FrictionalLaw::Kind::tresca;
        AssertThrow(!tresca || dim == 2,
                    ExcMessage("Analytical solution/Type = cattaneo: the closed form of a "
                               "Tresca law (Contact/Friction = '" +
                               laws.front()->description() +
                               "') is that of cylinders (2D); in 3D the comparison "
                               "needs a Coulomb law."));
      }
  }

  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Output directory", "results", Patterns::Anything(),
                      "Directory of every output file of the run (created if "
                      "needed): summary.json, log.txt, pressure profiles, VTU. "
                      "Before any work the run removes the files of an earlier "
                      "run from it (only the names contact_fem writes: "
                      "summary.json, log.txt, convergence.csv, "
                      "pressure_profile.csv, pressure_profile_cycle_*.csv, "
                      "tying_profile.csv, tying_profile_cycle_*.csv, "
                      "forces.csv, solution.pvd, "
                      "solution_cycle_*.pvd, solution_*.pvtu/vtu, "
                      "contact_surface.pvd, contact_surface_cycle_*.pvd, "
                      "contact_surface_*.vtu, tied_surface.pvd, "
                      "tied_surface_cycle_*.pvd, tied_surface_*.vtu, "
                      "error_indicators.pvd, "
                      "error_indicators_*.pvtu/vtu; doc/outputs.md) and "
                      "checks that it can write "
                      "there. Must not be named 'output' in tests.");
    prm.enter_subsection("Output");
    prm.declare_entry("Print timing", "true", Patterns::Bool(),
                      "Print wall times on the console (they are always in "
                      "summary.json). Tests switch this off.");
    prm.declare_entry("Print Newton iterations", "true", Patterns::Bool(),
                      "Print the table of the Newton iterations of every load "
                      "step (residuals, active-set changes). false: only the "
                      "events of a step (searches, splits, failures) and the "
                      "results, for tests whose iteration path is decided by "
                      "round-off (e.g. the first solve of a body held only by "
                      "contact, or a thousand nodes entering contact at once).");
    prm.declare_entry("Displacement probes", "", Patterns::Anything(),
                      "Mesh vertices whose displacement every cycle prints and "
                      "writes to summary.json (displacement_probes), as "
                      "'material id @ x, y; ...' (the vertex of that body at that "
                      "point, as for Fixed points); the vertex must exist.");
    prm.leave_subsection();
  }

  void
  OutputParameters::parse_parameters(ParameterHandler &prm, const unsigned int dim)
  {
    directory = prm.get("Output directory");
    AssertThrow(!Utilities::trim(directory).empty(),
                ExcMessage("Output directory: must not be empty."));
    prm.enter_subsection("Output");
    print_timing            = prm.get_bool("Print timing");
    print_newton_iterations = prm.get_bool("Print Newton iterations");
    displacement_probes.clear();
    const std::string probes_key = "Output/Displacement probes";
    for (const std::string &probe :
         Utilities::split_string_list(prm.get("Displacement probes"), ';'))
      if (!Utilities::trim(probe).empty())
        displacement_probes.push_back(parse_body_point(probe, dim, probes_key));
    prm.leave_subsection();
  }
  void
  ModelRange::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Model range");
    prm.declare_entry("Accept results outside the small-strain range", "false", Patterns::Bool(),
                      "The bodies are linear elastic with small strains and a "
                      "contact gap linear in the displacement. A converged state "
                      "whose largest principal strain exceeds 0.05, whose largest "
                      "rotation exceeds 0.1 rad or whose largest displacement "
                      "exceeds half the model size is not an answer of the real "
                      "bodies: with false the run ends after that cycle with the "
                      "status 'converged outside the model's range' in "
                      "summary.json and exit code 3 (the results are written); "
                      "true accepts such results (status 'converged', exit 0, "
                      "the warnings stay).");
    prm.declare_entry("Accept interpenetration", "false", Patterns::Bool(),
                      "With finite deformation (a finite-strain body or "
                      "Contact/Kinematics = current) every converged load step "
                      "is checked for boundary vertices inside a body where no "
                      "contact pair accounts for them (a body folding onto "
                      "itself, or passing through a body it is not paired "
                      "with): with false such a step is refused (exit 2). true "
                      "skips the check, for bodies that do not interact by "
                      "design (e.g. two specimens in one mesh whose deformed "
                      "shapes overlap).");
    prm.leave_subsection();
  }

  void
  ModelRange::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Model range");
    accept_outside = prm.get_bool("Accept results outside the small-strain range");
    accept_interpenetration = prm.get_bool("Accept interpenetration");
    prm.leave_subsection();
  }
} // namespace contact_fem
