// The VTU/PVD files of a run: the solution of every converged load step
// (displacement, stress, von Mises stress, contact fields, with tied pairs
// the tying traction), the slave
// contact surfaces (pressure, traction vector, gap, state), the tied slave
// surfaces (tying traction) and the error
// indicators of every adaptive cycle, with ParaView collections whose times
// are the load times (solution) and the cycles (indicators).
#ifndef contact_fem_vtu_output_h
#define contact_fem_vtu_output_h

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <contact_fem/material/material.h>
#include <contact_fem/material/volumetric_projection.h>
#include <contact_fem/postprocess/analytical_comparison.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace contact_fem
{
  template <int dim>
  class MeshTying;

  /// The converged solution on the current mesh, as the output reads it.
  template <int dim>
  struct SolutionView
  {
    const DoFHandler<dim>               &dof_handler;
    const Mapping<dim>                  &mapping;
    const TrilinosWrappers::MPI::Vector &solution; ///< with ghost entries
    const Materials<dim>                &materials;
    /// B-bar's projection of the volumetric strain, or null.
    const VolumetricProjection<dim> *volumetric_projection;
    /// The contact state, or null for a scene without contact pairs.
    const ContactState<dim> *contact;
  };

  template <int dim>
  class VtuOutput
  {
  public:
    VtuOutput(const std::string &directory, const MPI_Comm comm);

    /// solution_NNN.pvtu (NNN counts the files of the run) for the load
    /// step converged at load time @p time of adaptive cycle @p cycle,
    /// listed at @p time in solution_cycle_K.pvd and in solution.pvd (the
    /// load path of the latest cycle: the final mesh's after the run); with
    /// @p tying, its tying traction at the tied slave nodes is a field.
    /// With contact also contact_surface_NNN.vtu, the slave surfaces
    /// alone, in contact_surface_cycle_K.pvd and contact_surface.pvd.
    /// With @p tying (tied pairs) also tied_surface_NNN.vtu, the tied
    /// slave surfaces with the tying traction, in tied_surface_cycle_K.pvd
    /// and tied_surface.pvd. Collective.
    void
    write_solution(const SolutionView<dim> &view,
                   const unsigned int       cycle,
                   const double             time,
                   const MeshTying<dim>    *tying = nullptr);

    /// error_indicators_KK.pvtu: the mesh of cycle @p cycle with the
    /// displacement and the cell indicators @p indicators of its estimate,
    /// listed at time @p cycle in error_indicators.pvd.
    void
    write_error_indicators(const SolutionView<dim> &view,
                           const Vector<float>     &indicators,
                           const unsigned int       cycle);

  private:
    /// Writes @p records as the collection @p name (rank 0), collectively.
    void
    write_collection(const std::string                                 &name,
                     const std::vector<std::pair<double, std::string>> &records) const;

    /// Writes @p prefix_NNN.vtu (@p content, on rank 0) and lists it at
    /// @p time in @p records, @p prefix_cycle_K.pvd and @p prefix.pvd.
    void
    write_surface(const std::string                           &prefix,
                  const std::function<std::string()>          &content,
                  const unsigned int                           cycle,
                  const double                                 time,
                  std::vector<std::pair<double, std::string>> &records);

    std::string                                 directory;
    MPI_Comm                                    comm;
    unsigned int                                n_solutions   = 0;
    unsigned int                                records_cycle = 0;
    std::vector<std::pair<double, std::string>> cycle_records, surface_records,
      tied_records, indicator_records;
  };
} // namespace contact_fem

#endif
