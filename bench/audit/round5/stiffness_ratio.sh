#!/bin/bash
# Huge stiffness ratios with friction on the Gmsh tetrahedral block (round 5)
T=/work/wt/audit5/tests/metamorphic/tet_block_3d.prm.in
M=/work/wt/audit5/tests/metamorphic/metamorphic.py
B=/work/wt/audit5/build/contact_fem
for case in "ratio1e6:@E(100)@, @E(1e8)@:alm frictional" "ratio1e9:@E(100)@, @E(1e11)@:alm frictional" "ratio1e9_soft_base:@E(1e11)@, @E(100)@:alm frictional" "ratio1e6_mpc:@E(100)@, @E(1e8)@:mpc frictional"; do
  IFS=: read name moduli form <<< "$case"
  mkdir -p $name; cd $name
  timeout 900 nice -n 10 python3 $M --executable $B --template $T --set "Materials/Young's moduli=$moduli" --set "Contact/Formulation=$form" "turned=rotate_degrees:-71,1,2,3&translate:1e2,1e2,-1e2" "mm=scale_length:1e-3&scale_moduli:1e3&rotate_degrees:37,0.3,-1,0.4" > out.txt 2>&1
  echo "== $name rc=$?"; tail -4 out.txt; grep -m3 -iE "warn" results-identity/log.txt | cut -c1-300
  cd ..
done
