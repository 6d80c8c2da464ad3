// Hertz' solution as an analytical comparison: the contact size, the peak
// pressure and the pressure's L2 error of a run against Hertz' values for
// the transmitted load (the cylinder here, the sphere and the Cattaneo
// problem build on it).
#ifndef contact_fem_hertz_comparison_h
#define contact_fem_hertz_comparison_h

#include <contact_fem/postprocess/analytical_comparison.h>
#include <contact_fem/postprocess/hertz_solution.h>

namespace contact_fem
{
  /// 'hertz cylinder': plane strain, load per unit thickness.
  template <int dim>
  class HertzCylinder : public AnalyticalComparison<dim>
  {
  public:
    using AnalyticalComparison<dim>::AnalyticalComparison;

    Json
    compare(const ContactState<dim> &state,
            const Json              &contact,
            const Json              &reaction) const override;
    void
    print(const Json &record, std::ostream &out) const override;
    std::function<double(const Point<dim> &)>
    exact_pressure(const ContactState<dim> &state) const override;
    void
    report_recovered(const ContactState<dim>   &state,
                     const std::vector<double> &pressure,
                     const std::vector<double> &tangential,
                     const std::string         &label,
                     const std::string         &prefix,
                     Json                      &record,
                     std::ostream              &out) const override;

  protected:
    /// The Hertz load: the transmitted contact force, the same as the
    /// applied load when the balance holds, and the only measure when the
    /// scene is driven by a prescribed displacement.
    virtual double
    load(const ContactState<dim> &state) const;
    /// Hertz' solution for load(), E* from the materials of the first pair.
    virtual HertzContact
    solution(const ContactState<dim> &state) const;
    /// The distance from the first point of contact that the pressure is a
    /// function of: x - Center.
    virtual double
    coordinate(const Point<dim> &x) const;
    /// The measured contact half-width (or radius) of @p state, whose
    /// contact record is @p contact.
    virtual double
    measured_size(const ContactState<dim> &state, const Json &contact) const;
  };
} // namespace contact_fem

#endif
