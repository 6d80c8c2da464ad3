#!/bin/bash
# Round 6: which cause a singular solve names. The tetrahedral block on a
# base 1e9 / 3e9 / 1e10 times stiffer with friction (held by it: relative
# residual 9.2e-3 / 3.8e-3 / 1.7e-3), and the same block without friction
# (a free rigid-body mode: 5.0 alm, 1.3 penalty).
B=${B:-../../../build/contact_fem}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$(dirname "$0")"
for E in 1e11 3e11 1e12; do
  echo "== base E = $E, alm frictional"
  $B tet_block.prm --set "Materials/Young's moduli=100, $E" --output-directory /tmp/round6_singular 2>&1 |
    grep -m1 "^Error" -A1 | cut -c1-300
done
for f in "alm frictionless" "penalty frictionless"; do
  echo "== base E = 1e11, $f"
  $B tet_block.prm --set "Materials/Young's moduli=100, 1e11" --set "Contact/Formulation=$f" \
    --set "Contact/Friction=" --output-directory /tmp/round6_singular 2>&1 | grep -m1 "^Error" -A1 | cut -c1-300
done
