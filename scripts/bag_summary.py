#!/usr/bin/env python3
"""Prints a demo summary from a bag: topics with message counts, the final
ground-truth pose of every robot, and the real-time factor achieved
(simulated seconds recorded / wall seconds spent recording).

usage: bag_summary.py BAG WALL_SECONDS
"""
import math
import sys

import rosbag


def main(path, wall):
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
        sim = bag.get_end_time() - bag.get_start_time()
        print(f"simulated time recorded: {sim:.2f} s in {wall:.2f} s wall: "
              f"real-time factor {sim / wall:.2f}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], float(sys.argv[2]))
