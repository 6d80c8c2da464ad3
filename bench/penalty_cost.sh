#!/bin/bash
# Cost of the contact formulations on one Hertz mesh (doc/performance.md,
# "Cost of the penalty formulation"): three serial runs each of the ALM, the
# fixed penalty and the adaptive penalty with `Contact refinements = 8`
# (10,584 DoFs). Prints Newton iterations, linear-solve time, cycle time,
# p_max error and penetration per run. Run it on a quiet machine.
#   bash bench/penalty_cost.sh [BINARY]      (default build/contact_fem)
set -euo pipefail
cd "$(dirname "$0")/.."
binary=${1:-build/contact_fem}
export OMP_NUM_THREADS=1 DEAL_II_NUM_THREADS=1
out_root=bench/results-penalty-cost
rm -rf "$out_root"

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-9s %-4s %-10s %-12s %-10s %-12s %s\n' \
  formulation run "its/step" "linear [s]" "cycle [s]" "p_max err" "max gap/h"
for formulation in alm penalty adaptive; do
  case $formulation in
    alm)      options=() ;;
    penalty)  options=(--set "Contact/Formulation=penalty frictionless") ;;
    adaptive) options=(--set "Contact/Formulation=penalty frictionless"
                       --set "Contact/Adaptive penalty=true"
                       --set "Newton/Maximum iterations=40") ;;
  esac
  for run in 1 2 3; do
    dir=$out_root/$formulation-$run
    mkdir -p "$dir"
    "$binary" prm/hertz.prm \
      --set "Geometry/Hertz cylinder/Contact refinements=8" \
      --set "Output directory=$dir" "${options[@]}" > "$dir/stdout" 2>&1
    log=$dir/stdout
    # iterations per load step: the last row number before each 'converged'
    its=$(awk '/\| converged/ {printf "%s%s", sep, $2; sep=","}' "$log")
    linear=$(awk '/Solve: linear/ {print $3}' "$log")
    cycle=$(awk '/Wall time of cycle/ {print $6}' "$log")
    pmax=$(awk -F: '/p_max relative error/ {gsub(/ /, "", $2); print $2}' "$log")
    gap=$(awk -F: '/max \|gap\|\/h on active nodes/ {sub(/^ +/, "", $2); print $2}' "$log")
    printf '%-9s %-4s %-10s %-12s %-10s %-12s %s\n' \
      "$formulation" "$run" "$its" "$linear" "$cycle" "$pmax" "$gap"
  done
done
