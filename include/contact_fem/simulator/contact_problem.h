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
#include <contact_fem/core/json.h>
#include <contact_fem/core/warning_log.h>
#include <contact_fem/material/finite_strain_bulk.h>
#include <contact_fem/material/material.h>
#include <contact_fem/postprocess/convergence_table.h>
#include <contact_fem/postprocess/output_files.h>
#include <contact_fem/simulator/contact_diagnosis.h>
#include <contact_fem/simulator/input_checks.h>
#include <contact_fem/simulator/newton_failure.h>
#include <contact_fem/simulator/search_control.h>
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
#include <contact_fem/postprocess/checkerboard.h>
#include <contact_fem/postprocess/vtu_output.h>

#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <string>

namespace contact_fem
{
  using namespace dealii;

  template <int dim>
  struct ContactNodeTraction;
  template <int dim>
  class SolutionChecks;

  /// An output stream that writes to the console and, once attached, to a log file.
  class TeeStream : public std::ostream
  {
  public:
    explicit TeeStream(std::ostream &console);
    /// Also write to @p file from now on.
    void
    attach(std::ostream &file);
    /// Whether writing to the file failed (it is then no longer written;
    /// the console goes on).
    bool
    file_failed() const;

  private:
    class Buffer : public std::streambuf
    {
    public:
      std::streambuf *first = nullptr, *second = nullptr;
      bool            file_failed = false;

    protected:
      int
      overflow(int c) override;
      int
      sync() override;

    private:
      void
      drop_file();
    } buffer;
  };

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
    /// Distributes the DoFs on the current mesh, in a random order of each
    /// rank's own DoFs if Finite element/DoF renumbering seed is not 0.
    void
    distribute_dofs();
    void
    compute_cell_matrices();
    void
    compute_cell_loads(const double time);
    /// The dim DoFs of the vertex @p point of its body, if a non-artificial
    /// cell of this rank has it (else empty); throws naming @p key if no rank
    /// has it. Collective.
    std::vector<types::global_dof_index>
    vertex_dofs(const BodyPoint &point, const std::string &key) const;
    /// Finds the DoFs of the "Fixed points" and of the displacement probes on
    /// this mesh; throws if a point is not a vertex of its body.
    void
    locate_fixed_points();
    void
    make_dirichlet_constraints(const double time);
    /// Prints warnings for locking-prone Poisson's ratios and for a slave
    /// side much stiffer than its master.
    void
    warn_about_modelling_choices() const;
    /// The wall time of each timer section of the cycle (summary.json).
    Json
    cycle_timing() const;
    /// Prints the wall time of the cycle and of its timer sections.
    void
    print_cycle_timing(const double wall, const double cumulative) const;
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
    /// The largest change of a prescribed displacement from the current
    /// solution to the values at the present time (before they are
    /// distributed): a lower bound of the motion of the step. Collective.
    double
    prescribed_increment() const;
    void
    make_sparsity_pattern();
    void
    make_constraints();
    // --- Newton (contact_problem.cc)
    void
    solve_load_step(const unsigned int step,
                    const double       time,
                    const double       step_size,
                    const bool         first_step,
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
    prepare_load_step(const double time, const double step_size, const bool first_step);
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
    /// " Likely cause: ..." when a precision limit applies, else empty.
    std::string
    precision_hint() const;
    void
    assemble_system();
    /// Records the contact sets after @p iteration and throws a
    /// NewtonFailure (splittable) when they repeat those of an earlier
    /// iteration although they changed: the iteration cycles.
    void
    check_for_cycling(const std::string             &at,
                      const unsigned int             iteration,
                      const unsigned int             changes,
                      std::vector<std::vector<int>> &sets_of_iteration) const;

    /// Whether every cycle solves the whole load path from the unloaded
    /// state: with a formulation whose answer depends on the path.
    bool
    resolves_load_path() const
    {
      return contact && contact->path_dependent();
    }

    /// Adds a cell's matrix and load when the test space differs from the
    /// trial space (rows by test_constraints, columns by constraints).
    void
    distribute_unsymmetric(const FullMatrix<double>                   &K,
                           const Vector<double>                       &load,
                           const std::vector<types::global_dof_index> &dofs);

    void
    solve_linear_system(const double newton_residual_target);
    /// Tells the linear solver the scene and the size of the new mesh (it
    /// may pick its method by them) and gives it the near-null space if it
    /// asks.
    void
    select_linear_solver();
    void
    compute_residual();
    double
    equilibrium_residual_norm(const std::vector<double> &contact_force_at_interface) const;
    // --- adaptivity (contact_problem_refinement.cc)
    void
    estimate_error(Json &cycle_record);
    /// Records and prints how far the traction of the recovered stress at
    /// the paired slave nodes (@p node_stresses at @p nodes, the paired
    /// interface->slave_nodes in their order) is from the exact pressure
    /// (Hertz, reference profile) and from zero shear; keys prefixed with
    /// @p prefix.
    void
    report_recovered_tractions(const std::vector<ContactNodeTraction<dim>> &nodes,
                               const std::vector<SymmetricTensor<2, dim>>  &node_stresses,
                               const std::string                           &prefix,
                               Json                                        &cycle_record) const;
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
    /// After the @p n_solved th converged load step (at @p time): its
    /// forces, the comparison's load history and the formulation's accepted
    /// state.
    void
    finish_load_step(const unsigned int n_solved, const double time, Json &step_record);
    /// Steps the load of the cycle (LoadStepControl), splitting failed steps
    /// and restoring the last converged state; records the steps.
    LoadPath
    step_the_load(const unsigned int cycle, Json &cycle_record);
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
    /// Warns and records when the reactions do not balance the load.
    void
    check_reaction_balance(const Json &reaction, Json &cycle_record);
    /// Warns about Poisson's ratios and loads beyond double precision.
    void
    warn_about_precision_limits() const;
    // --- results (contact_output.cc)
    Json
    contact_results() const;
    Json
    reaction_results() const;
    /// The converged contact state that results read (with contact).
    ContactState<dim>
    contact_state() const
    {
      return {*interface, *contact, interface_displacement};
    }
    /// Relative L2 error of a pressure per interface node against Analytical
    /// solution/Reference pressure profile (pressure_l2_relative_error()).
    double
    reference_pressure_error(const std::vector<double> &pressure) const;
    /// Prints and returns the displacements at Output/Displacement probes.
    Json
    probe_results() const;
    /// The displacement components at the probes, probe by probe (the same
    /// on every rank). Collective.
    std::vector<double>
    probe_displacements() const;
    /// The converged solution on the current mesh, as the output reads it.
    SolutionView<dim>
    solution_view(const ContactState<dim> *contact_state) const
    {
      return {dof_handler,  *mapping, ghosted_solution, materials, volumetric_projection.get(),
              contact_state};
    }
    void
    write_pressure_profile() const;
    /// The reactions and pair forces of the converged load step @p step
    /// (postprocess/forces.h): printed, into @p step_record and as a row
    /// of forces.csv.
    void
    record_forces(const unsigned int step, const double time, Json &step_record);
    /// Prints the contact results and the balance of the last load step.
    void
    print_results(const Json &contact_json, const Json &reaction, const Json &hertz) const;
    void
    write_summary(const Json &cycles, const double wall_time, const std::string &status) const;
    /// Prepares the output directory (prepare_output_directory()) and opens
    /// log.txt; throws naming the path if either fails. Collective.
    OutputDirectoryReport
    open_output_directory();
    /// Says how many files of an earlier run the preparation removed.
    void
    report_earlier_outputs(const OutputDirectoryReport &report);
    /// Throws naming @p path unless @p ok on every rank. Collective.
    void
    check_written(const std::string &path, const bool ok) const;
    Tensor<1, dim>
    applied_load(const double time) const;

    MPI_Comm           comm;
    std::ofstream      log_file;
    TeeStream          console;
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
    IndexSet                               owned_dofs, relevant_dofs, writable_dofs;

    AffineConstraints<double>            hanging_constraints;
    AffineConstraints<double>            dirichlet_constraints;
    InclinedSupports<dim>                inclined_supports; ///< Boundary conditions/Rollers
    std::vector<types::global_dof_index> fixed_point_dofs;  ///< locally relevant
    /// Per Output/Displacement probes entry: its vertex DoFs (see
    /// vertex_dofs()).
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
    static constexpr const char  *multigrid_setup_section = "Solve: multigrid setup";
    TrilinosWrappers::MPI::Vector system_rhs;
    TrilinosWrappers::MPI::Vector solution;         ///< owned
    TrilinosWrappers::MPI::Vector ghosted_solution; ///< locally relevant
    TrilinosWrappers::MPI::Vector residual;         ///< C_h^T (K u - f), writable

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
    /// The search of the interface over the load steps (with contact).
    std::unique_ptr<SearchControl<dim>> search;
    /// A point names a vertex closer than this times the cell's diameter
    /// (far above the digits a user types, far below the distance of two
    /// vertices of a valid cell).
    static constexpr double vertex_match_tolerance = 1e-3;
    /// A direct solve whose residual exceeds this fraction of the
    /// right-hand side has met a singular matrix.
    static constexpr double singular_residual_ratio = 1e-3;

    std::unique_ptr<TimerOutput> timer; ///< made once the input is valid
    double                       current_time = 0.;
    /// The VTU/PVD files (with Output/Write VTU), made with the output directory.
    std::unique_ptr<VtuOutput<dim>> vtu_output;
    Vector<float>                   indicators; ///< of the last estimate
    double relative_estimate = 0.;              ///< eta / |u|_E of the last SPR estimate
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
    /// A cycle's reactions did not balance its load (check_reaction_balance()).
    bool balance_failed = false;
    /// A cycle converged beyond ModelRange (check_converged_solution()).
    bool outside_model_range = false;
    /// The per-cycle warnings of the run, each printed once.
    WarningLog warnings;
    /// The comparison with Analytical solution/Type; null for none.
    std::unique_ptr<AnalyticalComparison<dim>> comparison;
    /// forces.csv: its header and the rows of the run so far.
    std::string              force_history_header;
    std::vector<std::string> force_history;
    /// The materials, boundary conditions and pairs as the run takes them
    /// (apply_scene_settings()), printed at its start.
    std::string effective_input;
  };
} // namespace contact_fem

#endif
