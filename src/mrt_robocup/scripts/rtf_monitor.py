#!/usr/bin/python3
"""rtf_monitor: prints the measured real-time factor of a simulation.

Subscribes /clock and, every ~period wall seconds, prints (ROS_INFO) and
publishes on `rtf` (std_msgs/Float64) the simulated seconds that passed
divided by the wall seconds: what the whole team achieves, whatever the
simulator was asked for. ~camera_rate, ~camera_scale and ~vision are
printed with it, so a log says under which settings the factor was measured.
"""
import threading
import time

import rospy
from rosgraph_msgs.msg import Clock
from std_msgs.msg import Float64


class RtfMonitor:
    def __init__(self):
        self.period = float(rospy.get_param("~period", 10.0))
        if not self.period > 0.0:
            raise ValueError("~period: expected a number > 0, got %r" % self.period)
        self.settings = "camera %s Hz at scale %s, vision %s" % (rospy.get_param("~camera_rate", "?"),
                                                                 rospy.get_param("~camera_scale", "?"),
                                                                 rospy.get_param("~vision", "?"))
        self.lock = threading.Lock()
        self.sim = None
        self.pub = rospy.Publisher("rtf", Float64, queue_size=1, latch=True)
        rospy.Subscriber("/clock", Clock, self.on_clock, queue_size=1)

    def on_clock(self, msg):
        with self.lock:
            self.sim = msg.clock.to_sec()

    def run(self):
        last_wall, last_sim = time.time(), None
        total_wall, total_sim, first = 0.0, 0.0, None
        while not rospy.is_shutdown():
            time.sleep(self.period)
            with self.lock:
                sim = self.sim
            wall = time.time()
            if sim is not None and last_sim is not None and wall > last_wall:
                rtf = (sim - last_sim) / (wall - last_wall)
                total_wall += wall - last_wall
                total_sim += sim - last_sim
                self.pub.publish(Float64(rtf))
                rospy.loginfo("real-time factor: %.2f over the last %.0f s (%.2f over %.0f s; sim time %.1f s; %s)",
                              rtf, wall - last_wall, total_sim / total_wall, total_wall, sim, self.settings)
            last_wall, last_sim = wall, sim


if __name__ == "__main__":
    rospy.init_node("rtf_monitor")
    try:
        RtfMonitor().run()
    except ValueError as e:
        rospy.logfatal(str(e))
        raise SystemExit(1)
