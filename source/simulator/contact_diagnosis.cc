// The diagnoses of what went wrong during a run: a lost contact, a
// stalled Newton iteration, forces that do not balance, a model beyond
// double precision. Each names the real cause rather than the most common
// one.
#include <contact_fem/geometry/model_frame.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <contact_fem/simulator/contact_diagnosis.h>
#include <contact_fem/core/format.h>
#include <contact_fem/geometry/mesh_queries.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace contact_fem
{
  namespace
  {
    std::string
    format(const double x, const unsigned int digits = 2)
    {
      std::ostringstream s;
      s << std::setprecision(digits) << x;
      return s.str();
    }

    /// Loads smaller than this many units of round-off of the coordinates
    /// leave the gaps without a significant digit (measured on
    /// prm/hertz.prm: at 1e-12 of its load, 4 units, the reactions balance
    /// to 9e-5; at 1e-15 the contact is lost).
    constexpr double round_off_units = 1e3;

    /// Calls @p visit(cell, f) on each face of boundary @p id of the
    /// locally owned cells, until a call returns false; whether none did.
    template <int dim, typename Visit>
    bool
    for_each_owned_face(const DoFHandler<dim> &dof_handler,
                        const types::boundary_id id,
                        const Visit             &visit)
    {
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == id &&
                !visit(cell, f))
              return false;
      return true;
    }
  } // namespace

  template <int dim>
  ContactDiagnosis<dim>::ContactDiagnosis(const Run &run)
    : run(run)
    , comm(run.dof_handler.get_communicator())
  {}

  template <int dim>
  std::map<types::material_id, Tensor<1, dim>>
  ContactDiagnosis<dim>::body_loads(const double time) const
  {
    // The resultant of the applied pressures and tractions on each body
    // (their sum is applied_load()).
    const QGauss<dim - 1> quadrature(run.dof_handler.get_fe().degree + 1);
    FEFaceValues<dim>     fe_face(run.mapping, run.dof_handler.get_fe(), quadrature,
                                  update_normal_vectors | update_quadrature_points | update_JxW_values);
    std::map<types::material_id, Tensor<1, dim>> loads;
    for (const auto &[id, constants] : run.materials.bodies)
      loads[id] = Tensor<1, dim>();
    // Adds int force ds over the faces of boundary @p id to each body's load.
    const auto integrate = [&](const types::boundary_id id, const auto &force_at) {
      for_each_owned_face(run.dof_handler, id, [&](const auto &cell, const unsigned int f) {
        fe_face.reinit(cell, f);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          loads[cell->material_id()] += force_at(q) * fe_face.JxW(q);
        return true;
      });
    };
    for (const auto &condition : run.boundary_conditions.pressures)
      {
        UserFunction<dim> pressure({condition.expression}, run.scene.frame);
        pressure.set_time(time);
        integrate(condition.boundary_id, [&](const unsigned int q) {
          return -pressure.value(fe_face.quadrature_point(q)) * fe_face.normal_vector(q);
        });
      }
    for (const auto &condition : run.boundary_conditions.tractions)
      {
        UserFunction<dim> traction(condition.expressions, run.scene.frame);
        traction.set_time(time);
        integrate(condition.boundary_id, [&](const unsigned int q) {
          Tensor<1, dim> t;
          for (unsigned int d = 0; d < dim; ++d)
            t[d] = traction.value(fe_face.quadrature_point(q), d);
          return t;
        });
      }
    for (auto &[id, load] : loads)
      load = Utilities::MPI::sum(load, comm);
    return loads;
  }

  template <int dim>
  Tensor<1, dim>
  ContactDiagnosis<dim>::surface_normal(const types::boundary_id id) const
  {
    const QGauss<dim - 1> quadrature(run.dof_handler.get_fe().degree + 1);
    FEFaceValues<dim>     fe_face(run.mapping, run.dof_handler.get_fe(), quadrature,
                                  update_normal_vectors | update_JxW_values);
    Tensor<1, dim>        normal;
    for_each_owned_face(run.dof_handler, id, [&](const auto &cell, const unsigned int f) {
      fe_face.reinit(cell, f);
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        normal += fe_face.normal_vector(q) * fe_face.JxW(q);
      return true;
    });
    return Utilities::MPI::sum(normal, comm);
  }

  template <int dim>
  double
  ContactDiagnosis<dim>::largest_coordinate() const
  {
    double size = 0.;
    for (const auto &cell : run.dof_handler.get_triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto v : cell->vertex_indices())
          size = std::max(size, cell->vertex(v).norm());
    return Utilities::MPI::max(size, comm);
  }

  template <int dim>
  double
  ContactDiagnosis<dim>::load_displacement_scale(const double time) const
  {
    // A force F per unit thickness (2D) moves a body of modulus E by about
    // F / E: the softest body is the one that moves.
    // The largest load on one body, not the net load: loads that balance
    // each other (two bodies pressed together by opposite forces, held by
    // points that carry nothing) still move the bodies.
    const double youngs_min = run.materials.youngs_modulus_range().first;
    double       largest    = 0.;
    for (const auto &[id, load] : body_loads(time))
      {
        // norm() squares: a load of 1e-200 would vanish in underflow.
        double component = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          component = std::max(component, std::abs(load[d]));
        if (component > 0.)
          largest = std::max(largest, component * (load / component).norm());
      }
    const double by_force =
      largest /
      (youngs_min * std::pow(model_extent(run.dof_handler.get_triangulation()), dim - 2.));
    double prescribed = 0.;
    for (const auto &condition : run.boundary_conditions.displacements)
      {
        if (condition.expression == "0")
          continue;
        UserFunction<dim> function({condition.expression}, run.scene.frame);
        function.set_time(time);
        for (const auto &cell : run.dof_handler.get_triangulation().active_cell_iterators())
          if (cell->is_locally_owned())
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  cell->face(f)->boundary_id() == condition.boundary_id)
                for (const auto v : cell->face(f)->vertex_indices())
                  prescribed =
                    std::max(prescribed, std::abs(function.value(cell->face(f)->vertex(v))));
      }
    return std::max(by_force, Utilities::MPI::max(prescribed, comm));
  }

  template <int dim>
  bool
  ContactDiagnosis<dim>::load_vanishes(const double time) const
  {
    const QGauss<dim - 1> quadrature(run.dof_handler.get_fe().degree + 1);
    FEFaceValues<dim>     fe_face(run.mapping, run.dof_handler.get_fe(), quadrature,
                                  update_quadrature_points);
    bool vanishes = true;
    // Whether @p value(point) is 0 at the quadrature points and vertices of
    // every face of boundary @p id.
    const auto zero_on = [&](const types::boundary_id id, const auto &value) {
      return for_each_owned_face(run.dof_handler, id, [&](const auto &cell, const unsigned int f) {
        fe_face.reinit(cell, f);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          if (value(fe_face.quadrature_point(q)) != 0.)
            return false;
        for (const auto v : cell->face(f)->vertex_indices())
          if (value(cell->face(f)->vertex(v)) != 0.)
            return false;
        return true;
      });
    };
    for (const auto &condition : run.boundary_conditions.pressures)
      {
        UserFunction<dim> pressure({condition.expression}, run.scene.frame);
        pressure.set_time(time);
        vanishes = vanishes && zero_on(condition.boundary_id, [&](const Point<dim> &x) {
                     return pressure.value(x);
                   });
      }
    for (const auto &condition : run.boundary_conditions.tractions)
      {
        UserFunction<dim> traction(condition.expressions, run.scene.frame);
        traction.set_time(time);
        for (unsigned int d = 0; d < dim; ++d)
          vanishes = vanishes && zero_on(condition.boundary_id, [&](const Point<dim> &x) {
                       return traction.value(x, d);
                     });
      }
    for (const auto &condition : run.boundary_conditions.displacements)
      {
        UserFunction<dim> function({condition.expression}, run.scene.frame);
        function.set_time(time);
        vanishes = vanishes && zero_on(condition.boundary_id, [&](const Point<dim> &x) {
                     return function.value(x);
                   });
      }
    return Utilities::MPI::min(vanishes ? 1u : 0u, comm) == 1u;
  }

  template <int dim>
  std::string
  ContactDiagnosis<dim>::load_at_round_off(const double time) const
  {
    const double displacement = load_displacement_scale(time);
    // The resolution of the coordinates depends on their magnitude, not on
    // the model's extent.
    const double resolution = std::numeric_limits<double>::epsilon() * largest_coordinate();
    if (displacement == 0. || displacement >= round_off_units * resolution)
      return "";
    return "the load is at the round-off of the geometry: it moves the bodies by about " +
           format(displacement) + ", while coordinates of size " + format(largest_coordinate()) +
           " are resolved to " + format(resolution) +
           " in double precision, so the gaps and the active set are rounding noise; "
           "scale the load (or the units) up";
  }

  template <int dim>
  std::string
  ContactDiagnosis<dim>::precision_limits() const
  {
    if (const std::string contrast = stiffness_contrast_limit(); !contrast.empty())
      return contrast;
    if (const std::string auxetic = auxetic_limit(); !auxetic.empty())
      return auxetic;
    if (const std::string thin = aspect_ratio_limit(); !thin.empty())
      return thin;
    return incompressibility_limit();
  }

  template <int dim>
  std::string
  ContactDiagnosis<dim>::aspect_ratio_limit() const
  {
    // A cell's stiffness across its short edge exceeds that along its long
    // one by about the aspect ratio squared: beyond 1e6 (a ratio of 1e12) the
    // direct solve drops the weaker one as zero pivots (measured: a strip
    // 0.2 x 1e-7 on a block, 4 zero pivots; 0.2 x 1e-6 none). The coarse
    // cells, which every rank holds (refinement keeps their shape): no
    // communication.
    double largest = 0.;
    for (const auto &cell : run.dof_handler.get_triangulation().cell_iterators_on_level(0))
      {
        double shortest = std::numeric_limits<double>::max(), longest = 0.;
        for (unsigned int l = 0; l < cell->n_lines(); ++l)
          {
            shortest = std::min(shortest, cell->line(l)->diameter());
            longest  = std::max(longest, cell->line(l)->diameter());
          }
        if (shortest > 0.)
          largest = std::max(largest, longest / shortest);
      }
    if (!(largest > 1e6))
      return "";
    return "the mesh has cells with an aspect ratio (longest over shortest edge) of " +
           format(largest) +
           ": their stiffness along the long edge is about 1 / " + format(largest * largest) +
           " of that across, and the direct solve keeps few or none of its digits (it takes "
           "it for zero pivots beyond about 1e12); mesh thin parts with cells of aspect ratio "
           "below 1e6";
  }

  template <int dim>
  std::string
  ContactDiagnosis<dim>::stiffness_contrast_limit() const
  {
    const auto [youngs_min, youngs_max] = run.materials.youngs_modulus_range();
    if (!(youngs_max > 1e10 * youngs_min))
      return "";
    return "the stiffness ratio between the bodies, " + format(youngs_max / youngs_min) +
           ", is beyond what a direct solve in double precision resolves (about 1e10)" +
           (run.most_null_pivots > 0 ?
              ": the factorisation found " + std::to_string(run.most_null_pivots) +
                " zero pivot(s), i.e. the softer body's stiffness "
                "vanished in round-off" :
              std::string()) +
           "; model the stiff body as rigid (fixed) instead";
  }

  template <int dim>
  std::string
  ContactDiagnosis<dim>::incompressibility_limit() const
  {
    for (const auto &[id, constants] : run.materials.bodies)
      if (lambda_over_mu(constants.poisson_ratio) > warn_lambda_over_mu())
        return "body " + std::to_string(static_cast<unsigned int>(id)) +
               " is nearly incompressible: lambda/mu = " +
               format(lambda_over_mu(constants.poisson_ratio)) +
               ", and double precision resolves its shear stiffness next to its volumetric "
               "one only to about 1e-14 lambda/mu" +
               (run.most_null_pivots > 0 ?
                  " (the factorisation found " + std::to_string(run.most_null_pivots) +
                    " zero pivot(s))" :
                  std::string()) +
               "; use a Poisson's ratio of at most 0.49999999 (lambda/mu = 5e7)";
    return "";
  }

  template <int dim>
  std::string
  ContactDiagnosis<dim>::auxetic_limit() const
  {
    for (const auto &[id, constants] : run.materials.bodies)
      if (shear_over_bulk(constants.poisson_ratio) > warn_shear_over_bulk())
        return "body " + std::to_string(static_cast<unsigned int>(id)) + " has Poisson's ratio " +
               format(constants.poisson_ratio, 17) +
               " near -1: its bulk modulus K = E / (3 (1 - 2 nu)) vanishes next to its "
               "shear modulus mu = E / (2 (1 + nu)) (mu/K = " +
               format(shear_over_bulk(constants.poisson_ratio)) +
               "), and 1 + nu, hence the body's stiffness, keeps only about " +
               std::to_string(std::max(0, 16 - static_cast<int>(std::log10(
                                                 shear_over_bulk(constants.poisson_ratio))))) +
               " of the 16 digits of double precision; use a Poisson's ratio of at least "
               "-0.99999999 (mu/K = 1.5e8)";
    return "";
  }

  template <int dim>
  double
  ContactDiagnosis<dim>::load_toward_contact(const double time) const
  {
    // Per pair: the load on the slave bodies along the slave surface's
    // outward normal, plus the load on the master bodies along the master
    // surface's: positive pushes the bodies together.
    const auto loads = body_loads(time);
    double     push  = 0.;
    for (const auto &pair : run.contact_parameters.pairs)
      for (const types::boundary_id id : {pair.slave, pair.master})
        {
          const Tensor<1, dim> normal = surface_normal(id);
          if (normal.norm() == 0.)
            continue;
          for (const auto body : bodies_of_surface(run.dof_handler.get_triangulation(), id))
            push += loads.at(body) * normal / normal.norm();
        }
    return push;
  }

  template <int dim>
  NewtonFailure
  ContactDiagnosis<dim>::no_contact_failure(const std::string &where,
                                            const double       time,
                                            const bool         in_iteration,
                                            const bool         none_started) const
  {
    const std::string separation =
      where + ": no contact. No slave node is active" +
      (in_iteration ? " (every node is in tension or apart)" : "") +
      ": the load separates the bodies. Set Contact/Allow loss of contact = true if the "
      "scene may lose contact.";
    // Causes other than a separating load, most specific first. No node
    // paired, yet the master covers a sliver of some node's support: a
    // corner of one surface over the edge of the other, which the pairing
    // threshold leaves unseen whatever the load does.
    if (run.interface &&
        std::none_of(run.interface->slave_nodes.begin(), run.interface->slave_nodes.end(),
                     [](const auto &s) { return s.paired; }))
      {
        const auto *most = static_cast<const typename ContactInterface<dim>::SlaveNode *>(nullptr);
        for (const auto &s : run.interface->slave_nodes)
          if (s.D > 0. && s.full_area > 0. &&
              (!most || s.D / s.full_area > most->D / most->full_area))
            most = &s;
        if (most)
          return NewtonFailure(
            where +
              ": no contact. No slave node is paired with its master surface: the master "
              "covers at most " +
              format(100. * most->D / most->full_area, 2) +
              " % of a slave node's support (the node at " +
              coordinates_text(run.interface->nodes[most->node].reference) +
              ", in the mesh), below the " +
              format(100. * ContactInterface<dim>::least_covered_fraction) +
              " % a node needs to be paired (the gap of so small an overlap is ill-defined): "
              "a corner of one surface just over the edge of the other is not seen as "
              "contact, whatever the load does. Hint: let the surfaces overlap by more than " +
              format(100. * ContactInterface<dim>::least_covered_fraction) +
              " % of the slave's element size where they meet (or not at all), or refine the "
              "slave surface there.",
            false);
      }
    if (load_vanishes(time))
      return NewtonFailure(where +
                             ": no contact. No slave node is active because the load is zero "
                             "there: nothing presses the bodies together. Set Contact/Allow "
                             "loss of contact = true if the load path unloads the bodies.",
                           false);
    std::string cause = precision_limits();
    if (cause.empty())
      cause = load_at_round_off(time);
    if (!cause.empty())
      return NewtonFailure(where +
                             ": no contact. No slave node is active, but not because the load "
                             "separates the bodies: " +
                             cause + ".",
                           false);
    double total = 0.;
    for (const auto &[id, load] : body_loads(time))
      total += load.norm();
    const double push = load_toward_contact(time);
    if (total > 0. && push > 1e-3 * total)
      {
        const std::string pushing =
          where +
          ": no contact. No slave node is active, although the applied load "
          "pushes the bodies together (its resultant along the outward normals "
          "of the contact surfaces is " +
          format(push, 3) + ")";
        // Nothing was solved yet: the start rule, not the iteration, left
        // the loaded body without support.
        if (none_started)
          return NewtonFailure(
            pushing + ": no slave node started the step in contact, so nothing held the "
                      "loaded body. A node starts in contact when it carried pressure at "
                      "the end of the previous step, or, on the first step of a mesh, when "
                      "its gap is below Contact/Active check factor times its size (at 0, "
                      "round-off decides whether a touching node does). Hint: raise "
                      "Contact/Active check factor, or close the gap by a prescribed "
                      "displacement.",
            false);
        return NewtonFailure(pushing + ": the contact was lost numerically, not by the load. "
                                       "Hint: more load steps, or a different Contact/Penalty.",
                             in_iteration);
      }
    return NewtonFailure(separation, false);
  }

  template <int dim>
  std::string
  ContactDiagnosis<dim>::non_convergence_hint(const bool   stalled,
                                              const double r_u,
                                              const double r_lambda) const
  {
    // (The caller adds the precision limits of the model, if any.)
    if (!stalled)
      return precision_limits().empty() ?
               " Hint: more load steps, more Newton iterations, or a different "
               "Contact/Penalty." :
               "";
    // The residuals no longer decrease and the active set stays: that is
    // the round-off of this system, and more iterations or smaller steps do
    // not lower it.
    std::string keys;
    if (r_u > run.newton_parameters.displacement_absolute_tolerance)
      keys = "Newton/Displacement absolute tolerance (" +
             format(run.newton_parameters.displacement_absolute_tolerance) + ")";
    if (r_lambda > run.newton_parameters.multiplier_absolute_tolerance)
      keys += std::string(keys.empty() ? "" : " or ") + "Newton/Multiplier absolute tolerance (" +
              format(run.newton_parameters.multiplier_absolute_tolerance) + ")";
    return " The residuals stalled at the round-off of this system (no active-set change, "
           "no decrease): the tolerances lie below what double precision reaches here. Raise " +
           keys + " above the last residuals.";
  }

  template <int dim>
  ProblemTraits
  ContactDiagnosis<dim>::problem_traits() const
  {
    ProblemTraits traits;
    traits.dim = dim;
    if (run.interface)
      for (unsigned int p = 0; p < run.contact_parameters.pairs.size(); ++p)
        traits.slave_stiffness_ratio =
          std::max(traits.slave_stiffness_ratio, slave_stiffness_ratio(p));
    for (const auto &[id, constants] : run.materials.bodies)
      traits.largest_lambda_over_mu =
        std::max(traits.largest_lambda_over_mu, lambda_over_mu(constants.poisson_ratio));
    const auto [youngs_min, youngs_max] = run.materials.youngs_modulus_range();
    traits.youngs_modulus_contrast      = youngs_max / youngs_min;
    for (const auto &cell : run.dof_handler.get_triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          double shortest = std::numeric_limits<double>::max(), longest = 0.;
          for (unsigned int l = 0; l < cell->n_lines(); ++l)
            {
              const double length = cell->line(l)->diameter();
              shortest            = std::min(shortest, length);
              longest             = std::max(longest, length);
            }
          traits.largest_aspect_ratio = std::max(traits.largest_aspect_ratio, longest / shortest);
        }
    traits.largest_aspect_ratio = Utilities::MPI::max(traits.largest_aspect_ratio, comm);
    // A body is supported if a Dirichlet condition holds a face or a
    // vertex of it (the coarse mesh knows every body on every rank).
    std::set<types::material_id> supported;
    for (const auto &condition : run.boundary_conditions.displacements)
      for (const auto body :
           bodies_of_surface(run.dof_handler.get_triangulation(), condition.boundary_id))
        supported.insert(body);
    for (const auto &condition : run.boundary_conditions.points)
      supported.insert(condition.point.material_id);
    for (const auto &[id, constants] : run.materials.bodies)
      if (supported.count(id) == 0)
        traits.unsupported_bodies.push_back(id);
    return traits;
  }

  template <int dim>
  std::pair<std::vector<Tensor<1, dim>>, std::vector<double>>
  ContactDiagnosis<dim>::active_normals_and_areas() const
  {
    const ContactInterface<dim> &interface = *run.interface;
    const unsigned int           n_pairs   = run.contact_parameters.pairs.size();
    // The terms of each sum (pair p: components 0..dim-1 of D_j n_j, then
    // D_j) from the owners of the rows, keyed by the place in slave_nodes.
    std::vector<std::vector<std::pair<unsigned int, double>>> terms(n_pairs * (dim + 1));
    for (unsigned int k = 0; k < interface.slave_nodes.size(); ++k)
      if (const auto &s = interface.slave_nodes[k];
          interface.owns_row(s) && s.paired && run.contact->is_active(s.node))
        {
          const Tensor<1, dim> weighted = s.D * s.normal;
          for (unsigned int d = 0; d < dim; ++d)
            terms[s.pair * (dim + 1) + d].emplace_back(k, weighted[d]);
          terms[s.pair * (dim + 1) + dim].emplace_back(k, s.D);
        }
    std::vector<Tensor<1, dim>> normal(n_pairs);
    std::vector<double>         area(n_pairs);
    for (unsigned int p = 0; p < n_pairs; ++p)
      {
        for (unsigned int d = 0; d < dim; ++d)
          normal[p][d] = interface.sum_in_node_order(terms[p * (dim + 1) + d]);
        area[p] = interface.sum_in_node_order(terms[p * (dim + 1) + dim]);
      }
    return {normal, area};
  }

  template <int dim>
  std::string
  ContactDiagnosis<dim>::friction_held_translations() const
  {
    if (!run.interface || !run.contact)
      return "";
    const auto &tria = run.dof_handler.get_triangulation();
    const auto  axis = [](const unsigned int c) {
      Tensor<1, dim> e;
      e[c] = 1.;
      return e;
    };
    // The directions each body's supports hold.
    std::map<types::material_id, std::vector<Tensor<1, dim>>> held;
    for (const auto &condition : run.boundary_conditions.displacements)
      for (const auto body : bodies_of_surface(tria, condition.boundary_id))
        held[body].push_back(axis(condition.component));
    for (const auto &condition : run.boundary_conditions.points)
      held[condition.point.material_id].push_back(axis(condition.component));
    for (const auto id : run.boundary_conditions.rollers)
      {
        const Tensor<1, dim> normal = surface_normal(id);
        if (normal.norm() > 0.)
          for (const auto body : bodies_of_surface(tria, id))
            held[body].push_back(normal / normal.norm());
      }
    // The contact holds its bodies along the normal of its active nodes.
    const std::vector<Tensor<1, dim>> pair_normal = active_normals_and_areas().first;
    std::map<types::material_id, std::vector<Tensor<1, dim>>> contact_normals;
    for (unsigned int p = 0; p < pair_normal.size(); ++p)
      if (pair_normal[p].norm() > 0.)
        for (const auto id :
             {run.contact_parameters.pairs[p].slave, run.contact_parameters.pairs[p].master})
          for (const auto body : bodies_of_surface(tria, id))
            contact_normals[body].push_back(pair_normal[p] / pair_normal[p].norm());
    std::string result;
    for (const auto &[body, directions] : held)
      {
        if (contact_normals.count(body) == 0)
          continue;
        // Gram-Schmidt on unit vectors: a direction within 1e-6 of the
        // span so far adds nothing.
        std::vector<Tensor<1, dim>> basis;
        const auto                  add = [&basis](Tensor<1, dim> v) {
          for (const auto &b : basis)
            v -= (v * b) * b;
          if (v.norm() < 1e-6)
            return false;
          basis.push_back(v / v.norm());
          return true;
        };
        for (const auto &v : directions)
          add(v);
        for (const auto &v : contact_normals.at(body))
          add(v);
        std::string free;
        for (unsigned int c = 0; c < dim; ++c)
          if (add(axis(c)))
            {
              std::string components;
              for (unsigned int d = 0; d < dim; ++d)
                components +=
                  (d == 0 ? "" : ", ") +
                  significant(std::abs(basis.back()[d]) < 1e-10 ? 0. : basis.back()[d], 3);
              free += (free.empty() ? "" : " and ") + ("(" + components + ")");
            }
        if (!free.empty())
          result +=
            (result.empty() ? "" : "; ") + ("body " + std::to_string(body) + " along " + free);
      }
    return result;
  }

  template <int dim>
  std::string
  ContactDiagnosis<dim>::load_within_friction_capacity(
    const std::vector<unsigned int>                         &free_bodies,
    const std::vector<std::shared_ptr<const FrictionalLaw>> &laws,
    const double                                             time) const
  {
    if (!run.interface || !run.contact || free_bodies.empty())
      return "";
    const auto &pairs = run.contact_parameters.pairs;
    // Each pair's active area and mean normal.
    const auto [pair_normal, area] = active_normals_and_areas();
    const auto &tria  = run.dof_handler.get_triangulation();
    const auto  loads = body_loads(time);
    std::string result;
    for (const unsigned int body : free_bodies)
      {
        std::vector<unsigned int> touching;
        for (unsigned int p = 0; p < pairs.size(); ++p)
          if (area[p] > 0.)
            for (const auto id : {pairs[p].slave, pairs[p].master})
              for (const auto b : bodies_of_surface(tria, id))
                if (b == body && std::find(touching.begin(), touching.end(), p) == touching.end())
                  touching.push_back(p);
        const auto load = loads.find(body);
        if (touching.size() != 1 || load == loads.end() || laws.size() != pairs.size() ||
            !laws[touching[0]])
          return "";
        const unsigned int   p       = touching[0];
        const Tensor<1, dim> n       = pair_normal[p] / pair_normal[p].norm();
        const double         normal  = std::abs(load->second * n);
        const double         tangent = (load->second - (load->second * n) * n).norm();
        // The slip bound's resultant over the active area: mu N (Coulomb),
        // g A (Tresca). Beyond 0.99 of it the load may well exceed it.
        const double capacity = laws[p]->threshold(normal / area[p]) * area[p];
        if (!(tangent < 0.99 * capacity))
          return "";
        result += (result.empty() ? "" : "; ") + ("on body " + std::to_string(body) + ", " +
                                                  significant(tangent, 4) + " against " +
                                                  significant(capacity, 4));
      }
    return "the tangential load is within the friction capacity of the contact (its "
           "resultant against mu times the normal load under Coulomb, the bound times the "
           "active area under Tresca: " +
           result + ")";
  }

  template <int dim>
  std::string
  ContactDiagnosis<dim>::singular_system_hint(const double relative_residual) const
  {
    // Most specific first: what the input says, before the question.
    constexpr double penalty_digits = 1e6;
    if (run.contact && run.contact->penalty_over_automatic() > penalty_digits)
      return " Likely cause: Contact/Penalty is " + format(run.contact->penalty_over_automatic()) +
             " times its automatic value (Contact/Penalty = auto): the contact stiffness "
             "swamps the bodies' stiffness, and each factor of 10 above the automatic "
             "value costs the factorisation about one of the 16 digits of double "
             "precision; use a penalty near the automatic value.";
    if (const std::string limit = precision_limits(); !limit.empty())
      return " Likely cause: " + limit + ".";
    // A free rigid-body mode leaves the load's part along it unbalanced: a
    // relative residual of order 1 (1.4 to 5 measured, the tetrahedral
    // block held by frictionless contact alone). A stiffness contrast that
    // the factorisation resolves only in part leaves far less: the
    // tetrahedral block on a base 1e9 times stiffer, 91 nodes active with
    // friction, 9e-3 (bench/audit/round6). Beyond 1e10 precision_limits()
    // names the contrast whatever the residual.
    const auto [youngs_min, youngs_max] = run.materials.youngs_modulus_range();
    if (relative_residual < 0.1 && youngs_max > 1e6 * youngs_min)
      return " Likely cause: the stiffness ratio between the bodies, " +
             format(youngs_max / youngs_min) +
             ", together with the mesh's own conditioning, takes more digits than double "
             "precision holds (the residual is above the 1e-3 taken as singular but well "
             "below the order 1 that a rigid-body mode held by neither supports nor contact "
             "leaves); model the stiff body as rigid (fixed) instead, or bring the moduli "
             "closer.";
    const std::vector<unsigned int> free_bodies = problem_traits().unsupported_bodies;
    if (!free_bodies.empty())
      {
        std::string ids;
        for (const unsigned int id : free_bodies)
          ids += (ids.empty() ? "" : ", ") + std::to_string(id);
        return " Likely cause: " + std::string(free_bodies.size() == 1 ? "body " : "bodies ") +
               ids +
               " held by no support (no fixed or prescribed boundary, no fixed point): "
               "contact alone leaves a rigid-body mode free where no node is active, and "
               "tangentially without friction; add supports or Boundary conditions/Fixed "
               "points.";
      }
    return " Hint: is every body held by supports or by at least one active contact node?";
  }

  template <int dim>
  double
  ContactDiagnosis<dim>::slave_stiffness_ratio(const unsigned int pair) const
  {
    const double slave_E  = run.interface->largest_youngs_modulus(pair, true);
    const double master_E = run.interface->largest_youngs_modulus(pair, false);
    return master_E > 0. ? slave_E / master_E : 0.;
  }

  template <int dim>
  std::vector<std::string>
  ContactDiagnosis<dim>::modelling_warnings(const unsigned int degree,
                                            const bool         b_bar) const
  {
    std::vector<std::string> warnings;
    for (const auto &[id, constants] : run.materials.bodies)
      if (lambda_over_mu(constants.poisson_ratio) > warn_lambda_over_mu())
        {
          std::ostringstream text;
          text << "body " << static_cast<unsigned int>(id) << " has Poisson's ratio "
               << std::setprecision(16) << constants.poisson_ratio
               << ": lambda/mu = " << significant(lambda_over_mu(constants.poisson_ratio), 2)
               << ", beyond " << significant(warn_lambda_over_mu(), 2)
               << ", where double precision resolves the shear stiffness next to the "
                  "volumetric one only to about 1e-14 lambda/mu: expect the reactions to "
                  "balance the load to about that, or the solver to fail.";
          warnings.push_back(text.str());
        }
    for (const std::string &limit :
         {stiffness_contrast_limit(), auxetic_limit()})
      if (!limit.empty())
        warnings.push_back(limit + ".");
    // Volumetric locking: measured on the Hertz scene, p_max is off by more
    // than 2 % beyond these Poisson's ratios without B-bar
    // (doc/stability.md).
    const double locking_nu = degree == 1 ? 0.49 : 0.499;
    if (!b_bar)
      for (const auto &[id, constants] : run.materials.bodies)
        if (constants.poisson_ratio > locking_nu)
          {
            std::ostringstream text;
            text << "body " << static_cast<unsigned int>(id) << " has Poisson's ratio "
                 << constants.poisson_ratio << ": degree " << degree
                 << " elements lock volumetrically beyond about " << locking_nu
                 << "; set Finite element/Volumetric strain = B-bar.";
            warnings.push_back(text.str());
          }
    // The mortar side should be the softer one (and the finer mesh): a stiff
    // slave on a soft, coarse master cannot represent the pressure.
    const auto &pairs = run.contact_parameters.pairs;
    if (run.interface)
      for (unsigned int p = 0; p < pairs.size(); ++p)
        if (const double ratio = slave_stiffness_ratio(p); ratio > 10.)
          {
            std::ostringstream text;
            text << "contact pair " << static_cast<unsigned int>(pairs[p].slave) << ": "
                 << static_cast<unsigned int>(pairs[p].master) << ": the slave side is " << ratio
                 << " times stiffer than the master side; the softer (and finer) surface should "
                    "be the slave (Contact/Pairs).";
            warnings.push_back(text.str());
          }
    return warnings;
  }

  template <int dim>
  std::string
  ContactDiagnosis<dim>::balance_warning(const Json &reaction, const double time) const
  {
    // The stability study's verdict tolerance (doc/stability.md): converged
    // runs of the shipped scenes balance to 1e-10 or better, damped ones
    // with tightened tolerances to about 2e-8.
    constexpr double tolerance               = 1e-6;
    constexpr double contrast_costing_digits = 1e6;
    const double     imbalance               = reaction["relative_imbalance"].number_value();
    if (!(imbalance > tolerance))
      return "";
    std::string cause = precision_limits();
    if (cause.empty())
      cause = load_at_round_off(time);
    // Below the 1e10 limit a large contrast still costs the direct solve
    // about log10(ratio) of its 16 digits (stiffness/cyl-1e8-swapped: 1.5e-6
    // with the Newton residuals at their absolute tolerance, and smaller
    // Newton tolerances do not lower it).
    const auto [youngs_min, youngs_max] = run.materials.youngs_modulus_range();
    if (cause.empty() && youngs_max > contrast_costing_digits * youngs_min)
      cause = "the stiffness ratio between the bodies, " + significant(youngs_max / youngs_min, 2) +
              ", costs the solve about " +
              std::to_string(static_cast<int>(std::log10(youngs_max / youngs_min))) +
              " of the 16 digits of double precision, and the reactions balance only "
              "that well (smaller Newton tolerances do not help; a stiff body modelled "
              "as rigid does)";
    if (cause.empty())
      cause = "the Newton tolerances leave that much out of balance (Newton/Displacement "
              "relative tolerance = " +
              significant(run.newton_parameters.displacement_relative_tolerance, 2) +
              "); tighten them";
    return "the applied load and the support reactions are out of balance by " +
           scientific(imbalance, 1) + " of the forces (tolerance " + significant(tolerance, 2) +
           "): " + cause;
  }

  template <int dim>
  std::string
  ContactDiagnosis<dim>::precision_hint() const
  {
    // Stiffness ratios beyond ~1e10 (measured: 1e12 fails with either body
    // as the slave) and nearly incompressible bodies leave the direct solve
    // with too few digits: then that is the likely cause of any failure.
    const std::string cause = precision_limits();
    if (!cause.empty())
      return " Likely cause: " + cause + ".";
    // A penalty's penetration p / eps near the coordinates' round-off
    // leaves its pressures rounding noise (measured: the 3D frictional
    // patch at loads x 1e-9, p / eps = 6.7e-16 against a resolution of
    // 3.8e-16, the residual stalled at 4e-2 of its start).
    const double penetration = run.contact ? run.contact->largest_penalty_penetration() : 0.;
    const double resolution  = std::numeric_limits<double>::epsilon() * largest_coordinate();
    if (penetration > 0. && penetration < round_off_units * resolution)
      return " Likely cause: the penalty's penetration (p / eps, at most " + format(penetration) +
             ") is within " + format(round_off_units) +
             " units of the round-off of the coordinates (" + format(resolution) +
             "), so the gaps that set the penalty's pressures are rounding noise; scale the "
             "load or the units up, lower Contact/Stiffness factor, or use an alm formulation.";
    return "";
  }

  template <int dim>
  std::string
  ContactDiagnosis<dim>::preload(const Json &contact, const double time, const bool load_vanishes) const
  {
    const auto n_active = static_cast<unsigned int>(contact["active_slave_nodes"].number_value());
    const double pressure = std::max(std::abs(contact["max_contact_pressure"].number_value()),
                                     std::abs(contact["min_active_contact_pressure"].number_value()));
    // Round-off pressures are about 1e-16 of the moduli; a slave node that
    // starts inside its master by 1e-8 of its element size (what
    // check_load_resolved() lets run without a load) presses by about
    // 1e-8 of them.
    if (!load_vanishes || n_active == 0 ||
        !(pressure > 1e-10 * run.materials.youngs_modulus_range().first))
      return "";
    return "the load is zero at t = " + significant(time, 6) +
           ", yet the contact pressures reach " + significant(pressure, 2) + " at " +
           std::to_string(n_active) +
           " active slave node(s): the bodies press each other without a load, so a slave "
           "node starts inside its master (an overlap in the mesh, or, on a curved surface "
           "that touches the master at a node, the mortar gap of that node, negative by "
           "about h^2 / R: a preload that vanishes with refinement)";
  }

  template <int dim>
  std::string
  ContactDiagnosis<dim>::pressureless_contact(const Json  &contact,
                                              const double time,
                                              const bool   load_vanishes) const
  {
    const auto n_active = static_cast<unsigned int>(contact["active_slave_nodes"].number_value());
    if (n_active == 0)
      return "";
    const double pressure = std::max(std::abs(contact["max_contact_pressure"].number_value()),
                                     std::abs(contact["min_active_contact_pressure"].number_value()));
    // The mean stress of a force load, or the stress of a prescribed
    // displacement in the softer body: a pressed contact's pressures are of
    // its order, round-off about 1e-16 of it.
    const double stress = run.materials.youngs_modulus_range().first *
                          load_displacement_scale(time) /
                          model_extent(run.dof_handler.get_triangulation());
    std::string why;
    // Far above round-off (about 1e-16 of the moduli) the pressures of an
    // unloaded state are a preload: preload() says so.
    if (load_vanishes && !preload(contact, time, load_vanishes).empty())
      return "";
    if (load_vanishes)
      why = "the load is zero at t = " + significant(time, 6) +
            ": nothing presses the bodies together";
    else if (pressure < 1e-12 * stress)
      why = "the contact pressures at t = " + significant(time, 6) + " are below 1e-12 of the " +
            "load's stress scale (" + significant(stress, 2) +
            "): the bodies touch without pressing each other";
    else
      return "";
    return why + ", so the pressures are round-off (at most " + significant(pressure, 2) +
           " in size) and the " + std::to_string(n_active) +
           " active slave node(s) are picked by rounding: read the state as without contact";
  }

  template <int dim>
  std::string
  ContactDiagnosis<dim>::tension_failure(const Json &contact) const
  {
    const double p_min = contact["min_active_contact_pressure"].number_value();
    if (!(p_min < 0.))
      return "";
    const std::string cause = precision_limits();
    return "the converged state has an active slave node in tension (contact pressure " +
           scientific(p_min, 2) + ", largest " +
           scientific(contact["max_contact_pressure"].number_value(), 2) +
           "): its active set is rounding noise, no result" +
           (cause.empty() ? std::string() : ": " + cause);
  }

  template class ContactDiagnosis<2>;
  template class ContactDiagnosis<3>;
} // namespace contact_fem
