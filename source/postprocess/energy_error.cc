// The energy-norm error against Analytical solution/Reference potential
// energy, printed and recorded with each cycle's results.
#include <contact_fem/postprocess/postprocessor.h>
#include <contact_fem/simulator/scene_parameters.h>

#include <cmath>
#include <ostream>

namespace contact_fem
{
  namespace
  {
    template <int dim>
    class EnergyError : public Postprocessor<dim>
    {
    public:
      static std::unique_ptr<Postprocessor<dim>>
      create(const PostprocessorContext<dim> &context)
      {
        if (!std::isfinite(context.analytical.reference_potential_energy))
          return nullptr;
        return std::make_unique<EnergyError<dim>>();
      }

      /// Reads the cycle's potential energy and the analytical record.
      void
      after_cycle(const RunView<dim> &view, Json &cycle_record, std::ostream &out) override
      {
        // A conforming discrete solution minimises the energy over a subset:
        // its energy lies above the exact one, and 2 (Pi_h - Pi) is the
        // squared energy-norm error (plus the contact work, see the
        // parameter).
        // Degree-1 Hertz: the work of the contact force on the chord gap
        // (HertzCylinder::compare()) is a geometry error of the polygonal
        // arc, not part of the discretisation error the estimate is
        // compared with.
        const double chord_work     = cycle_record["analytical"]["chord_gap_work"].number_value();
        const double chord_gap_work = std::isfinite(chord_work) ? chord_work : 0.;
        const double excess = cycle_record["potential_energy"].number_value() + chord_gap_work -
                              view.analytical.reference_potential_energy;
        const double energy_error = std::sqrt(2. * std::abs(excess));
        cycle_record.set("energy_error", energy_error);
        out << "    energy-norm error:            " << energy_error << " (from Pi_h "
            << (chord_gap_work > 0. ? "+ W_chord " : "") << "- Pi_ref = " << excess << ")"
            << std::endl;
        if (excess < 0.)
          out << "  Warning: the potential energy is below the reference: the "
                 "discrete problem is softer than the exact one (a polygonal "
                 "curved boundary, the weak mortar gap) or the reference is not "
                 "accurate enough; sqrt(2 |Pi_h - Pi_ref|) is then not a bound "
                 "of the error."
              << std::endl;
      }
    };
  } // namespace

  CONTACT_FEM_REGISTER_POSTPROCESSOR(EnergyError, "energy error", 40)
} // namespace contact_fem
