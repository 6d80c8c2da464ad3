// The materials of a unit test, set through the "Materials" subsection as a
// scene file would set them (comma-separated lists, one entry per body;
// the models empty: every body linear).
#ifndef contact_fem_unit_test_materials_h
#define contact_fem_unit_test_materials_h

#include <deal.II/base/parameter_handler.h>

#include <contact_fem/material/material.h>

#include <string>

template <int dim>
contact_fem::Materials<dim>
make_materials(const std::string &ids,
               const std::string &youngs_moduli,
               const std::string &poissons_ratios,
               const std::string &models = "")
{
  dealii::ParameterHandler prm;
  contact_fem::Materials<dim>::declare_parameters(prm);
  prm.enter_subsection("Materials");
  prm.set("Material ids", ids);
  prm.set("Young's moduli", youngs_moduli);
  prm.set("Poisson's ratios", poissons_ratios);
  prm.set("Models", models);
  prm.leave_subsection();
  contact_fem::Materials<dim> materials;
  materials.parse_parameters(prm);
  return materials;
}

#endif
