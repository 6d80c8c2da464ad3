#!/bin/bash
# Counts the calls of the finite-strain and current-kinematics entry points
# in one contact_fem run (gdb breakpoints that never stop, count_calls.py):
# a small-strain scene must call none of them (doc/performance.md, "Cost of
# finite strain in 3D"). perf probes (uprobes) are not available on the
# container this was written on; gdb needs no kernel support. Under gdb a
# run is slower (each counted call traps): use small scenes.
#
# Usage: bench/finite_strain/count_calls.sh BINARY SCENE.prm [contact_fem options...]
# Prints one line per entry point: its name and the number of calls.
here=$(dirname "$(readlink -f "$0")")
functions=(
  "contact_fem::FiniteStrainBulk<3>::FiniteStrainBulk"           # a finite-strain body exists
  "contact_fem::FiniteStrainBulk<3>::linearise"                  # cell tangent and force
  "contact_fem::ContactProblem<3>::relinearise_finite_strain_cell"
  "contact_fem::NeoHookean<3>::second_piola"                     # the law, per quadrature point
  "contact_fem::InterpenetrationCheck<3>::InterpenetrationCheck" # issue 29 item 6
  "contact_fem::InterpenetrationCheck<3>::check"
  "contact_fem::ContactInterface<3>::linearise"                  # current kinematics, per iterate
  "contact_fem::Mortar::linearise_slave_face"                    # its AD per slave face
)
out=$(mktemp)
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
  COUNT_CALLS="$(printf '%s\n' "${functions[@]}")" COUNT_CALLS_OUT="$out" \
  gdb -batch -x "$here/count_calls.py" --args "$@" > /dev/null 2>&1
cat "$out"
rm -f "$out"
