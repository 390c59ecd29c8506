#!/usr/bin/env bash
# README command 2: installs what is missing, builds, builds the tests, runs
# every gtest and rostest through ctest, runs the workspace checks, runs the
# sanitizer and fuzzing stage, and prints as its last line
# "N passed, M failed" counted over test cases. Top to bottom:
#   1. setup       scripts/setup.sh when a Debian package is missing
#   2. stage       scripts/sanitize.sh starts in the background (lowest priority)
#   3. build       the workspace (Release: -O2, no debug information)
#   4. build tests the gtest and rostest targets
#   5. tests       ctest, one test at a time, on a private ROS master port
#   6. checks      catkin_lint --strict, check_sizes.py, check_install.sh,
#                  check_workspace.sh (a member of another catkin workspace)
#   7. stage       waits for the sanitizer stage, counts its cases
#   8. count       scripts/count_results.py: the last line
#
# Knobs (environment variables; every one has a default, none is needed):
#   SANITIZE=1       0 skips the sanitizer and fuzzing stage (about 5 of the
#                    ~25 minutes on a fresh clone of this 2-core machine)
#   FUZZ_SECONDS=5   run time of each libFuzzer target in the stage
#   JOBS=$(nproc)    parallel compile jobs
#   BUILD_TYPE=Release  the normal build (RelWithDebInfo keeps -g, for a debugger)
#   SAN_NICE=19      priority of the background stage; 0 gives it a fair
#                    share (on a machine loaded by other work)
#   SAN_UNITY=ON     the sanitizer builds are CMake unity builds (OFF: file by file)
#   ROS_HOME         where ROS writes its logs (default build/ros_home)
# scripts/sanitize.sh run by hand also takes SAN_GTESTS (a ctest regex of
# the ASan gtests to run) and SAN_SKIP (the gtests it leaves out).
#
# One measured tuning stays in the default path: the stage runs in its own
# session and scheduling group at nice 19 (sched_autogroup gives each
# session a group; nice alone left the stage half the CPU and the build
# phase took 701 s instead of 364 s on a fresh clone, issue 19).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

# Phase timing: wall time and the CPU time (user + system) of the child
# processes finished in the phase, printed after each phase and again at the
# end (the background sanitizer stage counts when it is waited for; its
# steps print their own, see build_san.log).
TIMES=()
T_WALL=$SECONDS
T_CPU=0
T_FILE=$(mktemp)
phase_done() {  # phase_done NAME
  local cpu
  # `times` in this shell (in a subshell it would see no children): its
  # second line is the children's user and system time, e.g. "1m2.5s 0m3.1s".
  times >"$T_FILE"
  cpu=$(awk 'NR == 2 { split($1, u, /[ms]/); split($2, s, /[ms]/); printf "%.0f", u[1] * 60 + u[2] + s[1] * 60 + s[2] }' "$T_FILE")
  TIMES+=("$(printf '%-22s %5d s wall %6d s CPU' "$1" $((SECONDS - T_WALL)) $((cpu - T_CPU)))")
  echo "== phase ${TIMES[-1]}"
  T_WALL=$SECONDS
  T_CPU=$cpu
}

ensure_setup
export SANITIZE="${SANITIZE:-1}"  # on: the whole run took 26 min 36 s on a fresh clone (README)
# Clean results for this run (the sanitizer stage writes there too).
rm -rf "$ROOT/build/test_results"
phase_done setup

# 2. The sanitizer and fuzzing stage (scripts/sanitize.sh) in the
# background at the lowest priority: it uses only the CPU the build and the
# tests leave idle (the tests run one at a time). Its own process group and
# session (so its own scheduling group, whose nice is set too: see the
# header), ended with this script; its results go to build/test_results.
san_pid=
if [ "$SANITIZE" != 0 ]; then
  # shellcheck disable=SC2016  # expanded by the inner bash
  setsid bash -c 'echo "$1" >/proc/self/autogroup 2>/dev/null || true; exec nice -n "$1" "$2" all' \
    sanitize "${SAN_NICE:-19}" "$ROOT/scripts/sanitize.sh" >"$ROOT/build_san.log" 2>&1 &
  san_pid=$!
  trap 'kill -- -$san_pid 2>/dev/null || true; rm -f "$T_FILE"' EXIT
else
  trap 'rm -f "$T_FILE"' EXIT
fi

# 3. The workspace (the libFuzzer programs are the stage's: clang only).
build_workspace
phase_done build
# 4. The test targets. --force-cmake: catkin caches the test environment (PYTHONPATH,
# LD_LIBRARY_PATH) when it configures, and keeps only devel directories
# that exist then; on a fresh clone devel/lib/python3/dist-packages (the
# generated mrt_msgs Python) exists only after the first build.
build_workspace --force-cmake tests
phase_done "build tests"

# 5. Every gtest and rostest; each run gets its own ROS master port.
export ROS_MASTER_URI="http://127.0.0.1:$(free_port)"
cd "$ROOT/build"
set +e
ctest --output-on-failure -j1 "$@"
ctest_rc=$?
set -e
phase_done "gtests + rostests"

# 6. Workspace-level checks, each counted as one more test case: runs the
# command, writes its JUnit file, and shows its output when it fails.
check_case() {  # check_case NAME COMMAND...
  local name=$1 out rc
  shift
  set +e
  out=$(cd "$ROOT" && "$@" 2>&1)
  rc=$?
  set -e
  mkdir -p "$ROOT/build/test_results/$name"
  CASE_OUT="$out" CASE_RC="$rc" /usr/bin/python3 - "$ROOT/build/test_results/$name/$name.xml" "$name" <<'PY'
import os, sys
from xml.sax.saxutils import escape, quoteattr
name = sys.argv[2]
failure = "" if os.environ["CASE_RC"] == "0" else \
    f'<failure message={quoteattr(name + " failed")}>{escape(os.environ["CASE_OUT"])}</failure>'
with open(sys.argv[1], "w") as f:
    f.write(f'<testsuite name={quoteattr(name)} tests="1"><testcase classname="workspace" name={quoteattr(name)}>'
            f'{failure}</testcase></testsuite>\n')
PY
  [ "$rc" -eq 0 ] || echo "$out" >&2
}

# catkin_lint clean (errors and warnings); no source file over 500 lines and
# no function over 80 unless scripts/size_exceptions.txt says why; the Roby
# bringup runs from `catkin_make install` moved elsewhere; the repository
# builds inside another workspace's src/ with catkin_make and catkin build.
check_case catkin_lint catkin_lint --strict src
check_case check_sizes /usr/bin/python3 scripts/check_sizes.py $(cd "$ROOT" && ls -d src/mrt_*/)
check_case check_install "$ROOT/scripts/check_install.sh"
check_case catkin_workspace "$ROOT/scripts/check_workspace.sh"

phase_done "checks"

# 7. Sanitizers and fuzzing: waits for the background stage (results counted
# below; the stage failing on its own, e.g. clang missing, is one failed
# case).
if [ -n "$san_pid" ]; then
  set +e
  echo "== waiting for the sanitizer and fuzzing stage (log: build_san.log)"
  wait "$san_pid"
  san_rc=$?
  set -e
  cat "$ROOT/build_san.log"
  if [ "$san_rc" -ne 0 ]; then
    /usr/bin/python3 "$ROOT/scripts/junit.py" case "$ROOT/build/test_results/sanitizers/sanitize.xml" \
      sanitizers sanitize.sh "$san_rc" "$ROOT/build_san.log"
  fi
  phase_done "wait for sanitizers"
fi
echo "== time per phase (CPU: of the processes the phase waited for; the sanitizer stage's, all of it, counts"
echo "   in the phase that waits for it; its steps are in its log above)"
printf '   %s\n' "${TIMES[@]}"

# 8. A ctest failure the result files do not show (a test that crashed before
# writing any) counts as one more failed case.
extra=0
if [ "$ctest_rc" -ne 0 ]; then extra=1; fi
/usr/bin/python3 "$ROOT/scripts/count_results.py" "$ROOT/build/test_results" --extra-failed "$extra"
