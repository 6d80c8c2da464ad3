// The driver of a scene: mesh, load steps, semi-smooth Newton, results.
#ifndef contact_fem_contact_problem_h
#define contact_fem_contact_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_fem/solvers/linear_solver.h>
#include <contact_fem/solvers/load_step_control.h>
#include <contact_fem/solvers/newton_monitor.h>
#include <contact_fem/solvers/rigid_body_modes.h>
#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/mesh_tying.h>
#include <contact_fem/core/json.h>
#include <contact_fem/core/warning_log.h>
#include <contact_fem/material/finite_strain_bulk.h>
#include <contact_fem/material/material.h>
#include <contact_fem/postprocess/convergence_table.h>
#include <contact_fem/postprocess/output_files.h>
#include <contact_fem/simulator/contact_diagnosis.h>
#include <contact_fem/simulator/dof_setup.h>
#include <contact_fem/simulator/input_checks.h>
#include <contact_fem/simulator/newton_failure.h>
#include <contact_fem/simulator/search_control.h>
#include <contact_fem/simulator/interpenetration_check.h>
#include <contact_fem/simulator/inclined_supports.h>
#include <contact_fem/simulator/scene_parameters.h>
#include <contact_fem/contact/contact_parameters.h>
#include <contact_fem/core/parameters.h>
#include <contact_fem/solvers/solver_parameters.h>
#include <contact_fem/adaptivity/refinement.h>
#include <contact_fem/geometry/scene.h>
#include <contact_fem/adaptivity/stress_recovery.h>
#include <contact_fem/material/volumetric_projection.h>
#include <contact_fem/postprocess/analytical_comparison.h>
#include <contact_fem/postprocess/postprocessor.h>
#include <contact_fem/postprocess/run_log.h>

#include <cmath>
#include <map>
#include <limits>
#include <memory>
#include <optional>
#include <string>

namespace contact_fem
{
  using namespace dealii;

  template <int dim>
  class SolutionChecks;

  /**
   * Solves one scene: builds the mesh, steps the load, solves each step with
   * the semi-smooth Newton method, and writes the results.
   *
   * Implemented in source/simulator/contact_problem.cc (set-up, load
   * steps, Newton, cycles), contact_problem_refinement.cc (estimate and
   * refinement) and contact_output.cc (results, summary); it hands the input
   * checks to InputChecks, the diagnoses to ContactDiagnosis, the checks of
   * a converged solution to SolutionChecks and the contact search to
   * SearchControl.
   */
  template <int dim>
  class ContactProblem
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    /// @p prm_directory resolves relative file names of the scene.
    ContactProblem(ParameterHandler  &prm,
                   const std::string &scene_name,
                   const std::string &prm_directory);
    ~ContactProblem();

    /// Runs the scene; returns the process exit code.
    int
    run();

    /// Prints the warnings the checks of the input found (e.g. a mesh that
    /// takes more than half the available memory); run() prints them too.
    void
    print_input_warnings() const;

    /// Whether run() got as far as its first solve: an error thrown after
    /// that is a failure of the run (exit 2), not bad input (exit 1).
    bool
    started_solving() const
    {
      return solving;
    }

    /// --validate: every check a run makes before its first solve (the
    /// mesh, its materials, the boundary conditions, fixed points and
    /// probes, the contact interface and the first contact search),
    /// without writing any output. Throws what the run would throw.
    void
    validate();

  private:
    // --- set-up (contact_problem.cc)
    /// Builds the scene's mesh and checks it (materials, cell shapes).
    void
    create_checked_mesh();
    /// Refuses an analytical solution of another radius or centre than the
    /// built-in Hertz body it is compared with.
    void
    check_analytical_geometry() const;
    /// The start of run(): the output directory, the first lines of the
    /// console, the mesh and convergence.csv.
    void
    start_run();
    /// The adaptive cycles of run(), recorded in @p cycles; returns the
    /// exit code.
    int
    run_cycles(Json &cycles, const Timer &total_timer);
    void
    setup_dofs();
    void
    compute_cell_matrices();
    void
    compute_cell_loads(const double time);
    /// Finds the DoFs of the "Fixed points" and of the displacement probes on
    /// this mesh; throws if a point is not a vertex of its body.
    void
    locate_fixed_points();
    /// The summary status of a run whose last cycle converged.
    std::string
    converged_status() const;
    /// The checks of a converged solution against the model's range
    /// (SolutionChecks) and the singular-stiffness warning; @p solved:
    /// whether a load step converged on this mesh.
    void
    check_converged_solution(const bool solved, Json &cycle_record);
    /// The weakly held rotation probe of check_converged_solution().
    void
    check_held_rotation(const SolutionChecks<dim> &checks, Json &cycle_record);
    /// Records warning @p text under @p kind in @p cycle_record and prints
    /// it in the first cycle that gives the kind (WarningLog).
    void
    warn(const std::string &kind, const std::string &text, Json &cycle_record);
    void
    make_sparsity_pattern();
    void
    make_constraints();
    /// Every constraint set of the program is built the same way: hanging
    /// nodes (also those of the interface), the coupling lines that
    /// @p add_coupling_lines adds (tied and contact lines: candidates, trial
    /// or test), the Dirichlet lines, closed. @p lines are the lines stored.
    void
    build_constraints(
      AffineConstraints<double>                              &constraints,
      const IndexSet                                         &lines,
      const std::function<void(AffineConstraints<double> &)> &add_coupling_lines) const;
    /// With the check of the held state: @p held, built on this rank's
    /// lines, must equal the same constraints built on every line.
    void
    check_held_constraints(
      const AffineConstraints<double>                        &held,
      const std::function<void(AffineConstraints<double> &)> &add_coupling_lines) const;
    /// The hanging-node lines of the contact surfaces' DoFs that
    /// make_hanging_node_constraints() leaves out on this rank (DoFs away
    /// from its cells, which the contact rows still reach), from the
    /// interface's parents.
    void
    add_interface_hanging_constraints(AffineConstraints<double> &constraints) const;
    // --- Newton (contact_problem.cc)
    void
    solve_load_step(const unsigned int step,
                    const double       time,
                    const double       step_size,
                    const StepStart    start,
                    Json              &step_record);
    /// The Newton iterations of load step @p step (@p where names it in
    /// messages) until it converges; returns their number, throws a
    /// NewtonFailure with the diagnosis if it does not converge.
    unsigned int
    newton_iterations(const std::string &where,
                      const unsigned int step,
                      const double       time,
                      const double       step_size);
    /// Throws a NewtonFailure before the solve of @p iteration (at @p at)
    /// where it cannot help: no node in contact (unless allowed), or every
    /// node slipping while a body is held by friction alone.
    void
    check_before_solve(const std::string &at, const unsigned int iteration) const;
    /// Dirichlet values and loads at @p time, the contact search and the
    /// sparsity pattern of the step.
    void
    prepare_load_step(const double time, const double step_size, const StepStart start);
    /// One Newton update: constraints, assembly, linear solve to a
    /// residual below Newton's @p newton_residual_target (failures become
    /// NewtonFailures naming @p where), damping.
    void
    newton_update(const std::string &where, const double newton_residual_target);
    /// What the contact part of one iteration gives.
    struct ContactUpdate
    {
      unsigned int                                changes        = 0;
      bool                                        searched_again = false;
      typename ContactFormulation<dim>::Residuals residuals;
    };
    /// Gathers the interface values, widens the search if the iterate
    /// outran it, recovers the multipliers and updates the active set.
    ContactUpdate
    update_contact(const unsigned int iteration);
    /// Releases, holds and opens tied nodes (Tied release in tension) after
    /// iteration @p iteration at @p at; the number of changes. Throws a
    /// NewtonFailure if the bonds cycle.
    unsigned int
    update_bonds(const std::string &at, const unsigned int iteration);
    /// Before the first solve: throws the input error of a load at the
    /// round-off of the geometry at the end time, or of a load that is
    /// zero at every load step while the slave nodes start outside their
    /// masters (nothing presses the bodies together; the answer is u = 0).
    /// Either way round-off would pick the active set. Collective.
    void
    check_load_resolved() const;
    /// After iteration 0: start_rule_nodes of this step.
    void
    record_start_rule_nodes();
    /// Why an iterate of the solve with the current active set may have
    /// inverted an element: the nodes of start_rule_nodes still active,
    /// whose gaps that solve closed whatever the load (Contact/Active check
    /// factor); empty if none. Collective.
    std::string
    opened_by_start_rule() const;
    void
    assemble_system();

    /// Whether every cycle solves the whole load path from the unloaded
    /// state: with a formulation whose answer depends on the path.
    bool
    resolves_load_path() const
    {
      return (contact && contact->path_dependent()) || (tying && tying->releases());
    }


    void
    solve_linear_system(const double newton_residual_target);
    /// Machine epsilon times || |A| |x| || over the unconstrained rows of
    /// the last solve's system: the size of the round-off of A x, and so of
    /// any residual evaluated at x. A displacement far larger than the
    /// load's own (a rigid motion that closes an initial gap) makes it
    /// exceed a tolerance relative to the load (doc/design.md, "What a
    /// failed step names").
    double
    residual_round_off() const;
    /// The failure of a Newton update whose linear system is singular
    /// (@p what: where and the solver's words): splittable when the tangent
    /// depends on the iterate and was regular before in this load path.
    NewtonFailure
    singular_failure(const std::string &what) const;
    /// Tells the linear solver the scene and the size of the new mesh (it
    /// may pick its method by them) and gives it the near-null space if it
    /// asks.
    void
    select_linear_solver();
    /// The residual at the solution and the finite-strain cells' tangent
    /// and offset there; with @p linearised_at_start, the finite-strain
    /// cells' residual linearised at the step's start (their tangent and
    /// offset, kept; start_tangent_kept).
    void
    compute_residual(bool linearised_at_start = false);
    /// compute_residual() on a finite-strain cell: its residual at
    /// @p local_u into @p local_r, its tangent and offset at @p local_u kept
    /// for the next Newton step, and with F-bar the residual of the last
    /// step's linear model added to linearised_residual (@p linear_minus_r:
    /// the caller's scratch of the cell's size).
    typename FiniteStrainBulk<dim>::CellLinearisation
    relinearise_finite_strain_cell(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                   const std::vector<types::global_dof_index>           &dofs,
                                   const Vector<double>                                 &local_u,
                                   Vector<double>                                       &local_r,
                                   Vector<double> &linear_minus_r);
    double
    equilibrium_residual_norm(const std::vector<double> &contact_force_at_interface) const;
    // --- adaptivity (contact_problem_refinement.cc)
    void
    estimate_error(Json &cycle_record);
    /// Marks and refines; false if the mesh is kept (nothing to refine).
    bool
    refine_mesh();
    /// Solves one cycle on the current mesh; returns false if Newton failed.
    bool
    run_cycle(const unsigned int cycle, Json &cycle_record);
    /// Records and prints the results of the cycle's last converged state
    /// (@p converged: the whole load path); false if that state is no
    /// result (an active node in tension).
    bool
    record_results(const bool converged, Json &cycle_record);
    /// A new mesh: DoFs, the transferred solution, cell matrices, the
    /// cycle's first line and record entries.
    void
    start_cycle(const unsigned int cycle, Json &cycle_record);
    /// How the load path of a cycle ended.
    struct LoadPath
    {
      unsigned int n_solved  = 0;    ///< converged load steps
      bool         converged = true; ///< false: gave up after splitting
    };
    /// The last converged state of the load path, taken back when a step
    /// fails: the solution, the formulation's state and the mortar
    /// operators (a failed step may have searched again, and results
    /// reported after giving up are those of the converged state with its
    /// own operators).
    struct ConvergedState
    {
      /// Copies the state (@p contact and @p interface null without contact).
      ConvergedState(const TrilinosWrappers::MPI::Vector &solution,
                     const ContactFormulation<dim>       *contact,
                     const ContactInterface<dim>         *interface);
      void
      restore(TrilinosWrappers::MPI::Vector &solution,
              ContactFormulation<dim>       *contact,
              ContactInterface<dim>         *interface) const;

      TrilinosWrappers::MPI::Vector                            solution;
      std::unique_ptr<typename ContactFormulation<dim>::State> contact_state;
      std::unique_ptr<ContactInterface<dim>>                   interface;
    };
    /// After the @p n_solved th converged load step: its
    /// forces, the comparison's load history and the formulation's accepted
    /// state.
    void
    finish_load_step(const unsigned int n_solved, Json &step_record);
    /// Steps the load of the cycle (LoadStepControl), splitting failed steps
    /// and restoring the last converged state; records the steps.
    LoadPath
    step_the_load(const unsigned int cycle, Json &cycle_record);
    /// What the prescribed displacements are made of (dof_setup.h).
    DirichletInputs<dim>
    dirichlet_inputs()
    {
      return {*mapping,         dof_handler,         scene.frame,      boundary_conditions,
              fixed_point_dofs, hanging_constraints, inclined_supports};
    }
    /// The checks of the parsed input (input_checks.h).
    InputChecks<dim>
    input_checks() const
    {
      return {scene,  materials, boundary_conditions, load_stepping, contact_parameters,
              degree, comm};
    }
    // --- diagnoses
    /// The diagnoses of the run's present state (contact_diagnosis.h).
    ContactDiagnosis<dim>
    diagnosis() const
    {
      return ContactDiagnosis<dim>({scene, materials, boundary_conditions, contact_parameters,
                                    newton_parameters, dof_handler, *mapping, interface.get(),
                                    contact.get(), most_null_pivots});
    }
    // --- results (contact_output.cc)
    /// The converged contact state that results read (with contact).
    ContactState<dim>
    contact_state() const
    {
      return {*interface, *contact, interface_displacement};
    }
    /// The converged state of load step @p step (0: the cycle's results)
    /// as the postprocessors read it; @p state is contact_state() or null,
    /// @p contact_force is interface_contact_force().
    RunView<dim>
    run_view(const unsigned int         step,
             const ContactState<dim>   *state,
             const std::vector<double> &contact_force) const;
    /// The contact force at each interface DoF of the current state (empty
    /// without contact).
    std::vector<double>
    interface_contact_force() const;
    /// Calls @p hook on every postprocessor in turn and prints what each
    /// writes to its stream.
    void
    postprocess(const std::function<void(Postprocessor<dim> &, std::ostream &)> &hook);
    void
    write_summary(const Json &cycles, const double wall_time, const std::string &status) const;

    MPI_Comm           comm;
    RunLog             log; ///< the console and log.txt
    ConditionalOStream pcout;

    std::string            scene_name;
    Scene<dim>             scene;
    Materials<dim>         materials;
    BoundaryConditions     boundary_conditions;
    LoadStepping           load_stepping;
    ContactParameters      contact_parameters;
    NewtonParameters       newton_parameters;
    AnalyticalSolution     analytical;
    OutputParameters       output;
    ModelRange             model_range;
    RefinementParameters   refinement;
    StressRecoverySettings spr_settings; ///< the contact-traction penalties of SPR
    unsigned int           degree;

    parallel::distributed::Triangulation<dim> triangulation;
    FESystem<dim>                             fe;
    /// Element degree, or 2 for Q1 on curved boundaries (Finite
    /// element/Mapping degree); made once the scene is known. Degree 2 is a
    /// MappingQCache, filled per mesh.
    std::unique_ptr<MappingQ<dim>> mapping;
    DoFHandler<dim>                dof_handler;
    unsigned int                   dof_renumbering_seed = 0;
    /// Present with Finite element/Volumetric strain = B-bar (after fe and
    /// mapping, which it refers to).
    std::unique_ptr<VolumetricProjection<dim>> volumetric_projection;
    /// Present when a body has a finite-strain law (Materials/Models): its
    /// cells' matrices are the tangent at the last residual's iterate.
    std::unique_ptr<FiniteStrainBulk<dim>> finite_strain;
    /// The finite-strain tangent of the step's start (before the new
    /// prescribed values) is in the cells: the step's first solve uses it.
    bool start_tangent_kept = false;
    /// A solve of this load path had no zero pivot (singular_failure()).
    bool regular_solve_seen = false;
    /// How the current load step started (prepare_load_step()).
    StepStart step_start = StepStart::continued;
    /// The owned slave nodes (index into interface->slave_nodes) that the
    /// first active set of an unloaded step took with a gap above 1e-2 of
    /// their size, the default Active check factor's margin, with that
    /// gap: opened_by_start_rule().
    std::vector<std::pair<unsigned int, double>> start_rule_nodes;

    IndexSet owned_dofs, relevant_dofs, writable_dofs;

    AffineConstraints<double>            hanging_constraints;
    AffineConstraints<double>            dirichlet_constraints;
    InclinedSupports<dim>                inclined_supports; ///< Boundary conditions/Rollers
    std::vector<types::global_dof_index> fixed_point_dofs;  ///< locally relevant
    /// Per Output/Displacement probes entry: its vertex DoFs (see
    /// vertex_dofs(), dof_setup.h).
    std::vector<std::vector<types::global_dof_index>> probe_dofs;
    AffineConstraints<double>                         constraints;
    /// The constraints of the test space when the contact formulation's
    /// is not the trial space (Coulomb slip); else unused.
    AffineConstraints<double> test_constraints;

    TrilinosWrappers::SparseMatrix system_matrix;
    std::unique_ptr<LinearSolver>  linear_solver; ///< after the matrix it refers to
    /// Newton solves of this cycle whose matrix had zero pivots, and the most.
    unsigned int singular_solves = 0, most_null_pivots = 0;
    /// Krylov iterations of each Newton solve of the current load step
    /// (iterative linear solver).
    std::vector<unsigned int> linear_iterations_of_step;
    /// Wall time of the multigrid set-ups of this cycle, part of "Solve:
    /// linear".
    double                        multigrid_setup_seconds = 0.;
    /// The frictional law of each contact pair (Contact/Friction), empty
    /// without: the diagnosis of a step in which every node slips.
    std::vector<std::shared_ptr<const FrictionalLaw>> friction_laws;
    /// ||A x - b|| of the last linear solve, for the Newton monitor.
    double last_linear_residual = 0.;
    /// ||A x - b|| / ||b|| of the last linear solve, NaN while it runs (a
    /// solve that throws leaves it so): a singular system's diagnosis.
    double last_relative_linear_residual = std::numeric_limits<double>::quiet_NaN();
    TrilinosWrappers::MPI::Vector system_rhs;
    TrilinosWrappers::MPI::Vector solution;         ///< owned
    TrilinosWrappers::MPI::Vector ghosted_solution; ///< locally relevant
    TrilinosWrappers::MPI::Vector residual;         ///< C_h^T (K u - f), writable
    /// With F-bar bodies: the residual of the linear model that gave the
    /// iterate (each finite-strain cell's force from the tangent and offset
    /// of its last step), zero on the free DoFs up to the linear solve; the
    /// multipliers are recovered from it. The nonlinear remainder that
    /// residual adds at the contact rows alternates from node to node under
    /// F-bar and outweighs the reactions (doc/finite_strain.md).
    TrilinosWrappers::MPI::Vector linearised_residual;
    /// Whether the finite-strain bodies use F-bar (linearised_residual).
    bool
    f_bar() const
    {
      return finite_strain && volumetric_projection;
    }

    std::vector<FullMatrix<double>> cell_matrices; ///< by active cell index
    std::vector<Vector<double>>     cell_loads;    ///< by active cell index, may be empty
    /// Finite-strain cells: f_int(u) - K_T(u) u at the last residual's
    /// iterate u, so that K_T u_new = f - f_int(u) + K_T u is Newton's step
    /// for the total displacement; empty for linear cells.
    std::vector<Vector<double>> cell_offsets;

    /// Present only when the scene has contact pairs.
    std::unique_ptr<ContactInterface<dim>>   interface;
    std::unique_ptr<ContactFormulation<dim>> contact;
    std::vector<double>                      interface_displacement;
    std::vector<double>                      interface_fixed_values;
    std::vector<double>                      interface_residual;
    std::vector<bool>                        interface_dof_fixed;
    /// Present only when the scene has tied pairs (Contact/Tied pairs).
    std::unique_ptr<MeshTying<dim>> tying;
    /// The search of the interface over the load steps (with contact).
    std::unique_ptr<SearchControl<dim>> search;
    /// With finite deformation (a finite-strain body or Contact/Kinematics
    /// = current) only: the interpenetration check of each converged load
    /// step, and what it found (summary.json, cycles[].interpenetration).
    std::unique_ptr<InterpenetrationCheck<dim>> interpenetration;
    std::optional<Json>                         interpenetration_finding;
    /// A direct solve whose residual exceeds this fraction of the
    /// right-hand side has met a singular matrix.
    static constexpr double singular_residual_ratio = 1e-3;

    std::unique_ptr<TimerOutput> timer; ///< made once the input is valid
    double                       current_time = 0.;
    /// The outputs the scene wants (postprocessor.h), made with the output
    /// directory.
    std::vector<std::unique_ptr<Postprocessor<dim>>> postprocessors;
    Vector<float>                                    indicators; ///< of the last estimate
    double relative_estimate = 0.; ///< eta / |u|_E of the last SPR estimate
    /// The linear solver can still answer for the current load step's last
    /// Newton system (LinearSolver::solve_again()).
    bool factorisation_current = false;
    /// Time of diagnostics of the current cycle left out of its wall time.
    double uncounted_wall_time = 0.;
    /// Displacement interpolated from the previous mesh (owned entries).
    std::unique_ptr<TrilinosWrappers::MPI::Vector> transferred_solution;
    unsigned int                                   cycle = 0;
    std::vector<unsigned int>                      newton_iterations_of_cycle; ///< per load step
    double strain_energy = 0., external_work = 0.; ///< at the last residual
    /// convergence.csv, made with the output directory.
    std::unique_ptr<ConvergenceTable<dim>> convergence_table;
    /// Of InputChecks::check_scene_before_meshing(), printed by run().
    std::string memory_warning;
    /// Set by the first solve_load_step() (started_solving()).
    bool solving = false;
    /// A cycle's reactions did not balance its load (ContactDiagnosis::balance_warning()).
    bool balance_failed = false;
    /// A cycle converged beyond ModelRange (check_converged_solution()).
    bool outside_model_range = false;
    /// The per-cycle warnings of the run, each printed once.
    WarningLog warnings;
    /// The comparison with Analytical solution/Type; null for none.
    std::unique_ptr<AnalyticalComparison<dim>> comparison;
    /// The materials, boundary conditions and pairs as the run takes them
    /// (apply_scene_settings()), printed at its start.
    std::string effective_input;
  };
} // namespace contact_fem

#endif
