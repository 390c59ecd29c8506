#!/usr/bin/env bash
# Checks that `catkin_make install` produces a working FollowMe, as
# check_install.sh does for Roby. Installs the workspace (the build that
# scripts/test.sh made, so nothing is compiled again; with INSTALLED=1 the
# install space already there is taken as it is) and, in a clean environment
# that knows only the install space:
#  1. Mr. BRIAN loads FollowMe's rule base, which names Roby's files by
#     package path (package://mrt_roby/...): brian_check on the installed
#     BrianConfigs.ini;
#  2. followme_run, from the install space on installed files only, guides
#     the 4-exhibit tour to its end (exit 0);
#  3. `roslaunch mrt_followme followme.launch rviz:=false airboard:=false`
#     comes up: the guide publishes its status, Mr. BRIAN its commands
#     (the rule base loaded), SPIKE plans the first leg (the guide's status
#     reaches Guide; nav_msgs/Path is not read here: rostopic may lack the
#     Python message).
# Exit 0 when all pass; 1 otherwise, with the end of the log.
#   ./scripts/check_install_followme.sh [NAME:=VALUE ...]   extra roslaunch arguments
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

WORK="$ROOT/build/check_install_followme"
mkdir -p "$WORK/ros_home"
cd "$ROOT"
INSTALL_DIR="$ROOT/install"
if [ "${INSTALLED:-0}" != 1 ]; then
  rm -rf "$INSTALL_DIR"
  build_workspace install >"$WORK/build.log" 2>&1 ||
    { tail -30 "$WORK/build.log" >&2; echo "check_install_followme: install failed ($WORK/build.log)" >&2; exit 1; }
fi

# The checks, with nothing of the source or devel space in sight.
env -i HOME="$HOME" PATH=/usr/bin:/bin LANG=C.UTF-8 ROS_HOME="$WORK/ros_home" \
  ROS_MASTER_URI="http://127.0.0.1:$(free_port)" INSTALL="$INSTALL_DIR" LOG="$WORK/roslaunch.log" \
  bash -s -- "$@" <<'CHECK'
source "$INSTALL/setup.bash"
set -u
fail() { echo "check_install_followme: $*" >&2; [ -f "$LOG" ] && tail -30 "$LOG" >&2; exit 1; }
share="$INSTALL/share"
for p in mrt_followme mrt_roby; do
  where=$(rospack find $p) || fail "$p is not in the install space"
  [ "$where" = "$share/$p" ] || fail "$p found at $where, not in $INSTALL"
done
rules="$share/mrt_followme/config/brian/BrianConfigs.ini"
grep -q "package://mrt_roby/" "$rules" || fail "the installed rule base does not name Roby's files by package path"
"$INSTALL/lib/mrt_brian/brian_check" "$rules" >"$LOG" 2>&1 || fail "brian_check refuses the installed rule base"
"$INSTALL/lib/mrt_followme/followme_run" --world "$share/mrt_world/worlds/museum.yaml" \
  --config "$share/mrt_followme/config/followme.yaml" --brian "$rules" >"$LOG" 2>&1 ||
  fail "followme_run from the install space did not complete the tour"
grep -q "completed: yes" "$LOG" || fail "followme_run printed no completed tour"
roslaunch mrt_followme followme.launch rviz:=false airboard:=false "$@" >"$LOG" 2>&1 &
launch=$!
trap 'kill -INT $launch 2>/dev/null; sleep 3; kill -TERM $launch 2>/dev/null; wait $launch 2>/dev/null' EXIT
deadline=$((SECONDS + 90))
until timeout 20 rostopic echo -n 1 /clock >/dev/null 2>&1; do
  kill -0 $launch 2>/dev/null || fail "roslaunch ended early"
  [ "$SECONDS" -lt "$deadline" ] || fail "no /clock after 90 s"
  sleep 1
done
for topic in /robot1/tour_status /robot1/commands; do
  timeout 60 rostopic echo -n 1 "$topic" >/dev/null 2>&1 || fail "nothing published on $topic"
done
timeout 90 rostopic echo -n 1 --filter "m.job == 'Guide'" /robot1/tour_status >/dev/null 2>&1 ||
  fail "the guide never guided (no plan from SPIKE?)"
nodes=$(rosnode list)
for n in /sim /robot1/guide /robot1/brian /robot1/map /visitor /followme_monitor; do
  grep -qx "$n" <<<"$nodes" || fail "node $n is not running"
done
kill -0 $launch 2>/dev/null || fail "roslaunch ended early"
echo "check_install_followme: FollowMe runs from $INSTALL (rule base by package path, followme_run, the bringup)"
CHECK
