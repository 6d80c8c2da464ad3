// 'hertz sphere': Hertz' sphere on a half-space (3D), for the whole sphere
// or a part of it cut by symmetry planes (Analytical solution/Symmetry
// fraction); the sphere's axis is parallel to z through (Center, Center y).
#include <deal.II/base/mpi.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/core/format.h>
#include <contact_fem/postprocess/hertz_comparison.h>
#include <contact_fem/simulator/scene_parameters.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>

namespace contact_fem
{
  namespace
  {
    template <int dim>
    class HertzSphere : public HertzCylinder<dim>
    {
    public:
      using HertzCylinder<dim>::HertzCylinder;

      Json
      compare(const ContactState<dim> &state,
              const Json              &contact,
              const Json              &reaction) const override
      {
        Json result = HertzCylinder<dim>::compare(state, contact, reaction);
        // F of the model against the pressure resultant applied to it.
        const double applied        = reaction["applied_load"].number_value();
        const double modelled_force = std::abs(state.contact_force()[dim - 1]);
        const Extent extent         = radial_extent(state);
        result.set("symmetry_fraction", this->analytical.symmetry_fraction)
          .set("contact_force_along_axis", modelled_force)
          .set("contact_force_over_applied_load", applied > 0. ? modelled_force / applied : 0.)
          .set("contact_radius", extent.last_active)
          .set("first_inactive_radius", extent.first_inactive); // null if none
        return result;
      }

      void
      print(const Json &hertz, std::ostream &out) const override
      {
        const double first_inactive = hertz["first_inactive_radius"].number_value();
        // The errors are printed to 3 digits: the tests compare them.
        out << std::setprecision(6)
            << "    Hertz load F (whole sphere):  " << hertz["load"].number_value()
            << " (contact force along z " << hertz["contact_force_along_axis"].number_value()
            << " over symmetry fraction " << hertz["symmetry_fraction"].number_value() << ")"
            << std::endl
            << "    contact force / applied load: "
            << hertz["contact_force_over_applied_load"].number_value() << std::endl
            << "    Hertz a:                      " << hertz["a"].number_value() << std::endl
            << "    Hertz p0:                     " << hertz["p_max"].number_value() << std::endl
            << "    contact radius:               " << hertz["contact_radius"].number_value()
            << " (farthest active node; first inactive node beyond: "
            << (std::isfinite(first_inactive) ? significant(first_inactive, 6) : "none") << ")"
            << std::endl
            << std::setprecision(3)
            << "    p_max relative error:         " << hertz["p_max_relative_error"].number_value()
            << std::endl
            << "    |a - a_Hertz| / slave h:      "
            << hertz["a_error_in_slave_elements"].number_value() << std::endl
            << "    pressure L2 error vs Hertz:   "
            << hertz["pressure_l2_relative_error"].number_value() << std::endl
            << "    p_max within 3 % of Hertz:    "
            << (std::abs(hertz["p_max_relative_error"].number_value()) < 0.03 ? "yes" : "no")
            << std::endl
            << "    a within one slave element:   "
            << (hertz["a_error_in_slave_elements"].number_value() <= 1. ? "yes" : "no") << std::endl
            << std::setprecision(6);
      }

    protected:
      /// The sphere takes the force's component along its axis (z; a model
      /// cut by symmetry planes transmits a horizontal part too), for the
      /// whole sphere.
      double
      load(const ContactState<dim> &state) const override
      {
        return std::abs(state.contact_force()[dim - 1]) / this->analytical.symmetry_fraction;
      }

      HertzContact
      solution(const ContactState<dim> &state) const override
      {
        return HertzContact::sphere(load(state), this->analytical.radius,
                                    state.interface.contact_modulus(0));
      }

      double
      coordinate(const Point<dim> &x) const override
      {
        return this->analytical.axis_distance(x[0], x[1]);
      }

      /// The contact radius is measured about the axis.
      double
      measured_size(const ContactState<dim> &state, const Json &) const override
      {
        return radial_extent(state).last_active;
      }

    private:
      /// Radial extent of the contact zone about the axis, at the deformed
      /// positions of the paired slave nodes: the farthest active node, and
      /// the nearest inactive one beyond it (the exact radius should lie
      /// between; infinite if there is none).
      struct Extent
      {
        double last_active = 0., first_inactive = std::numeric_limits<double>::infinity();
      };

      /// Each rank the nodes whose rows it owns, the extremes reduced
      /// exactly (MPI max, then min). Collective.
      Extent
      radial_extent(const ContactState<dim> &state) const
      {
        std::vector<std::pair<double, bool>> nodes;
        for (const auto &s : state.interface.slave_nodes)
          if (s.paired && state.interface.owns_row(s))
            {
              const Point<dim> x = state.position(s.node);
              nodes.emplace_back(this->analytical.axis_distance(x[0], x[1]),
                                 state.contact.is_active(s.node));
            }
        const MPI_Comm comm = state.interface.communicator();
        Extent         extent;
        for (const auto &[r, active] : nodes)
          if (active)
            extent.last_active = std::max(extent.last_active, r);
        extent.last_active = Utilities::MPI::max(extent.last_active, comm);
        for (const auto &[r, active] : nodes)
          if (!active && r > extent.last_active)
            extent.first_inactive = std::min(extent.first_inactive, r);
        extent.first_inactive = Utilities::MPI::min(extent.first_inactive, comm);
        return extent;
      }
    };
  } // namespace

  CONTACT_FEM_REGISTER_ANALYTICAL_COMPARISON(HertzSphere, "hertz sphere")
} // namespace contact_fem
