// The tiling check of the 3D segmentation (ContactInterface::check_tiling())
// on curved Q2 faces: the blocks of contact_interface_linearisation_01 in
// 3D (the lower block's top, 3 x 3 cells, the slave; the upper block's
// base, 2 x 2 cells overhanging it by 0.1, the master; 0.05 apart), Q2 on a
// quadratic mapping, every interface DoF displaced at random by up to 1 %
// and 2 % of the width (deterministic generator, 8 seeds): curved faces,
// master edges crossing slave faces near the slave's fan cuts. The masters
// cover every slave face, so the check must pass on each. It stopped at
// 2 %, seed 29, with 1.000580 of a slave face covered: it summed the
// overlap polygons' areas in the slave parameters, where a zero-width
// join of the clipping (along a fan cut and back) has an area of the
// order of the face's bending; it now measures in the auxiliary plane
// (Mortar::projected_area()), where that join has none.
#include <deal.II/base/mpi.h>

#include "unit_test_random.h"
#include "unit_test_stacked_interface.h"

#include <exception>
#include <iostream>
#include <vector>

using namespace dealii;
using namespace contact_fem;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  StackedBlocksInterface           blocks(2);
  auto                            &interface = blocks.interface;
  for (const double amplitude : {0.01, 0.02})
    for (unsigned int seed : {29u, 1u, 2u, 3u, 4u, 5u, 6u, 7u})
      {
        Random              random(seed);
        std::vector<double> u(interface.dofs().size());
        for (double &value : u)
          value = amplitude * random.next();
        try
          {
            interface.update(u, 3.);
            std::cout << "amplitude " << amplitude << ", seed " << seed
                      << ": the overlaps tile every slave face" << std::endl;
          }
        catch (const std::exception &e)
          {
            std::cout << "amplitude " << amplitude << ", seed " << seed << ": " << e.what()
                      << std::endl;
          }
      }
}
