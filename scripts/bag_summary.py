#!/usr/bin/env python3
"""Prints a demo summary from a bag: topics with message counts, the final
ground-truth pose of every robot, and the real-time factor achieved
(simulated seconds recorded / wall seconds spent recording); for the Roby
demo (APP roby) also Roby's route: path points reached, tasks failed,
clearance, time. Other applications print their own summaries (demo.sh).

usage: bag_summary.py BAG WALL_SECONDS [APP]
"""
import math
import sys

import rosbag


def roby_summary(bag, info):
    """Roby (launch/roby.launch): path points, clearance, time, from
    SCARE's task status."""
    status_topics = [t for t in info.topics if t.endswith("/task_status")]
    if not status_topics:
        return
    first = last = done = None
    plan_size = 0
    for _, msg, _ in bag.read_messages(topics=status_topics):
        if first is None:
            first = msg
        if not plan_size and msg.plan_size:
            plan_size = msg.plan_size
        if msg.event == "route_completed" and done is None:
            done = msg
        last = msg
    end = done if done is not None else last
    print(f"roby: path points reached: {end.reached} of {plan_size}"
          + ("" if done is not None else " (route still running when the recording ended)"))
    print(f"roby: tasks failed: {end.failed}, re-plan requests: {end.replans}, mode: {end.mode}")
    minimum = None
    clearance = [t for t in info.topics if t.endswith("/min_clearance")]
    # read_messages(topics=[]) would read every topic: only when recorded.
    for _, msg, _ in bag.read_messages(topics=clearance) if clearance else []:
        minimum = msg.data
    if minimum is not None:
        print(f"roby: minimum obstacle clearance (ground truth): {minimum:.3f} m")
    took = end.header.stamp.to_sec() - first.header.stamp.to_sec()
    what = "time taken for the route" if done is not None else "time driven"
    print(f"roby: {what}: {took:.1f} s (sim time {end.header.stamp.to_sec():.1f} s)")


def main(path, wall, app):
    with rosbag.Bag(path) as bag:
        info = bag.get_type_and_topic_info()
        print("topics recorded:")
        for topic in sorted(info.topics):
            t = info.topics[topic]
            print(f"  {topic:40s} {t.message_count:7d}  {t.msg_type}")
        last = {}
        for topic, msg, _ in bag.read_messages(
                topics=[t for t in info.topics if t.endswith("/ground_truth")]):
            last[topic] = msg
        for topic, msg in sorted(last.items()):
            p = msg.pose.pose.position
            q = msg.pose.pose.orientation
            yaw = math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
            print(f"final ground truth {topic}: x={p.x:.3f} m y={p.y:.3f} m "
                  f"theta={math.degrees(yaw):.1f} deg (t={msg.header.stamp.to_sec():.2f} s)")
        if app == "roby":
            roby_summary(bag, info)
        sim = bag.get_end_time() - bag.get_start_time()
        print(f"simulated time recorded: {sim:.2f} s in {wall:.2f} s wall: "
              f"real-time factor {sim / wall:.2f}")


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    main(sys.argv[1], float(sys.argv[2]), sys.argv[3] if len(sys.argv) == 4 else "")
