#!/bin/sh
# Perturbed twin of a scene test (ctest label 'perturbed'): runs contact_fem
# on the test's .prm with a random DoF numbering (Finite element/DoF
# renumbering seed, from CONTACT_FEM_PERTURBATION_SEED, default 1) and
# compares its output with the test's own .output as deal.II's run_test.sh
# does (normalize.pl, then numdiff with the same tolerances). Round-off
# changes; an output that then changes beyond numdiff's tolerances hangs on
# round-off and fails on another machine too.
#
# Usage: run_perturbed.sh NUMDIFF NORMALIZE_PL COMPARISON_FILE RANKS CONTACT_FEM PRM [MPIEXEC...]
# (RANKS 0: a serial run; else MPIEXEC... launches RANKS processes.)
set -u
. "$(dirname "$0")/output_filters.sh"
numdiff="$1" normalize="$2" comparison="$3" ranks="$4" contact_fem="$5" prm="$6"
shift 6
seed="${CONTACT_FEM_PERTURBATION_SEED:-1}"
export OMP_NUM_THREADS=2 OMPI_MCA_rmaps_base_oversubscribe=1 LC_ALL=C
rm -rf output results
if [ "$ranks" -eq 0 ]; then
  set -- "$contact_fem"
else
  set -- "$@" "$contact_fem"
fi
"$@" "$prm" --set "Finite element/DoF renumbering seed=$seed" > output 2>&1
status=$?
perl -pi "$normalize" output
if [ $status -ne 0 ]; then
  echo "contact_fem failed (exit $status) with DoF renumbering seed $seed:"
  cat output
  exit 1
fi
strip_krylov_counts "$comparison" > expected
strip_krylov_counts output > compared
if ! numdiff_outputs "$numdiff" expected compared diff; then
  echo "Output with DoF renumbering seed $seed differs from $comparison"
  echo "(run: $(pwd)/output); first 30 lines of numdiff:"
  head -n 30 diff
  exit 1
fi
