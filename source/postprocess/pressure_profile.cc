#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/contact/formulations/contact_formulation.h>
#include <contact_fem/postprocess/pressure_profile.h>

#include <algorithm>
#include <iomanip>
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
    // Sorted by (pair, row): one pair's nodes together, along x.
    std::vector<std::pair<unsigned int, std::vector<double>>> rows;
    for (const auto &s : interface.slave_nodes)
      if (s.paired)
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
          rows.emplace_back(s.pair, row);
        }
    std::sort(rows.begin(), rows.end());
    std::ostringstream out;
    out << (dim == 2 ? "x" : "x,y,z") << ",pressure,hertz_pressure,gap,active";
    for (const auto &field : fields)
      out << "," << field.name;
    out << ",pair" << (dim == 2 ? ",y" : "") << ",reference_x,reference_y"
        << (dim == 3 ? ",reference_z" : "") << "\n"
        << std::setprecision(10);
    for (const auto &[pair, r] : rows)
      for (unsigned int k = 0; k < r.size(); ++k)
        out << r[k] << (k + 1 < r.size() ? ',' : '\n');
    return out.str();
  }

  template std::string
  pressure_profile_csv(const ContactState<2> &,
                       const ModelFrame<2> &,
                       const std::function<double(const Point<2> &)> &);
  template std::string
  pressure_profile_csv(const ContactState<3> &,
                       const ModelFrame<3> &,
                       const std::function<double(const Point<3> &)> &);
} // namespace contact_fem
