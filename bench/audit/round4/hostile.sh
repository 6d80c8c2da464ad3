#!/bin/bash
# usage: hostile.sh PRM 'Key=value' ...: one run per --set, prints the exit code and the last lines
B=${B:-/work/main/build/contact_fem}
prm=$1; shift
for s in "$@"; do
  out=$(nice -n 10 timeout 300 $B $prm --set "$s" --output-directory /tmp/a4/hostile 2>&1); rc=$?
  echo "=== [$s] rc=$rc"
  echo "$out" | grep -v "^ *|" | grep -iE "error|warning|fail|stopped|converged|active slave|max contact|tangential / normal|imbalance:|Results" | head -6 | cut -c1-400
done
