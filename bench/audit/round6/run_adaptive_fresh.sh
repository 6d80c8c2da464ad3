#!/bin/bash
# The adaptive-against-fresh comparisons of round 6 (adaptive_fresh.sh).
cd "$(dirname "$0")"
REV=("Geometry/Global refinements=0" "Boundary conditions/Pressure=1: min(t,1)"
     "Boundary conditions/Traction=1: 0.12*min(t,1) - 0.25*max(t-1,0), 0.1*min(t,1), 0"
     "Load stepping/End time=2" "Load stepping/Number of load steps=4")
./adaptive_fresh.sh cattaneo_2d cattaneo.prm 3 "Geometry/Global refinements=0"
./adaptive_fresh.sh tet_alm tet_block.prm 2 "${REV[@]}"
./adaptive_fresh.sh tet_penalty tet_block.prm 2 "${REV[@]}" "Contact/Formulation=penalty frictional"
./adaptive_fresh.sh tet_mpc tet_block.prm 2 "${REV[@]}" "Contact/Formulation=mpc frictional"
./adaptive_fresh.sh tet_tresca tet_block.prm 2 "${REV[@]}" "Contact/Friction=tresca 0.15"
