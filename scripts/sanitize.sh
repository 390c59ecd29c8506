#!/usr/bin/env bash
# The sanitizer and fuzzing stage of scripts/test.sh (issue 19), which runs
# it unless SANITIZE=0 (on by default: the whole command fits 30 min). Its results go to
# build/test_results beside the others, so count_results.py counts them in
# the final "N passed, M failed":
#  * build_san/ (devel space devel_san/): the workspace configured with
#    clang++, -O0 (at -O1 clang took 1.6-2.8 times the CPU time on the
#    sources measured for issue 19) -gline-tables-only and
#    -fsanitize=address,undefined
#    -fno-sanitize-recover=all (any ASan or UBSan report ends the program
#    with an error; LeakSanitizer on), as a CMake unity build (the sources
#    of a target compiled in batches: each header parsed once per batch;
#    SAN_UNITY=OFF compiles file by file). Only the gtest targets and the
#    libFuzzer targets are built (and what they depend on), less the
#    *_cli_test ones (SAN_SKIP below). Every gtest binary runs through
#    ctest; its cases are counted again as <pkg>_asan/.
#  * every libFuzzer target of scripts/fuzz_targets.txt runs FUZZ_SECONDS
#    (default 5) from its seed corpus, JOBS at a time, each one test case
#    (<pkg>_fuzz/): a crash, a sanitizer report, a leak, an input slower
#    than 25 s or over 2 GiB fails it; the report and the reproducer are in
#    build_san/fuzz/<target>/.
#  * build_tsan/ (devel_tsan/): mrt_common and mrt_dcdt only, with -O1
#    -fsanitize=thread; the mrt_dcdt gtests counted as mrt_dcdt_tsan/.
# The normal build (build/, devel/) is not touched: demo.sh and
# check_install.sh keep using uninstrumented programs. Each sanitizer build
# directory is configured once; make re-runs cmake when a CMakeLists changes.
# Each step prints its wall and CPU time. SAN_GTESTS (a ctest regex, default
# _gtest_) narrows the ASan gtests run by hand; SAN_SKIP='^$' keeps the
# *_cli_test ones.
#   scripts/sanitize.sh [all|build|run|fuzz]  all (default): the ASan
#       build, then two lanes of one core each: its gtests | the fuzzers,
#       the TSan build, its gtests; build / run: the builds / the rest, one
#       after the other; fuzz: only the fuzzers. test.sh starts `all` at
#       the start of the run in the background (nice 19).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

RESULTS="$ROOT/build/test_results"
FUZZ_SECONDS="${FUZZ_SECONDS:-5}"
# The gtests the stage leaves out (a ctest regex over the test names): the
# *_cli_test programs run the command-line tools, so their ASan build links
# every CLI tool of the package; the normal run covers them.
SAN_SKIP="${SAN_SKIP:-_cli_test\$}"
PY=/usr/bin/python3
JUNIT="$ROOT/scripts/junit.py"
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1"

# san_configure BUILD_DIR DEVEL_DIR OPT SANITIZER_FLAGS [CMAKE_ARGS...]:
# once, and again when these arguments change (BUILD_DIR/.args); touches
# BUILD_DIR/.fresh when it configured (see san_build).
san_configure() {
  local build=$1 devel=$2 opt=$3 flags=$4 args="$*"
  shift 4
  if [ -f "$build/CMakeCache.txt" ] && [ "$(cat "$build/.args" 2>/dev/null)" = "$args" ]; then return 0; fi
  mkdir -p "$build"
  touch "$build/.fresh"
  cmake -S "$ROOT/src" -B "$build" "${CATKIN_ARGS[@]}" \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DCATKIN_DEVEL_PREFIX="$devel" -DCMAKE_INSTALL_PREFIX="$build/install" \
    -DCMAKE_BUILD_TYPE=Sanitize \
    -DCMAKE_C_FLAGS_SANITIZE="$opt -gline-tables-only -fno-omit-frame-pointer $flags" \
    -DCMAKE_CXX_FLAGS_SANITIZE="$opt -gline-tables-only -fno-omit-frame-pointer $flags" \
    -DCMAKE_EXE_LINKER_FLAGS="$flags" -DCMAKE_SHARED_LINKER_FLAGS="$flags" \
    -DCMAKE_UNITY_BUILD="${SAN_UNITY:-ON}" -DCMAKE_PROJECT_INCLUDE="$ROOT/scripts/san_unity.cmake" \
    "-DMRT_SAN_NO_UNITY_FILES=$ROOT/scripts/san_no_unity.txt;$build/no_unity.txt" "$@" >"$build/configure.log" 2>&1 \
    || { cat "$build/configure.log" >&2; return 1; }
  echo "$args" >"$build/.args"
}

# gtest_targets BUILD_DIR REGEX: the gtest targets ctest knows, matching REGEX
# and not SAN_SKIP.
gtest_targets() {
  (cd "$1" && ctest -N -R "$2" -E "$SAN_SKIP") | sed -n 's/.*Test *#[0-9]*: _ctest_.*_gtest_//p'
}

# san_build BUILD_DIR NAME TARGETS...: builds the targets (make -k, so one
# broken target does not hide the others); a failed build is one failed case
# (BUILD_DIR/NAME.xml, copied to the results by the run phase).
san_build() {
  local build=$1 name=$2 rc failed
  shift 2
  rm -f "$build/$name.xml"
  for _ in 1 2 3 4; do
    set +e
    make -C "$build" -k -j"$JOBS" "$@" >"$build/make.log" 2>&1
    rc=$?
    set -e
    [ "$rc" -ne 0 ] || break
    # A unity batch that does not compile (two sources of one target
    # define the same internal name): that target again file by file
    # (scripts/san_unity.cmake), then make again.
    failed=$(sed -n 's|.*CMakeFiles/\([^/]*\)\.dir/Unity/unity_.*Error.*|\1|p' "$build/make.log" | sort -u)
    [ -n "$failed" ] || break
    echo "== sanitizers: not as a unity build (add to scripts/san_no_unity.txt):" $failed
    echo "$failed" >>"$build/no_unity.txt"
    cmake "$build" >>"$build/make.log" 2>&1 || break
  done
  # As in test.sh (--force-cmake): catkin caches the test environment when
  # it configures, keeping only the devel directories that exist then; after
  # the first build the generated mrt_msgs Python exists.
  if [ -f "$build/.fresh" ]; then
    cmake "$build" >>"$build/make.log" 2>&1 || rc=1
    rm -f "$build/.fresh"
  fi
  if [ "$rc" -ne 0 ]; then
    grep -E -B2 -A6 'error|Error' "$build/make.log" | tail -60 >&2
    "$PY" "$JUNIT" case "$build/$name.xml" sanitizers "$name" "$rc" "$build/make.log"
  fi
}

# san_gtests BUILD_DIR REGEX SUFFIX: runs the gtests through ctest (the
# catkin command: environment, working directory, result file) and copies
# their results to build/test_results/<pkg>_SUFFIX.
san_gtests() {
  local build=$1 regex=$2 suffix=$3
  rm -rf "$build/test_results" "$build/ctest.xml"
  (cd "$build" && ctest -R "$regex" -E "$SAN_SKIP" --output-on-failure -j1 --timeout 600 --output-junit "$build/ctest.xml") || true
  "$PY" "$JUNIT" collect "$build/test_results" "$RESULTS" "$suffix" "$build/ctest.xml"
}

# fuzz_one TARGET PACKAGE SEED_DIR...: one bounded libFuzzer run, one case.
fuzz_one() {
  local target=$1 pkg=$2 rc d
  shift 2
  local bin="$ROOT/devel_san/lib/$pkg/$target" work="$ROOT/build_san/fuzz/$target" seeds=()
  for d in "$@"; do seeds+=("$ROOT/$d"); done
  rm -rf "$work"
  mkdir -p "$work/corpus"
  set +e
  if [ -x "$bin" ]; then
    timeout --kill-after=10 $((FUZZ_SECONDS + 120)) "$bin" -max_total_time="$FUZZ_SECONDS" -timeout=25 \
      -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$work/" "$work/corpus" "${seeds[@]}" \
      >"$work/log" 2>&1
    rc=$?
  else
    echo "$bin: not built (see build_san/make.log)" >"$work/log"
    rc=1
  fi
  set -e
  "$PY" "$JUNIT" case "$RESULTS/${pkg}_fuzz/$target.xml" "${pkg}_fuzz" "$target" "$rc" "$work/log"
  if [ "$rc" -eq 0 ]; then
    echo "fuzz $target: ok, $(grep -o 'Done [0-9]* runs in [0-9]* second(s)' "$work/log" | tail -1)," \
      "$(grep -o 'cov: [0-9]*' "$work/log" | tail -1)"
  else
    echo "fuzz $target: FAILED (exit $rc), report and reproducer in $work" >&2
    tail -40 "$work/log" >&2
  fi
}

run_fuzzers() {
  local target pkg seeds running=0
  while read -r target pkg seeds; do
    case "$target" in "" | \#*) continue ;; esac
    # shellcheck disable=SC2086  # seeds: a list of directories
    fuzz_one "$target" "$pkg" $seeds &
    running=$((running + 1))
    if [ "$running" -ge "$JOBS" ]; then
      wait -n || true
      running=$((running - 1))
    fi
  done <"$ROOT/scripts/fuzz_targets.txt"
  wait
}

# Step timing, as in test.sh: wall time and the CPU time of finished children.
T_WALL=$SECONDS
T_CPU=0
T_FILE=$(mktemp)
trap 'rm -f "$T_FILE"' EXIT
step_done() {  # step_done NAME
  local cpu
  times >"$T_FILE"
  cpu=$(awk 'NR == 2 { split($1, u, /[ms]/); split($2, s, /[ms]/); printf "%.0f", u[1] * 60 + u[2] + s[1] * 60 + s[2] }' "$T_FILE")
  printf '== sanitizers: step %-14s %5d s wall %6d s CPU\n' "$1" $((SECONDS - T_WALL)) $((cpu - T_CPU))
  T_WALL=$SECONDS
  T_CPU=$cpu
}

# ASan + UBSan: the gtests and the fuzz targets, one build.
build_asan() {
  local targets fuzz
  san_configure "$ROOT/build_san" "$ROOT/devel_san" -O0 "-fsanitize=address,undefined -fno-sanitize-recover=all"
  mapfile -t targets < <(gtest_targets "$ROOT/build_san" _gtest_)
  mapfile -t fuzz < <(sed -n 's/^\([a-z_]*fuzz_[a-z_]*\) .*/\1/p' "$ROOT/scripts/fuzz_targets.txt")
  echo "== sanitizers: building ${#targets[@]} gtests and ${#fuzz[@]} fuzz targets with ASan+UBSan (build_san)"
  san_build "$ROOT/build_san" asan_build "${fuzz[@]}" "${targets[@]}"
  step_done "asan build"
}

# TSan: the DCDT suite.
build_tsan() {
  local targets
  san_configure "$ROOT/build_tsan" "$ROOT/devel_tsan" -O1 "-fsanitize=thread" "-DCATKIN_WHITELIST_PACKAGES=mrt_common;mrt_dcdt"
  mapfile -t targets < <(gtest_targets "$ROOT/build_tsan" _ctest_mrt_dcdt_gtest_)
  echo "== sanitizers: building ${#targets[@]} mrt_dcdt gtests with TSan (build_tsan)"
  san_build "$ROOT/build_tsan" tsan_build "${targets[@]}"
  step_done "tsan build"
}

# A failed sanitizer build is one failed case (san_build wrote it).
copy_build_results() {
  local f
  mkdir -p "$RESULTS/sanitizers"
  for f in "$ROOT/build_san/asan_build.xml" "$ROOT/build_tsan/tsan_build.xml"; do
    if [ -f "$f" ]; then cp "$f" "$RESULTS/sanitizers/"; fi
  done
}

run_asan() {
  echo "== sanitizers: gtests under ASan+UBSan"
  san_gtests "$ROOT/build_san" "${SAN_GTESTS:-_gtest_}" asan
  step_done "asan gtests"
}

run_fuzz() {
  echo "== fuzzing: $(grep -c '^[a-z]' "$ROOT/scripts/fuzz_targets.txt") targets, ${FUZZ_SECONDS} s each, $JOBS at a time"
  run_fuzzers
  step_done "fuzzing"
}

run_tsan() {
  echo "== sanitizers: mrt_dcdt gtests under TSan"
  san_gtests "$ROOT/build_tsan" _ctest_mrt_dcdt_gtest_ tsan
  step_done "tsan gtests"
}

# lane FUNCTION...: runs them in a background subshell with its own step
# timing (a subshell's `times` starts from zero).
lane() {
  (
    T_WALL=$SECONDS
    T_CPU=0
    for f in "$@"; do "$f"; done
  ) &
}

if [ "${SANITIZE:-1}" = 0 ]; then exit 0; fi
case "${1:-all}" in
  all)
    build_asan
    copy_build_results
    # Two lanes, one core each: the ASan gtests (one at a time, as ctest
    # runs the normal ones: some measure time) beside the fuzzers (one at
    # a time), the TSan build and the TSan gtests.
    JOBS=1
    lane run_asan
    asan_lane=$!
    lane run_fuzz build_tsan copy_build_results run_tsan
    other_lane=$!
    rc=0
    wait "$asan_lane" || rc=1
    wait "$other_lane" || rc=1
    step_done "both lanes"
    exit "$rc"
    ;;
  build)
    build_asan
    build_tsan
    ;;
  run)
    copy_build_results
    run_asan
    run_fuzz
    run_tsan
    ;;
  fuzz) run_fuzz ;;
  *) echo "usage: scripts/sanitize.sh [all|build|run|fuzz]" >&2; exit 2 ;;
esac
