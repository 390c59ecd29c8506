#!/usr/bin/env python3
"""plot_run on bags written here with known contents: the series read, the
errors computed against the ground truth, the figures written or skipped,
the world reader and the command line's exit codes."""
import math
import os
import subprocess
import sys
import tempfile
import unittest

import genmsg
import genmsg.gentools
import genmsg.msg_loader
import genpy.dynamic
import rosbag
import rospkg
import rospy
import rostest
from mrt_msgs.msg import BrianBehavior, BrianIntrospection
from std_msgs.msg import String

from mrt_tools import bag_data, plots
from mrt_tools.plot_run import main
from mrt_tools.world import WorldError, load_world

HERE = os.path.dirname(os.path.realpath(__file__))
SCRIPT = os.path.join(HERE, "..", "scripts", "plot_run")
T0 = 100.0  # first receive time of the synthetic bag (s)


def message_class(name):
    """A message class generated from the .msg files: Debian's ROS ships no
    Python modules for geometry_msgs and nav_msgs, only their definitions."""
    rp = rospkg.RosPack()
    search = {p: [os.path.join(rp.get_path(p), "msg")] for p in ("std_msgs", "geometry_msgs", "nav_msgs")}
    ctx = genmsg.MsgContext.create_default()
    spec = genmsg.msg_loader.load_msg_by_type(ctx, name, search)
    genmsg.msg_loader.load_depends(ctx, spec, search)
    return genpy.dynamic.generate_dynamic(name, genmsg.gentools.compute_full_text(ctx, spec))[name]


Odometry = message_class("nav_msgs/Odometry")
PoseWithCovarianceStamped = message_class("geometry_msgs/PoseWithCovarianceStamped")
Twist = message_class("geometry_msgs/Twist")


def odom(stamp, x, y, yaw, cls=Odometry):
    """A planar pose at stamp in map as cls (Odometry, the ground truth, or
    PoseWithCovarianceStamped, the stack's type on pose): both keep it in
    .pose.pose."""
    m = cls()
    m.header.stamp = rospy.Time.from_sec(stamp)
    m.header.frame_id = "map"
    m.pose.pose.position.x, m.pose.pose.position.y = x, y
    m.pose.pose.orientation.z, m.pose.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return m


def estimate(stamp, x, y, yaw):
    return odom(stamp, x, y, yaw, PoseWithCovarianceStamped)


def write_run_bag(path):
    """10 s: the truth drives along x at 1 m/s, heading 0, at 10 Hz; the
    estimate is off by (+0.3, +0.4) m and +0.1 rad; a Twist at 20 Hz; the
    estimate is received 20 ms after its stamp; Mr. BRIAN's introspection
    with two behaviours at 10 Hz."""
    with rosbag.Bag(path, "w") as bag:
        for k in range(101):
            t = T0 + 0.1 * k
            bag.write("/robot1/ground_truth", odom(t, 0.1 * k, 0.0, 0.0), rospy.Time.from_sec(t))
            bag.write("/robot1/pose", estimate(t, 0.1 * k + 0.3, 0.4, 0.1), rospy.Time.from_sec(t + 0.02))
            intro = BrianIntrospection()
            intro.header.stamp = rospy.Time.from_sec(t)
            intro.behaviors = [BrianBehavior(name="ReachPathPoint", level=1, cando=1.0, active=True, weight=0.75),
                               BrianBehavior(name="AvoidObstacle", level=2, cando=0.25, active=False, weight=0.0)]
            bag.write("/robot1/brian/introspection", intro, rospy.Time.from_sec(t))
        for k in range(201):
            cmd = Twist()
            cmd.linear.x = 1.0
            bag.write("/robot1/cmd_vel", cmd, rospy.Time.from_sec(T0 + 0.05 * k))


class Figures(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.TemporaryDirectory()
        cls.bag = os.path.join(cls.dir.name, "run.bag")
        write_run_bag(cls.bag)
        cls.data = bag_data.read_bag(cls.bag, progress=False)

    @classmethod
    def tearDownClass(cls):
        cls.dir.cleanup()

    def test_series_read(self):
        d = self.data
        self.assertEqual(sorted(d.truth), ["robot1"])
        self.assertEqual(sorted(d.estimates), ["/robot1/pose"])
        self.assertEqual(d.types["/robot1/pose"], "geometry_msgs/PoseWithCovarianceStamped")
        self.assertEqual(len(d.truth["robot1"].t), 101)
        # The truth's last pose: x = 0.1 * 100 = 10 m at 10 s after the start.
        self.assertAlmostEqual(d.truth["robot1"].x[-1], 10.0, places=9)
        self.assertAlmostEqual(d.truth["robot1"].t[-1], 10.0, places=6)
        self.assertEqual(sorted(d.twists["/robot1/cmd_vel"].series), ["angular.z (rad/s)", "linear.x (m/s)",
                                                                        "linear.y (m/s)"])
        self.assertEqual(sorted(d.behaviours["/robot1/brian/introspection"]), ["AvoidObstacle", "ReachPathPoint"])
        self.assertEqual(d.behaviours["/robot1/brian/introspection"]["ReachPathPoint"].weight[0], 0.75)

    def test_errors_against_the_truth(self):
        t, pos, head = plots.pose_errors(self.data.estimates["/robot1/pose"], self.data.truth["robot1"])
        self.assertEqual(len(t), 101)
        # (0.3, 0.4) m off: a 3-4-5 triangle, 0.5 m; heading 0.1 rad off.
        for e in pos:
            self.assertAlmostEqual(e, 0.5, places=9)
        for e in head:
            self.assertAlmostEqual(e, 0.1, places=6)

    def test_timing(self):
        periods = [b - a for a, b in zip(self.data.timing["/robot1/cmd_vel"].received,
                                         self.data.timing["/robot1/cmd_vel"].received[1:])]
        # 20 Hz: 50 ms between messages; the estimate arrives 20 ms after its stamp.
        for p in periods:
            self.assertAlmostEqual(p, 0.05, places=6)
        for lat in self.data.timing["/robot1/pose"].latency:
            self.assertAlmostEqual(lat, 0.02, places=6)
        self.assertEqual(self.data.timing["/robot1/cmd_vel"].latency, [])  # Twist has no header

    def test_figures_written_and_skipped(self):
        out = os.path.join(self.dir.name, "out")
        self.assertEqual(main([self.bag, "-o", out, "-q"]), 0)
        for name in ("trajectory", "errors", "commands", "behaviours", "timing_periods", "timing_latency"):
            path = os.path.join(out, f"run_{name}.png")
            with open(path, "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n", path)
            self.assertGreater(os.path.getsize(path), 5000, path)
        # No WheelState or JointState in this bag: the wheel figure is skipped.
        self.assertFalse(os.path.exists(os.path.join(out, "run_wheels.png")))


class OldBags(unittest.TestCase):
    def test_odometry_on_pose_still_read(self):
        # Bags recorded before `pose` became PoseWithCovarianceStamped hold
        # nav_msgs/Odometry there (SCARE's inputs, the DGPS localizer): the
        # estimate is read all the same, recognised by its type.
        with tempfile.TemporaryDirectory() as d:
            bag = os.path.join(d, "old.bag")
            with rosbag.Bag(bag, "w") as b:
                for k in range(11):
                    t = T0 + 0.1 * k
                    b.write("/robot1/ground_truth", odom(t, 0.1 * k, 0.0, 0.0), rospy.Time.from_sec(t))
                    b.write("/robot1/pose", odom(t, 0.1 * k, 0.5, 0.0), rospy.Time.from_sec(t))
            data = bag_data.read_bag(bag, progress=False)
        self.assertEqual(data.types["/robot1/pose"], "nav_msgs/Odometry")
        _, pos, _ = plots.pose_errors(data.estimates["/robot1/pose"], data.truth["robot1"])
        self.assertEqual(len(pos), 11)
        for e in pos:
            self.assertAlmostEqual(e, 0.5, places=9)


class Headings(unittest.TestCase):
    def test_wrapped_heading_error(self):
        truth, est = bag_data.Trajectory(), bag_data.Trajectory()
        truth.t, truth.x, truth.y, truth.yaw = [0.0, 1.0], [0.0, 2.0], [0.0, 0.0], [3.1, 3.1]
        est.t, est.x, est.y, est.yaw = [0.25, 5.0], [0.5, 0.0], [0.0, 0.0], [-3.1, 0.0]
        t, pos, head = plots.pose_errors(est, truth)
        # Only t = 0.25 lies inside the truth's span; the truth there is at
        # x = 0.5 (interpolated), so no position error; -3.1 - 3.1 = -6.2 rad
        # wraps to 2 pi - 6.2 = 0.0831853 rad.
        self.assertEqual(list(t), [0.25])
        self.assertAlmostEqual(pos[0], 0.0, places=12)
        self.assertAlmostEqual(head[0], 2 * math.pi - 6.2, places=12)


class Worlds(unittest.TestCase):
    def test_arc_expanded(self):
        w = load_world(os.path.join(HERE, "data", "arc_world.yaml"))
        self.assertEqual(w.name, "arc_world")
        self.assertEqual(len(w.walls), 1)
        self.assertEqual(len(w.lines), 5)  # one segment + 4 chords
        # First chord of the quarter arc: (1, 0) to (cos 22.5 deg, sin 22.5 deg) = (0.9238795, 0.3826834).
        x1, y1, x2, y2 = w.lines[1]
        self.assertAlmostEqual(x1, 1.0, places=12)
        self.assertAlmostEqual(y1, 0.0, places=12)
        self.assertAlmostEqual(x2, 0.9238795, places=7)
        self.assertAlmostEqual(y2, 0.3826834, places=7)
        self.assertEqual(len(w.posts), 1)
        self.assertEqual(len(w.movers[0][0]), 2)

    def test_colour_names_outside_matplotlib(self):
        # World files name colours for the camera ("bronze" in the museum).
        self.assertEqual(plots.colour("orange"), "orange")
        self.assertEqual(plots.colour("bronze"), "#cd7f32")
        self.assertEqual(plots.colour("no-such-colour"), "0.5")

    def test_bad_world_names_the_file(self):
        path = os.path.join(HERE, "data", "bad_world.yaml")
        with self.assertRaises(WorldError) as e:
            load_world(path)
        self.assertIn("bad_world.yaml: walls[0]: expected [x1, y1, x2, y2]", str(e.exception))


class CommandLine(unittest.TestCase):
    def run_tool(self, *args):
        return subprocess.run([sys.executable, SCRIPT] + list(args), capture_output=True, text=True, timeout=60)

    def test_help_exits_0(self):
        r = self.run_tool("--help")
        self.assertEqual(r.returncode, 0)
        self.assertIn("usage: plot_run", r.stdout)

    def test_bad_option_exits_2(self):
        r = self.run_tool("--no-such-option", "x.bag")
        self.assertEqual(r.returncode, 2)
        self.assertIn("unrecognized arguments: --no-such-option", r.stderr)

    def test_missing_bag_exits_2(self):
        r = self.run_tool("/nonexistent/run.bag")
        self.assertEqual(r.returncode, 2)
        self.assertIn("/nonexistent/run.bag: not a readable bag", r.stderr)

    def test_bad_world_exits_2(self):
        r = self.run_tool("--world", os.path.join(HERE, "data", "bad_world.yaml"), "x.bag")
        self.assertEqual(r.returncode, 2)
        self.assertIn("bad_world.yaml: walls[0]", r.stderr)

    def test_nothing_to_plot_exits_1(self):
        with tempfile.TemporaryDirectory() as d:
            bag = os.path.join(d, "chatter.bag")
            with rosbag.Bag(bag, "w") as b:
                b.write("/chatter", String(data="hi"), rospy.Time.from_sec(1.0))
            r = self.run_tool(bag, "-o", d)
            self.assertEqual(r.returncode, 1)
            self.assertIn("skipped", r.stderr)
            self.assertIn("nothing to plot", r.stderr)
            self.assertEqual([f for f in os.listdir(d) if f.endswith(".png")], [])


if __name__ == "__main__":
    rostest.rosrun("mrt_tools", "plot_offline", "__main__")
