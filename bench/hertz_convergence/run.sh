#!/usr/bin/env bash
# ---------------------------------------------------------------------------
# run.sh - convergence study of the 2D Hertz contact scene (prm/hertz.prm):
# uniform ('global') against adaptive ('kelly', 'spr', 'spr contact')
# refinement, degrees 1 and 2, plus an overkill reference for the energy.
#
# What runs (one job at a time, serial, one thread):
#   study runs   start mesh: prm/hertz.prm with
#                "Geometry/Hertz cylinder/Contact refinements" = 3 (coarse
#                grading, 912 cells), Q1 and Q2;
#                global       Q1: 4 cycles, Q2: 3 cycles (uniform refinement);
#                kelly, spr, spr contact: fixed fraction (Doerfler) marking,
#                refine fraction 0.3, no coarsening, at most 30 cycles, the
#                run is stopped after the first cycle with at least
#                DOF_CAP_Q1 / DOF_CAP_Q2 DoFs.
#   reference    (runs first) Q2, 'spr contact', 'fixed number' 0.3, started
#                from the default (finer) graded mesh, REF_CYCLES cycles: the
#                overkill whose potential energy (extrapolated) is Pi_ref and
#                whose last pressure_profile.csv is the reference pressure of
#                the study runs (mortar and recovered contact pressures).
#   mesh         Q1 and Q2 'spr contact' runs with VTU output up to about
#                MESH_DOF_CAP DoFs, only to show where the refinement goes (not timed
#                in the study).
# Then analyse.py computes errors, rates and effectivities, writes the gnuplot
# data and doc/convergence.md, and gnuplot draws doc/figures/convergence_*.png.
#
# Usage: bench/hertz_convergence/run.sh [options]
#   --binary FILE    contact_fem executable (default: <repo>/build/contact_fem);
#                    it is copied into the results directory first, so that
#                    every run uses the same binary even if it is rebuilt
#   --results DIR    where the runs go (default: bench/hertz_convergence/results)
#   --analyse-only   do not run anything, only analyse DIR and plot
#   -h, --help       this text
# Environment: DOF_CAP_Q1 (default 100000), DOF_CAP_Q2 (60000),
#   REF_CYCLES (5), MESH_DOF_CAP (15000), STUDY_START_CONTACT_REFINEMENTS (3).
# ---------------------------------------------------------------------------
set -euo pipefail

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo_root=$(cd "$script_dir/../.." && pwd)

binary="$repo_root/build/contact_fem"
results="$script_dir/results"
analyse_only=0
prm="$repo_root/prm/hertz.prm"
dof_cap_q1=${DOF_CAP_Q1:-100000}
dof_cap_q2=${DOF_CAP_Q2:-60000}
ref_cycles=${REF_CYCLES:-5}
mesh_cap=${MESH_DOF_CAP:-15000}
start_cr=${STUDY_START_CONTACT_REFINEMENTS:-3}

usage() { sed -n '3,/^# ----/p' "${BASH_SOURCE[0]}" | sed '$d' | sed 's/^# \{0,1\}//'; }

while [[ $# -gt 0 ]]; do
  case "$1" in
    --binary)       binary="${2:?--binary needs a file}"; shift 2 ;;
    --results)      results="${2:?--results needs a directory}"; shift 2 ;;
    --analyse-only) analyse_only=1; shift ;;
    -h|--help)      usage; exit 0 ;;
    *) echo "run.sh: unknown argument '$1'" >&2; usage >&2; exit 1 ;;
  esac
done
[[ "$binary" = /* ]] || binary="$PWD/$binary"
mkdir -p "$results"
results=$(cd "$results" && pwd)

# --- gnuplot (Debian package gnuplot-nox) -----------------------------------
ensure_gnuplot() {
  command -v gnuplot > /dev/null && return 0
  local sudo=()
  if (( EUID != 0 )); then
    command -v sudo > /dev/null || { echo "run.sh: gnuplot missing and no sudo" >&2; return 1; }
    sudo=(sudo)
  fi
  echo "installing gnuplot-nox ..." >&2
  "${sudo[@]}" apt-get install -y gnuplot-nox > /dev/null 2>&1 ||
    { "${sudo[@]}" apt-get update > /dev/null && "${sudo[@]}" apt-get install -y gnuplot-nox > /dev/null; }
}

# --- the binary ---------------------------------------------------------------
# It may be missing or half-written while another build links it: wait until
# it exists, has not changed for 10 s and answers --help, then copy it.
snapshot_binary() {
  local waited=0 now mtime
  while true; do
    if [[ -x "$binary" ]]; then
      now=$(date +%s); mtime=$(stat -c %Y "$binary")
      if (( now - mtime >= 10 )) && "$binary" --help > /dev/null 2>&1; then
        mkdir -p "$results/bin"
        cp "$binary" "$results/bin/contact_fem.tmp"
        mv "$results/bin/contact_fem.tmp" "$results/bin/contact_fem"
        # The copy must be the file that was checked.
        [[ $(stat -c %Y "$binary") == "$mtime" ]] && return 0
      fi
    fi
    if (( waited >= ${BINARY_WAIT:-600} )); then
      echo "run.sh: no usable binary at $binary" >&2; exit 1
    fi
    (( waited == 0 )) && echo "waiting for $binary ..." >&2
    sleep 5; waited=$(( waited + 5 ))
  done
}

# --- one run ----------------------------------------------------------------
# run_case NAME DOF_CAP --set ... : runs the copied binary into $results/NAME.
# DOF_CAP > 0: the run is ended (by its process id) once summary.json holds a
# cycle with at least that many DoFs; the cycles written so far are complete.
run_case() {
  local name=$1 cap=$2; shift 2
  local dir="$results/$name"
  rm -rf "$dir"; mkdir -p "$dir"
  local cmd=("$results/bin/contact_fem" "$prm" "$@"
             --set "Output/Print timing=false" --output-directory "$dir")
  echo "== $name: ${cmd[*]}" >&2
  local load_before start end rc=0 stopped=0 pid
  load_before=$(cut -d' ' -f1-3 /proc/loadavg)
  start=$(date +%s.%N)
  "${cmd[@]}" > "$dir/stdout.txt" 2>&1 &
  pid=$!
  if (( cap > 0 )); then
    while kill -0 "$pid" 2> /dev/null; do
      sleep 0.5
      if [[ -f "$dir/convergence.csv" ]] &&
         awk -F, -v cap="$cap" 'NR > 1 && $3 + 0 >= cap { hit = 1 } END { exit !hit }' \
           "$dir/convergence.csv"; then
        # summary.json is written right after the csv row: give it a moment.
        sleep 1
        kill "$pid" 2> /dev/null && stopped=1
        break
      fi
    done
  fi
  wait "$pid" || rc=$?
  end=$(date +%s.%N)
  {
    echo "name=$name"
    echo "exit_code=$rc"
    echo "stopped_at_dof_cap=$stopped"
    echo "dof_cap=$cap"
    echo "elapsed=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", b - a }')"
    echo "loadavg_before=$load_before"
    echo "loadavg_after=$(cut -d' ' -f1-3 /proc/loadavg)"
    echo "command=${cmd[*]}"
  } > "$dir/run.txt"
  if (( rc != 0 && stopped == 0 )); then
    echo "   exit code $rc (see $dir/stdout.txt)" >&2
    failed=1
  fi
}

failed=0
if (( analyse_only == 0 )); then
  ensure_gnuplot
  snapshot_binary
  n_cores=$(nproc)
  export OMP_NUM_THREADS=1 DEAL_II_NUM_THREADS=1
  {
    echo "date=$(date -u '+%Y-%m-%d %H:%M UTC')"
    echo "git=$(git -C "$repo_root" describe --always --dirty 2> /dev/null || echo unknown)"
    echo "binary=$binary"
    echo "binary_mtime=$(date -u -r "$binary" '+%Y-%m-%d %H:%M:%S UTC')"
    echo "binary_sha256=$(sha256sum "$results/bin/contact_fem" | cut -c1-16)"
    echo "cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')"
    echo "nproc=$n_cores"
    echo "dof_cap_q1=$dof_cap_q1"
    echo "dof_cap_q2=$dof_cap_q2"
    echo "ref_cycles=$ref_cycles"
    echo "start_contact_refinements=$start_cr"
  } > "$results/study.txt"
  study_start=$(date +%s)

  common=(--set "Output/Write VTU=false" --set "Output/Write pressure profile=false")

  # Overkill reference first: Q2, spr contact, fixed number 0.3 from the
  # default graded mesh (Contact refinements = 6, slave elements ~0.05). Its
  # pressure profile is the reference pressure of the study runs.
  run_case reference 0 --set "Output/Write VTU=false" --set "Finite element/Degree=2" \
    --set "Refinement/Estimator=spr contact" --set "Refinement/Strategy=fixed number" \
    --set "Refinement/Refine fraction=0.3" --set "Refinement/Number of cycles=$ref_cycles"
  reference_profile=(--set "Analytical solution/Reference pressure profile=$results/reference/pressure_profile.csv")
  # Study runs: plain SPR alongside the SPR-contact estimate, on the same
  # solution (not counted in the cycle wall times), and the pressures
  # against the reference: what the contact terms change.
  compare=(--set "Refinement/Compare with plain SPR=true" "${reference_profile[@]}")
  start_mesh=(--set "Geometry/Hertz cylinder/Contact refinements=$start_cr")
  adaptive=(--set "Refinement/Strategy=fixed fraction" --set "Refinement/Refine fraction=0.3"
            --set "Refinement/Coarsen fraction=0" --set "Refinement/Number of cycles=30")

  for degree in 1 2; do
    if (( degree == 1 )); then cap=$dof_cap_q1; global_cycles=4; else cap=$dof_cap_q2; global_cycles=3; fi
    fe=(--set "Finite element/Degree=$degree")
    run_case "q$degree-global" 0 "${common[@]}" "${compare[@]}" "${start_mesh[@]}" "${fe[@]}" \
      --set "Refinement/Estimator=global" --set "Refinement/Number of cycles=$global_cycles"
    for est in kelly spr "spr contact"; do
      run_case "q$degree-${est// /-}" "$cap" "${common[@]}" "${compare[@]}" "${start_mesh[@]}" "${fe[@]}" \
        "${adaptive[@]}" --set "Refinement/Estimator=$est"
    done
  done

  # Meshes for the picture of where the refinement goes (VTU on; not part of
  # the timing comparison).
  for degree in 1 2; do
    run_case "mesh-q$degree" "$mesh_cap" --set "Output/Write pressure profile=false" \
      "${start_mesh[@]}" --set "Finite element/Degree=$degree" "${adaptive[@]}" \
      --set "Refinement/Estimator=spr contact" --set "Output/Write VTU=true"
  done
  echo "study_seconds=$(( $(date +%s) - study_start ))" >> "$results/study.txt"
  if [[ $(sha256sum "$binary" 2> /dev/null | cut -c1-16) != \
        $(sha256sum "$results/bin/contact_fem" | cut -c1-16) ]]; then
    echo "binary_changed_during_study=1 (the runs used the copy taken at the start)" >> "$results/study.txt"
  fi
fi

ensure_gnuplot
python3 "$script_dir/analyse.py" --results "$results" --doc "$repo_root/doc/convergence.md" \
  --plot-data "$results/plot"
mkdir -p "$repo_root/doc/figures"
for gp in convergence_dofs convergence_time convergence_mesh; do
  (cd "$script_dir" && gnuplot -e "datadir='$results/plot'; outfile='$repo_root/doc/figures/$gp.png'" "$gp.gp")
done
echo "runs in $results, report in doc/convergence.md, figures in doc/figures/" >&2
exit "$failed"
