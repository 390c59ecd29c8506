#!/usr/bin/python3
"""robocup_summary: the summary of a recorded RoboCup match (launch/robocup.launch).

usage: robocup_summary.py BAG

Reads from the bag (sim time throughout):
  /referee                       score, and when play is on (start ... stop)
  /ball/ground_truth             the true ball
  /<robot>/ground_truth          true poses (nav_msgs/Odometry)
  /<robot>/pose                  MUREA's estimates (PoseWithCovarianceStamped; read as
                                 msg.pose.pose, so a nav_msgs/Odometry there reads too)
  /<robot>/world_model           MAP's fused model: its Ball anchor
  /<robot>/scare/job             SCARE's job of each robot
and prints:
  score; ball control (the share of play time a cyan robot has the ball in
  reach: centre within body + ball + 5 cm + 3 cm of slack, within 30 deg of
  its heading, the kicker's reach of msl_match.yaml); passes completed (the
  ball controlled by one robot, released, travelling at least 1 m and next
  controlled by another cyan robot); role changes per minute (changes of any
  robot's SCARE job, per minute of sim time, team total); localization error
  (MUREA's estimate against the ground truth at the estimate's stamp: mean
  and 95th percentile per robot); ball error (MAP's fused ball of every robot
  against the true ball at the model's stamp, while the model has a ball).
"""
import bisect
import math
import sys

import rosbag

REACH = 0.25 + 0.11 + 0.05 + 0.03
HALF_ANGLE = math.radians(30)


class Track:
    """Time-sorted (t, x, y, yaw) samples with nearest-in-time lookup."""

    def __init__(self):
        self.t, self.v = [], []

    def add(self, t, v):
        self.t.append(t)
        self.v.append(v)

    def at(self, t, tolerance=0.02):
        i = bisect.bisect_left(self.t, t)
        best = None
        for j in (i - 1, i):
            if 0 <= j < len(self.t) and abs(self.t[j] - t) <= tolerance:
                if best is None or abs(self.t[j] - t) < abs(self.t[best] - t):
                    best = j
        return None if best is None else self.v[best]


def yaw(q):
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


def stats(errors):
    if not errors:
        return "n/a"
    e = sorted(errors)
    return f"mean {sum(e) / len(e):.3f} m, 95% {e[min(len(e) - 1, int(0.95 * len(e)))]:.3f} m ({len(e)} samples)"


def play_intervals(referee, end):
    """[start, stop) intervals of play from the referee's start/stop commands."""
    out, on = [], None
    for t, m in referee:
        if m.name == "start" and on is None:
            on = t
        elif m.name != "start" and on is not None:
            out.append((on, t))
            on = None
    if on is not None:
        out.append((on, end))
    return out


def in_play(t, intervals):
    return any(a <= t < b for a, b in intervals)


def main(path):
    bag = rosbag.Bag(path)
    topics = bag.get_type_and_topic_info().topics
    robots = sorted({t.split("/")[1] for t in topics if t.endswith("/ground_truth") and t != "/ball/ground_truth"})
    referee, ball, truth, est, job_changes, ball_err = [], Track(), {r: Track() for r in robots}, {}, 0, []
    jobs = {}
    end = 0.0
    wanted = ["/referee", "/ball/ground_truth"] + [f"/{r}/{s}" for r in robots
                                                   for s in ("ground_truth", "pose", "world_model", "scare/job")]
    models = []
    for topic, msg, stamp in bag.read_messages(topics=[w for w in wanted if w in topics]):
        t = msg.header.stamp.to_sec() if hasattr(msg, "header") else stamp.to_sec()
        end = max(end, t)
        robot = topic.split("/")[1]
        if topic == "/referee":
            referee.append((t, msg))
        elif topic == "/ball/ground_truth":
            ball.add(t, (msg.pose.pose.position.x, msg.pose.pose.position.y))
        elif topic.endswith("/ground_truth"):
            p = msg.pose.pose
            truth[robot].add(t, (p.position.x, p.position.y, yaw(p.orientation)))
        elif topic.endswith("/pose"):
            est.setdefault(robot, []).append((t, msg.pose.pose.position.x, msg.pose.pose.position.y))
        elif topic.endswith("/world_model"):
            models.append((t, msg))
        elif topic.endswith("/scare/job"):
            if robot in jobs and jobs[robot] != msg.data and msg.data:
                job_changes += 1
            if msg.data:
                jobs[robot] = msg.data
    bag.close()
    play = play_intervals(referee, end)
    play_time = sum(b - a for a, b in play)
    score = next((m for _, m in reversed(referee) if m.score), None)
    if score is not None:
        print("robocup: score " + " - ".join(f"{n} {s}" for n, s in zip(score.teams, score.score)))
    else:
        print("robocup: score: no referee message with a score recorded")

    # Ball control and passes, on the ball's samples during play.
    controlled, holder, last_holder, release_at = 0, None, None, None
    passes, samples = 0, 0
    for t, (bx, by) in zip(ball.t, ball.v):
        if not in_play(t, play):
            continue
        samples += 1
        now = None
        for r in robots:
            s = truth[r].at(t)
            if s is None:
                continue
            dx, dy = bx - s[0], by - s[1]
            ang = abs(math.atan2(math.sin(math.atan2(dy, dx) - s[2]), math.cos(math.atan2(dy, dx) - s[2])))
            if math.hypot(dx, dy) <= REACH and ang <= HALF_ANGLE:
                now = r
        if now is not None:
            controlled += 1
            if last_holder is not None and now != last_holder and release_at is not None and \
                    math.hypot(bx - release_at[0], by - release_at[1]) >= 1.0:
                passes += 1
            last_holder, release_at = now, None
        elif holder is not None:
            release_at = (bx, by)
        holder = now
    share = 100.0 * controlled / samples if samples else 0.0
    print(f"robocup: ball control (a cyan robot has the ball in reach): {share:.0f} % of {play_time:.0f} s of play")
    print(f"robocup: passes completed: {passes}")
    minutes = end / 60.0 if end > 0 else float("nan")
    print(f"robocup: role changes: {job_changes} ({job_changes / minutes:.1f} per minute, team total)")
    for r in robots:
        if r.startswith("opp_"):
            continue  # the scripted opponents: no MUREA
        errors = []
        for t, x, y in est.get(r, []):
            s = truth[r].at(t)
            if s is not None:
                errors.append(math.hypot(x - s[0], y - s[1]))
        print(f"robocup: localization error {r} (MUREA vs ground truth): {stats(errors)}")
    for t, m in models:
        balls = [a for a in m.anchors if a.membership_class == "Ball"]
        b = ball.at(t)
        if balls and b is not None:
            best = max(balls, key=lambda a: a.reliability)
            ball_err.append(math.hypot(best.x - b[0], best.y - b[1]))
    print(f"robocup: ball error (MAP's fused ball vs ground truth, all robots): {stats(ball_err)}")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        sys.exit(2)
    main(sys.argv[1])
