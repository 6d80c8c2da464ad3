#!/bin/bash
# Round 6: an adaptive study's refined cycle against a fresh run on the same
# mesh. Estimator = global refines every cell, so cycle k's mesh is the one
# Global refinements = g0 + k builds; friction re-solves the whole load path
# in every cycle (doc/design.md), so every number must agree.
# Usage: adaptive_fresh.sh NAME SCENE.prm CYCLES [--set ...]...
B=${B:-../../../build/contact_fem}
name=$1; scene=$2; cycles=$3; shift 3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
out=${OUT:-/tmp/a6}/$name
g0=$(grep -m1 "Global refinements" "$scene" | sed 's/.*= *\([0-9]*\).*/\1/')
for s in "$@"; do case $s in Geometry/Global\ refinements=*) g0=${s#*=};; esac; done
args=(); for s in "$@"; do args+=(--set "$s"); done
nice -n 10 $B "$scene" "${args[@]}" --set "Refinement/Number of cycles=$cycles" \
  --set "Refinement/Estimator=global" --set "Output/Write VTU=false" \
  --output-directory $out/study > $out.study.txt 2>&1
echo "== $name study rc=$? (cycles $cycles from level $g0)"
for ((k = 1; k < cycles; ++k)); do
  nice -n 10 $B "$scene" "${args[@]}" --set "Geometry/Global refinements=$((g0 + k))" \
    --set "Refinement/Number of cycles=1" --set "Output/Write VTU=false" \
    --output-directory $out/fresh$k > $out.fresh$k.txt 2>&1
  echo "   cycle $k against a fresh run (rc=$?):"
  python3 compare_cycle.py $out/study/summary.json $k $out/fresh$k/summary.json
done
