#!/bin/sh
# Every scene's expected output on N ranks must equal its serial one (but
# for the first line, which names the rank count) within numdiff's
# tolerances. Partitioning renumbers the DoFs and reorders every sum, so a
# 2-rank run is a perturbation of the serial one: a scene with both outputs
# needs no perturbed twin of its N-rank run, provided the two agree, which
# this checks.
#
# Usage: compare_mpi_outputs.sh NUMDIFF SCENE_DIRECTORY [NAME_TO_SKIP...]
set -u
. "$(dirname "$0")/output_filters.sh"
numdiff="$1" directory="$2"
shift 2
failed=0 compared=0
for parallel in "$directory"/*.mpirun=*.output; do
  serial="${parallel%.mpirun=*.output}.output"
  name=$(basename "${serial%.output}")
  [ -f "$serial" ] || continue
  skip=0
  for excluded in "$@"; do [ "$name" = "$excluded" ] && skip=1; done
  [ $skip -eq 1 ] && continue
  strip_krylov_counts "$serial" | tail -n +2 > serial.txt
  strip_krylov_counts "$parallel" | tail -n +2 > parallel.txt
  compared=$((compared + 1))
  if ! numdiff_outputs "$numdiff" serial.txt parallel.txt diff.txt; then
    echo "$(basename "$parallel") differs from $(basename "$serial"):"
    head -n 20 diff.txt
    failed=1
  fi
done
echo "$compared pairs of serial and parallel outputs compared"
[ $compared -gt 0 ] || failed=1
exit $failed
