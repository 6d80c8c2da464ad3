#!/bin/bash
# The held-surface rehearsal (issue 32 item 1; doc/performance.md, "The held
# surface rehearsed"): every 2-rank scene test of tests/scenes run with
# CONTACT_FEM_CHECK_HELD_SURFACE set, its output compared with the stored
# .mpirun=2.output (timing lines dropped). A scene whose readers read only
# what each rank will hold prints the same (or differs from the stored
# output only where a plain 2-rank run does, within numdiff's tolerances);
# one that reads more prints NaN, fails or hangs (cut at 60 s).
#
# Usage: bench/held_surface/rehearse.sh BUILD_DIR [OUT_DIR]
set -u
build=$(cd "$1" && pwd)
out=${2:-/tmp/held_surface_rehearsal}
repo=$(cd "$(dirname "$0")/../.." && pwd)
scenes=$repo/tests/scenes
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 CONTACT_FEM_CHECK_HELD_SURFACE=1
drop_timings() { grep -vE "wall|seconds|time \(|Time|[0-9] s$|[0-9] s\)|MPI process" "$1"; }
for stored in "$scenes"/*.mpirun=2.output; do
  name=$(basename "$stored" .mpirun=2.output)
  prm=$scenes/$name.prm
  if [ ! -f "$prm" ]; then
    prm=$out/$name.prm
    sed "s|@SOURCE_DIR@|$scenes|g" "$scenes/$name.prm.in" > "$prm"
  fi
  rm -rf "${out:?}/$name"
  (cd "$out" && timeout 60 mpirun -np 2 "$build/contact_fem" "$prm" \
     --output-directory "$out/$name" > "$out/$name.log" 2>&1)
  rc=$?
  differing=$(diff <(drop_timings "$out/$name.log") <(drop_timings "$stored") | grep -c '^[<>]')
  echo "$name exit=$rc nan_lines=$(grep -ci '\bnan\b' "$out/$name.log") differing_lines=$differing"
done
