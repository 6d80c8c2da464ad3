#!/usr/bin/env bash
# ---------------------------------------------------------------------------
# run.sh - contact_fem under AddressSanitizer + UndefinedBehaviorSanitizer.
#
# Builds the repository this script belongs to a second time, in a build
# directory of its own, with our sources instrumented by ASan and UBSan
# (deal.II, Trilinos, Open MPI & co. are the installed, uninstrumented
# libraries), then runs
#   1. the ctest suite (tests/, picked up by DEAL_II_PICKUP_TESTS), and
#   2. the stability suite (bench/stability/run.sh, no report written),
# and finally greps every output for sanitizer reports ("ERROR:
# AddressSanitizer", "runtime error:", "ERROR: LeakSanitizer") and writes
# them, grouped, to <build>/sanitizer-summary.txt (summarize.py).
#
# Usage: bench/sanitizers/run.sh [options]
#   --build-dir DIR      build directory (default: <repo>/build-sanitize)
#   --build-type TYPE    Debug (default): our code at -O0, linked against
#                        deal.II's debug library, so deal.II's Assert()s are
#                        on as well. Release: our code at -O2, release
#                        library. deal.II's cmake macros know no other type
#                        (RelWithDebInfo would silently become Debug); debug
#                        info (-g) is on in both.
#   --jobs N             make and ctest parallelism (default: nproc)
#   --test-time-limit S  per-test ctest limit in seconds (default 3600)
#   --timeout-scale X    stability suite time limits times X (default 5)
#   --only REGEX         run only these stability cases (see its --list)
#   --ctest-args "ARGS"  extra ctest arguments, e.g. "-R scenes/"
#   --no-build | --no-tests | --no-stability   skip that phase
#   -h, --help           this text
#
# Results, all in the build directory:
#   logs/configure.log, logs/build.log (make VERBOSE=1), logs/ctest.log,
#   logs/stability.log, logs/times.txt (wall time of each phase),
#   tests/<dir>/<test>.<type>/ (ctest outputs), stability/<group>/<case>/,
#   sanitizer-summary.txt.
# Exit status: 0 no sanitizer report, 1 at least one report, 2 setup error.
# A test that fails only its numdiff comparison is listed in the summary but
# is not a sanitizer finding and does not change the exit status.
#
# Sanitizer settings: ASAN_OPTIONS / UBSAN_OPTIONS / LSAN_OPTIONS below
# (halt on the first error, stack traces on, full allocation stacks). The
# leaks Open MPI (with its hwloc and libevent) leaves at exit are suppressed
# by lsan.supp next to this script, by function names that our code never
# calls; see the comments there. A Debug build runs about 20 times slower
# than the Release build. Running as root needs the two
# OMPI_ALLOW_RUN_AS_ROOT variables, which are set here.
# ---------------------------------------------------------------------------
set -euo pipefail

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$script_dir/../.." && pwd)

build_dir="$repo/build-sanitize"
build_type=Debug
jobs=$(nproc)
test_time_limit=3600
timeout_scale=5
only=""
ctest_args=""
do_build=1
do_tests=1
do_stability=1

usage() { sed -n '3,/^# ----/p' "${BASH_SOURCE[0]}" | sed '$d' | sed 's/^# \{0,1\}//'; }

while [[ $# -gt 0 ]]; do
  case "$1" in
    --build-dir)       build_dir="${2:?--build-dir needs a directory}"; shift 2 ;;
    --build-type)      build_type="${2:?--build-type needs Debug or Release}"; shift 2 ;;
    --jobs)            jobs="${2:?--jobs needs a number}"; shift 2 ;;
    --test-time-limit) test_time_limit="${2:?--test-time-limit needs seconds}"; shift 2 ;;
    --timeout-scale)   timeout_scale="${2:?--timeout-scale needs a number}"; shift 2 ;;
    --only)            only="${2:?--only needs a regex}"; shift 2 ;;
    --ctest-args)      ctest_args="${2?--ctest-args needs a string}"; shift 2 ;;
    --no-build)        do_build=0; shift ;;
    --no-tests)        do_tests=0; shift ;;
    --no-stability)    do_stability=0; shift ;;
    -h|--help)         usage; exit 0 ;;
    *)                 echo "run.sh: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
case "$build_type" in
  Debug|Release) ;;
  *) echo "run.sh: --build-type must be Debug or Release (deal.II accepts no other)" >&2; exit 2 ;;
esac
[[ "$build_dir" = /* ]] || build_dir="$PWD/$build_dir"
mkdir -p "$build_dir/logs"
logs="$build_dir/logs"
binary="$build_dir/contact_fem"

# --- sanitizer run-time settings ---------------------------------------------
sanitize_flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined -g"
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:check_initialization_order=1:detect_stack_use_after_return=0:malloc_context_size=30:fast_unwind_on_malloc=0:symbolize=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:report_error_type=1:symbolize=1"
# fast_unwind_on_malloc=0: record full allocation stacks (through the
# frame-pointer-less third-party libraries too), which lsan.supp needs; it
# makes the runs about twice as slow. print_suppressions=0 because the
# statistics would end up in the test outputs and break every numdiff; a
# sample of them is written to logs/lsan-suppressions.txt instead.
export LSAN_OPTIONS="suppressions=$script_dir/lsan.supp:print_suppressions=0"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
if command -v llvm-symbolizer > /dev/null; then
  export ASAN_SYMBOLIZER_PATH; ASAN_SYMBOLIZER_PATH=$(command -v llvm-symbolizer)
fi

times="$logs/times.txt"
stamp() { date '+%Y-%m-%d %H:%M:%S'; }
record_time() {  # record_time PHASE SECONDS
  printf '%-10s %6d s  (%s)\n' "$1" "$2" "$(stamp)" | tee -a "$times" >&2
}
{ echo "# $(stamp) $(git -C "$repo" describe --always --dirty 2>/dev/null || echo unknown)" \
       "build type $build_type, jobs $jobs"; } >> "$times"

# --- 1. configure and build ----------------------------------------------------
if (( do_build )); then
  echo "== configure ($build_type) in $build_dir" >&2
  t0=$SECONDS
  cmake -S "$repo" -B "$build_dir" \
        -DCMAKE_BUILD_TYPE="$build_type" \
        -DCMAKE_CXX_FLAGS="$sanitize_flags" \
        -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
        -DTEST_TIME_LIMIT="$test_time_limit" > "$logs/configure.log" 2>&1 \
    || { tail -n 30 "$logs/configure.log" >&2; exit 2; }
  # deal.II's macros force the build type to Debug or Release: check it.
  actual_type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build_dir/CMakeCache.txt")
  if [[ "$actual_type" != "$build_type" ]]; then
    echo "run.sh: cmake ended up with build type '$actual_type', not '$build_type'" >&2
    exit 2
  fi
  echo "== build (make -j$jobs VERBOSE=1, log: $logs/build.log)" >&2
  nice -n 10 make -C "$build_dir" -j "$jobs" VERBOSE=1 > "$logs/build.log" 2>&1 \
    || { grep -E 'error|Error' "$logs/build.log" | head -n 30 >&2; exit 2; }
  record_time build $(( SECONDS - t0 ))
fi

# The flags must reach every compile line of our code (deal_ii_setup_target
# appends its own flags after CMAKE_CXX_FLAGS, it must not drop ours) and
# the executables must carry the sanitizer run-times.
# flags.make exists for every target from configure on, including the unit
# tests that ctest compiles later.
n_targets=0
while IFS= read -r flags_file; do
  n_targets=$(( n_targets + 1 ))
  if ! grep -q -- '-fsanitize=address,undefined' "$flags_file"; then
    echo "run.sh: -fsanitize=address,undefined missing from $flags_file" >&2
    exit 2
  fi
done < <(find "$build_dir" -path '*/CMakeFiles/*.dir/flags.make')
if (( n_targets == 0 )); then
  echo "run.sh: no flags.make under $build_dir: not configured?" >&2
  exit 2
fi
n_compiled=$(grep -cE '(c\+\+|g\+\+).* -c .*/(source|tests)/[a-z_0-9]+\.cc' "$logs/build.log" || true)
n_without=$(grep -E '(c\+\+|g\+\+).* -c .*/(source|tests)/[a-z_0-9]+\.cc' "$logs/build.log" \
            | grep -vc -- '-fsanitize=address,undefined' || true)
if (( n_without > 0 )); then
  echo "run.sh: $n_without compile line(s) in build.log without the sanitizer flags" >&2
  exit 2
fi
for exe in "$binary" "$build_dir/expect_failure"; do
  needed=$(readelf -d "$exe" 2> /dev/null || true)   # (no grep -q in a pipe: SIGPIPE + pipefail)
  if [[ "$needed" != *libasan.so* || "$needed" != *libubsan.so* ]]; then
    echo "run.sh: $exe is not linked against libasan/libubsan" >&2
    exit 2
  fi
done
echo "== instrumented: $n_targets target(s) with -fsanitize in flags.make, $n_compiled" \
     "compile line(s) in build.log, all with it;" \
     "contact_fem and expect_failure link libasan + libubsan" >&2

# --- 2. ctest ------------------------------------------------------------------
if (( do_tests )); then
  # shellcheck disable=SC2086  # $ctest_args is split on purpose
  n_tests=$(cd "$build_dir" && ctest -C "$build_type" -N $ctest_args | sed -n 's/^Total Tests: //p')
  if [[ -z "$n_tests" || "$n_tests" == 0 ]]; then
    echo "run.sh: ctest -N finds no tests in $build_dir" >&2
    exit 2
  fi
  # deal.II's test targets re-run a test only when its executable or input
  # changed: drop the outputs of the last run so that every test runs again
  # (a changed ASAN_OPTIONS or lsan.supp changes neither).
  if [[ -d "$build_dir/tests" ]]; then
    find "$build_dir/tests" -mindepth 3 -maxdepth 4 -type f \
         \( -name output -o -name failing_output -o -name stdout \
            -o -name 'diff*' -o -name 'failing_diff*' \) -delete
  fi
  echo "== ctest: $n_tests test(s), -j$jobs (log: $logs/ctest.log)" >&2
  t0=$SECONDS
  ctest_rc=0
  # $ctest_args is split on purpose.
  # shellcheck disable=SC2086
  (cd "$build_dir" && nice -n 10 ctest -C "$build_type" -j "$jobs" --output-on-failure \
                         $ctest_args) > "$logs/ctest.log" 2>&1 || ctest_rc=$?
  record_time ctest $(( SECONDS - t0 ))
  grep -E 'tests passed|tests failed' "$logs/ctest.log" >&2 || true
  echo "   ctest exit code $ctest_rc" >&2
fi

# --- what lsan.supp hides: one serial and one 2-rank run with statistics ----
if (( do_tests || do_stability )); then
  sample="$logs/lsan-suppressions.txt"
  scene="$repo/tests/scenes/contact_patch_01.prm"
  : > "$sample"
  for np in 1 2; do
    echo "== $np MPI process(es): contact_fem tests/scenes/contact_patch_01.prm" >> "$sample"
    launcher=()
    (( np > 1 )) && launcher=(mpirun -n "$np")
    (cd "$build_dir" && LSAN_OPTIONS="$LSAN_OPTIONS:print_suppressions=1" \
       "${launcher[@]}" "$binary" "$scene" --output-directory "$build_dir/lsan-sample" \
       2>&1 | sed -n '/Suppressions used/,/^---/p;/ERROR: LeakSanitizer/,/^SUMMARY/p') \
       >> "$sample" || true
  done
  rm -rf "$build_dir/lsan-sample"
fi

# --- 3. stability suite --------------------------------------------------------
if (( do_stability )); then
  stab_args=(--results "$build_dir/stability" --doc - --timeout-scale "$timeout_scale")
  [[ -n "$only" ]] && stab_args+=(--only "$only")
  n_cases=$("$repo/bench/stability/run.sh" --list ${only:+--only "$only"} | wc -l)
  echo "== stability suite: $n_cases case(s), time limits x$timeout_scale" \
       "(log: $logs/stability.log)" >&2
  t0=$SECONDS
  nice -n 10 "$repo/bench/stability/run.sh" "${stab_args[@]}" "$binary" \
    > "$logs/stability.log" 2>&1 || echo "   stability suite exited with $?" >&2
  record_time stability $(( SECONDS - t0 ))
  tail -n 2 "$logs/stability.log" >&2
fi

# --- 4. collect the sanitizer reports ----------------------------------------
python3 "$script_dir/summarize.py" --repo "$repo" --build "$build_dir" \
        --out "$build_dir/sanitizer-summary.txt"
