#!/bin/bash
# Round 7: the forces per boundary on 2 ranks. Meshes of the tetrahedral
# block on its base (meshes/tet_block_on_base.geo with element sizes hb of
# the base and ht of the block), tetblock.prm (load (0.25, 0.2) pull, 2
# press: the base bottom's reaction is (-0.25, -0.2, 2) exactly) on 2 ranks.
# B=/path/to/contact_fem; run from bench/audit/round7.
B=${B:-../../../build/contact_fem}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p scan && sed 's/= 0.7;/= hb;/; s/= 0.4;$/= ht;/' ../../../meshes/tet_block_on_base.geo > scan/tb.geo
for hb in 0.9 0.8 0.6 0.5; do for ht in 0.6 0.5 0.45 0.35; do
  gmsh -3 -setnumber hb $hb -setnumber ht $ht scan/tb.geo -o scan/tb_${hb}_${ht}.msh > /dev/null 2>&1
  r=$(nice -n 10 mpirun -np 2 $B tetblock.prm --set "Geometry/Mesh file=scan/tb_${hb}_${ht}.msh" \
      --output-directory scan/out 2>&1 | grep -E "Cycle|boundary 2|rror" | tr '\n' ' ')
  echo "$hb $ht $r"
done; done
