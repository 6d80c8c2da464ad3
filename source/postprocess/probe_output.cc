// The displacements at Output/Displacement probes, printed and recorded
// with each cycle's results.
#include <contact_fem/core/parameters.h>
#include <contact_fem/postprocess/postprocessor.h>
#include <contact_fem/simulator/scene_parameters.h>

#include <iomanip>
#include <ostream>

namespace contact_fem
{
  namespace
  {
    template <int dim>
    class DisplacementProbes : public Postprocessor<dim>
    {
    public:
      static std::unique_ptr<Postprocessor<dim>>
      create(const PostprocessorContext<dim> &context)
      {
        if (context.output.displacement_probes.empty())
          return nullptr;
        return std::make_unique<DisplacementProbes<dim>>();
      }

      void
      after_cycle(const RunView<dim> &view, Json &cycle_record, std::ostream &out) override
      {
        const std::vector<double> values = view.probe_displacements();
        Json                      probes = Json::array();
        for (unsigned int i = 0; i < view.probe_dofs.size(); ++i)
          {
            const std::string point        = to_string(view.output.displacement_probes[i]);
            Json              displacement = Json::array();
            out << "    displacement at " << point << ":" << std::scientific
                << std::setprecision(7);
            for (unsigned int d = 0; d < dim; ++d)
              {
                displacement.push(values[i * dim + d]);
                out << "  u"
                    << "xyz"[d] << " = " << values[i * dim + d];
              }
            out << std::defaultfloat << std::setprecision(6) << std::endl;
            probes.push(Json::object().set("point", point).set("displacement", displacement));
          }
        cycle_record.set("displacement_probes", probes);
      }
    };
  } // namespace

  CONTACT_FEM_REGISTER_POSTPROCESSOR(DisplacementProbes, "displacement probes", 20)
} // namespace contact_fem
