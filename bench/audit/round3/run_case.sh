#!/bin/bash
# usage (from this directory, where the .prm files include and read their
# meshes): run_case.sh NAME PRM [--set ...]: runs the build's binary, prints the
# verdict lines and the exit code
B=${B:-$(cd "$(dirname "$0")/../../.." && pwd)/build/contact_fem}
name=$1; shift; prm=$1; shift
out=$(nice -n 10 timeout 120 $B $prm "$@" --output-directory /tmp/a3/$name 2>&1); rc=$?
echo "=== $name (rc=$rc)"
echo "$out" | grep -v "^ *|" | grep -iE "error|warning|failed|converged|active slave|max contact pressure|min active|contact force|tangential / normal|stick|slip nodes|imbalance:|applied load|total" | head -14
