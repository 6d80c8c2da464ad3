#!/usr/bin/env bash
# Copies the outputs of the last ctest run (build/) over the stored .output
# files of the tests that failed their comparison. Review with `git diff
# tests/` and give the reason for every change in the commit message.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
for out in "$build"/tests/*/*.release/output "$build"/tests/*/*.release/mpirun=*/output; do
  [ -f "$out" ] || continue
  dir=$(dirname "$out")
  case "$dir" in
    */mpirun=*) n=${dir##*/mpirun=}; test_dir=$(dirname "$dir"); suffix=".mpirun=$n.output" ;;
    *) test_dir=$dir; suffix=".output" ;;
  esac
  name=$(basename "$test_dir" .release)
  category=$(basename "$(dirname "$test_dir")")
  target="$root/tests/$category/$name$suffix"
  if [ -f "$target" ] && ! cmp -s "$out" "$target"; then
    cp "$out" "$target"
    echo "updated tests/$category/$name$suffix"
  fi
done
