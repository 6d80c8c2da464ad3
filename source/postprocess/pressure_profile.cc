#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/core/format.h>
#include <contact_fem/postprocess/output_files.h>
#include <contact_fem/postprocess/owned_rows.h>
#include <contact_fem/postprocess/postprocessor.h>
#include <contact_fem/postprocess/pressure_profile.h>
#include <contact_fem/simulator/scene_parameters.h>

#include <algorithm>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <utility>
#include <vector>

namespace contact_fem
{
  template <int dim>
  std::string
  pressure_profile_csv(const ContactState<dim>                         &state,
                       const ModelFrame<dim>                           &frame,
                       const std::function<double(const Point<dim> &)> &exact)
  {
    const ContactInterface<dim>   &interface = state.interface;
    const ContactFormulation<dim> &contact   = state.contact;
    // The formulation's own nodal fields (friction: tangential traction,
    // slip increment of the last load step, stick flag) follow the state.
    const auto fields = contact.nodal_fields(interface);
    // Each rank the nodes whose rows it owns, gathered to rank 0 and sorted
    // there by (pair, row): one pair's nodes together, along x, in an order
    // that does not depend on the partition.
    std::vector<std::vector<double>> rows;
    for (const auto &s : interface.slave_nodes)
      if (s.paired && interface.owns_row(s))
        {
          const Point<dim>    position  = state.position(s.node);
          const Point<dim>    current   = frame.to_user(position);
          const Point<dim>    reference = frame.to_user(interface.nodes[s.node].reference);
          std::vector<double> row;
          for (unsigned int d = 0; d < (dim == 2 ? 1 : dim); ++d)
            row.push_back(current[d]);
          row.insert(row.end(),
                     {contact.normal_pressure(s.node), exact ? exact(position) : 0.,
                      interface.gap(s, state.displacement), contact.is_active(s.node) ? 1. : 0.});
          for (const auto &field : fields)
            row.push_back(field.values[s.node]);
          row.push_back(s.pair);
          if (dim == 2)
            row.push_back(current[1]);
          for (unsigned int d = 0; d < dim; ++d)
            row.push_back(reference[d]);
          row.insert(row.begin(), s.pair);
          rows.push_back(row);
        }
    rows = gather_rows(interface.communicator(), rows, false);
    std::sort(rows.begin(), rows.end());
    std::ostringstream out;
    out << (dim == 2 ? "x" : "x,y,z") << ",pressure,hertz_pressure,gap,active";
    for (const auto &field : fields)
      out << "," << field.name;
    out << ",pair" << (dim == 2 ? ",y" : "") << ",reference_x,reference_y"
        << (dim == 3 ? ",reference_z" : "") << "\n"
        << std::setprecision(10);
    for (const auto &r : rows)
      for (unsigned int k = 1; k < r.size(); ++k)
        out << r[k] << (k + 1 < r.size() ? ',' : '\n');
    return out.str();
  }

  template <int dim>
  double
  reference_pressure_error(const AnalyticalSolution  &analytical,
                           const ContactState<dim>   &state,
                           const std::vector<double> &pressure)
  {
    return pressure_l2_relative_error<dim>(state, pressure, [&](const Point<dim> &x) {
      return analytical.reference_pressure(dim == 2 ? x[0] : analytical.axis_distance(x[0], x[1]));
    });
  }

  namespace
  {
    /// pressure_profile.csv (the latest cycle's) and
    /// pressure_profile_cycle_K.csv (each cycle's), with Output/Write
    /// pressure profile and contact pairs.
    template <int dim>
    class PressureProfileFiles : public Postprocessor<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Write pressure profile", "true", Patterns::Bool(),
                          "Write the slave pressure profile of every cycle as CSV "
                          "(and, with tied pairs, the tying traction profile).");
      }

      static std::unique_ptr<Postprocessor<dim>>
      create(const PostprocessorContext<dim> &context)
      {
        context.prm.enter_subsection("Output");
        const bool wanted = context.prm.get_bool("Write pressure profile");
        context.prm.leave_subsection();
        if (!wanted || !context.has_contact)
          return nullptr;
        return std::make_unique<PressureProfileFiles<dim>>();
      }

      void
      after_cycle(const RunView<dim> &view, Json &, std::ostream &) override
      {
        const ContactState<dim> &state = *view.solution.contact;
        // The exact pressure where the analytical solution gives one (else
        // 0). Both collective: every rank, before rank 0 writes.
        const std::function<double(const Point<dim> &)> exact =
          view.comparison ? view.comparison->exact_pressure(state) : nullptr;
        const std::string text = pressure_profile_csv(state, view.frame, exact);
        write_cycle_csv(
          view.output.directory, "pressure_profile", view.cycle,
          [&text] {
            return text;
          },
          view.comm);
      }
    };

    /// The L2 error of the pressure against Analytical solution/Reference
    /// pressure profile, printed and recorded with each cycle's results.
    template <int dim>
    class ReferencePressureError : public Postprocessor<dim>
    {
    public:
      static std::unique_ptr<Postprocessor<dim>>
      create(const PostprocessorContext<dim> &context)
      {
        if (context.analytical.reference_pressure_profile.empty() || !context.has_contact)
          return nullptr;
        return std::make_unique<ReferencePressureError<dim>>();
      }

      void
      after_cycle(const RunView<dim> &view, Json &cycle_record, std::ostream &out) override
      {
        const ContactState<dim> &state = *view.solution.contact;
        const double             error = reference_pressure_error(view.analytical, state,
                                                                  state.contact.pressures(state.interface));
        cycle_record.set("pressure_reference_l2_relative_error", error);
        out << "    pressure, L2 error against the reference: " << value_or_ok(error, 1e-10)
            << std::endl;
      }
    };
  } // namespace

  CONTACT_FEM_REGISTER_POSTPROCESSOR(ReferencePressureError, "reference pressure error", 30)
  CONTACT_FEM_REGISTER_POSTPROCESSOR(PressureProfileFiles, "pressure profile", 50)

  template double
  reference_pressure_error(const AnalyticalSolution &,
                           const ContactState<2> &,
                           const std::vector<double> &);
  template double
  reference_pressure_error(const AnalyticalSolution &,
                           const ContactState<3> &,
                           const std::vector<double> &);
  template std::string
  pressure_profile_csv(const ContactState<2> &,
                       const ModelFrame<2> &,
                       const std::function<double(const Point<2> &)> &);
  template std::string
  pressure_profile_csv(const ContactState<3> &,
                       const ModelFrame<3> &,
                       const std::function<double(const Point<3> &)> &);
} // namespace contact_fem
