#!/usr/bin/env python3
"""Records a bag of the simulated Roby bringup with `rosbag record` (the
topics scripts/demo.sh records) and runs plot_run on it: every figure is
written as a non-empty PNG, and the bag's series show the robot driving."""
import os
import subprocess
import sys
import tempfile
import unittest

import rospy
import rostest

from mrt_tools import bag_data

HERE = os.path.dirname(os.path.realpath(__file__))
SCRIPT = os.path.join(HERE, "..", "scripts", "plot_run")
FIGURES = ("trajectory", "errors", "commands", "wheels", "behaviours", "timing_periods", "timing_latency")


class PlotRoby(unittest.TestCase):
    def test_record_and_plot(self):
        rospy.init_node("plot_roby_test")
        world = rospy.get_param("~world")
        seconds = rospy.get_param("~record_seconds", 12.0)
        # Start recording once the simulated clock runs.
        rospy.wait_for_message("/clock", rospy.AnyMsg, timeout=60)
        with tempfile.TemporaryDirectory() as d:
            bag = os.path.join(d, "roby.bag")
            rec = subprocess.run(["rosbag", "record", "--quiet", "-a", "-x",
                                  "/clock|/rosout(_agg)?|.*/ground_truth_path",
                                  f"--duration={seconds}", "-O", bag],
                                 capture_output=True, text=True, timeout=90)
            self.assertTrue(os.path.isfile(bag), f"rosbag record wrote no bag: {rec.stderr}")
            plot = subprocess.run([sys.executable, SCRIPT, bag, "--world", world, "-q"],
                                  capture_output=True, text=True, timeout=120)
            self.assertEqual(plot.returncode, 0, plot.stderr)
            for name in FIGURES:
                path = os.path.join(d, f"roby_{name}.png")
                self.assertTrue(os.path.isfile(path), f"{path} missing; plot_run said: {plot.stderr}")
                with open(path, "rb") as f:
                    self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n", path)
                self.assertGreater(os.path.getsize(path), 10000, path)
            data = bag_data.read_bag(bag, progress=False)
        truth = data.truth["robot1"]
        # The route's first leg goes from (0, 0) towards (8, 0): the robot
        # has left the start by more than 0.5 m after 12 s.
        self.assertGreater(max(truth.x) - min(truth.x), 0.5)
        self.assertIn("/robot1/pose", data.estimates)
        self.assertEqual(data.types["/robot1/pose"], "geometry_msgs/PoseWithCovarianceStamped")
        self.assertEqual(data.estimates["/robot1/pose"].frame, "map")
        self.assertIn("ReachPathPoint", data.behaviours["/robot1/brian/introspection"])


if __name__ == "__main__":
    rostest.rosrun("mrt_tools", "plot_roby", PlotRoby)
