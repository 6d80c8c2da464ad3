// Which interface nodes lie on a symmetry plane (Node::symmetry_plane):
// a support that holds one component along a flat face beside the contact
// surface mirrors the surface only if it moves as a whole. The lower block
// of make_stacked_blocks() (2D, slave top id 3, master base id 4) gets its
// face x = 0 as id 5 and its x displacement held there. As a plain support
// (Fixed, or a prescribed value uniform along the face) the slave node at
// (0, 1) lies on the plane x = 0; named as a moving support (a prescribed
// value that varies along the face, which turns or bends it) it does not.
// DisplacementCondition::varies_in_space() decides which, from the
// expression's names.

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/numerics/vector_tools.h>

#include <contact_fem/contact/contact_interface.h>
#include <contact_fem/material/material.h>
#include <contact_fem/simulator/scene_parameters.h>

#include "unit_test_blocks.h"
#include "unit_test_materials.h"

#include <cmath>
#include <iostream>

using namespace dealii;
using namespace contact_fem;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  for (const std::string expression :
       {"0", "-0.01*t", "1e-3*max(t-1, 0)", "0.1*x*t", "-0.2*t*y", "sin(z)", "exp(2*x_0)"})
    std::cout << "'" << expression << "' varies in space: "
              << DisplacementCondition{5, 0, expression, "test"}.varies_in_space() << std::endl;

  Triangulation<2> tria;
  make_stacked_blocks(tria);
  for (const auto &cell : tria.active_cell_iterators())
    for (const auto f : cell->face_indices())
      if (cell->face(f)->at_boundary() && cell->material_id() == 1 &&
          std::abs(cell->face(f)->center()[0]) < 1e-12)
        cell->face(f)->set_boundary_id(5);
  const FESystem<2> fe(FE_Q<2>(1), 2);
  DoFHandler<2>     dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const MappingQ<2>  mapping(1);
  const Materials<2> materials = make_materials<2>("1, 2", "100, 200", "0.3, 0.3");

  AffineConstraints<double> support, none;
  VectorTools::interpolate_boundary_values(mapping, dof_handler, 5, Functions::ZeroFunction<2>(2),
                                           support, ComponentMask(std::vector<bool>{true, false}));
  support.close();
  none.close();

  for (const bool moving : {false, true})
    {
      ContactInterface<2> interface;
      interface.initialize(mapping, dof_handler, {ContactPair{3, 4}}, support, none, materials,
                           MPI_COMM_WORLD,
                           moving ? std::set<types::boundary_id>{5} : std::set<types::boundary_id>{});
      std::cout << (moving ? "id 5 a moving support:" : "id 5 a plain support:") << std::endl;
      for (const auto &node : interface.nodes)
        if (!node.master)
          std::cout << "  slave node (" << node.reference[0] << ", " << node.reference[1]
                    << "): on a plane normal to x " << node.symmetry_plane[0] << ", to y "
                    << node.symmetry_plane[1] << std::endl;
    }
}
