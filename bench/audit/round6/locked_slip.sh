#!/bin/bash
# Round 6: every node slips with the load inside the friction capacity. The
# 2D blocks (blocks2d.prm: pressure t, traction 0.1 t, Coulomb 0.3) with
# the upper block's Poisson's ratio from 0.3 to 0.49, degree-1 elements
# without and with B-bar, and the other formulations at 0.48.
B=${B:-../../../build/contact_fem}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$(dirname "$0")"
run() {
  printf "%s: " "$*"
  $B blocks2d.prm "$@" --output-directory /tmp/round6_locked 2>&1 |
    grep -E "^Error|stick / slip" | tr -s ' ' | tr '\n' ' ' | cut -c1-240
  echo
}
for nu in 0.3 0.4 0.45 0.48 0.49; do
  for v in standard B-bar; do
    run --set "Materials/Poisson's ratios=$nu, 0.3" --set "Finite element/Volumetric strain=$v"
  done
done
for extra in "Contact/Formulation=mpc frictional" "Contact/Formulation=penalty frictional" \
  "Geometry/Contact blocks/Upper cells=10" "Finite element/Degree=2" \
  "Boundary conditions/Traction=1: 0*t, 0" "Contact/Friction=tresca 0.2"; do
  run --set "Materials/Poisson's ratios=0.48, 0.3" --set "$extra"
done
