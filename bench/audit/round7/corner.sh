#!/bin/bash
# Round 7: grazing contact at a corner (corner_2d.geo / corner_2d.prm.in):
# overhangs xo, formulations; metamorphic.py variants turned, moved, in mm,
# renumbered. Run from bench/audit/round7.
M=../../../../tests/metamorphic/metamorphic.py
B=${B:-../../../../build/contact_fem}
for xo in 0.5 0.55 0.9999; do
  gmsh -2 -setnumber xo $xo corner_2d.geo -o corner_2d.msh > /dev/null 2>&1
  for form in "alm frictional:coulomb 0.3" "penalty frictional:coulomb 0.3" "mpc frictional:coulomb 0.3" "alm frictionless:" "mpc frictionless:"; do
    IFS=: read f fr <<< "$form"
    d=run_corner_${xo}_${f// /_}; rm -rf $d; mkdir -p $d; cd $d
    timeout 600 nice -n 10 python3 $M --executable $B --template ../corner_2d.prm.in \
      --set "Contact/Formulation=$f" --set "Contact/Friction=$fr" \
      "turned_far=rotate_degrees:33&translate:1e3,-2e3" \
      "mm_turned=scale_length:1e-3&scale_moduli:1e3&rotate_degrees:-117&translate:1e2,5e1" \
      "renumbered=renumber&swap" > out.txt 2>&1
    echo "== xo=$xo $f rc=$? $(grep -E 'active_slave|max_contact' out.txt | tr -s ' ' | tr '\n' ' ')"; grep -E "same|differ|fail|exit" out.txt
    cd ..
  done
done
gmsh -2 corner_2d.geo -o corner_2d.msh > /dev/null 2>&1
