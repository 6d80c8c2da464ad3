// Checks that the numbers of a scene fit double precision, done on the
// coarse mesh before any work: coordinates, moduli and loads whose products
// would overflow, and loads that are not numbers somewhere on the load path.
#include <contact_fem/geometry/model_frame.h>
#include <deal.II/grid/grid_tools.h>

#include <contact_fem/core/format.h>
#include <contact_fem/core/value_range.h>
#include <contact_fem/geometry/mesh_file.h>
#include <contact_fem/simulator/input_checks.h>

#include <cctype>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace contact_fem
{
  namespace
  {
    const std::string units_hint =
      "; the residual norms square forces and overflow double precision (1.8e308) from "
      "about 1.3e154: express lengths, moduli and loads in other units";
  } // namespace

  template <int dim>
  std::string
  InputChecks<dim>::geometry_key() const
  {
    if (scene.type == "mesh file")
      return "Geometry/Mesh file '" + scene.mesh_file + "'";
    // The lengths of "hertz cylinder" are in "Geometry/Hertz cylinder".
    std::string key = "Geometry/" + scene.type;
    key[9]          = static_cast<char>(std::toupper(key[9]));
    return key;
  }

  template <int dim>
  void
  InputChecks<dim>::create_scene_mesh(const Scene<dim>                          &coarse_scene,
                                      parallel::distributed::Triangulation<dim> &coarse) const
  {
    try
      {
        coarse_scene.create_mesh(coarse);
      }
    catch (const ExceptionBase &e)
      {
        // A library's own check (e.g. deal.II's "Matrix of normal equations
        // not positive definite" for lengths of 1e308): say what we were
        // doing and where the numbers came from. Our own messages name
        // their Geometry key and pass unchanged.
        std::string what = e.what();
        if (what.find("Geometry/") != std::string::npos)
          throw;
        const auto info = what.find("Additional information:");
        if (info != std::string::npos)
          what = Utilities::trim(what.substr(info + 23));
        what = what.substr(0, what.find("\n\nStacktrace"));
        AssertThrow(false, ExcMessage(geometry_key() + ": building the mesh failed in deal.II ('" +
                                      Utilities::trim(what) +
                                      "'); check the lengths and coordinates (finite, of magnitude "
                                      "at most " +
                                      significant(largest_input_magnitude, 3) +
                                      ", the parts of the scene of positive size)."));
      }
  }

  template <int dim>
  void
  InputChecks<dim>::check_value_ranges(const Triangulation<dim> &coarse) const
  {
    const std::string key    = geometry_key();
    double            extent = 0.;
    {
      const auto box = GridTools::compute_bounding_box(coarse).get_boundary_points();
      for (unsigned int d = 0; d < dim; ++d)
        {
          for (const double x : {box.first[d], box.second[d]})
            AssertThrow(std::abs(x) <= largest_input_magnitude,
                        ExcMessage(key + ": a vertex coordinate is " + significant(x, 3) +
                                   "; expected coordinates of magnitude at most " +
                                   significant(largest_input_magnitude, 3) +
                                   ": lengths multiply into areas, volumes and forces that "
                                   "overflow double precision (1.8e308) beyond it; express "
                                   "the lengths in larger units."));
          extent = std::max(extent, box.second[d] - box.first[d]);
        }
    }
    // The force that a unit strain of a body over the model carries.
    const double area = std::pow(extent, dim - 1);
    for (const auto &[id, constants] : materials.bodies)
      AssertThrow(constants.youngs_modulus * area <= largest_input_magnitude,
                  ExcMessage("Materials/Young's moduli: body " +
                             std::to_string(static_cast<unsigned int>(id)) +
                             " has E = " + significant(constants.youngs_modulus, 3) +
                             ", and over the model size " + significant(extent, 3) +
                             " it carries forces of E L^" + std::to_string(dim - 1) + " = " +
                             significant(constants.youngs_modulus * area, 3) +
                             "; expected at most " + significant(largest_input_magnitude, 3) +
                             units_hint + "."));
    check_load_path(coarse, area);
  }

  template <int dim>
  void
  InputChecks<dim>::check_load_path(const Triangulation<dim> &coarse, const double area) const
  {
    // Each load and prescribed displacement at the vertices of its boundary
    // at the start and at the end of every load step: a value that is not
    // a number would stop the first solve without naming its key.
    const auto check = [&](const std::string &key, const types::boundary_id id,
                           const std::vector<std::string> &expressions, const bool force) {
      UserFunction<dim> function(expressions, scene.frame);
      for (unsigned int step = 0; step <= load_stepping.n_steps; ++step)
        {
          const double time = load_stepping.end_time * step / load_stepping.n_steps;
          function.set_time(time);
          for (const auto &face : coarse.active_face_iterators())
            if (face->at_boundary() && face->boundary_id() == id)
              for (const auto v : face->vertex_indices())
                for (unsigned int c = 0; c < expressions.size(); ++c)
                  {
                    const double value  = function.value(face->vertex(v), c);
                    const bool   finite = std::isfinite(value);
                    const bool   bounded =
                      !force || std::abs(value) * area <= largest_input_magnitude;
                    // The message is built only for a failure (it costs more
                    // than the check, at every boundary vertex and step).
                    if (finite && bounded)
                      continue;
                    std::ostringstream where;
                    where << key << ": '" << expressions[c] << "' on boundary "
                          << static_cast<unsigned int>(id) << " is "
                          << (std::isnan(value) ? std::string("not a number") :
                                                  significant(value, 3))
                          << " at t = " << time << " at the point "
                          << coordinates_text(face->vertex(v));
                    AssertThrow(finite, ExcMessage(where.str() +
                                                   "; expected a finite number at every point and "
                                                   "time of the load path (t from 0 to Load "
                                                   "stepping/End time)."));
                    AssertThrow(bounded, ExcMessage(where.str() +
                                                    ", which over the model's size "
                                                    "gives forces of " +
                                                    significant(std::abs(value) * area, 3) +
                                                    "; expected at most " +
                                                    significant(largest_input_magnitude, 3) +
                                                    units_hint + "."));
                  }
        }
    };
    for (const auto &condition : boundary_conditions.pressures)
      check("Boundary conditions/Pressure", condition.boundary_id, {condition.expression}, true);
    for (const auto &condition : boundary_conditions.tractions)
      check("Boundary conditions/Traction", condition.boundary_id, condition.expressions, true);
    for (const auto &condition : boundary_conditions.displacements)
      check(condition.key, condition.boundary_id, {condition.expression}, false);
  }

  // The class is instantiated in input_checks.cc; here the members
  // defined in this file.
#define INSTANTIATE(dim)                                                                                \
  template std::string InputChecks<dim>::geometry_key() const;                                          \
  template void        InputChecks<dim>::create_scene_mesh(const Scene<dim> &,                          \
                                                           parallel::distributed::Triangulation<dim> &) \
    const;                                                                                              \
  template void InputChecks<dim>::check_value_ranges(const Triangulation<dim> &) const;                 \
  template void InputChecks<dim>::check_load_path(const Triangulation<dim> &, const double) const;
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace contact_fem
