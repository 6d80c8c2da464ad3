#!/usr/bin/env bash
# ---------------------------------------------------------------------------
# run.sh - cost of the curved mapping's cache on an imported mesh with many
# circle manifolds (issue 32 item 4).
#
# Meshes plate_holes.geo with Gmsh (13 x 12 holes, 12,480 coarse
# quadrilaterals), writes a scene with one 'circle' entry per hole
# (Geometry/Manifolds), a plate held at its bottom and pressed on its top,
# Q1 (on the quadratic mapping that curved boundaries get), Kelly marking,
# and runs it with every given binary, one after the other, printing
# "Setup: DoFs" and the cells and DoFs per adaptive cycle.
#
# Usage: bench/mapping_cache/run.sh [--cycles N] [--np N] BINARY [BINARY ...]
#   --cycles N   adaptive cycles (default 4)
#   --np N       run with mpirun -np N (default: serial)
# Threads are pinned to one per process. The runs go to a temporary folder.
# ---------------------------------------------------------------------------
set -euo pipefail

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
cycles=4
np=0
binaries=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --cycles) cycles="${2:?--cycles needs a number}"; shift 2 ;;
    --np)     np="${2:?--np needs a number}"; shift 2 ;;
    -h|--help) sed -n '3,/^# ----/p' "${BASH_SOURCE[0]}" | sed '$d' | sed 's/^# \{0,1\}//'; exit 0 ;;
    *)        binaries+=("$1"); shift ;;
  esac
done
[[ ${#binaries[@]} -gt 0 ]] || { echo "run.sh: give at least one contact_fem binary" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
gmsh -2 -format msh22 "$script_dir/plate_holes.geo" -o "$work/plate_holes.msh" > "$work/gmsh.log"
# One circle per hole, in the numbering of plate_holes.geo (N = 13, M = 12).
manifolds=$(awk 'BEGIN { for (j = 0; j < 12; ++j) for (i = 0; i < 13; ++i)
  printf "%s%d: circle %g, %g, 0.3", (i + j > 0 ? "; " : ""), 3 + i + 13 * j, i + 0.5, j + 0.5 }')

export OMP_NUM_THREADS=1 DEAL_II_NUM_THREADS=1
for binary in "${binaries[@]}"; do
  out="$work/run"
  rm -rf "$out"
  cat > "$work/plate.prm" <<PRM
set Dimension        = 2
set Output directory = $out
subsection Geometry
  set Type      = mesh file
  set Mesh file = $work/plate_holes.msh
  set Manifolds = $manifolds
end
subsection Materials
  set Material ids     = 1
  set Young's moduli   = 200
  set Poisson's ratios = 0.3
end
subsection Boundary conditions
  set Fixed    = 1: xy
  set Pressure = 2: 0.1*t
end
subsection Contact
  set Pairs =
end
subsection Refinement
  set Number of cycles = $cycles
  set Estimator        = kelly
end
subsection Output
  set Write VTU    = false
  set Print timing = true
end
PRM
  launcher=()
  [[ $np -gt 0 ]] && launcher=(mpirun -np "$np")
  start=$(date +%s.%N)
  "${launcher[@]}" "$binary" "$work/plate.prm" > "$work/log.txt"
  end=$(date +%s.%N)
  echo "$binary ($(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f", b - a }') s in all)"
  awk '/^Cycle/ { cycle = $2 " " $3 " cells, " $5 " DoFs" } /Setup: DoFs/ { print "  cycle " cycle ": Setup: DoFs " $3 " s" }' "$work/log.txt"
done
