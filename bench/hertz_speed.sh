#!/usr/bin/env bash
# ---------------------------------------------------------------------------
# hertz_speed.sh - timing benchmark of the 2D Hertz contact scene.
#
# Runs prm/hertz.prm at three uniform refinements ("Geometry/Global
# refinements" = 0, 1, 2) one after the other, single-threaded, each into its
# own directory under bench/results-<date>/level-<N>/, then calls
# hertz_speed_report.py, which reads the summary.json files, prints the table
# and writes it into doc/performance.md.
#
# Usage: bench/hertz_speed.sh [options] [BINARY]
#   BINARY            contact_fem executable (default: <repo>/build/contact_fem)
#   --mpi N           run every level with "mpirun -np N" (default: serial)
#   --levels "0 1 2"  refinement levels to run (default: "0 1 2")
#   --results DIR     where the runs go (default: <repo>/bench/results-<date>)
#   --doc FILE        report file (default: <repo>/doc/performance.md);
#                     "-" prints the table only
#   -h, --help        this text
#
# Threads are pinned to one per process (OMP_NUM_THREADS=1,
# DEAL_II_NUM_THREADS=1). The runs are serial so they do not compete for the
# cores. VTU output is switched on so that it is part of the timing.
# ---------------------------------------------------------------------------
set -euo pipefail

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo_root=$(cd "$script_dir/.." && pwd)

binary="$repo_root/build/contact_fem"
mpi_np=0
levels="0 1 2"
results=""
doc="$repo_root/doc/performance.md"
prm="$repo_root/prm/hertz.prm"

usage() { sed -n '3,/^# ----/p' "${BASH_SOURCE[0]}" | sed '$d' | sed 's/^# \{0,1\}//'; }

while [[ $# -gt 0 ]]; do
  case "$1" in
    --mpi)     mpi_np="${2:?--mpi needs a number}"; shift 2 ;;
    --levels)  levels="${2:?--levels needs a list}"; shift 2 ;;
    --results) results="${2:?--results needs a directory}"; shift 2 ;;
    --doc)     doc="${2:?--doc needs a file name or -}"; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    -*)        echo "hertz_speed.sh: unknown option '$1'" >&2; usage >&2; exit 1 ;;
    *)         binary="$1"; shift ;;
  esac
done

if ! [[ "$mpi_np" =~ ^[0-9]+$ ]]; then
  echo "hertz_speed.sh: --mpi expects a number, got '$mpi_np'" >&2
  exit 1
fi
[[ "$binary" = /* ]] || binary="$PWD/$binary"

# The binary may be missing for a moment while it is being rebuilt: wait.
wait_for_binary() {
  local waited=0
  until [[ -x "$binary" ]]; do
    if (( waited >= ${HERTZ_SPEED_WAIT:-300} )); then
      echo "hertz_speed.sh: $binary not found or not executable" >&2
      exit 1
    fi
    (( waited == 0 )) && echo "waiting for $binary ..." >&2
    sleep 5; waited=$(( waited + 5 ))
  done
}
wait_for_binary

if [[ -z "$results" ]]; then
  results="$script_dir/results-$(date +%Y%m%d-%H%M%S)"
fi
mkdir -p "$results"

export OMP_NUM_THREADS=1 DEAL_II_NUM_THREADS=1
launcher=()
if (( mpi_np > 0 )); then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  launcher=(mpirun -np "$mpi_np")
fi

# Fixed cost of starting the program (libraries, MPI): time "--help".
start=$(date +%s.%N)
"${launcher[@]}" "$binary" --help > /dev/null 2>&1 || true
end=$(date +%s.%N)
awk -v a="$start" -v b="$end" 'BEGIN{printf "%.3f\n", b-a}' > "$results/startup.txt"

git_rev=$(git -C "$repo_root" describe --always --dirty 2>/dev/null || echo unknown)
failed=0
for level in $levels; do
  wait_for_binary
  dir="$results/level-$level"
  rm -rf "$dir"; mkdir -p "$dir"
  cmd=("${launcher[@]}" "$binary" "$prm"
       --set "Geometry/Global refinements=$level"
       --set "Output/Write VTU=true"
       --output-directory "$dir")
  echo "== level $level: ${cmd[*]}" >&2
  load_before=$(cut -d' ' -f1-3 /proc/loadavg)
  binary_sum=$(sha256sum "$binary" | cut -c1-16)
  start=$(date +%s.%N)
  rc=0
  "${cmd[@]}" > "$dir/stdout.txt" 2>&1 || rc=$?
  end=$(date +%s.%N)
  # Side facts of the run for the report (key=value, one per line).
  {
    echo "level=$level"
    echo "exit_code=$rc"
    echo "elapsed=$(awk -v a="$start" -v b="$end" 'BEGIN{printf "%.3f", b-a}')"
    echo "loadavg_before=$load_before"
    echo "binary=$binary"
    echo "binary_sha256=$binary_sum"
    echo "git=$git_rev"
    echo "mpi_np=$mpi_np"
    echo "command=${cmd[*]}"
  } > "$dir/run.txt"
  if (( rc != 0 )); then
    echo "   exit code $rc (see $dir/stdout.txt)" >&2
    failed=1
  fi
done

report_args=(--results "$results")
[[ "$doc" == "-" ]] || report_args+=(--doc "$doc")
python3 "$script_dir/hertz_speed_report.py" "${report_args[@]}"
echo "runs in $results" >&2
exit "$failed"
