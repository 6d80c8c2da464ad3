// The contact interface of make_stacked_blocks() (unit_test_blocks.h):
// Q<degree> on a mapping of degree mapping_degree, the lower block's top (id 3)
// the slave, the upper block's base (id 4) the master, E = 100 and 200,
// nu = 0.3, no constraints. The members keep what the interface points to
// alive for the test's run.
#ifndef contact_fem_unit_test_stacked_interface_h
#define contact_fem_unit_test_stacked_interface_h

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/material/material.h>

#include "unit_test_blocks.h"
#include "unit_test_materials.h"

template <int dim>
struct StackedInterface
{
  StackedInterface(const unsigned int degree, const unsigned int mapping_degree)
    : fe(dealii::FE_Q<dim>(degree), dim)
    , mapping(mapping_degree)
    , materials(make_materials<dim>("1, 2", "100, 200", "0.3, 0.3"))
  {
    make_stacked_blocks(tria);
    dof_handler.reinit(tria);
    dof_handler.distribute_dofs(fe);
    none.close();
    interface.initialize(mapping, dof_handler, {contact_fem::ContactPair{3, 4}}, none, none,
                         materials, MPI_COMM_WORLD);
  }

  dealii::Triangulation<dim>         tria;
  dealii::FESystem<dim>              fe;
  dealii::DoFHandler<dim>            dof_handler;
  dealii::MappingQ<dim>              mapping;
  contact_fem::Materials<dim>        materials;
  dealii::AffineConstraints<double>  none;
  contact_fem::ContactInterface<dim> interface;
};

/// The 3D blocks, Q<degree> on a mapping of the same degree.
struct StackedBlocksInterface : StackedInterface<3>
{
  explicit StackedBlocksInterface(const unsigned int degree)
    : StackedInterface<3>(degree, degree)
  {}
};

#endif
