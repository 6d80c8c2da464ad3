#!/bin/bash
# Finite deformation, near-incompressible, on the Gmsh tetrahedral block (round 5)
T=/work/wt/audit5/tests/metamorphic/tet_block_3d.prm.in
M=/work/wt/audit5/tests/metamorphic/metamorphic.py
B=/work/wt/audit5/build/contact_fem
for case in "nu4999_fric:alm frictional:coulomb 0.3:0.4999, 0.4999:B-bar" "nu4999_nofric:alm frictionless::0.4999, 0.4999:B-bar" "nu4999_std:alm frictional:coulomb 0.3:0.4999, 0.4999:standard"; do
  IFS=: read name form fric nus vol <<< "$case"
  mkdir -p $name; cd $name
  args=(--set "Contact/Formulation=$form" --set "Materials/Models=neo-hookean, neo-hookean" --set "Contact/Kinematics=current" --set "Materials/Poisson's ratios=$nus" --set "Finite element/Volumetric strain=$vol")
  [ -n "$fric" ] && args+=(--set "Contact/Friction=$fric") || args+=(--set "Contact/Friction=")
  timeout 900 nice -n 10 python3 $M --executable $B --template $T "${args[@]}" "turned=rotate_degrees:-71,1,2,3&translate:1e2,1e2,-1e2" "mm=scale_length:1e-3&scale_moduli:1e3&rotate_degrees:37,0.3,-1,0.4" > out.txt 2>&1
  echo "== $name rc=$?"; tail -6 out.txt
  cd ..
done
