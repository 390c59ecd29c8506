#!/usr/bin/env bash
# README command 1: installs what is missing, builds, runs the demo headless
# (under Xvfb unless --gui is given and a display exists), saves an rviz
# screenshot to build/demo/rviz.png and a bag to build/demo/demo.bag, draws
# the run's plots next to them (build/demo/demo_*.png, mrt_tools' plot_run),
# and prints a summary.
#   ./scripts/demo.sh [--gui] [NAME]    NAME: a launch file in launch/ (default: roby;
#                                       "demo" is the figure eight on the MSL field)
#   DURATION=<s>  simulated seconds to record at most (default: 200 for roby,
#                 which stops as soon as the route is completed; 400 for
#                 followme, which stops when the tour is over; 120 for robocup;
#                 30 otherwise)
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

GUI=0
NAME=roby
for arg in "$@"; do
  case "$arg" in
    --gui) GUI=1 ;;
    -h|--help) sed -n '2,9p' "$0"; exit 0 ;;
    *) NAME="$arg" ;;
  esac
done
LAUNCH="$ROOT/launch/$NAME.launch"
[ -f "$LAUNCH" ] || { echo "demo: no launch file $LAUNCH" >&2; exit 2; }
case "$NAME" in
  roby) DURATION="${DURATION:-200}" ;;
  followme) DURATION="${DURATION:-400}" ;;
  robocup) DURATION="${DURATION:-120}" ;;
  *) DURATION="${DURATION:-30}" ;;
esac

ensure_setup
build_workspace
set +u; source "$ROOT/devel/setup.bash"; set -u

OUT="$ROOT/build/demo"
mkdir -p "$OUT" "$ROS_LOG_DIR"
rm -f "$OUT/demo.bag" "$OUT/rviz.png" "$OUT"/demo_*.png
export ROS_MASTER_URI="http://127.0.0.1:$(free_port)"

pids=()
cleanup() {
  local p
  for p in "${pids[@]}"; do kill -INT "$p" 2>/dev/null || true; done
  sleep 2
  for p in "${pids[@]}"; do kill -TERM "$p" 2>/dev/null || true; done
}
trap cleanup EXIT

if [ "$GUI" -eq 0 ] || [ -z "${DISPLAY:-}" ]; then
  n=90
  while [ -e "/tmp/.X11-unix/X$n" ] || [ -e "/tmp/.X$n-lock" ]; do n=$((n + 1)); done
  Xvfb ":$n" -screen 0 1280x1024x24 -nolisten tcp >"$OUT/xvfb.log" 2>&1 &
  pids+=($!)
  export DISPLAY=":$n"
  sleep 1
fi

echo "demo: launching $NAME after ${SECONDS} s of setup and build (logs in $ROS_LOG_DIR)"
roslaunch "$LAUNCH" >"$OUT/roslaunch.log" 2>&1 &
pids+=($!)

# Wait for the simulated clock to tick (rostopic fails at once while the
# master is not up yet, so retry; each try waits long on a loaded machine).
deadline=$((SECONDS + 120))
until timeout 30 rostopic echo -n 1 /clock >/dev/null 2>&1; do
  if [ "$SECONDS" -ge "$deadline" ] || ! kill -0 "${pids[-1]}" 2>/dev/null; then
    echo "demo: the simulator did not start; see $OUT/roslaunch.log" >&2
    tail -20 "$OUT/roslaunch.log" >&2
    exit 1
  fi
  sleep 1
done

echo "demo: simulator up after ${SECONDS} s; recording at most ${DURATION} s of simulated time"
start=$(date +%s.%N)
# Left out: /clock (`rosbag play --clock` publishes its own) and the growing
# ground-truth trails (nav_msgs/Path, derivable from ground_truth).
# RoboCup and FollowMe: not the camera images either (10 Hz x 900 kB each).
exclude='/clock|/rosout(_agg)?|.*/ground_truth_path'
[ "$NAME" = robocup ] || [ "$NAME" = followme ] && exclude="$exclude|.*/camera/.*"
rosbag record --quiet -a -x "$exclude" --duration="$DURATION" -O "$OUT/demo.bag" \
  >"$OUT/rosbag.log" 2>&1 &
bag=$!
waiters=("$bag")
if [ "$NAME" = roby ]; then
  # Roby stops recording once SCARE reports the route completed.
  rostopic echo -n 1 --filter "m.event == 'route_completed'" /robot1/task_status >/dev/null 2>&1 &
  waiters+=($!)
fi
if [ "$NAME" = followme ]; then
  # FollowMe stops recording once the tour's summary is out.
  rostopic echo -n 1 /robot1/tour_summary >"$OUT/tour_summary.txt" 2>/dev/null &
  waiters+=($!)
fi
# Until the first waiter ends: a progress line every 15 s (simulated time,
# the bag's size), so that a run of several minutes is not silent.
next_report=$((SECONDS + 15))
while true; do
  running=1
  for p in "${waiters[@]}"; do kill -0 "$p" 2>/dev/null || running=0; done
  [ "$running" -eq 1 ] || break
  if [ "$SECONDS" -ge "$next_report" ]; then
    sim=$(timeout 10 rostopic echo -n 1 /clock/clock/secs 2>/dev/null | head -n 1 || true)
    size=$(du -m "$OUT"/demo.bag* 2>/dev/null | awk '{s += $1} END {print s + 0}')
    echo "demo: recording: simulated time ${sim:-?} s (of at most ${DURATION} s), bag ${size} MB, ${SECONDS} s since start"
    next_report=$((SECONDS + 15))
  fi
  sleep 1
done
if kill -0 "$bag" 2>/dev/null; then
  sleep 2  # the last moments of the route
  kill -INT "$bag"
fi
wait "$bag" || true
for p in "${waiters[@]:1}"; do kill "$p" 2>/dev/null || true; done
wall=$(/usr/bin/python3 -c "import time; print(time.time() - $start)")

kill -0 "${pids[-1]}" 2>/dev/null ||
  { echo "demo: the launch ended early; see $OUT/roslaunch.log" >&2; tail -20 "$OUT/roslaunch.log" >&2; exit 1; }
import -window root "$OUT/rviz.png" || true
# A black or empty frame has a handful of colours; rviz showing a world has hundreds.
colours=$(identify -format '%k' "$OUT/rviz.png" 2>/dev/null || echo 0)
if [ "$colours" -lt 50 ]; then
  echo "demo: the screenshot $OUT/rviz.png is missing or blank ($colours colours)" >&2
  exit 1
fi
[ -s "$OUT/demo.bag" ] || { echo "demo: no bag was recorded; see $OUT/rosbag.log" >&2; exit 1; }

/usr/bin/python3 "$ROOT/scripts/bag_summary.py" "$OUT/demo.bag" "$wall" "$NAME"
if [ "$NAME" = followme ]; then
  echo "FollowMe tour:"
  # the summary: exhibits visited, wanders handled, time, longest time the
  # visitor was out of sight, localization error from ground truth (the
  # distributed bringup's followme_monitor_node; followme_node's with
  # distributed:=false)
  /usr/bin/python3 -c 'import sys, yaml; print(yaml.safe_load(open(sys.argv[1]).read().split("---")[0])["data"])' \
    "$OUT/tour_summary.txt" | sed 's/^/  /' || echo "  (no summary: see $OUT/roslaunch.log)"
fi
if [ "$NAME" = robocup ]; then
  # score, ball control, passes, role changes per minute, localization and
  # ball errors from ground truth; the real-time factor the team held
  /usr/bin/python3 "$ROOT/src/mrt_robocup/scripts/robocup_summary.py" "$OUT/demo.bag" ||
    echo "robocup: no summary (see $OUT/roslaunch.log)"
  # rtf_monitor's last line, without the console's colour codes: printed
  # again as the demo's last line.
  rtf_line=$(grep -h "real-time factor:" "$OUT/roslaunch.log" | tail -n 1 |
    sed -e 's/\x1b\[[0-9;]*m//g' -e 's/^.*real-time factor/real-time factor/' || true)
  rtf_line="robocup: ${rtf_line:-real-time factor: none printed (see $OUT/roslaunch.log)}"
  echo "$rtf_line"
fi

# The plots of the run, over the launch file's world (its `world` argument).
world=$(sed -n 's|.*<arg name="world" default="\$(dirname)/\.\./\([^"]*\)".*|\1|p' "$LAUNCH" | head -n 1)
world_args=()
[ -n "$world" ] && [ -f "$ROOT/$world" ] && world_args=(--world "$ROOT/$world")
/usr/bin/python3 "$ROOT/scripts/plot_run.py" "$OUT/demo.bag" "${world_args[@]}" ||
  { echo "demo: plot_run could not draw the run's plots" >&2; exit 1; }
echo "demo: screenshot $OUT/rviz.png ($colours colours)"
echo "demo: bag        $OUT/demo.bag"
echo "demo: done in ${SECONDS} s"
if [ "$NAME" = robocup ]; then echo "$rtf_line"; fi
