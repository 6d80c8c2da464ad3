#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <contact_fem/core/format.h>
#include <contact_fem/simulator/scene_parameters.h>
#include <contact_fem/simulator/solution_checks.h>
#include <contact_fem/solvers/linear_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace contact_fem
{
  template <int dim>
  SolutionChecks<dim>::SolutionChecks(const ConvergedSystem &system)
    : system(system)
    , comm(system.dof_handler.get_communicator())
  {}

  template <int dim>
  double
  SolutionChecks<dim>::BodyMoments::radius_of_gyration() const
  {
    double sum = 0.;
    for (unsigned int i = 0; i < dim; ++i)
      sum += central[i];
    return std::sqrt(sum / volume);
  }

  template <int dim>
  std::string
  SolutionChecks<dim>::large_displacement(const std::set<types::material_id> &finite_strain_bodies,
                                          const bool                          with_contact) const
  {
    // Linear elasticity is a small-displacement theory: displacements of
    // half the model size mean a rigid-body mode that the supports (and
    // frictionless contact) leave free, or a load far beyond the model.
    // (A tenth would flag prescribed rigid shifts, e.g. a deep initial
    // overlap pushed apart.) A finite-strain body holds at any displacement
    // (a free rigid-body mode shows as a singular matrix), unless a contact
    // gap linear in u assumes it small.
    Point<dim> low, high;
    for (unsigned int d = 0; d < dim; ++d)
      {
        low[d]  = std::numeric_limits<double>::max();
        high[d] = -std::numeric_limits<double>::max();
      }
    for (const auto &cell : system.dof_handler.get_triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto v : cell->vertex_indices())
          for (unsigned int d = 0; d < dim; ++d)
            {
              low[d]  = std::min(low[d], cell->vertex(v)[d]);
              high[d] = std::max(high[d], cell->vertex(v)[d]);
            }
    double size = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      size =
        std::max(size, Utilities::MPI::max(high[d], comm) + Utilities::MPI::max(-low[d], comm));
    double              u_max = 0.;
    std::vector<double> values(system.dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : system.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() &&
          (with_contact || finite_strain_bodies.count(cell->material_id()) == 0))
        {
          cell->get_dof_values(system.ghosted_solution, values.begin(), values.end());
          for (const double v : values)
            u_max = std::max(u_max, std::abs(v));
        }
    u_max = Utilities::MPI::max(u_max, comm);
    if (!(u_max > ModelRange::displacement_limit * size))
      return "";
    std::ostringstream text;
    text << "the largest displacement, " << u_max << ", exceeds half the model size (" << size
         << "): a rigid-body mode that the supports leave free (e.g. a rotation; "
         << "see Boundary conditions/Fixed points) or a load beyond small-strain theory";
    return text.str();
  }

  template <int dim>
  std::string
  SolutionChecks<dim>::large_strain(Json                               &record,
                                    const std::set<types::material_id> &finite_strain_bodies,
                                    const bool                          with_contact) const
  {
    // Linear elasticity and a contact gap linear in u assume small strains
    // and rotations: beyond a few percent the answer is that of a model the
    // bodies no longer follow (and the step count would matter to any
    // geometry update).
    constexpr double                 strain_limit   = ModelRange::strain_limit;
    constexpr double                 rotation_limit = ModelRange::rotation_limit;
    const FiniteElement<dim>        &fe             = system.dof_handler.get_fe();
    const QGauss<dim>                quadrature(fe.degree + 1);
    FEValues<dim>                    fe_values(system.mapping, fe, quadrature, update_gradients);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, dim>>      gradients(quadrature.size());
    double                           strain = 0., rotation = 0.;
    for (const auto &cell : system.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const bool finite = finite_strain_bodies.count(cell->material_id()) > 0;
          if (finite && !with_contact)
            continue;
          fe_values.reinit(cell);
          fe_values[displacement].get_function_gradients(system.ghosted_solution, gradients);
          for (const auto &grad : gradients)
            {
              if (!finite)
                for (const double e : dealii::eigenvalues(symmetrize(grad)))
                  strain = std::max(strain, std::abs(e));
              // The infinitesimal rotation: the skew part's largest entry.
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = 0; j < i; ++j)
                  rotation = std::max(rotation, 0.5 * std::abs(grad[i][j] - grad[j][i]));
            }
        }
    strain   = Utilities::MPI::max(strain, comm);
    rotation = Utilities::MPI::max(rotation, comm);
    record.set("largest_strain", strain).set("largest_rotation", rotation);
    if (strain <= strain_limit && rotation <= rotation_limit)
      return "";
    std::ostringstream text;
    text << "the solution leaves the small-strain range (largest principal strain "
         << scientific(strain, 2) << ", largest rotation " << scientific(rotation, 2)
         << " rad; linear elasticity and the contact gap assume below " << strain_limit << " and "
         << rotation_limit << "): the load is beyond what this model describes";
    return text.str();
  }

  template <int dim>
  double
  SolutionChecks<dim>::rotation_under_couple(const types::material_id body,
                                             const BodyMoments       &moments,
                                             const unsigned int       axis,
                                             LinearSolver            &solver) const
  {
    const FiniteElement<dim>            &fe = system.dof_handler.get_fe();
    const QGauss<dim>                    quadrature(fe.degree + 1);
    FEValues<dim>                        fe_values(system.mapping, fe, quadrature,
                                                   update_values | update_gradients | update_quadrature_points |
                                                     update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    Vector<double>                       cell_load(fe.n_dofs_per_cell());
    std::vector<Tensor<2, dim>>          gradients(quadrature.size());
    Tensor<1, dim>                       omega_axis;
    if constexpr (dim == 3)
      omega_axis[axis] = 1.;
    double polar = 0.;
    for (unsigned int i = 0; i < dim; ++i)
      if (dim == 2 || i != axis)
        polar += moments.central[i];
    // A body force f = omega x (x - c) / J: no net force, and with J = int
    // |x - c|^2 minus the part along the axis, unit moment about the axis.
    const auto couple = [&](const Point<dim> &x) {
      const Tensor<1, dim> r = x - moments.centre;
      Tensor<1, dim>       f;
      if constexpr (dim == 2)
        {
          f[0] = -r[1];
          f[1] = r[0];
        }
      else
        f = cross_product_3d(omega_axis, r);
      return f / polar;
    };
    TrilinosWrappers::MPI::Vector probe_load(system.owned_dofs, comm);
    for (const auto &cell : system.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->material_id() == body)
        {
          fe_values.reinit(cell);
          cell_load = 0.;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const Tensor<1, dim> f = couple(fe_values.quadrature_point(q));
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                cell_load(i) += fe_values[displacement].value(i, q) * f * fe_values.JxW(q);
            }
          cell->get_dof_indices(dofs);
          // The vector form condenses without inhomogeneities.
          system.constraints.distribute_local_to_global(cell_load, dofs, probe_load);
        }
    probe_load.compress(VectorOperation::add);

    // Response: solution + K^-1 probe, distributed, minus solution
    // (the inhomogeneities cancel).
    TrilinosWrappers::MPI::Vector response(system.owned_dofs, comm);
    solver.solve_again(response, probe_load);
    response += system.solution;
    system.constraints.distribute(response);
    response -= system.solution;
    TrilinosWrappers::MPI::Vector ghosted_response(system.owned_dofs, system.relevant_dofs, comm);
    ghosted_response = response;

    // Mean rotation of the body about the axis.
    double rotation = 0.;
    for (const auto &cell : system.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->material_id() == body)
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_gradients(ghosted_response, gradients);
          const unsigned int i = (axis + 1) % 3, j = (axis + 2) % 3;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const Tensor<2, dim> &G = gradients[q];
              rotation += (dim == 2 ? 0.5 * (G[1][0] - G[0][1]) :
                                      0.5 * (G[j % dim][i % dim] - G[i % dim][j % dim])) *
                          fe_values.JxW(q);
            }
        }
    return std::abs(Utilities::MPI::sum(rotation, comm)) / moments.volume;
  }

  template <int dim>
  std::vector<bool>
  SolutionChecks<dim>::supporting_dofs(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                       const std::vector<types::global_dof_index> &dofs) const
  {
    const FiniteElement<dim> &fe = system.dof_handler.get_fe();
    std::vector<bool>         fixed(dofs.size());
    for (unsigned int i = 0; i < dofs.size(); ++i)
      fixed[i] = system.dirichlet_constraints.is_constrained(dofs[i]) &&
                 system.dirichlet_constraints.get_constraint_entries(dofs[i])->empty();
    // A fixed point in 2D stiffens only logarithmically as the mesh around
    // it is refined (the Hertz disc on its two fixed points: theta G V 2.9
    // with 4 contact refinements, 3.4 with 6); in 3D its stiffness falls
    // with the element size (the upper body of two_cylinders_3d, turned
    // about z against four fixed points: 9.0 at 12.5k DoFs, 14.8 refined
    // once), so there only fixed faces count as supports.
    if (dim == 2 || std::find(fixed.begin(), fixed.end(), true) == fixed.end())
      return fixed;
    std::vector<bool> supporting(dofs.size(), false);
    for (const auto f : cell->face_indices())
      if (cell->face(f)->at_boundary())
        for (unsigned int d = 0; d < dim; ++d)
          {
            const auto on_face = [&](const unsigned int i) {
              return fe.has_support_on_face(i, f) && fe.system_to_component_index(i).first == d;
            };
            bool whole_face = true;
            for (unsigned int i = 0; i < dofs.size(); ++i)
              whole_face = whole_face && (!on_face(i) || fixed[i]);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              supporting[i] = supporting[i] || (whole_face && on_face(i));
          }
    return supporting;
  }

  template <int dim>
  std::map<types::material_id, std::vector<FixedDof<dim>>>
  SolutionChecks<dim>::fixed_dofs_by_body() const
  {
    const FiniteElement<dim> &fe = system.dof_handler.get_fe();
    // The support points of every DoF of a cell, mapped (Q2 has DoFs off
    // the vertices); only cells with a fixed DoF are mapped.
    FEValues<dim> fe_values(system.mapping, fe, Quadrature<dim>(fe.get_unit_support_points()),
                            update_quadrature_points);
    std::map<types::material_id, std::vector<FixedDof<dim>>> fixed;
    // A DoF is shared by the cells around it: take it once, on its owner;
    // from ghost cells too, whose fixed face may be the one it is on.
    std::vector<bool>                    taken(system.owned_dofs.n_elements(), false);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : system.dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          cell->get_dof_indices(dofs);
          const std::vector<bool> supporting = supporting_dofs(cell, dofs);
          bool                    mapped     = false;
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (supporting[i] && system.owned_dofs.is_element(dofs[i]) &&
                !taken[system.owned_dofs.index_within_set(dofs[i])])
              {
                taken[system.owned_dofs.index_within_set(dofs[i])] = true;
                if (!mapped)
                  fe_values.reinit(cell);
                mapped = true;
                fixed[cell->material_id()].push_back(
                  {fe_values.quadrature_point(i), fe.system_to_component_index(i).first});
              }
        }
    return fixed;
  }

  template <int dim>
  typename SolutionChecks<dim>::BodyMoments
  SolutionChecks<dim>::body_moments(const types::material_id body) const
  {
    const QGauss<dim> quadrature(system.dof_handler.get_fe().degree + 1);
    FEValues<dim>     fe_values(system.mapping, system.dof_handler.get_fe(), quadrature,
                                update_quadrature_points | update_JxW_values);
    double            volume = 0.;
    Tensor<1, dim>    first_moment, second_moments; // int x_i, int x_i^2
    for (const auto &cell : system.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->material_id() == body)
        {
          fe_values.reinit(cell);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const Point<dim> &x = fe_values.quadrature_point(q);
              volume += fe_values.JxW(q);
              first_moment += x * fe_values.JxW(q);
              for (unsigned int i = 0; i < dim; ++i)
                second_moments[i] += x[i] * x[i] * fe_values.JxW(q);
            }
        }
    BodyMoments moments;
    moments.volume = Utilities::MPI::sum(volume, comm);
    moments.centre = Point<dim>(Utilities::MPI::sum(first_moment, comm) / moments.volume);
    second_moments = Utilities::MPI::sum(second_moments, comm);
    for (unsigned int i = 0; i < dim; ++i)
      moments.central[i] =
        second_moments[i] - moments.volume * moments.centre[i] * moments.centre[i];
    return moments;
  }


  template <int dim>
  typename SolutionChecks<dim>::HeldRotation
  SolutionChecks<dim>::weakly_held_rotation(const std::vector<types::material_id> &bodies,
                                            const double softest_shear_modulus,
                                            const std::set<types::boundary_id> &contact_surfaces,
                                            LinearSolver                       &solver) const
  {
    // Frictionless contact on a curved surface resists a rotation about its
    // centre of curvature only through the discretisation (a polygon or a
    // piecewise-quadratic arc is not quite a circle): that rigid-body mode
    // has a stiffness far below the elastic ones, the solver finds no zero
    // pivot, and the solution carries a rotation set by the mesh. Probe:
    // load every body that touches a contact surface with a unit couple and
    // solve with the factors of the converged system (one back
    // substitution).
    std::vector<unsigned int> touches(bodies.size(), 0);
    for (const auto &cell : system.dof_handler.get_triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && contact_surfaces.count(cell->face(f)->boundary_id()))
            touches[std::lower_bound(bodies.begin(), bodies.end(), cell->material_id()) -
                    bodies.begin()] = 1;
    Utilities::MPI::max(touches, comm, touches);

    const auto   fixed = fixed_dofs_by_body();
    HeldRotation result;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (touches[b] != 0)
        {
          const auto own_fixed = fixed.find(bodies[b]);
          try
            {
              probe_body(bodies[b],
                         own_fixed == fixed.end() ? std::vector<FixedDof<dim>>() :
                                                    own_fixed->second,
                         softest_shear_modulus, solver, result);
            }
          catch (const LinearSolverFailure &e)
            {
              // An iterative solver may not converge on the probe of a
              // nearly free rotation: say that the check did not run.
              result.skipped = e.what();
              return result;
            }
        }
    return result;
  }

  template <int dim>
  void
  SolutionChecks<dim>::probe_body(const types::material_id          body,
                                  const std::vector<FixedDof<dim>> &fixed,
                                  const double                      softest_shear_modulus,
                                  LinearSolver                     &solver,
                                  HeldRotation                     &result) const
  {
    // An elastically held body of volume V turns by about 1 / (G V), G a
    // shear modulus; the softest one of the model is taken, since a stiff
    // body may rest on a soft one. Measured on the Hertz disc (theta G V):
    // 3.4 with its fixed points, 300-500 without them.
    constexpr double compliance_limit = 50.;
    // A rotation that the body's own supports hold with a lever arm (see
    // support_lever_arms()) of at least this fraction of the body's radius
    // of gyration is held elastically: its probe (with the iterative
    // solver a full Krylov solve) is skipped. Held by two fixed points on
    // its axis, the Hertz disc gives theta G V 2.9, 9.9, 35, 54 and 146 at
    // lever arms 0.88, 0.44, 0.22, 0.17 and 0.055 (about 2 / arm^2): at 0.5
    // about 8, well below the limit; closer supports are probed.
    constexpr double          held_lever_arm = 0.5;
    const BodyMoments         moments        = body_moments(body);
    const std::vector<double> lever_arms =
      support_lever_arms(fixed, moments.centre, moments.radius_of_gyration(), comm);

    // Per axis: held by the supports, probed (with theta G V), or not
    // probed because an earlier axis of the body warned already.
    Json held = Json::array(), probed = Json::array(), unprobed = Json::array();
    Json levers = Json::object(), compliances = Json::object();
    bool warned = false;
    for (unsigned int axis = 0; axis < (dim == 2 ? 1 : 3); ++axis)
      {
        // In 2D the rotation of the plane, about z.
        const std::string name(1, "xyz"[dim == 2 ? 2 : axis]);
        levers.set(name, lever_arms[axis]);
        if (lever_arms[axis] >= held_lever_arm || warned)
          {
            (lever_arms[axis] >= held_lever_arm ? held : unprobed).push(name);
            continue;
          }
        const double compliance = rotation_under_couple(body, moments, axis, solver) *
                                  softest_shear_modulus * moments.volume;
        probed.push(name);
        compliances.set(name, compliance);
        if (!(compliance > compliance_limit))
          continue;
        std::ostringstream text;
        text << "body " << static_cast<unsigned int>(body)
             << " is held only weakly against rotation: a couple turns it " << std::setprecision(3)
             << compliance << std::setprecision(6)
             << " times more than elasticity would (theta G V, G the smallest shear "
             << "modulus); frictionless contact on a curved surface resists a rotation "
             << "about its centre only through the discretisation, so the results along "
             << "that rotation depend on the mesh; hold it (see Boundary "
             << "conditions/Fixed points)";
        result.warnings.push_back(text.str());
        warned = true;
      }
    // Lever arms over the radius of gyration.
    result.check.push(Json::object()
                        .set("body", static_cast<unsigned int>(body))
                        .set("held_by_supports", held)
                        .set("probed", probed)
                        .set("not_probed_after_warning", unprobed)
                        .set("support_lever_arms", levers)
                        .set("probe_compliances", compliances));
  }

  template class SolutionChecks<2>;
  template class SolutionChecks<3>;
} // namespace contact_fem
