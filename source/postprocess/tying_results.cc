// The results of the tied pairs (Contact/Tied pairs), printed and recorded
// with each cycle's results, and their profile of tying tractions.
#include <contact_fem/contact/mesh_tying.h>
#include <contact_fem/geometry/model_frame.h>
#include <contact_fem/postprocess/output_files.h>
#include <contact_fem/postprocess/owned_rows.h>
#include <contact_fem/postprocess/postprocessor.h>

#include <algorithm>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <utility>
#include <vector>

namespace contact_fem
{
  namespace
  {
    /// The tying results of each cycle (with tied pairs): the force, the
    /// traction range and the nodes per tied pair.
    template <int dim>
    class TyingResults : public Postprocessor<dim>
    {
    public:
      static std::unique_ptr<Postprocessor<dim>>
      create(const PostprocessorContext<dim> &context)
      {
        if (!context.has_tied_pairs)
          return nullptr;
        return std::make_unique<TyingResults<dim>>();
      }

      void
      after_cycle(const RunView<dim> &view, Json &cycle_record, std::ostream &out) override
      {
        cycle_record.set("tying", view.tying->results(out));
      }
    };

    /// The tied slave nodes of @p tying as CSV, as pressure_profile.csv
    /// holds the contact slave nodes: per node its position (deformed by
    /// @p u, in the user's coordinates), the normal tying traction
    /// (positive in tension), the traction vector on the slave, the tied
    /// flag (0 once released in tension), the pair and the reference
    /// position; sorted by pair, then along x. Each rank the nodes whose
    /// rows it owns, gathered to rank 0 (the text is whole there only).
    /// Collective.
    template <int dim>
    std::string
    tying_profile_csv(const MeshTying<dim>      &tying,
                      const std::vector<double> &u,
                      const ModelFrame<dim>     &frame)
    {
      const ContactInterface<dim>     &interface = tying.interface();
      std::vector<std::vector<double>> rows;
      for (unsigned int k = 0; k < interface.slave_nodes.size(); ++k)
        {
          const auto &s = interface.slave_nodes[k];
          if (!s.paired || !interface.owns_row(s))
            continue;
          const Point<dim> reference = interface.nodes[s.node].reference;
          const Point<dim> current   = frame.to_user(reference + interface.displacement(s.node, u));
          const Tensor<1, dim> &traction = tying.tractions()[k];
          std::vector<double>   row(current.begin_raw(), current.end_raw());
          row.push_back(traction * s.normal + 0.); // no -0
          row.insert(row.end(), traction.begin_raw(), traction.end_raw());
          row.push_back(tying.bond_of(k) == MeshTying<dim>::Bond::tied ? 1. : 0.);
          row.push_back(s.pair);
          const Point<dim> user_reference = frame.to_user(reference);
          row.insert(row.end(), user_reference.begin_raw(), user_reference.end_raw());
          row.insert(row.begin(), s.pair);
          rows.push_back(row);
        }
      // (pair, row) as the key: the order does not depend on the partition.
      rows = gather_rows(interface.communicator(), rows, false);
      std::sort(rows.begin(), rows.end());
      const std::string  axes[3] = {"x", "y", "z"};
      std::ostringstream out;
      for (unsigned int d = 0; d < dim; ++d)
        out << axes[d] << ",";
      out << "normal_traction";
      for (unsigned int d = 0; d < dim; ++d)
        out << ",traction_" << axes[d];
      out << ",tied,pair";
      for (unsigned int d = 0; d < dim; ++d)
        out << ",reference_" << axes[d];
      out << "\n" << std::setprecision(10);
      for (const auto &r : rows)
        for (unsigned int k = 1; k < r.size(); ++k)
          out << r[k] << (k + 1 < r.size() ? ',' : '\n');
      return out.str();
    }

    /// tying_profile.csv (the latest cycle's) and tying_profile_cycle_K.csv
    /// (each cycle's), with Output/Write pressure profile and tied pairs.
    template <int dim>
    class TyingProfileFiles : public Postprocessor<dim>
    {
    public:
      static std::unique_ptr<Postprocessor<dim>>
      create(const PostprocessorContext<dim> &context)
      {
        context.prm.enter_subsection("Output");
        const bool wanted = context.prm.get_bool("Write pressure profile");
        context.prm.leave_subsection();
        if (!wanted || !context.has_tied_pairs)
          return nullptr;
        return std::make_unique<TyingProfileFiles<dim>>();
      }

      void
      after_cycle(const RunView<dim> &view, Json &, std::ostream &) override
      {
        const std::vector<double> u =
          view.tying->interface().gather(view.solution.solution);               // collective
        const std::string text = tying_profile_csv(*view.tying, u, view.frame); // collective
        write_cycle_csv(
          view.output.directory, "tying_profile", view.cycle,
          [&] {
            return text;
          },
          view.comm);
      }
    };
  } // namespace

  // Printed right after the contact results, before the other outputs.
  CONTACT_FEM_REGISTER_POSTPROCESSOR(TyingResults, "tying results", 0)
  CONTACT_FEM_REGISTER_POSTPROCESSOR(TyingProfileFiles, "tying profile", 51)

} // namespace contact_fem
