#!/usr/bin/env bash
# Checks that the repository builds as a member of another catkin workspace,
# as a ROS user would use it: the working tree (tracked and untracked files,
# not the build products) is copied into the src/ of a fresh workspace under
# build/check_workspace, catkin_pkg's crawler must find each of its packages
# once (it stops with "Multiple packages found with the same name" otherwise),
# and mrt_msgs, mrt_common and mrt_brian (with their dependencies) are built
# there with `catkin_make` and with `catkin build` (catkin-tools).
# Exit 0 when all of that holds; 1 with the log's end otherwise.
#   ./scripts/check_workspace.sh [PACKAGE ...]   other packages to build
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

WORK="$ROOT/build/check_workspace"
PACKAGES=("$@")
[ $# -gt 0 ] || PACKAGES=(mrt_msgs mrt_common mrt_brian)
fail() { echo "check_workspace: $1" >&2; [ -z "${2:-}" ] || tail -30 "$2" >&2; exit 1; }

rm -rf "$WORK" && mkdir -p "$WORK/ws/src/mrt"
(cd "$ROOT" && git ls-files -z -co --exclude-standard | tar --null -T - --ignore-failed-read -cf - 2>/dev/null) |
  tar -C "$WORK/ws/src/mrt" -xf -

# The crawl (catkin_make and catkin build both use catkin_pkg's).
expected=$(find "$WORK/ws/src/mrt/src" -mindepth 2 -maxdepth 2 -name package.xml | wc -l)
found=$(/usr/bin/python3 -c 'import sys; from catkin_pkg.packages import find_packages
print(len(find_packages(sys.argv[1])))' "$WORK/ws/src" 2>"$WORK/crawl.log") || fail "the crawl failed" "$WORK/crawl.log"
[ "$found" -eq "$expected" ] || fail "the crawl finds $found packages, the repository has $expected"
echo "check_workspace: the crawl finds each of the $found packages once"
absolute=$(cd "$WORK/ws/src/mrt" && find . -type l -lname '/*')
[ -z "$absolute" ] || fail "absolute links in the tree: $absolute"

cd "$WORK/ws"
catkin_make "${CATKIN_ARGS[@]}" -DCMAKE_BUILD_TYPE=Release --only-pkg-with-deps "${PACKAGES[@]}" -j"$JOBS" \
  >"$WORK/catkin_make.log" 2>&1 || fail "catkin_make failed" "$WORK/catkin_make.log"
echo "check_workspace: catkin_make built ${PACKAGES[*]}"
rm -rf build devel
catkin init >"$WORK/catkin_build.log" 2>&1 &&
  catkin config --cmake-args "${CATKIN_ARGS[@]}" -DCMAKE_BUILD_TYPE=Release >>"$WORK/catkin_build.log" 2>&1 &&
  catkin build --no-status --no-notify -j"$JOBS" "${PACKAGES[@]}" >>"$WORK/catkin_build.log" 2>&1 ||
  fail "catkin build failed" "$WORK/catkin_build.log"
echo "check_workspace: catkin build built ${PACKAGES[*]}"
