#include <contact_fem/geometry/model_frame.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q_cache.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/numerics/vector_tools.h>

#include <contact_fem/postprocess/contact_results.h>
#include <contact_fem/simulator/contact_problem.h>
#include <contact_fem/simulator/dof_setup.h>
#include <contact_fem/contact/friction/friction_capacity.h>
#include <contact_fem/simulator/search_control.h>
#include <contact_fem/simulator/solution_checks.h>
#include <contact_fem/core/format.h>
#include <contact_fem/core/interruption.h>
#include <contact_fem/core/parameters.h>
#include <contact_fem/geometry/mesh_file.h>
#include <contact_fem/geometry/mesh_queries.h>
#include <contact_fem/geometry/manifold_mapping.h>
#include <contact_fem/solvers/rigid_body_modes.h>

#include <Epetra_Import.h>
#include <Epetra_Vector.h>

#include <algorithm>
#include <filesystem>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numeric>
#include <optional>
#include <random>
#include <set>
#include <sstream>

namespace contact_fem
{
  namespace
  {
    const char *const multigrid_setup_section = "Solve: multigrid setup";

    /// The wall time of each timer section of the cycle (summary.json),
    /// with the multigrid set-ups' part (@p multigrid_seconds, negative for
    /// a direct solver).
    Json
    timing_record(const TimerOutput &timer, const double multigrid_seconds)
    {
      Json timing = Json::object();
      for (const auto &[name, seconds] : timer.get_summary_data(TimerOutput::total_wall_time))
        timing.set(name, seconds);
      if (multigrid_seconds >= 0.)
        timing.set(multigrid_setup_section, multigrid_seconds);
      return timing;
    }

    /// The wall time of cycle @p cycle and of its timer sections, as
    /// timing_record().
    std::string
    timing_text(const TimerOutput &timer,
                const unsigned int cycle,
                const double       wall,
                const double       cumulative,
                const double       multigrid_seconds)
    {
      std::ostringstream out;
      out << "  Wall time of cycle " << cycle << ": " << wall << " s (cumulative " << cumulative
          << " s), of which" << std::endl;
      for (const auto &[name, seconds] : timer.get_summary_data(TimerOutput::total_wall_time))
        out << "    " << std::left << std::setw(22) << name << std::right << std::setw(10)
            << std::fixed << std::setprecision(4) << seconds << " s" << std::defaultfloat
            << std::setprecision(6) << std::endl;
      if (multigrid_seconds >= 0.)
        out << "    (" << multigrid_setup_section << ": " << std::fixed << std::setprecision(4)
            << multigrid_seconds << " s)" << std::defaultfloat << std::setprecision(6) << std::endl;
      return out.str();
    }

    /// The largest change of a prescribed displacement from @p solution to
    /// the values of @p dirichlet (before they are distributed): a lower
    /// bound of the motion of the step. Collective.
    double
    largest_prescribed_change(const AffineConstraints<double>     &dirichlet,
                              const TrilinosWrappers::MPI::Vector &solution,
                              const MPI_Comm                       comm)
    {
      double largest = 0.;
      for (const auto i : solution.locally_owned_elements())
        if (dirichlet.is_constrained(i) && dirichlet.get_constraint_entries(i)->empty())
          largest = std::max(largest, std::abs(dirichlet.get_inhomogeneity(i) - solution(i)));
      return Utilities::MPI::max(largest, comm);
    }

    /// The contact sets of one Newton iteration (the codes of the rows this
    /// rank owns) and its equilibrium residual (check_for_cycling()).
    struct IterationSets
    {
      std::vector<int> sets;
      double           r_u = 0.;
    };

    /// Records the contact sets of @p contact after @p iteration, with its
    /// equilibrium residual @p r_u, and throws a NewtonFailure (splittable)
    /// when they repeat those of an earlier iteration although they changed
    /// and the residual has not fallen far since: the iteration cycles.
    /// Each rank records and compares the codes of the rows it owns (the
    /// others hold copies of the owners' states), the verdicts reduced over
    /// the ranks. Collective.
    template <int dim>
    void
    check_for_cycling(const ContactFormulation<dim> &contact,
                      const ContactInterface<dim>   &interface,
                      const std::string             &at,
                      const unsigned int             iteration,
                      const unsigned int             changes,
                      const double                   r_u,
                      std::vector<IterationSets>    &sets_of_iteration)
    {
      // An empty set: the formulation offers no detection.
      const std::vector<int> codes   = contact.contact_sets();
      const bool             detects = !codes.empty();
      std::vector<int>       owned;
      if (detects)
        for (const auto &s : interface.slave_nodes)
          if (interface.owns_row(s))
            owned.push_back(codes[s.node]);
      sets_of_iteration.push_back({owned, r_u});
      // The sets of the
      // step's start (iteration 0) do not count: the first iterate takes the
      // whole increment in one linear step and may push a node across its
      // bound for one iteration, and coming back to the start's sets is then
      // the iteration recovering, not a cycle (3D ironing with mu = 0.3: a
      // slip node behind the die stuck after the first iterate only, whose
      // slip pointed forward at every step size, and the step failed after
      // 4 splits; the next iterates converged). A real cycle repeats the
      // sets of its own iterates one iteration later.
      constexpr unsigned int first_compared = 1;
      // Nor does a set the iteration comes back to with a residual below
      // 1e-2 of the one it had there: it passes through the set again on
      // its way in, not round a cycle, whose iterates keep their distance
      // from the solution. (A rotating step of 3D mpc frictional: the
      // linearised rotation leaves errors far above the slip of the nodes
      // that slip least for two iterations, one such node sticks when its
      // slip turns back and slips again along its traction, and the sets
      // of iteration 1 return at iteration 5 with the residual 4e-5 of
      // theirs; the next iterations converge. doc/finite_strain.md,
      // "Multipoint constraints on the current configuration".) The
      // residual is the same on every rank.
      constexpr double progress = 1e-2;
      const auto      &now      = sets_of_iteration.back();
      if (changes == 0 || iteration < first_compared + 2 || !detects)
        return;
      const MPI_Comm   comm = interface.communicator();
      std::vector<int> same;
      for (unsigned int k = first_compared; k + 1 < iteration; ++k)
        same.push_back(sets_of_iteration[k].sets == now.sets);
      Utilities::MPI::min(same, comm, same);
      for (unsigned int k = first_compared; k + 1 < iteration; ++k)
        if (same[k - first_compared] && !(now.r_u < progress * sets_of_iteration[k].r_u))
          {
            unsigned int differing = 0;
            for (unsigned int n = 0; n < now.sets.size(); ++n)
              differing += sets_of_iteration[iteration - 1].sets[n] != now.sets[n];
            differing = Utilities::MPI::sum(differing, comm);
            throw NewtonFailure(at + ": the stick/slip set cycles: iteration " +
                                  std::to_string(iteration) +
                                  " brings back the contact sets "
                                  "of iteration " +
                                  std::to_string(k) + " (period " + std::to_string(iteration - k) +
                                  ", " + std::to_string(differing) +
                                  " node(s) switching), so the "
                                  "semi-smooth Newton iteration cannot settle. Smaller load "
                                  "steps usually break the cycle (the step is split)." +
                                  contact.non_convergence_note(),
                                true);
          }
    }


    /// Throws a NewtonFailure at @p at if a residual is not a number, with
    /// the hint that @p singular_hint() gives.
    template <typename Hint>
    void
    throw_if_not_finite(const std::string &at,
                        const double       r_u,
                        const double       r_lambda,
                        const Hint        &singular_hint)
    {
      if (!std::isfinite(r_u) || !std::isfinite(r_lambda))
        throw NewtonFailure(at + ": the residual is not a number (|r_u| = " + scientific(r_u) +
                            ", |r_lambda| = " + scientific(r_lambda) +
                            "). The linear system is singular or the input is extreme." +
                            singular_hint());
    }

    /// Why a run whose converged state is outside the model's range stops
    /// (summary.json @p status, exit code 3).
    std::string
    outside_model_range_stop(const std::string &status)
    {
      return "Stopped: the converged state is outside the model's range (see the warnings "
             "above): small-strain linear elasticity does not describe these bodies under "
             "this load, so the results are no answer of them (summary.json status '" +
             status +
             "', exit code 3). Model range/Accept results outside the small-strain range = "
             "true accepts them.";
    }

    /// "Progress: load step k of N of cycle c done, ..." after @p n_solved
    /// load steps with @p left to go, @p elapsed seconds into the cycle; the
    /// remainder is estimated from the mean time per load step so far.
    std::string
    progress_line(const unsigned int cycle,
                  const unsigned int n_solved,
                  const unsigned int left,
                  const double       elapsed)
    {
      std::string line = "  Progress: load step " + std::to_string(n_solved) + " of " +
                         std::to_string(n_solved + left) + " of cycle " + std::to_string(cycle) +
                         " done, " + significant(elapsed, 3) + " s in this cycle";
      if (left > 0)
        line += ", about " + significant(elapsed / n_solved * left, 2) + " s to go";
      return line;
    }
  } // namespace


  template <int dim>
  void
  ContactProblem<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3),
                      "Space dimension of the scene: 2 (plane strain) or 3.");
    prm.enter_subsection("Finite element");
    prm.declare_entry("Degree", "1", Patterns::Integer(1, 2),
                      "Polynomial degree of the displacement (Q1 or Q2).");
    prm.declare_entry("Mapping degree", "auto", Patterns::Selection("auto|1|2"),
                      "Polynomial degree of the geometry. auto: the element "
                      "degree, but 2 for Q1 on scenes with curved boundaries "
                      "(Geometry/Type = hertz cylinder or hertz sphere, or "
                      "Geometry/Manifolds), in 2D and 3D: Q1 faces then "
                      "follow the arc (the sphere, the cylinder) instead of "
                      "its chords (facets), whose "
                      "sag, where the "
                      "element size changes along a contact surface, shifts "
                      "the gap and disturbs the contact pressure by up to "
                      "0.5 % (doc/convergence.md). 1 keeps the chords (as "
                      "Kratos' linear elements do).");
    prm.declare_entry("Volumetric strain", "standard", Patterns::Selection("standard|B-bar"),
                      "standard: the full strain in the elastic law. B-bar: the "
                      "volumetric strain div u is projected per cell onto "
                      "polynomials of degree p - 1 (selective, mean dilatation "
                      "for Q1, Q2-P1 for Q2), which removes volumetric locking "
                      "of nearly incompressible bodies (nu close to 0.5). "
                      "Finite-strain bodies (Materials/Models) then use its "
                      "finite-strain counterpart F-bar (the volume change of "
                      "the cell centre at every point), implemented for Q1 "
                      "only (doc/finite_strain.md).");
    prm.declare_entry("DoF renumbering seed", "0", Patterns::Integer(0),
                      "0: the DoFs in deal.II's order. Else a random order "
                      "of each rank's DoFs, drawn with this seed (the same "
                      "for a given seed and number of ranks): the results "
                      "change by round-off only. The tests with the ctest "
                      "label 'perturbed' use it to find outputs that depend "
                      "on round-off.");
    prm.leave_subsection();
    LinearSolver::declare_parameters(prm);
    Scene<dim>::declare_parameters(prm);
    Materials<dim>::declare_parameters(prm);
    BoundaryConditions::declare_parameters(prm);
    LoadStepping::declare_parameters(prm);
    ContactParameters::declare_parameters(prm);
    ContactFormulation<dim>::declare_parameters(prm);
    NewtonParameters::declare_parameters(prm);
    RefinementParameters::declare_parameters(prm);
    StressRecoverySettings::declare_parameters(prm);
    AnalyticalSolution::declare_parameters(prm);
    OutputParameters::declare_parameters(prm);
    Postprocessor<dim>::declare_all_parameters(prm);
    ModelRange::declare_parameters(prm);
  }

  namespace
  {
    /// One entry of @p subsection, for the members made before the body
    /// of the constructor runs.
    std::string
    read_entry(ParameterHandler &prm, const std::string &subsection, const std::string &key)
    {
      prm.enter_subsection(subsection);
      const std::string value = prm.get(key);
      prm.leave_subsection();
      return value;
    }
  } // namespace

  template <int dim>
  ContactProblem<dim>::ContactProblem(ParameterHandler  &prm,
                                      const std::string &scene_name,
                                      const std::string &prm_directory)
    : comm(MPI_COMM_WORLD)
    , log(comm)
    , pcout(log.stream(), Utilities::MPI::this_mpi_process(comm) == 0)
    , scene_name(scene_name)
    , degree(std::stoul(read_entry(prm, "Finite element", "Degree")))
    , triangulation(comm,
                    typename Triangulation<dim>::MeshSmoothing(
                      Triangulation<dim>::limit_level_difference_at_vertices))
    , fe(FE_Q<dim>(degree), dim)
    , dof_handler(triangulation)
    , linear_solver(LinearSolver::create(prm))
  {
    // Every parameter is read and checked before any work is done.
    scene.parse_parameters(prm, prm_directory);
    effective_input = apply_scene_settings(prm, scene.type);
    // "auto" depends on the scene: Q1 follows curved boundaries on a
    // quadratic mapping, in 2D and 3D.
    const std::string  mapping_degree  = read_entry(prm, "Finite element", "Mapping degree");
    const unsigned int geometry_degree = mapping_degree != "auto"    ? std::stoul(mapping_degree) :
                                         scene.has_curved_boundary() ? std::max(degree, 2u) :
                                                                       degree;
    // A curved mapping takes its support points from the manifolds: cached
    // once per mesh, in setup_dofs() (fill_mapping_cache()).
    if (geometry_degree > 1)
      mapping = std::make_unique<MappingQCache<dim>>(geometry_degree);
    else
      mapping = std::make_unique<MappingQ<dim>>(1);
    prm.enter_subsection("Finite element");
    if (prm.get("Volumetric strain") == "B-bar")
      volumetric_projection = std::make_unique<VolumetricProjection<dim>>(*mapping, fe);
    dof_renumbering_seed = prm.get_integer("DoF renumbering seed");
    prm.leave_subsection();
    materials.parse_parameters(prm);
    if (materials.finite_strain())
      finite_strain = std::make_unique<FiniteStrainBulk<dim>>(materials, *mapping, fe,
                                                              volumetric_projection != nullptr);
    boundary_conditions.parse_parameters(prm, dim);
    load_stepping.parse_parameters(prm);
    contact_parameters.parse_parameters(prm);
    // Read (and checked) whether or not the scene has contact pairs; kept
    // only if it has.
    auto formulation = ContactFormulation<dim>::create(prm);
    if (!contact_parameters.pairs.empty())
      {
        contact       = std::move(formulation);
        friction_laws = FrictionParameters::parse_laws(prm);
      }
    // Finite deformation only: small-strain scenes pay nothing.
    if (finite_strain || (contact && contact_parameters.current_kinematics))
      {
        std::vector<ContactPair> pairs = contact_parameters.pairs;
        pairs.insert(pairs.end(), contact_parameters.tied_pairs.begin(),
                     contact_parameters.tied_pairs.end());
        interpenetration =
          std::make_unique<InterpenetrationCheck<dim>>(dof_handler, *mapping, pairs,
                                                       contact_parameters.penetration_tolerance);
      }
    newton_parameters.parse_parameters(prm);
    refinement.parse_parameters(prm);
    spr_settings.parse_parameters(prm);
    analytical.parse_parameters(prm, prm_directory, dim);
    check_analytical_geometry();
    analytical.move_origin(scene.frame.origin[0], scene.frame.origin[1], dim);
    comparison = AnalyticalComparison<dim>::create(analytical);
    output.parse_parameters(prm, dim);
    model_range.parse_parameters(prm);
    if (model_range.accept_interpenetration)
      interpenetration.reset();
    memory_warning = input_checks().check_scene_before_meshing(inclined_supports, triangulation);

    timer = std::make_unique<TimerOutput>(comm, pcout, TimerOutput::never, TimerOutput::wall_times);
    postprocessors = Postprocessor<dim>::create_wanted(
      {prm, output, analytical, static_cast<bool>(contact), !contact_parameters.tied_pairs.empty(),
       [this](const std::string &kind, const std::string &text, Json &record) {
         warn(kind, text, record);
       },
       *timer, comm});
  }

  template <int dim>
  void
  ContactProblem<dim>::check_analytical_geometry() const
  {
    // A built-in Hertz body has its own radius and touches at the origin:
    // a closed form of another radius or centre compares the run with
    // another problem ("p_max within 2 % of Hertz: no" on a right answer).
    const bool cylinder = scene.type == "hertz cylinder" &&
                          (analytical.type == "hertz cylinder" || analytical.type == "cattaneo");
    const bool sphere = scene.type == "hertz sphere" &&
                        (analytical.type == "hertz sphere" || analytical.type == "cattaneo");
    if (!cylinder && !sphere)
      return;
    const std::string geometry = cylinder ? "Hertz cylinder" : "Hertz sphere";
    const double      R        = cylinder ? scene.hertz.radius : scene.hertz_sphere.radius;
    const auto        text     = [](const double v) {
      std::ostringstream out;
      out << std::setprecision(10) << v;
      return out.str();
    };
    AssertThrow(std::abs(analytical.radius - R) <= 1e-10 * R,
                ExcMessage("Analytical solution/Radius = " + text(analytical.radius) +
                           " differs from the radius of the body it is compared with, "
                           "Geometry/" +
                           geometry + "/Radius = " + text(R) +
                           " (the closed form would be that of another body); set both "
                           "to the same value."));
    AssertThrow(std::abs(analytical.center) <= 1e-10 * R &&
                  (cylinder || std::abs(analytical.center_y) <= 1e-10 * R),
                ExcMessage("Analytical solution/Center" +
                           std::string(cylinder ? "" : " and Center y") + " = " +
                           text(analytical.center) +
                           (cylinder ? "" : ", " + text(analytical.center_y)) + ": the built-in '" +
                           scene.type + "' touches its plate at the origin; set 0."));
  }

  template <int dim>
  ContactProblem<dim>::~ContactProblem()
  {
    dof_handler.clear();
  }

  template <int dim>
  void
  ContactProblem<dim>::setup_dofs()
  {
    TimerOutput::Scope t(*timer, "Setup: DoFs");
    if (auto *cache = dynamic_cast<MappingQCache<dim> *>(mapping.get()))
      fill_mapping_cache(triangulation, *cache);
    distribute_dofs(dof_handler, fe, dof_renumbering_seed);
    owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant_dofs);

    hanging_constraints.clear();
    hanging_constraints.reinit(relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, hanging_constraints);
    hanging_constraints.close();

    solution.reinit(owned_dofs, comm);
    ghosted_solution.reinit(owned_dofs, relevant_dofs, comm);

    locate_fixed_points();
    make_dirichlet_constraints(dirichlet_inputs(), relevant_dofs, 0., dirichlet_constraints);
    if (!contact_parameters.pairs.empty())
      {
        std::set<types::boundary_id> moving_supports;
        for (const auto &condition : boundary_conditions.displacements)
          if (condition.varies_in_space())
            moving_supports.insert(condition.boundary_id);
        interface = std::make_unique<ContactInterface<dim>>();
        interface->initialize(*mapping, dof_handler, contact_parameters.pairs,
                              dirichlet_constraints, hanging_constraints, materials, comm,
                              moving_supports);
        contact->initialize(*interface);
        search = std::make_unique<SearchControl<dim>>(*interface, *contact, contact_parameters,
                                                      *timer, pcout);
      }
    tying.reset();
    if (!contact_parameters.tied_pairs.empty())
      {
        TimerOutput::Scope t(*timer, "Setup: mesh tying");
        tying = std::make_unique<MeshTying<dim>>();
        tying->initialize(*mapping, dof_handler, contact_parameters.tied_pairs,
                          dirichlet_constraints, hanging_constraints, materials,
                          contact_parameters.search_factor,
                          contact_parameters.tied_release_threshold, comm);
        if (interface)
          tying->check_apart_from(*interface);
      }
    // Contact and tying constraints couple slave DoFs to master DoFs
    // anywhere: every rank may write to the rows and entries of all
    // interface DoFs. The constraints store the lines a rank needs only
    // (line_dofs(), with each pattern and constraints), the vectors and the
    // pattern keep this set: the residual is read across a search.
    writable_dofs = relevant_dofs;
    for (const auto *dofs :
         {interface ? &interface->dofs() : nullptr, tying ? &tying->dofs() : nullptr})
      if (dofs)
        {
          IndexSet interface_set(dof_handler.n_dofs());
          interface_set.add_indices(dofs->begin(), dofs->end());
          writable_dofs.add_indices(interface_set);
        }
    system_rhs.reinit(owned_dofs, writable_dofs, comm, true);
    residual.reinit(owned_dofs, writable_dofs, comm, true);
    if (f_bar())
      linearised_residual.reinit(owned_dofs, writable_dofs, comm, true);
    select_linear_solver();
  }

  template <int dim>
  void
  ContactProblem<dim>::select_linear_solver()
  {
    const ProblemTraits traits = diagnosis().problem_traits();
    linear_solver->set_problem(traits);
    if (linear_solver->select(dof_handler.n_dofs()))
      linear_solver->set_near_null_space(rigid_body_modes(*mapping, dof_handler));
  }

  template <int dim>
  void
  ContactProblem<dim>::locate_fixed_points()
  {
    fixed_point_dofs.clear();
    for (const auto &condition : boundary_conditions.points)
      {
        const auto dofs = vertex_dofs(dof_handler, scene.frame, condition.point,
                                      "Boundary conditions/Fixed points");
        if (!dofs.empty())
          fixed_point_dofs.push_back(dofs[condition.component]);
      }
    std::sort(fixed_point_dofs.begin(), fixed_point_dofs.end());
    fixed_point_dofs.erase(std::unique(fixed_point_dofs.begin(), fixed_point_dofs.end()),
                           fixed_point_dofs.end());
    probe_dofs.clear();
    for (const auto &probe : output.displacement_probes)
      probe_dofs.push_back(
        vertex_dofs(dof_handler, scene.frame, probe, "Output/Displacement probes"));
  }

  template <int dim>
  void
  ContactProblem<dim>::compute_cell_matrices()
  {
    TimerOutput::Scope t(*timer, "Assembly: bulk");
    const QGauss<dim>  quadrature(degree + 1);
    FEValues<dim>      fe_values(*mapping, fe, quadrature, update_gradients | update_JxW_values);
    const unsigned int n = fe.n_dofs_per_cell();
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> strains(n);
    std::vector<double>                  theta(n);

    cell_matrices.assign(triangulation.n_active_cells(), FullMatrix<double>());
    cell_offsets.assign(finite_strain ? triangulation.n_active_cells() : 0, Vector<double>());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && !(finite_strain && finite_strain->law(cell->material_id())))
        {
          fe_values.reinit(cell);
          FullMatrix<double> &K = cell_matrices[cell->active_cell_index()];
          K.reinit(n, n);
          if (volumetric_projection)
            {
              // B-bar: 2 mu eps:eps + lambda theta theta, theta projected.
              volumetric_projection->reinit(cell);
              const ElasticConstants &c      = materials.constants(cell->material_id());
              const double            lambda = c.lambda(), mu = c.mu();
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                {
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      strains[i] = fe_values[displacement].symmetric_gradient(i, q);
                      theta[i]   = volumetric_projection->shape_value(i, quadrature.point(q));
                    }
                  for (unsigned int i = 0; i < n; ++i)
                    for (unsigned int j = 0; j <= i; ++j)
                      K(i, j) +=
                        (2. * mu * (strains[i] * strains[j]) + lambda * theta[i] * theta[j]) *
                        fe_values.JxW(q);
                }
            }
          else
            {
              const SymmetricTensor<4, dim> C = materials.stiffness_tensor(cell->material_id());
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                {
                  for (unsigned int i = 0; i < n; ++i)
                    strains[i] = fe_values[displacement].symmetric_gradient(i, q);
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      const SymmetricTensor<2, dim> Ceps = C * strains[i];
                      for (unsigned int j = 0; j <= i; ++j)
                        K(i, j) += (Ceps * strains[j]) * fe_values.JxW(q);
                    }
                }
            }
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = i + 1; j < n; ++j)
              K(i, j) = K(j, i);
        }
  }

  template <int dim>
  void
  ContactProblem<dim>::compute_cell_loads(const double time)
  {
    TimerOutput::Scope    t(*timer, "Assembly: bulk");
    const QGauss<dim - 1> quadrature(degree + 1);
    FEFaceValues<dim>     fe_face(*mapping, fe, quadrature,
                                  update_values | update_normal_vectors | update_quadrature_points |
                                    update_JxW_values);
    cell_loads.assign(triangulation.n_active_cells(), Vector<double>());
    // Adds the loads of the faces on the boundaries @p ids (one per
    // condition c), cell by cell and face by face: traction(c, q) is the
    // traction of condition c at quadrature point q of the face.
    const auto add_face_loads = [&](const std::vector<types::boundary_id> &ids,
                                    const auto                            &traction) {
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              for (unsigned int c = 0; c < ids.size(); ++c)
                if (cell->face(f)->boundary_id() == ids[c])
                  {
                    fe_face.reinit(cell, f);
                    Vector<double> &load = cell_loads[cell->active_cell_index()];
                    if (load.size() == 0)
                      load.reinit(fe.n_dofs_per_cell());
                    for (unsigned int q = 0; q < quadrature.size(); ++q)
                      {
                        const Tensor<1, dim> t_q = traction(c, q);
                        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                          load(i) += t_q[fe.system_to_component_index(i).first] *
                                     fe_face.shape_value(i, q) * fe_face.JxW(q);
                      }
                  }
    };
    std::vector<types::boundary_id>                 ids;
    std::vector<std::unique_ptr<UserFunction<dim>>> functions;
    for (const auto &condition : boundary_conditions.pressures)
      {
        ids.push_back(condition.boundary_id);
        functions.push_back(
          std::make_unique<UserFunction<dim>>(std::vector<std::string>{condition.expression},
                                              scene.frame));
        functions.back()->set_time(time);
      }
    add_face_loads(ids, [&](const unsigned int c, const unsigned int q) {
      return -functions[c]->value(fe_face.quadrature_point(q)) * fe_face.normal_vector(q);
    });
    // Traction vectors (Boundary conditions/Traction): one parser per
    // component.
    ids.clear();
    functions.clear();
    for (const auto &condition : boundary_conditions.tractions)
      {
        ids.push_back(condition.boundary_id);
        functions.push_back(
          std::make_unique<UserFunction<dim>>(condition.expressions, scene.frame));
        functions.back()->set_time(time);
      }
    add_face_loads(ids, [&](const unsigned int c, const unsigned int q) {
      Tensor<1, dim> t_q;
      for (unsigned int d = 0; d < dim; ++d)
        t_q[d] = functions[c]->value(fe_face.quadrature_point(q), d);
      return t_q;
    });
  }

  template <int dim>
  void
  ContactProblem<dim>::add_interface_hanging_constraints(
    AffineConstraints<double> &constraints) const
  {
    // A contact patch couples DoFs of the whole surface: on 2 ranks a hanging
    // vertex off this rank's cells kept its raw row and column, and the
    // owner dropped them (3D adaptive current kinematics stalled).
    if (!interface)
      return;
    for (const auto &node : interface->nodes)
      if (!node.parents.empty())
        for (unsigned int d = 0; d < dim; ++d)
          if (constraints.can_store_line(node.dofs[d]) && !constraints.is_constrained(node.dofs[d]))
            {
              constraints.add_line(node.dofs[d]);
              for (const auto &[parent, weight] : node.parents)
                constraints.add_entry(node.dofs[d], interface->nodes[parent].dofs[d], weight);
            }
  }

  namespace
  {
    /// The DoFs a rank's constraints store lines at (their local lines), a
    /// subset of the DoFs the vectors and the pattern may write to
    /// (writable_dofs): the relevant DoFs, the contact formulation's lines
    /// (ContactFormulation::line_dofs()) and the tied interface's, closed
    /// under the masters of both together.
    template <int dim>
    IndexSet
    line_dofs(const IndexSet                &relevant_dofs,
              const ContactFormulation<dim> *contact,
              const ContactInterface<dim>   *interface,
              const MeshTying<dim>          *tying)
    {
      IndexSet lines = relevant_dofs;
      if (contact)
        lines.add_indices(contact->line_dofs(*interface));
      if (tying)
        lines.add_indices(tying->interface().line_dofs());
      ContactInterface<dim>::close_line_dofs(lines,
                                             {interface, tying ? &tying->interface() : nullptr});
      return lines;
    }

    /// With the check of the held state: the lines of @p held at @p dofs,
    /// the formulation's line_seeds() (read beyond the relevant DoFs, which
    /// check_held_lines() compares), must be those of @p full, bit for bit,
    /// as check_held_lines() asks. Collective: every rank stops when one
    /// finds a difference.
    void
    check_lines_at(const AffineConstraints<double>            &held,
                   const AffineConstraints<double>            &full,
                   const std::vector<types::global_dof_index> &dofs,
                   const MPI_Comm                              comm)
    {
      const unsigned int wrong = count_differing_lines(held, full, dofs, comm);
      AssertThrow(wrong == 0,
                  ExcMessage("The constraint lines of the held slave nodes differ from those of "
                             "every slave node at " +
                             std::to_string(wrong) +
                             " DoFs of the formulation's seeds (ContactFormulation::line_seeds()) "
                             "the ranks read."));
    }
  } // namespace

  template <int dim>
  void
  ContactProblem<dim>::build_constraints(
    AffineConstraints<double>                              &c,
    const IndexSet                                         &lines,
    const std::function<void(AffineConstraints<double> &)> &add_coupling_lines) const
  {
    c.clear();
    c.reinit(lines);
    DoFTools::make_hanging_node_constraints(dof_handler, c);
    add_interface_hanging_constraints(c);
    add_coupling_lines(c);
    c.merge(dirichlet_constraints, AffineConstraints<double>::left_object_wins, true);
    c.close();
  }

  template <int dim>
  void
  ContactProblem<dim>::check_held_constraints(
    const AffineConstraints<double>                        &held,
    const std::function<void(AffineConstraints<double> &)> &add_coupling_lines) const
  {
    const ContactInterface<dim> *checker = interface ? interface.get() :
                                           tying     ? &tying->interface() :
                                                       nullptr;
    if (!checker || !ContactInterface<dim>::checking_held_state())
      return;
    AffineConstraints<double> full;
    build_constraints(full, writable_dofs, add_coupling_lines);
    checker->check_held_lines(held, full);
    check_lines_at(held,
                   full,
                   contact ? contact->line_seeds(*interface) :
                             std::vector<types::global_dof_index>(),
                   comm);
  }

  template <int dim>
  void
  ContactProblem<dim>::make_sparsity_pattern()
  {
    TimerOutput::Scope t(*timer, "Setup: sparsity");
    // All candidate contact constraints at once: the pattern then holds
    // every coupling any active set of this search can create, and the
    // constrained rows keep their own entries (keep_constrained_dofs).
    // The lines of the slave nodes this rank needs only (line_dofs()).
    const auto candidate_lines = [this](AffineConstraints<double> &c) {
      if (tying)
        tying->add_constraints(c, false, true);
      if (contact)
        contact->add_constraints(*interface, interface_fixed_values, c, true);
    };
    AffineConstraints<double> candidates;
    build_constraints(candidates,
                      line_dofs(relevant_dofs, contact.get(), interface.get(), tying.get()),
                      candidate_lines);
    check_held_constraints(candidates, candidate_lines);
    // close() drops from a chained line (a slave whose master is another
    // pair's slave) the middle DoF, replaced by that DoF's own masters; but
    // when the middle node is open, or sticks/slips along other components,
    // the lines of the iterate name it directly (a frictional chain summed
    // outside the pattern). The walk below follows the unclosed contact
    // lines to such middle DoFs too: only where a chain can occur, a node
    // on a slave and a master surface (other scenes pay nothing).
    AffineConstraints<double> open_lines;
    if (contact && interface->has_chained_nodes())
      {
        open_lines.reinit(writable_dofs);
        contact->add_constraints(*interface, interface_fixed_values, open_lines, true);
      }
    const auto is_chain_middle = [&](const types::global_dof_index dof) {
      return open_lines.can_store_line(dof) && open_lines.is_constrained(dof);
    };

    // Every DoF of a cell couples with every other one and with the masters
    // of those that are constrained: a superset of the couplings of any
    // subset of the candidate constraints.
    DynamicSparsityPattern               dsp(writable_dofs);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> closure;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          // A slave DoF may also be the parent of a hanging node: follow the
          // hanging parents and the (closed) candidate masters of every DoF
          // reached, so both the chained and the unchained forms are covered.
          // Every DoF enters the closure once, so the walk ends by itself
          // (a bound on it cut off the DoFs of a Q2 hexahedron, 81 > 64).
          closure = dofs;
          for (unsigned int k = 0; k < closure.size(); ++k)
            for (const auto *c : {&hanging_constraints, &candidates, &open_lines})
              if (c->can_store_line(closure[k]))
                if (const auto *entries = c->get_constraint_entries(closure[k]))
                  for (const auto &entry : *entries)
                    if ((c != &open_lines || is_chain_middle(entry.first)) &&
                        std::find(closure.begin(), closure.end(), entry.first) == closure.end())
                      closure.push_back(entry.first);
          std::sort(closure.begin(), closure.end());
          closure.erase(std::unique(closure.begin(), closure.end()), closure.end());
          for (const auto row : closure)
            dsp.add_entries(row, closure.begin(), closure.end(), true);
        }
    if (contact)
      contact->add_sparsity(*interface, candidates, owned_dofs, dsp);
    SparsityTools::distribute_sparsity_pattern(dsp, owned_dofs, comm, writable_dofs);
    linear_solver->clear();
    system_matrix.reinit(owned_dofs, owned_dofs, dsp, comm);
  }

  template <int dim>
  void
  ContactProblem<dim>::make_constraints()
  {
    // The lines of the slave nodes this rank needs (line_dofs()).
    const IndexSet lines = line_dofs(relevant_dofs, contact.get(), interface.get(), tying.get());
    const auto     trial_lines = [this](AffineConstraints<double> &c) {
      if (tying)
        tying->add_constraints(c);
      if (contact)
        contact->add_constraints(*interface, interface_fixed_values, c, false);
    };
    build_constraints(constraints, lines, trial_lines);
    check_held_constraints(constraints, trial_lines);
    if (contact && !contact->symmetric())
      {
        const auto test_lines = [this](AffineConstraints<double> &c) {
          if (tying)
            tying->add_constraints(c, true);
          contact->add_test_constraints(*interface, interface_fixed_values, c);
        };
        build_constraints(test_constraints, lines, test_lines);
        check_held_constraints(test_constraints, test_lines);
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::assemble_system()
  {
    TimerOutput::Scope t(*timer, "Assembly: system");
    system_matrix = 0.;
    system_rhs    = 0.;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    const Vector<double>                 no_load(fe.n_dofs_per_cell());
    Vector<double>                       load_with_offset;
    const bool                           symmetric = !contact || contact->symmetric();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          const unsigned int    index = cell->active_cell_index();
          const Vector<double> *load = cell_loads[index].size() > 0 ? &cell_loads[index] : &no_load;
          if (finite_strain && cell_offsets[index].size() > 0)
            {
              // f - (f_int(u) - K_T(u) u): Newton's step for the total u.
              load_with_offset = *load;
              load_with_offset -= cell_offsets[index];
              load = &load_with_offset;
            }
          if (symmetric)
            constraints.distribute_local_to_global(cell_matrices[index], *load, dofs, system_matrix,
                                                   system_rhs);
          else
            distribute_two_space(cell_matrices[index], *load, dofs, constraints, test_constraints,
                                 system_matrix, system_rhs);
        }
    if (contact)
      contact->assemble(*interface, constraints, symmetric ? constraints : test_constraints,
                        owned_dofs, system_matrix, system_rhs);
    system_matrix.compress(VectorOperation::add);
    system_rhs.compress(VectorOperation::add);
  }

  template <int dim>
  void
  ContactProblem<dim>::solve_linear_system(const double newton_residual_target)
  {
    TimerOutput::Scope  t(*timer, "Solve: linear");
    LinearSystemRequest request;
    request.symmetric              = !contact || contact->matrix_symmetric();
    request.newton_residual_target = newton_residual_target;
    last_relative_linear_residual  = std::numeric_limits<double>::quiet_NaN();
    last_linear_residual =
      linear_solver->solve(system_matrix, solution, system_rhs, request);
    const double linear_residual = last_linear_residual;
    last_relative_linear_residual = linear_residual / system_rhs.l2_norm();
    linear_iterations_of_step.push_back(linear_solver->last_iterations());
    multigrid_setup_seconds += linear_solver->take_setup_seconds();
    if (const std::string note = linear_solver->take_note(); !note.empty())
      pcout << "    Note: " << note << "." << std::endl;
    // A singular system (a body held by nothing) does not always make the
    // direct solver fail: check that the solution solves it. Singular
    // systems leave O(1) residuals that refinement does not reduce.
    AssertThrow(std::isfinite(linear_residual) &&
                  linear_residual <= singular_residual_ratio * system_rhs.l2_norm() + 1e-300,
                ExcMessage("the linear system is singular (relative residual " +
                           scientific(linear_residual / system_rhs.l2_norm()) +
                           " after the linear solve)"));
    // Only solves whose solution is used: a failed one is reported (and
    // its step may be split), it leaves no undetermined mode in the results.
    if (linear_solver->n_null_pivots() > 0)
      {
        ++singular_solves;
        most_null_pivots = std::max(most_null_pivots, linear_solver->n_null_pivots());
      }
    else
      regular_solve_seen = true;
    constraints.distribute(solution);
    ghosted_solution = solution;
  }

  template <int dim>
  double
  ContactProblem<dim>::residual_round_off() const
  {
    // The columns of the owned rows may reach DoFs that are not locally
    // relevant (mortar couplings): x on the matrix' column map.
    const Epetra_CrsMatrix &A = system_matrix.trilinos_matrix();
    Epetra_Vector           x(A.ColMap());
    x.Import(solution.trilinos_vector(),
             Epetra_Import(A.ColMap(), solution.trilinos_vector().Map()), Insert);
    // The rows are those of the test space (distribute_two_space()).
    const AffineConstraints<double> &rows =
      !contact || contact->symmetric() ? constraints : test_constraints;
    double local = 0.;
    for (int row = 0; row < A.NumMyRows(); ++row)
      if (!rows.is_constrained(TrilinosWrappers::global_row_index(A, row)))
        {
          int     n       = 0;
          double *values  = nullptr;
          int    *columns = nullptr;
          A.ExtractMyRowView(row, n, values, columns);
          double sum = 0.;
          for (int k = 0; k < n; ++k)
            sum += std::abs(values[k]) * std::abs(x[columns[k]]);
          local += sum * sum;
        }
    return std::numeric_limits<double>::epsilon() * std::sqrt(Utilities::MPI::sum(local, comm));
  }

  template <int dim>
  typename FiniteStrainBulk<dim>::CellLinearisation
  ContactProblem<dim>::relinearise_finite_strain_cell(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const std::vector<types::global_dof_index>           &dofs,
    const Vector<double>                                 &local_u,
    Vector<double>                                       &local_r,
    Vector<double>                                       &linear_minus_r)
  {
    const unsigned int index = cell->active_cell_index();
    // The last step's linear model at this u, K_T u + offset: with F-bar
    // the multipliers are recovered from its residual (linearised_residual).
    const bool linear_model = f_bar() && cell_offsets[index].size() > 0;
    if (linear_model)
      {
        cell_matrices[index].vmult(linear_minus_r, local_u);
        linear_minus_r += cell_offsets[index];
      }
    // The tangent and offset of the next Newton step, at this u.
    const auto linearisation =
      finite_strain->linearise(cell, local_u, cell_matrices[index], local_r);
    cell_offsets[index].reinit(local_u.size());
    cell_matrices[index].vmult(cell_offsets[index], local_u);
    cell_offsets[index].sadd(-1., 1., local_r);
    if (linear_model)
      {
        linear_minus_r -= local_r;
        hanging_constraints.distribute_local_to_global(linear_minus_r, dofs, linearised_residual);
      }
    return linearisation;
  }

  template <int dim>
  void
  ContactProblem<dim>::compute_residual(const bool linearised_at_start)
  {
    TimerOutput::Scope t(*timer, "Assembly: residual");
    residual = 0.;
    if (f_bar())
      linearised_residual = 0.;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    Vector<double> local_u(fe.n_dofs_per_cell()), local_r(fe.n_dofs_per_cell()),
      linear_minus_r(fe.n_dofs_per_cell());
    double local_strain = 0., local_work = 0.;
    double smallest_jacobian = std::numeric_limits<double>::max();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            local_u(i) = ghosted_solution(dofs[i]);
          const unsigned int index = cell->active_cell_index();
          if (finite_strain && finite_strain->law(cell->material_id()))
            {
              if (linearised_at_start)
                {
                  // f_int(u_n) + K_T(u_n) (u - u_n) = K_T(u_n) u + offset,
                  // with the tangent and offset of the step's start u_n
                  // (which is also the F-bar linear model: no remainder).
                  cell_matrices[index].vmult(local_r, local_u);
                  local_r += cell_offsets[index];
                }
              else
                {
                  const auto linearisation =
                    relinearise_finite_strain_cell(cell, dofs, local_u, local_r, linear_minus_r);
                  smallest_jacobian = std::min(smallest_jacobian, linearisation.smallest_jacobian);
                  local_strain += linearisation.energy;
                }
            }
          else
            {
              cell_matrices[index].vmult(local_r, local_u);
              local_strain += 0.5 * (local_u * local_r);
            }
          if (cell_loads[index].size() > 0)
            {
              local_work += local_u * cell_loads[index];
              local_r -= cell_loads[index];
            }
          // Hanging DoFs pass their residual to their parents (C_h^T r).
          hanging_constraints.distribute_local_to_global(local_r, dofs, residual);
        }
    residual.compress(VectorOperation::add);
    if (tying)
      tying->condense_residual(residual, owned_dofs);
    if (f_bar())
      {
        linearised_residual.compress(VectorOperation::add);
        linearised_residual += residual;
      }
    // An inverted element (det F <= 0) has no strain energy: the iterate
    // overshot, a smaller load step may not.
    if (finite_strain)
      smallest_jacobian = Utilities::MPI::min(smallest_jacobian, comm);
    if (!(smallest_jacobian > 0.))
      throw NewtonFailure(
        "an element of a finite-strain body is inverted (det F = " + scientific(smallest_jacobian) +
        " <= 0 at a quadrature point). Hint: more load steps (Load stepping/"
        "Number of load steps, Maximum step splits)");
    strain_energy = Utilities::MPI::sum(local_strain, comm);
    external_work = Utilities::MPI::sum(local_work, comm);
  }

  template <int dim>
  double
  ContactProblem<dim>::equilibrium_residual_norm(const std::vector<double> &contact_force) const
  {
    // Free DoFs: not Dirichlet, not hanging, each by its owner.
    double local = 0.;
    for (const auto i : owned_dofs)
      if (!dirichlet_constraints.is_constrained(i) && !hanging_constraints.is_constrained(i) &&
          !inclined_supports.holds(i) &&
          !(interface && std::binary_search(interface->dofs().begin(), interface->dofs().end(), i)))
        local += residual(i) * residual(i);
    local += inclined_supports.free_residual_squared(residual);
    double sum = Utilities::MPI::sum(local, comm);
    if (!interface)
      return std::sqrt(sum);
    // The interface DoFs by their owners (contact_force is exact only at
    // the locally relevant DoFs), added in DoF order as in serial.
    std::vector<std::pair<unsigned int, double>> terms;
    for (unsigned int k = 0; k < interface->dofs().size(); ++k)
      if (!interface_dof_fixed[k] && owned_dofs.is_element(interface->dofs()[k]))
        {
          const double r = interface_residual[k] - contact_force[k]; // K u - f - f_contact
          terms.emplace_back(k, r * r);
        }
    return std::sqrt(interface->sum_in_node_order(terms, sum));
  }

  template <int dim>
  void
  ContactProblem<dim>::prepare_load_step(const double    time,
                                         const double    step_size,
                                         const StepStart start)
  {
    current_time = time;
    step_start   = start;
    start_rule_nodes.clear(); // recorded after this step's iteration 0
    make_dirichlet_constraints(dirichlet_inputs(), relevant_dofs, time, dirichlet_constraints);
    compute_cell_loads(time);
    // Finite strain: the step's first solve takes the tangent of the last
    // converged state with the new prescribed values (the tangential
    // predictor), not the tangent of that state with only the prescribed
    // DoFs moved, whose elements along those boundaries are squeezed by the
    // whole increment (a 15 % step of the 3D patch inverted an element, the
    // 3D patch in 2 steps failed from it). That state itself is never an
    // iterate: the first residual is its linearisation at the start.
    start_tangent_kept = false;
    if (finite_strain)
      try
        {
          ghosted_solution = solution;
          compute_residual();
          start_tangent_kept = true;
        }
      catch (const NewtonFailure &) // no tangent there: the first iterate's
        {}
    // Start from the last converged state with the new prescribed values.
    const double prescribed =
      contact ? largest_prescribed_change(dirichlet_constraints, solution, comm) : 0.;
    dirichlet_constraints.distribute(solution);
    ghosted_solution = solution;
    if (tying)
      tying->set_fixed_values([this](const types::global_dof_index i) {
        return dirichlet_constraints.is_constrained(i) ?
                 dirichlet_constraints.get_inhomogeneity(i) :
                 0.;
      });
    if (contact)
      {
        interface_fixed_values = interface->gather([this](const types::global_dof_index i) {
          return dirichlet_constraints.is_constrained(i) ?
                   dirichlet_constraints.get_inhomogeneity(i) :
                   0.;
        });
        interface_displacement = interface->gather(solution);
        search->start_step(interface_displacement, prescribed, step_size, start);
      }
    make_sparsity_pattern();
    factorisation_current = false;
  }

  template <int dim>
  void
  ContactProblem<dim>::newton_update(const std::string &where, const double newton_residual_target)
  {
    make_constraints();
    assemble_system();
    const TrilinosWrappers::MPI::Vector previous_solution = solution;
    try
      {
        solve_linear_system(newton_residual_target);
        factorisation_current = true;
      }
    catch (const LinearSolverFailure &e)
      {
        if (e.singular && contact && contact->slides_everywhere())
          throw NewtonFailure(
            where + ": " + e.what() + ": " +
            exceeded_friction_capacity({}, diagnosis().friction_held_translations()));
        if (e.singular)
          throw singular_failure(where + ": " + e.what());
        throw NewtonFailure(where + ": " + e.what() + "." + diagnosis().precision_hint(), false);
      }
    catch (const std::exception &e)
      {
        const std::string what  = e.what();
        const auto        pos   = what.find("the linear system is singular");
        const std::string cause = pos != std::string::npos ?
                                    what.substr(pos, what.find(')', pos) - pos + 1) :
                                    std::string("the linear solver failed");
        // Split: an overshooting iterate near a load reversal slips everywhere.
        if (pos != std::string::npos && contact && contact->slides_everywhere())
          throw NewtonFailure(
            where + ": " + cause + ": " +
            exceeded_friction_capacity({}, diagnosis().friction_held_translations()));
        if (pos != std::string::npos)
          throw singular_failure(where + ": " + cause);
        throw NewtonFailure(where + ": " + cause + "." + diagnosis().singular_system_hint(), false);
      }
    // Both iterates satisfy the hanging-node and Dirichlet constraints, and
    // so does their combination.
    if (newton_parameters.damping < 1.)
      {
        solution.sadd(newton_parameters.damping, 1. - newton_parameters.damping, previous_solution);
        ghosted_solution = solution;
      }
    // A formulation may shorten the update (a penalty's node re-entering
    // contact on the current configuration: step_fraction()).
    if (contact && contact->limits_steps())
      {
        const double fraction =
          contact->step_fraction(*interface, interface->gather(previous_solution),
                                 interface->gather(solution));
        if (fraction < 1.)
          {
            solution.sadd(fraction, 1. - fraction, previous_solution);
            ghosted_solution = solution;
          }
      }
  }

  template <int dim>
  NewtonFailure
  ContactProblem<dim>::singular_failure(const std::string &what) const
  {
    // A tangent that depends on the iterate (finite strain, contact on the
    // current configuration) and was regular in an earlier solve of this
    // load path: the supports hold the bodies, this iterate is far from
    // equilibrium (or past a limit point), and a smaller step may not be.
    if ((finite_strain || (contact && contact_parameters.current_kinematics)) && regular_solve_seen)
      return NewtonFailure(what +
                           ": the tangent of this iterate is singular, although an earlier "
                           "solve of this load path was regular (the bodies are held). Hint: "
                           "more load steps (Load stepping/Number of load steps, Maximum step "
                           "splits)");
    return NewtonFailure(what + "." + diagnosis().singular_system_hint(last_relative_linear_residual),
                         false);
  }

  template <int dim>
  typename ContactProblem<dim>::ContactUpdate
  ContactProblem<dim>::update_contact(const unsigned int iteration)
  {
    ContactUpdate update;
    if (!contact)
      {
        update.residuals.contact_force.assign(interface_residual.size(), 0.);
        return update;
      }
    interface_displacement = interface->gather(solution);
    // F-bar: the multipliers of the linear model that gave the iterate, as
    // the semi-smooth Newton takes them (linearised_residual).
    const auto reactions = [this] {
      return interface->gather(f_bar() ? linearised_residual : residual);
    };
    // Current kinematics: the operators of every iterate on its own
    // configuration (the search then always reaches the iterate).
    if (iteration > 0 && contact_parameters.current_kinematics)
      {
        if (search->follow(interface_displacement))
          {
            update.searched_again = true;
            make_sparsity_pattern();
          }
        else if (contact->transmits_shear())
          // The friction rows of an iterate couple its nodes with the
          // masters of its own operators and of the converged ones: the
          // pattern follows the iterate (3D ironing with mu = 0.3 assembled
          // outside it, a Trilinos error, when a node turned to stick).
          make_sparsity_pattern();
      }
    else if (iteration > 0)
      {
        // A wider search restarts the active set from the multipliers: they
        // must be this iterate's, or a node held at zero gap would be
        // decided by the round-off of that gap.
        contact->recover_multipliers(*interface, reactions());
        if (search->extend_if_outrun(interface_displacement))
          {
            update.searched_again = true;
            make_sparsity_pattern();
          }
      }
    TimerOutput::Scope t(*timer, "Contact: active set");
    interface_residual = interface->gather(residual);
    if (iteration > 0)
      {
        contact->recover_multipliers(*interface, f_bar() ? reactions() : interface_residual);
        update.changes = contact->update_active_set(*interface, interface_displacement);
      }
    update.residuals = contact->residuals(*interface, interface_displacement);
    return update;
  }

  template <int dim>
  unsigned int
  ContactProblem<dim>::update_bonds(const std::string &at, const unsigned int iteration)
  {
    const auto update = tying->update_bonds(solution, iteration);
    if (!update.cycling.empty())
      throw NewtonFailure(at + ": " + update.cycling, true);
    return update.changes;
  }

  template <int dim>
  void
  ContactProblem<dim>::solve_load_step(const unsigned int step,
                                       const double       time,
                                       const double       step_size,
                                       const StepStart    start,
                                       Json              &record)
  {
    solving = true;
    Timer step_timer;
    prepare_load_step(time, step_size, start);
    if (step == 0 && start == StepStart::unloaded)
      {
        // Nothing was solved yet: a zero load is an input error.
        solving = false;
        check_load_resolved();
        solving = true;
      }
    pcout << "  Load step " << step + 1 << ", t = " << time << std::endl;
    if (output.print_newton_iterations)
      pcout << NewtonMonitor::header(contact ? contact->iteration_header() : "",
                                     linear_solver->iterative())
            << std::endl;
    linear_iterations_of_step.clear();
    const std::string where =
      "load step " + std::to_string(step + 1) + " (t = " + std::to_string(time) + ")";

    const unsigned int iterations = newton_iterations(where, step, time, step_size);
    if (interpenetration)
      {
        // Before "converged": no boundary vertex inside a body where no
        // contact pair accounts for it (a fold, an unpaired body).
        TimerOutput::Scope t(*timer, "Check: interpenetration");
        const auto         finding =
          interpenetration->check(solution, ghosted_solution,
                                  search ? search->allowed_depths(interface_displacement) :
                                           std::map<types::global_dof_index, double>());
        record.set("interpenetration_check", interpenetration->record(finding));
        if (finding.found)
          {
            interpenetration_finding = interpenetration->record(finding);
            throw NewtonFailure(where + ": " + interpenetration->message(finding), false);
          }
      }
    newton_iterations_of_cycle.push_back(iterations);
    record.set("time", time)
      .set("newton_iterations", iterations)
      .set("converged", true)
      .set("active_slave_nodes", contact ? contact->n_active() : 0u)
      .set("released_tied_nodes", tying ? tying->n_released() : 0u)
      .set("wall_time", step_timer.wall_time());
    if (linear_solver->iterative())
      {
        Json counts = Json::array();
        for (const unsigned int n : linear_iterations_of_step)
          counts.push(n);
        record.set("linear_iterations", counts);
      }
  }

  template <int dim>
  unsigned int
  ContactProblem<dim>::newton_iterations(const std::string &where,
                                         const unsigned int step,
                                         const double       time,
                                         const double       step_size)
  {
    // Per iteration: the equilibrium residual of the free DoFs with the
    // multipliers of the current active set, and the complementarity
    // residual (gap of active nodes, multiplier / k of the others). With
    // it > 0 the multipliers are first recovered from the solution of
    // iteration it and the active set is updated.
    // Nonlinear beyond the active set: the bulk (finite strain), the
    // contact geometry (current kinematics) or the 3D slip directions.
    const bool nonlinear =
      finite_strain != nullptr || (contact && (contact_parameters.current_kinematics ||
                                               (dim == 3 && contact->transmits_shear())));
    NewtonMonitor monitor(newton_parameters, nonlinear);
    {
      const double extent = model_extent(triangulation);
      monitor.set_scene_units(materials.youngs_modulus_range().second * std::pow(extent, dim - 1),
                              extent,
                              contact ? diagnosis().load_displacement_scale(current_time) : 0.,
                              contact ? diagnosis().largest_coordinate() : 0.);
    }
    NewtonMonitor::Assessment assessment;
    // The contact sets after each iteration: a set that comes back after
    // changes means the iteration cycles and would never settle.
    std::vector<IterationSets> sets_of_iteration;
    unsigned int               iteration = 0;
    for (; iteration <= newton_parameters.max_iterations; ++iteration)
      {
        const std::string at = where + ", iteration " + std::to_string(iteration);
        stop_if_interrupted(comm);
        if (iteration > 0)
          {
            check_before_solve(at, iteration);
            newton_update(at, monitor.displacement_target());
            monitor.set_linear_residual(last_linear_residual);
            // Only a flat run may end at a floor: the scale costs a pass over
            // the matrix, which converging iterations do not pay.
            if (monitor.in_flat_run())
              monitor.set_round_off(residual_round_off());
          }
        try
          {
            compute_residual(iteration == 0 && start_tangent_kept);
          }
        catch (const NewtonFailure &failure) // an inverted element: say where
          {
            // And why, when this solve closed gaps that the start rule,
            // not the load, put in contact: that cause comes first.
            std::string       what  = failure.what();
            const std::string cause = contact ? opened_by_start_rule() : std::string();
            if (!cause.empty())
              what = what.substr(0, what.find(" Hint:")) + cause;
            throw NewtonFailure(at + ": " + what, failure.splittable);
          }
        ContactUpdate update;
        try
          {
            update = update_contact(iteration);
          }
        catch (const GeometryFailure &failure)
          {
            // Current kinematics rebuilds the operators on every iterate:
            // surfaces the segmentation refuses are this iterate's (split).
            // Otherwise the search runs on the step start's configuration:
            // fatal there.
            if (!contact_parameters.current_kinematics)
              throw;
            throw NewtonFailure(at + ": its contact surfaces: " + failure.what());
          }
        if (iteration == 0 && contact)
          record_start_rule_nodes();
        const unsigned int bond_changes = tying && iteration > 0 ? update_bonds(at, iteration) : 0u;
        const unsigned int changes      = update.changes + bond_changes;
        const double       r_u          = equilibrium_residual_norm(update.residuals.contact_force);
        const double       r_lambda     = update.residuals.multiplier;
        throw_if_not_finite(at, r_u, r_lambda, [this] {
          return diagnosis().singular_system_hint();
        });
        assessment = monitor.assess(iteration, r_u, r_lambda, changes, update.searched_again);
        // A released tied node changes the model: never accepted at round-off.
        assessment.converged = assessment.converged && bond_changes == 0;
        std::optional<unsigned int> linear_iterations;
        if (linear_solver->iterative())
          linear_iterations = iteration > 0 ? linear_iterations_of_step.back() : 0u;
        if (output.print_newton_iterations)
          pcout << monitor.row(iteration, changes, contact ? contact->n_active() : 0u, assessment,
                               contact ? contact->iteration_cells(iteration) : "",
                               linear_iterations)
                << std::endl;
        if (contact)
          check_for_cycling(*contact, *interface, at, iteration, update.changes, r_u,
                            sets_of_iteration);
        if (assessment.converged && contact &&
            !search->accept(interface_displacement, step, time, step_size))
          {
            // A wider search paired other faces: Newton goes on.
            make_sparsity_pattern();
            assessment.converged = false;
            continue;
          }
        if (assessment.converged)
          break;
      }
    if (assessment.converged && contact && contact->n_active() == 0 &&
        !contact_parameters.allow_loss_of_contact)
      throw diagnosis().no_contact_failure(where, current_time, false, false);
    // A load path whose load at this step is at the round-off of the
    // coordinates (only the end time is checked before the solve: a load
    // path may pass through such loads, e.g. sin(pi t) at t = 1) leaves
    // nothing to converge to; smaller steps do not help. Not on a split
    // step: splits from an unloaded start reach such loads by themselves.
    const bool split_step =
      step_size < load_stepping.end_time / load_stepping.n_steps * (1. - 1e-9);
    if (const std::string round_off =
          contact && !split_step ? diagnosis().load_at_round_off(time) : "";
        !assessment.converged && !round_off.empty())
      throw NewtonFailure(where + " did not converge in " +
                            std::to_string(newton_parameters.max_iterations) +
                            " iterations (its residuals and active-set changes are rounding "
                            "noise). Likely cause: " + round_off + ".",
                          false);
    if (!assessment.converged)
      throw NewtonFailure(where + " did not converge in " +
                            std::to_string(newton_parameters.max_iterations) + " iterations " +
                            monitor.last_residuals() + "." +
                            (!assessment.stalled && !monitor.floor_hint().empty() ?
                               monitor.floor_hint() :
                               diagnosis().non_convergence_hint(assessment.stalled,
                                                                monitor.last_r_u(),
                                                                monitor.last_r_lambda())) +
                            (contact ? contact->non_convergence_note() : std::string()) +
                            diagnosis().precision_hint(),
                          !assessment.stalled && monitor.floor_hint().empty());

    return iteration;
  }

  template <int dim>
  void
  ContactProblem<dim>::check_load_resolved() const
  {
    if (!contact)
      return;
    if (const std::string cause = diagnosis().load_at_round_off(load_stepping.end_time);
        !cause.empty())
      throw std::runtime_error("Boundary conditions: nothing is solved: " + cause + ".");
    // The nominal step times; splits fall between them, where a load that
    // is zero at every one of them is not looked at.
    for (unsigned int k = load_stepping.n_steps; k > 0; --k)
      if (!diagnosis().load_vanishes(load_stepping.end_time * k / load_stepping.n_steps))
        return;
    // Bodies that start inside each other (a shrink fit) press themselves
    // together without a load. 1e-8 of the element size is far above the
    // round-off of touching surfaces.
    double deepest = 0.;
    for (const auto &s : interface->slave_nodes)
      if (interface->owns_row(s))
        deepest = std::max(deepest, -interface->gap(s, interface_displacement) / s.size);
    if (Utilities::MPI::max(deepest, comm) > 1e-8)
      return;
    const std::string steps = std::to_string(load_stepping.n_steps) +
                              " load step(s) up to End time = " +
                              significant(load_stepping.end_time, 6);
    // A load that is not zero between the step times (a pulse, a cycle
    // sampled at its zeros) is never seen by the solves: say so, rather than
    // call the load zero.
    const unsigned int samples = 8;
    for (unsigned int k = 0; k < load_stepping.n_steps; ++k)
      for (unsigned int j = 1; j < samples; ++j)
        if (const double t = load_stepping.end_time * (k + double(j) / samples) /
                             load_stepping.n_steps;
            !diagnosis().load_vanishes(t))
          throw std::runtime_error(
            "Load stepping: the load is zero at each of the " + steps +
            " but not between them (at t = " + significant(t, 6) +
            "): the solves see the load at the step times only, so this scene would solve "
            "u = 0 throughout. Set Number of load steps to resolve the load's path, or check "
            "its expression.");
    throw std::runtime_error(
      "Boundary conditions: the load is zero (every Pressure, Traction and Prescribed "
      "displacement is 0 at each of the " +
      steps +
      "), and no slave node starts inside its master: nothing presses the bodies together, so "
      "the answer is u = 0 without contact pressure, and which touching nodes are in contact "
      "is undetermined (round-off would decide it). Set a load, or check its expression.");
  }

  template <int dim>
  void
  ContactProblem<dim>::record_start_rule_nodes()
  {
    // Only a step from the unloaded state takes nodes apart by the factor
    // beyond 1e-2 of their size (about_to_touch()); no pressure is carried
    // then, so an active node with such a gap is the start rule's.
    start_rule_nodes.clear();
    if (step_start != StepStart::unloaded)
      return;
    for (unsigned int k = 0; k < interface->slave_nodes.size(); ++k)
      {
        const auto &s = interface->slave_nodes[k];
        if (!interface->owns_row(s) || !contact->is_active(s.node))
          continue;
        const double g = interface->gap(s, interface_displacement);
        if (g > 1e-2 * s.size)
          start_rule_nodes.emplace_back(k, g);
      }
  }

  template <int dim>
  std::string
  ContactProblem<dim>::opened_by_start_rule() const
  {
    unsigned int count = 0;
    double       gap = 0., ratio = 0.;
    for (const auto &[k, g] : start_rule_nodes)
      {
        const auto &s = interface->slave_nodes[k];
        if (contact->is_active(s.node))
          {
            ++count;
            gap   = std::max(gap, g);
            ratio = std::max(ratio, g / s.size);
          }
      }
    count = Utilities::MPI::sum(count, comm);
    if (count == 0)
      return "";
    gap   = Utilities::MPI::max(gap, comm);
    ratio = Utilities::MPI::max(ratio, comm);
    return " The solve of this iterate held in contact " + std::to_string(count) +
           " slave node(s) that started the step apart (gaps up to " + significant(gap, 2) + ", " +
           significant(ratio, 2) +
           " of their element size): the first active set of the unloaded state takes every "
           "node whose gap is below Contact/Active check factor times its size, and the solve "
           "closes those gaps whatever the load, so smaller load steps do not change them. "
           "Hint: lower Contact/Active check factor (the default, 1e-2, takes no node farther "
           "than 1e-2 of its size), then more load steps if an element still inverts";
  }

  template <int dim>
  void
  ContactProblem<dim>::check_before_solve(const std::string &at, const unsigned int iteration) const
  {
    if (contact && contact->n_active() == 0 && !contact_parameters.allow_loss_of_contact)
      throw diagnosis().no_contact_failure(at, current_time, true, iteration == 1);
    // With every node slipping, a body that only friction holds is free
    // to slide: the next solve would be (nearly) singular. Also a body
    // that supports hold only in part (a half model on its symmetry plane,
    // loaded along it): along a translation they leave free and tangential
    // to the contact, friction holds it alone.
    if (contact && contact->slides_everywhere())
      {
        if (const auto free = diagnosis().problem_traits().unsupported_bodies; !free.empty())
          {
            // "The load exceeds the capacity" only where it may: a body
            // whose lateral expansion under a pressure slides every node
            // outwards is loaded tangentially by nothing.
            if (const std::string within =
                  diagnosis().load_within_friction_capacity(free, friction_laws, current_time);
                !within.empty())
              throw NewtonFailure(
                at + ": every active contact node slips (none sticks), so nothing holds " +
                (free.size() == 1 ? "body " + std::to_string(free[0]) : std::string("the bodies")) +
                " tangentially in the linearised step (no support does), although " + within +
                ": the slip comes from the bodies' own deformation, not from the load (the "
                "lateral expansion under pressure of a body with Poisson's ratio near 0.5, "
                "larger still where degree-1 elements lock without B-bar), or the iterate "
                "overshot. Hint: a support or Boundary conditions/Fixed points that holds the "
                "tangential translation, Finite element/Volumetric strain = B-bar, or a finer "
                "mesh");
            throw NewtonFailure(at + ": " + exceeded_friction_capacity(free));
          }
        if (const auto along = diagnosis().friction_held_translations(); !along.empty())
          throw NewtonFailure(at + ": " + exceeded_friction_capacity({}, along));
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::create_checked_mesh()
  {
    {
      TimerOutput::Scope t(*timer, "Setup: mesh");
      // The input checks built the mesh of a scene without refinements.
      if (triangulation.n_levels() == 0)
        input_checks().create_scene_mesh(scene, triangulation);
      std::set<types::material_id> material_ids;
      for (const auto &[id, constants] : materials.bodies)
        material_ids.insert(id);
      Scene<dim>::check_mesh(triangulation, material_ids);
    }
    if (!scene.mesh_note.empty())
      pcout << "Mesh file: " << scene.mesh_note << std::endl;
    if (!scene.facet_note.empty())
      pcout << "Mesh file: " << scene.facet_note << std::endl;
    // Refining a polygon of a curve without its manifold moves p_max away
    // from the converged value with every level: say so once, up front.
    const bool refines =
      scene.global_refinements > 0 || !scene.refinement_boxes.empty() || refinement.n_cycles > 1;
    if (const std::string chords = scene.chord_warning(); refines && !chords.empty())
      pcout << "Warning: " << chords << std::endl;
    if (mapping->get_degree() > degree)
      pcout << "Q" << degree << " elements on a mapping of degree " << mapping->get_degree()
            << " (the curved boundaries are not replaced by chords)" << std::endl;
  }

  template <int dim>
  void
  ContactProblem<dim>::print_input_warnings() const
  {
    if (!memory_warning.empty())
      pcout << "Warning: " << memory_warning << "." << std::endl;
  }

  template <int dim>
  void
  ContactProblem<dim>::validate()
  {
    print_input_warnings();
    create_checked_mesh();
    Json record = Json::object();
    start_cycle(0, record);
    // The first load step up to its solve: constraints, loads, contact
    // search.
    LoadStepControl control(load_stepping, 0., load_stepping.n_steps);
    const double    time = control.next_time();
    prepare_load_step(time, time, StepStart::unloaded);
    check_load_resolved();
  }

  template <int dim>
  void
  ContactProblem<dim>::start_run()
  {
    // The output directory is prepared only now, after all input was
    // checked: an earlier run's files go (they would pass for this run's),
    // and a directory that cannot take the new ones stops the run before
    // any work.
    const OutputDirectoryReport earlier_outputs = log.open(output.directory);
    pcout << "contact_fem: scene '" << scene_name << "', " << dim << "D, "
          << Utilities::MPI::n_mpi_processes(comm) << " MPI process(es)" << std::endl
          << effective_input;
    if (scene.frame.shifted())
      {
        std::string origin;
        for (unsigned int d = 0; d < dim; ++d)
          origin += (d > 0 ? ", " : "") + significant(scene.frame.origin[d], 17);
        pcout << "  The mesh lies far from the origin: it is computed moved next to it by "
                 "-("
              << origin
              << ") (deal.II's geometry loses the digits of small cells far "
                 "out). Inputs, messages and pressure_profile.csv use the mesh file's "
                 "coordinates; the VTU files (32-bit points) the moved ones: add ("
              << origin << ") (summary.json: coordinate_origin)." << std::endl;
      }
    log.report_earlier_outputs(earlier_outputs, scene_name);
    print_input_warnings();

    create_checked_mesh();

    convergence_table =
      std::make_unique<ConvergenceTable<dim>>(output.directory + "/convergence.csv",
                                              contact_parameters.pairs, comm);
  }

  template <int dim>
  int
  ContactProblem<dim>::run()
  {
    Timer total_timer;
    try
      {
        start_run();
      }
    catch (const Interrupted &)
      {
        throw;
      }
    catch (const std::exception &e)
      {
        // A mesh refused after the output directory was opened.
        log.note_error(user_message(e));
        throw;
      }
    Json cycles    = Json::array();
    int  exit_code = 0;
    try
      {
        exit_code = run_cycles(cycles, total_timer);
      }
    catch (const Interrupted &e)
      {
        pcout << std::endl
              << "Error: " << e.what() << ": stopped; summary.json keeps the finished "
              << "cycles and says \"interrupted\"." << std::endl;
        write_summary(cycles, total_timer.wall_time(),
                      std::string(e.what()) + ": results of the finished cycles only");
        exit_code = 128 + e.signal;
      }
    catch (const OutputFailure &e)
      {
        // A full disk: say so, and try to mark the summary (it may fail too).
        pcout << std::endl << "Error: " << e.what() << std::endl;
        try
          {
            write_summary(cycles, total_timer.wall_time(), std::string("failed: ") + e.what());
          }
        catch (const OutputFailure &)
          {}
        exit_code = 2;
      }
    catch (const std::bad_alloc &)
      {
        pcout << std::endl
              << "Error: out of memory in cycle " << cycle << " (std::bad_alloc): the "
              << "mesh needs more memory than the run may use (RAM, cgroup or ulimit -v). "
              << "summary.json keeps the finished cycles; refine "
              << "less (" << input_checks().refinement_keys() << ", Refinement/Maximum cells)."
              << std::endl;
        write_summary(cycles, total_timer.wall_time(),
                      "failed: out of memory; results of the finished cycles only");
        exit_code = 2;
      }
    catch (const std::exception &e)
      {
        // Anything else thrown after the first solve started is a failure of
        // the run (main() gives exit 2): the summary says so. Before it, an
        // input error (a probe or fixed point at no vertex): the log says
        // it, and the table of no cycle goes.
        if (solving)
          write_summary(cycles, total_timer.wall_time(), "failed: " + user_message(e));
        else
          {
            log.note_error(user_message(e));
            convergence_table.reset();
            if (Utilities::MPI::this_mpi_process(comm) == 0)
              {
                std::error_code ignored;
                std::filesystem::remove(output.directory + "/convergence.csv", ignored);
              }
          }
        throw;
      }
    pcout << warnings.repeats();
    if (log.failed())
      pcout << "Warning: writing '" << output.directory
            << "/log.txt' failed during the run: the log is incomplete (the console has "
               "everything)."
            << std::endl;
    return exit_code;
  }

  template <int dim>
  int
  ContactProblem<dim>::run_cycles(Json &cycles, const Timer &total_timer)
  {
    double cumulative = 0.;
    for (cycle = 0; cycle < refinement.n_cycles; ++cycle)
      {
        const double old_dofs = dof_handler.n_dofs();
        if (cycle > 0 && !refine_mesh())
          {
            // The last cycle's results are final: mark the run complete.
            write_summary(cycles, total_timer.wall_time(), converged_status());
            break;
          }
        if (const std::string shortage =
              cycle > 0 ? input_checks().memory_shortage(cycle, old_dofs, dof_handler.n_dofs()) :
                          "";
            !shortage.empty())
          {
            pcout << "Error: " << shortage << std::endl;
            write_summary(cycles, total_timer.wall_time(),
                          "stopped before the memory ran out: results of cycle " +
                            std::to_string(cycle - 1));
            return 2;
          }
        timer->reset();
        uncounted_wall_time = 0.;
        Timer        cycle_timer;
        Json         record    = Json::object();
        const bool   converged = run_cycle(cycle, record);
        const double wall      = cycle_timer.wall_time() - uncounted_wall_time;
        cumulative += wall;
        const double multigrid = linear_solver->iterative() ? multigrid_setup_seconds : -1.;
        record.set("wall_time", wall).set("cumulative_wall_time", cumulative);
        record.set("timing", timing_record(*timer, multigrid));
        cycles.push(record);
        convergence_table->add_row(record, refinement.estimator,
                                   std::accumulate(newton_iterations_of_cycle.begin(),
                                                   newton_iterations_of_cycle.end(), 0u),
                                   cumulative);
        // Written after every cycle, so an interrupted study keeps its data;
        // the status says whether the run is complete.
        // Refining does not bring a state beyond the model back into it.
        const bool beyond_model = converged && outside_model_range && !model_range.accept_outside;
        const bool last         = !converged || beyond_model || cycle + 1 == refinement.n_cycles;
        write_summary(cycles, total_timer.wall_time(),
                      !converged ? "failed: results of the last converged load step" :
                      !last      ? "running" :
                                   converged_status());
        if (output.print_timing)
          pcout << timing_text(*timer, cycle, wall, cumulative, multigrid);
        if (!converged)
          return 2;
        if (beyond_model)
          {
            pcout << std::endl << outside_model_range_stop(converged_status()) << std::endl;
            return 3;
          }
      }
    return 0;
  }

  template <int dim>
  std::string
  ContactProblem<dim>::converged_status() const
  {
    if (outside_model_range && !model_range.accept_outside)
      return "converged outside the model's range (cycles[].small_strain_warning, "
             "cycles[].warning)";
    return balance_failed ? "converged, but the reactions do not balance the load "
                            "(cycles[].balance_warning)" :
                            "converged";
  }

  template <int dim>
  void
  ContactProblem<dim>::warn(const std::string &kind, const std::string &text, Json &cycle_record)
  {
    cycle_record.set(kind, text);
    if (warnings.add(kind, cycle))
      pcout << "  Warning: " << text << "." << std::endl;
  }

  template <int dim>
  void
  ContactProblem<dim>::check_converged_solution(const bool solved, Json &cycle_record)
  {
    const SolutionChecks<dim>    checks({dof_handler, *mapping, constraints, dirichlet_constraints,
                                         owned_dofs, relevant_dofs, solution, ghosted_solution});
    std::set<types::material_id> finite_strain_bodies;
    for (const auto &[id, constants] : materials.bodies)
      if (constants.model != ElasticModel::linear)
        finite_strain_bodies.insert(id);
    // a gap linear in u (not current kinematics)
    const bool linear_gap = contact != nullptr && !contact_parameters.current_kinematics;
    if (const std::string text = checks.large_displacement(finite_strain_bodies, linear_gap);
        !text.empty())
      {
        outside_model_range = true;
        warn("warning", text, cycle_record);
      }
    if (solved)
      if (const std::string text =
            checks.large_strain(cycle_record, finite_strain_bodies, linear_gap);
          !text.empty())
        {
          outside_model_range = true;
          warn("small_strain_warning", text, cycle_record);
        }
    check_held_rotation(checks, cycle_record);
    if (singular_solves == 0)
      return;
    std::ostringstream text;
    text << "the stiffness matrix was singular in " << singular_solves
         << " Newton solve(s) of this cycle (up to " << most_null_pivots << " zero pivot(s))";
    // Zero pivots also come from stiffness lost in round-off: then that is
    // the cause, not a free rigid-body mode.
    if (const std::string cause = diagnosis().precision_limits(); !cause.empty())
      text << ": " << cause;
    else
      text << ": a rigid-body mode that neither the supports nor the "
           << "active contact hold (see Boundary conditions/Fixed points). The solver "
           << "held it at one DoF; results along that mode are not determined by the model";
    warn("singular_stiffness_warning", text.str(), cycle_record);
  }

  template <int dim>
  void
  ContactProblem<dim>::check_held_rotation(const SolutionChecks<dim> &checks, Json &cycle_record)
  {
    if (!contact || !factorisation_current || !linear_solver->can_solve_again() ||
        linear_solver->n_null_pivots() > 0)
      return;
    // Stick nodes tie the bodies together: a rotation is then resisted by
    // the elasticity of the contact zone (compliant for a small zone, but
    // physical, not a discretisation artefact), and the factors of an
    // unsymmetric slip system are not those of the probe's test space.
    // Each rank asks about the rows it owns (it holds no other state).
    bool held = false;
    for (const auto &s : interface->slave_nodes)
      held = held || (interface->owns_row(s) && contact->held_tangentially(s.node));
    if (Utilities::MPI::max(held ? 1u : 0u, interface->communicator()) > 0)
      return;
    TimerOutput::Scope              t(*timer, "Check: held rotation");
    double                          softest = std::numeric_limits<double>::max();
    std::vector<types::material_id> bodies;
    for (const auto &[id, constants] : materials.bodies)
      {
        softest = std::min(softest, constants.mu());
        bodies.push_back(id);
      }
    std::set<types::boundary_id> contact_surfaces;
    for (const auto &pair : contact_parameters.pairs)
      contact_surfaces.insert({pair.slave, pair.master});
    const auto probe =
      checks.weakly_held_rotation(bodies, softest, contact_surfaces, *linear_solver);
    for (const std::string &text : probe.warnings)
      warn("rotation_warning", text, cycle_record);
    if (!probe.skipped.empty())
      {
        pcout << "  Note: the check for a weakly held rotation was skipped: " << probe.skipped
              << "." << std::endl;
        cycle_record.set("held_rotation_check_skipped", probe.skipped);
        return;
      }
    cycle_record.set("held_rotation_check", probe.check);
  }

  template <int dim>
  void
  ContactProblem<dim>::start_cycle(const unsigned int cycle, Json &cycle_record)
  {
    newton_iterations_of_cycle.clear();
    singular_solves         = 0;
    most_null_pivots        = 0;
    multigrid_setup_seconds = 0.;
    setup_dofs();
    if (transferred_solution && resolves_load_path())
      transferred_solution.reset();
    if (transferred_solution)
      {
        solution = *transferred_solution;
        hanging_constraints.distribute(solution);
        ghosted_solution = solution;
        transferred_solution.reset();
      }
    if (interface)
      {
        interface_dof_fixed.assign(interface->dofs().size(), false);
        for (unsigned int i = 0; i < interface_dof_fixed.size(); ++i)
          interface_dof_fixed[i] = interface->dof_fixed(i);
      }
    compute_cell_matrices();
    pcout << "Cycle " << cycle << ": " << triangulation.n_global_active_cells() << " cells, "
          << dof_handler.n_dofs() << " DoFs";
    if (interface)
      {
        const auto [n_slave, n_hanging] = interface->count_slave_nodes();
        pcout << ", " << n_slave << " slave nodes";
        if (n_hanging > 0)
          pcout << " and " << n_hanging << " hanging slave vertices";
      }
    if (tying)
      {
        const unsigned int n_tied = tying->n_tied_nodes();
        pcout << ", " << n_tied << " tied slave nodes";
        // A slave surface may run beyond its master by design: say so,
        // since those nodes carry no tie.
        if (const unsigned int n_free = tying->n_slave_surface_nodes() - n_tied; n_free > 0)
          pcout << " (" << n_free << " more nodes of the tied slave surfaces lie beyond their "
                << "masters and are free)";
      }
    pcout << std::endl;
    // The direct solver is the quiet default; an iterative one says so, and
    // that it cannot see zero pivots.
    if (linear_solver->iterative())
      pcout << "  Linear solver: " << linear_solver->description()
            << "; zero pivots (free rigid-body modes) are not detected by it" << std::endl;

    if (cycle == 0)
      for (const std::string &text :
           diagnosis().modelling_warnings(degree, volumetric_projection != nullptr))
        pcout << "  Warning: " << text << std::endl;

    cycle_record.set("cycle", cycle)
      .set("n_cells", static_cast<double>(triangulation.n_global_active_cells()))
      .set("n_dofs", static_cast<double>(dof_handler.n_dofs()))
      .set("linear_solver", linear_solver->description());
    // The partition, for reading the parallel speed-up.
    Json dofs_per_rank = Json::array();
    for (const auto n : Utilities::MPI::all_gather(comm, owned_dofs.n_elements()))
      dofs_per_rank.push(static_cast<double>(n));
    cycle_record.set("dofs_per_rank", dofs_per_rank);
  }

  template <int dim>
  typename ContactProblem<dim>::LoadPath
  ContactProblem<dim>::step_the_load(const unsigned int cycle, Json &cycle_record)
  {
    // The first cycle steps the load; later cycles start from the
    // transferred solution at the end time, except with friction, whose
    // answer depends on the load path: then every mesh re-solves the whole
    // path from the unloaded state (start_cycle() did not transfer). A step
    // whose Newton iteration fails is split and retried from the last
    // converged state.
    const bool         whole_path = cycle == 0 || resolves_load_path();
    const unsigned int n_steps    = whole_path ? load_stepping.n_steps : 1;
    LoadStepControl    control(load_stepping,
                            whole_path ? 0. : load_stepping.end_time * (n_steps - 1) / n_steps,
                               n_steps);
    LoadPath           path;
    Json               steps = Json::array();
    Timer              path_timer;
    if (comparison)
      comparison->start_load_path();
    ConvergedState saved(solution, contact.get(), interface.get());
    regular_solve_seen = false;
    while (!control.finished())
      {
        stop_if_interrupted(comm);
        const double time        = control.next_time();
        Json         step_record = Json::object();
        try
          {
            const StepStart start = path.n_solved > 0 ? StepStart::continued :
                                    whole_path        ? StepStart::unloaded :
                                                        StepStart::transferred;
            solve_load_step(path.n_solved, time, time - control.converged_time(), start,
                            step_record);
          }
        catch (const NewtonFailure &failure)
          {
            pcout << "  Newton failed at " << failure.what() << std::endl;
            saved.restore(solution, contact.get(), interface.get());
            if (tying)
              tying->restore_load_step();
            ghosted_solution = solution;
            if (failure.splittable && control.split())
              {
                pcout << "  Splitting the step: retrying from t = " << control.converged_time()
                      << " with step " << control.step_size() << " (split " << control.n_splits()
                      << " of at most " << load_stepping.max_splits << ")" << std::endl;
                continue;
              }
            pcout << std::endl << "Error: giving up at " << failure.what() << std::endl;
            // A point of the load path that no step passes: the splits end
            // at the floor of the step size, or sub-steps converged between
            // them up to the deepest split allowed; the hint to split was
            // wrong.
            const char *not_the_step_size =
              ", so the step size is not the cause. One cause: no contact state is consistent "
              "there (with a Tresca law, a slip node whose pressure falls to zero keeps its "
              "whole bound, so releasing it removes a finite tangential force and the node "
              "comes back).";
            if (failure.splittable && control.at_smallest_step())
              pcout << "Smaller steps did not help: the step was split down to "
                    << control.step_size() << " ("
                    << control.step_size() / control.nominal_step_size()
                    << " of the nominal load step; a further split would fall below 1e-12 "
                       "of the end time), and still fails after t = "
                    << control.converged_time() << not_the_step_size << std::endl;
            else if (failure.splittable && control.at_deepest_split() &&
                     control.n_splits() < load_stepping.max_splits)
              // Sub-steps converged between the splits: the failing point
              // of the load path was approached, not passed.
              pcout << "Smaller steps did not help: from t = " << control.creep_start_time()
                    << " converged sub-steps crept to t = " << control.converged_time()
                    << " with steps split down to " << control.step_size() << " (1/"
                    << std::lround(control.nominal_step_size() / control.step_size())
                    << " of the nominal load step, the most that Load stepping/Maximum step "
                       "splits = "
                    << load_stepping.max_splits
                    << " allows, counted across converged sub-steps), and the step from there "
                       "still fails"
                    << not_the_step_size << std::endl;
            pcout << "The results written are those of the last converged load step"
                  << " (t = " << control.converged_time() << ")." << std::endl;
            path.converged = false;
            break;
          }
        ++path.n_solved;
        finish_load_step(path.n_solved, step_record);
        steps.push(step_record);
        if (control.accept())
          pcout << "  Growing the step to " << control.step_size() << std::endl;
        // Progress, with the wall times (which tests leave out).
        if (output.print_timing)
          pcout << progress_line(cycle, path.n_solved, control.n_steps_left(),
                                 path_timer.wall_time())
                << std::endl;
        saved = ConvergedState(solution, contact.get(), interface.get());
      }
    current_time = control.converged_time();
    cycle_record.set("load_steps", steps);
    return path;
  }

  template <int dim>
  ContactProblem<dim>::ConvergedState::ConvergedState(const TrilinosWrappers::MPI::Vector &solution,
                                                      const ContactFormulation<dim>       *contact,
                                                      const ContactInterface<dim> *interface)
    : solution(solution)
    , contact_state(contact ? contact->save_state() : nullptr)
    , interface(interface ? std::make_unique<ContactInterface<dim>>(*interface) : nullptr)
  {}

  template <int dim>
  void
  ContactProblem<dim>::ConvergedState::restore(TrilinosWrappers::MPI::Vector &solution,
                                               ContactFormulation<dim>       *contact,
                                               ContactInterface<dim>         *interface) const
  {
    solution = this->solution;
    if (contact)
      {
        contact->restore_state(*contact_state);
        *interface = *this->interface;
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::finish_load_step(const unsigned int n_solved, Json &step_record)
  {
    // The contact force of the step, before the formulation accepts it
    // (its tangential residual is taken from the last accepted state).
    const std::vector<double>                contact_force = interface_contact_force();
    const std::unique_ptr<ContactState<dim>> state =
      contact ? std::make_unique<ContactState<dim>>(contact_state()) : nullptr;
    const RunView<dim> view = run_view(n_solved, state.get(), contact_force);
    // The load history a comparison may need (Cattaneo unloading).
    if (comparison && contact)
      comparison->record_load_step(contact_state());
    if (contact)
      contact->accept_load_step(*interface, interface_displacement);
    if (tying)
      tying->accept_load_step();
    postprocess([&](Postprocessor<dim> &postprocessor, std::ostream &out) {
      postprocessor.after_load_step(view, step_record, out);
    });
  }

  template <int dim>
  bool
  ContactProblem<dim>::run_cycle(const unsigned int cycle, Json &cycle_record)
  {
    start_cycle(cycle, cycle_record);
    interpenetration_finding.reset();
    const LoadPath path = step_the_load(cycle, cycle_record);
    if (interpenetration_finding)
      cycle_record.set("interpenetration", *interpenetration_finding);
    check_converged_solution(path.n_solved > 0, cycle_record);
    if (path.n_solved == 0)
      return false;
    if (!path.converged && contact)
      {
        // Results of the last converged state: its residual and gaps.
        make_dirichlet_constraints(dirichlet_inputs(), relevant_dofs, current_time,
                                   dirichlet_constraints);
        compute_cell_loads(current_time);
        compute_residual();
        interface_displacement = interface->gather(solution);
      }
    if (!record_results(path.converged, cycle_record) || !path.converged)
      return false;
    if (refinement.n_cycles > 1)
      {
        estimate_error(cycle_record);
        const RunView<dim> view = run_view(0, nullptr, interface_contact_force());
        postprocess([&](Postprocessor<dim> &postprocessor, std::ostream &) {
          postprocessor.after_estimate(view, indicators);
        });
      }
    return true;
  }

  template <int dim>
  bool
  ContactProblem<dim>::record_results(const bool converged, Json &cycle_record)
  {
    const std::vector<double> contact_force = interface_contact_force();
    const Json                contact_json =
      contact ? contact_results(contact_state(), search->last_penetration_excess()) :
                               Json::object();
    const std::function<bool(types::global_dof_index)> held = [this](const auto dof) {
      return inclined_supports.holds(dof);
    };
    const Json reaction_json = reaction_results<dim>(
      {run_view(0, nullptr, contact_force).forces, held, diagnosis().body_loads(current_time),
       materials.youngs_modulus_range().first, solution.linfty_norm()});
    cycle_record.set("contact", contact_json).set("reaction", reaction_json);
    // Bodies that touch without pressing (a load path back to zero load, a
    // slide at zero normal load): round-off picks the active set and the
    // signs of its pressures. The state is right (the pressures vanish to
    // round-off); its active set means nothing. Also for the last converged
    // state of a failed run, which is printed as the results.
    const bool        unloaded     = contact && diagnosis().load_vanishes(current_time);
    const std::string pressureless = contact ? diagnosis().pressureless_contact(
                                                 contact_json, current_time, unloaded) :
                                               "";
    if (!pressureless.empty())
      warn("unloaded_warning", pressureless, cycle_record);
    if (const std::string text =
          contact ? diagnosis().preload(contact_json, current_time, unloaded) : "";
        !text.empty())
      warn("preload_warning", text, cycle_record);
    if (const std::string text =
          converged && pressureless.empty() ? diagnosis().tension_failure(contact_json) : "";
        !text.empty())
      {
        pcout << std::endl << "Error: " << text << "." << std::endl;
        cycle_record.set("failure", text);
        return false;
      }
    // Unloaded with contact, the reactions are round-off: their balance is
    // no check.
    const bool balance_meaningful = !unloaded || pressureless.empty();
    if (converged && balance_meaningful)
      if (const std::string text = diagnosis().balance_warning(reaction_json, current_time);
          !text.empty())
        {
          warn("balance_warning", text, cycle_record);
          balance_failed = true;
        }
    Json hertz_json = Json::object();
    if (comparison)
      {
        if (contact)
          hertz_json = comparison->compare(contact_state(), contact_json, reaction_json);
        cycle_record.set("analytical", hertz_json);
        cycle_record.set("pressure_l2_relative_error", hertz_json["pressure_l2_relative_error"]);
      }
    // Total potential energy 1/2 u.K u - f.u of the bodies (from the last
    // residual evaluation): its difference to that of an overkill solution
    // measures the energy-norm error.
    const double potential_energy = strain_energy - external_work;
    cycle_record.set("strain_energy", strain_energy).set("potential_energy", potential_energy);
    pcout << "  Results at t = " << current_time << ":" << std::endl
          << std::setprecision(6)
          << (contact ? contact_results_text(contact_state(),
                                             contact_json,
                                             reaction_json,
                                             contact_parameters.penetration_tolerance,
                                             !pressureless.empty()) :
                        std::string())
          << reaction_results_text(reaction_json, balance_meaningful);
    if (comparison && contact)
      {
        std::ostringstream text;
        comparison->print(hertz_json, text);
        pcout << text.str();
      }
    const std::unique_ptr<ContactState<dim>> state =
      contact ? std::make_unique<ContactState<dim>>(contact_state()) : nullptr;
    const RunView<dim> view = run_view(0, state.get(), contact_force);
    postprocess([&](Postprocessor<dim> &postprocessor, std::ostream &out) {
      postprocessor.after_cycle(view, cycle_record, out);
    });
    return true;
  }

  template class ContactProblem<2>;
  template class ContactProblem<3>;
} // namespace contact_fem
