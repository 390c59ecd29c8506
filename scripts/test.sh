#!/usr/bin/env bash
# README command 2: installs what is missing, builds, builds the tests, runs
# every gtest and rostest through ctest, checks the workspace with
# catkin_lint --strict and the sources' sizes (scripts/check_sizes.py), and
# prints, as its last line, "N passed, M failed" counted over test cases.
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

# The workspace stays catkin_lint clean (errors and warnings), counted as
# one more test case.
set +e
lint_out=$(cd "$ROOT" && catkin_lint --strict src 2>&1)
lint_rc=$?
set -e
mkdir -p "$ROOT/build/test_results/catkin_lint"
LINT_OUT="$lint_out" LINT_RC="$lint_rc" /usr/bin/python3 - "$ROOT/build/test_results/catkin_lint/catkin_lint.xml" <<'PY'
import os, sys
from xml.sax.saxutils import escape
failure = "" if os.environ["LINT_RC"] == "0" else \
    f'<failure message="catkin_lint found problems">{escape(os.environ["LINT_OUT"])}</failure>'
with open(sys.argv[1], "w") as f:
    f.write(f'<testsuite name="catkin_lint" tests="1"><testcase classname="workspace" name="catkin_lint_strict">'
            f'{failure}</testcase></testsuite>\n')
PY
[ "$lint_rc" -eq 0 ] || echo "$lint_out" >&2

# No source file over 500 lines and no function over 80 (issue 12), counted
# as one more test case.
/usr/bin/python3 "$ROOT/scripts/check_sizes.py" --junit "$ROOT/build/test_results/check_sizes/check_sizes.xml" \
  $(cd "$ROOT" && ls -d mrt_*/) >&2 || true

# A ctest failure the result files do not show (a test that crashed before
# writing any) counts as one more failed case.
extra=0
if [ "$ctest_rc" -ne 0 ]; then extra=1; fi
/usr/bin/python3 "$ROOT/scripts/count_results.py" "$ROOT/build/test_results" --extra-failed "$extra"
