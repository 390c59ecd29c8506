#!/usr/bin/env bash
# Checks that `catkin_make install` produces a working Roby. Installs the
# workspace (the build that scripts/test.sh made, so nothing is compiled
# again; with SCRATCH=1 a separate build of mrt_roby and its dependencies
# under build/check_install), moves the install space to another directory
# (build/check_install/moved: an install space is relocatable, its files
# found through package paths) and, in a clean environment that knows only
# that copy, runs `roslaunch mrt_roby roby.launch rviz:=false` for a few
# seconds. Passes (exit 0) when the bringup's nodes come up, Mr. BRIAN's
# commands and the AIRBoard's wheel commands are published and SCARE runs the
# route (it has the plan and the localizer's pose); exit 1 otherwise, with
# the end of the roslaunch log.
#   ./scripts/check_install.sh [NAME:=VALUE ...]   extra roslaunch arguments
#   SCRATCH=1 PACKAGES="a b"  scratch build of these and their dependencies
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

WORK="$ROOT/build/check_install"
mkdir -p "$WORK/ros_home"
cd "$ROOT"
if [ "${SCRATCH:-0}" = 1 ]; then
  INSTALL_DIR="$WORK/install"
  rm -rf "$INSTALL_DIR"
  # shellcheck disable=SC2086
  catkin_make "${CATKIN_ARGS[@]}" -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-RelWithDebInfo}" \
    --build "$WORK/build" -DCATKIN_DEVEL_PREFIX="$WORK/devel" -DCMAKE_INSTALL_PREFIX="$INSTALL_DIR" \
    --only-pkg-with-deps ${PACKAGES:-mrt_roby} -j"$JOBS" install >"$WORK/build.log" 2>&1 ||
    { tail -30 "$WORK/build.log" >&2; echo "check_install: build or install failed ($WORK/build.log)" >&2; exit 1; }
else
  INSTALL_DIR="$ROOT/install"
  rm -rf "$INSTALL_DIR"
  build_workspace install >"$WORK/build.log" 2>&1 ||
    { tail -30 "$WORK/build.log" >&2; echo "check_install: install failed ($WORK/build.log)" >&2; exit 1; }
fi

# The install space moved elsewhere: the original is removed, so that
# nothing can still be found at its old path.
MOVED="$WORK/moved"
rm -rf "$MOVED" && mv "$INSTALL_DIR" "$MOVED"
INSTALL_DIR="$MOVED"

# The check itself, with nothing of the source or devel space in sight.
env -i HOME="$HOME" PATH=/usr/bin:/bin LANG=C.UTF-8 ROS_HOME="$WORK/ros_home" \
  ROS_MASTER_URI="http://127.0.0.1:$(free_port)" INSTALL="$INSTALL_DIR" LOG="$WORK/roslaunch.log" \
  bash -s -- "$@" <<'CHECK'
source "$INSTALL/setup.bash"
set -u
fail() { echo "check_install: $*" >&2; tail -30 "$LOG" >&2; exit 1; }
where=$(rospack find mrt_roby) || fail "mrt_roby is not in the install space"
[ "$where" = "$INSTALL/share/mrt_roby" ] || fail "mrt_roby found at $where, not in $INSTALL"
roslaunch mrt_roby roby.launch rviz:=false "$@" >"$LOG" 2>&1 &
launch=$!
trap 'kill -INT $launch 2>/dev/null; sleep 3; kill -TERM $launch 2>/dev/null; wait $launch 2>/dev/null' EXIT
deadline=$((SECONDS + 90))
until timeout 20 rostopic echo -n 1 /clock >/dev/null 2>&1; do
  kill -0 $launch 2>/dev/null || fail "roslaunch ended early"
  [ "$SECONDS" -lt "$deadline" ] || fail "no /clock after 90 s"
  sleep 1
done
for topic in /robot1/commands /robot1/wheel_cmd; do
  timeout 30 rostopic echo -n 1 "$topic" >/dev/null 2>&1 || fail "nothing published on $topic"
done
# SCARE runs a plan only once the localizer's pose has arrived.
timeout 30 rostopic echo -n 1 --filter "m.state == m.RUNNING" /robot1/task_status >/dev/null 2>&1 ||
  fail "SCARE is not running the route (no plan, or no pose from the localizer)"
nodes=$(rosnode list)
for n in /sim /world /robot1/route_planner /robot1/dgps_localizer /robot1/scare /robot1/sonar_crisp /robot1/brian \
         /robot1/airboard /clearance_monitor; do
  grep -qx "$n" <<<"$nodes" || fail "node $n is not running"
done
kill -0 $launch 2>/dev/null || fail "roslaunch ended early"
echo "check_install: the Roby bringup runs from $INSTALL (nodes up, commands published)"
CHECK
