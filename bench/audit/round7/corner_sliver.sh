#!/bin/bash
# Round 7: the corner of the upper block over the lower block's top by
# w = 1 - xo, pushed straight down by 0.01 (corner_2d.prm.in without the
# sideways push). Run from bench/audit/round7.
B=${B:-../../../build/contact_fem}
mkdir -p sliver
for xo in 0.9 0.99 0.999 0.9999 0.99999 0.999999 1.0; do
  gmsh -2 -setnumber xo $xo corner_2d.geo -o sliver/c_$xo.msh > /dev/null 2>&1
  sed "s#@MESH(corner_2d.msh)@#c_$xo.msh#; s/@MAT(\([12]\))@/\1/g; s/@E(\([0-9]*\))@/\1/g; s/@DX(0.002, -0.01)@/0/; s/@DY(0.002, -0.01)@/-0.01/" corner_2d.prm.in > sliver/c_$xo.prm
  nice -n 5 $B sliver/c_$xo.prm --output-directory sliver/out > sliver/out.txt 2>&1
  echo "xo=$xo rc=$? $(grep -E 'active slave nodes|max contact pressure|normal contact force|Error' sliver/out.txt | tr -s ' ' | tr '\n' '|')"
done
