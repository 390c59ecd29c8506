#!/usr/bin/env bash
# README command 2: installs what is missing, builds, builds the tests, runs
# every gtest and rostest through ctest and prints, as its last line,
# "N passed, M failed" counted over individual test cases.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

ensure_setup
build_workspace
build_workspace tests

# Each run gets its own ROS master port and clean results.
export ROS_MASTER_URI="http://127.0.0.1:$(free_port)"
rm -rf "$ROOT/build/test_results"
cd "$ROOT/build"
set +e
ctest --output-on-failure -j1 "$@"
ctest_rc=$?
set -e

# A ctest failure the result files do not show (a test that crashed before
# writing any) counts as one more failed case.
extra=0
if [ "$ctest_rc" -ne 0 ]; then extra=1; fi
/usr/bin/python3 "$ROOT/scripts/count_results.py" "$ROOT/build/test_results" --extra-failed "$extra"
