// The outputs of a run that only read its converged states, one plug-in per
// output in the manner of ASPECT's postprocessors: each registers itself by
// name in its own file and decides from the scene's parameters whether the
// scene wants it, so that a new output is one new file and a scene pays
// only for the outputs its .prm turns on.
#ifndef contact_fem_postprocessor_h
#define contact_fem_postprocessor_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <contact_fem/core/json.h>
#include <contact_fem/postprocess/forces.h>
#include <contact_fem/postprocess/vtu_output.h>

#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace contact_fem
{
  using namespace dealii;

  struct AnalyticalSolution;
  struct OutputParameters;
  template <int dim>
  class AnalyticalComparison;
  template <int dim>
  struct ModelFrame;
  template <int dim>
  class MeshTying;

  /// What a postprocessor reads of a converged state (read only).
  template <int dim>
  struct RunView
  {
    /// The displacement (with ghosts), the materials and the contact state
    /// (null without contact pairs).
    SolutionView<dim> solution;
    /// The residual, supports and pairs the forces are computed from.
    ForceInputs<dim> forces;
    /// The DoFs of each Output/Displacement probes vertex (vertex_dofs()).
    const std::vector<std::vector<types::global_dof_index>> &probe_dofs;
    const TrilinosWrappers::MPI::Vector                     &owned_solution;
    const ModelFrame<dim>                                   &frame;
    const OutputParameters                                  &output;
    const AnalyticalSolution                                &analytical;
    /// The comparison with Analytical solution/Type, or null.
    const AnalyticalComparison<dim> *comparison;
    /// The tied pairs' coupling and tractions, or null without tied pairs.
    const MeshTying<dim> *tying;
    unsigned int          cycle;
    /// The converged load step (counted from 1 in the cycle), or 0 for the
    /// cycle's results.
    unsigned int step;
    double       time;
    MPI_Comm     comm;

    /// The displacement components at the probes, probe by probe (the same
    /// on every rank). Collective.
    std::vector<double>
    probe_displacements() const;
  };

  /// What decides which postprocessors a scene wants, and what they keep.
  template <int dim>
  struct PostprocessorContext
  {
    /// The scene's parameters: a plug-in reads its own keys (those its
    /// declare_parameters() declared) from the subsection Output.
    ParameterHandler         &prm;
    const OutputParameters   &output;
    const AnalyticalSolution &analytical;
    bool                      has_contact;
    bool                      has_tied_pairs;
    /// Records a warning (kind, text) in the cycle's record and prints it
    /// once per run (the driver's WarningLog).
    std::function<void(const std::string &, const std::string &, Json &)> warn;
    TimerOutput                                                          &timer;
    MPI_Comm                                                              comm;
  };

  template <int dim>
  class Postprocessor
  {
  public:
    virtual ~Postprocessor() = default;

    /// A plug-in's own keys, declared in the subsection Output (a plug-in
    /// with keys hides this one by its own).
    static void
    declare_parameters(ParameterHandler &prm)
    {
      (void)prm;
    }
    /// The keys of every registered plug-in, in the subsection Output.
    static void
    declare_all_parameters(ParameterHandler &prm);

    /// A load step converged (its state accepted by the formulation);
    /// @p step_record is the step's record.
    virtual void
    after_load_step(const RunView<dim> &view, Json &step_record, std::ostream &out)
    {
      (void)view, (void)step_record, (void)out;
    }
    /// The cycle's results are recorded and printed: @p cycle_record holds
    /// "contact", "reaction", "analytical" and the energies so far.
    virtual void
    after_cycle(const RunView<dim> &view, Json &cycle_record, std::ostream &out)
    {
      (void)view, (void)cycle_record, (void)out;
    }
    /// The error of the cycle was estimated: @p indicators per active cell.
    virtual void
    after_estimate(const RunView<dim> &view, const Vector<float> &indicators)
    {
      (void)view, (void)indicators;
    }

    /// Makes the postprocessor, or returns null if the scene does not want it.
    using Factory =
      std::function<std::unique_ptr<Postprocessor<dim>>(const PostprocessorContext<dim> &)>;
    /// The declaration of a plug-in's keys (declare_parameters()).
    using Declaration = void (*)(ParameterHandler &);
    /// Adds the postprocessor called @p name with its keys (@p declare);
    /// they run in the order of @p rank (the order of their console lines
    /// and files), then of name. See CONTACT_FEM_REGISTER_POSTPROCESSOR.
    static void
    register_postprocessor(const std::string &name,
                           const int          rank,
                           const Factory     &factory,
                           const Declaration  declare);
    /// The postprocessors @p context wants, in their order.
    static std::vector<std::unique_ptr<Postprocessor<dim>>>
    create_wanted(const PostprocessorContext<dim> &context);
  };

  /// Registers class template @p classname (a Postprocessor<dim> for dim 2
  /// and 3 with a static `create(const PostprocessorContext<dim> &)` that
  /// returns null when the scene does not want it, and the static
  /// `declare_parameters` of its keys if it has any) under @p name and
  /// @p rank when the library is loaded.
#define CONTACT_FEM_REGISTER_POSTPROCESSOR(classname, name, rank)                  \
  namespace                                                                        \
  {                                                                                \
    const bool classname##_registered = [] {                                       \
      Postprocessor<2>::register_postprocessor(name, rank, &classname<2>::create,  \
                                               &classname<2>::declare_parameters); \
      Postprocessor<3>::register_postprocessor(name, rank, &classname<3>::create,  \
                                               &classname<3>::declare_parameters); \
      return true;                                                                 \
    }();                                                                           \
  }
} // namespace contact_fem

#endif
