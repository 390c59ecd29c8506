"""Reads, in one pass over a bag of any MRT bringup, the series plot_run
draws. Topics are recognised by message type (and, for the ground truth, by
the name mrt_sim gives it), never by a fixed list, so a bag of any bringup
works and a missing topic only leaves its series empty.

Times are seconds since the start of the bag. Messages with a header are
placed at their stamp, the others (geometry_msgs/Twist) at the time the
recorder received them.
"""
import math
import struct
import sys
import time

import rosbag

ODOMETRY = "nav_msgs/Odometry"
POSE_TYPES = ("geometry_msgs/PoseWithCovarianceStamped", "geometry_msgs/PoseStamped")
PATH = "nav_msgs/Path"
TWIST = "geometry_msgs/Twist"
TWIST_STAMPED = "geometry_msgs/TwistStamped"
BRIAN_COMMANDS = "mrt_msgs/CommandArray"
BRIAN_INTROSPECTION = "mrt_msgs/BrianIntrospection"
WHEEL_STATE = "mrt_msgs/WheelState"
WHEEL_COMMAND = "mrt_msgs/WheelCommand"
JOINT_STATE = "sensor_msgs/JointState"
CONTENT_TYPES = (ODOMETRY, PATH, TWIST, TWIST_STAMPED, BRIAN_COMMANDS, BRIAN_INTROSPECTION,
                 WHEEL_STATE, WHEEL_COMMAND, JOINT_STATE) + POSE_TYPES


def yaw_of(q):
    """Heading (rad) of a planar quaternion."""
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def robot_of(topic):
    """The robot namespace of a topic ("/robot1/pose" -> "robot1"); "" when
    the topic is global."""
    parts = topic.strip("/").split("/")
    return parts[0] if len(parts) > 1 else ""


class Trajectory:
    """A planar pose over time."""

    def __init__(self, frame=""):
        self.frame = frame
        self.t, self.x, self.y, self.yaw = [], [], [], []

    def add(self, t, pose):
        self.t.append(t)
        self.x.append(pose.position.x)
        self.y.append(pose.position.y)
        self.yaw.append(yaw_of(pose.orientation))


class Channels:
    """Named scalar series over time (e.g. "linear.x", "wheel 0")."""

    def __init__(self):
        self.series = {}

    def add(self, name, t, value):
        ts, vs = self.series.setdefault(name, ([], []))
        ts.append(t)
        vs.append(value)


class Behaviour:
    """One Mr. BRIAN behaviour over time: CANDO, Composer weight, active."""

    def __init__(self, level):
        self.level = level
        self.t, self.cando, self.weight, self.active = [], [], [], []


class Timing:
    """Receive times and header-stamp latencies of one topic."""

    def __init__(self):
        self.received = []
        self.latency = []


class RunData:
    """Every series of one bag."""

    def __init__(self):
        self.start = 0.0
        self.duration = 0.0
        self.truth = {}        # robot -> Trajectory (.../ground_truth)
        self.estimates = {}    # topic -> Trajectory (odometry and pose topics)
        self.paths = {}        # topic -> ([x], [y]) of the last nav_msgs/Path
        self.twists = {}       # topic -> Channels
        self.brian_commands = {}  # topic -> Channels (rule-base units)
        self.wheel_commands = {}  # topic -> Channels
        self.wheel_speeds = {}    # topic -> Channels (measured and set-point, rad/s)
        self.behaviours = {}   # topic -> {name: Behaviour}
        self.timing = {}       # topic -> Timing
        self.types = {}        # topic -> message type


class Progress:
    """Percentage with ETA on stderr, only when stderr is a terminal."""

    def __init__(self, what, total, stream=sys.stderr):
        self.what, self.total, self.stream = what, max(total, 1), stream
        self.enabled = stream.isatty()
        self.begin = self.last = time.monotonic()

    def update(self, done):
        now = time.monotonic()
        if not self.enabled or now - self.last < 0.2:
            return
        self.last = now
        fraction = done / self.total
        eta = (now - self.begin) * (1.0 - fraction) / fraction if fraction > 0 else 0.0
        self.stream.write(f"\r{self.what}: {100.0 * fraction:5.1f}% ({done}/{self.total}), "
                          f"ETA {eta:.0f} s  ")
        self.stream.flush()

    def finish(self):
        if self.enabled:
            self.stream.write(f"\r{self.what}: 100.0% ({self.total}/{self.total}) in "
                              f"{time.monotonic() - self.begin:.1f} s      \n")
            self.stream.flush()


def _read_twist(data, topic, t, twist):
    ch = data.twists.setdefault(topic, Channels())
    ch.add("linear.x (m/s)", t, twist.linear.x)
    ch.add("linear.y (m/s)", t, twist.linear.y)
    ch.add("angular.z (rad/s)", t, twist.angular.z)


def _read_introspection(data, topic, t, msg):
    table = data.behaviours.setdefault(topic, {})
    for b in msg.behaviors:
        entry = table.setdefault(b.name, Behaviour(b.level))
        entry.t.append(t)
        entry.cando.append(b.cando)
        entry.weight.append(b.weight)
        entry.active.append(bool(b.active))


def _read_content(data, topic, kind, t, msg):
    """Adds one deserialized message to its series; t is already chosen."""
    if kind == ODOMETRY:
        if topic.endswith("/ground_truth"):
            data.truth.setdefault(robot_of(topic), Trajectory(msg.header.frame_id)).add(t, msg.pose.pose)
        else:
            data.estimates.setdefault(topic, Trajectory(msg.header.frame_id)).add(t, msg.pose.pose)
    elif kind == POSE_TYPES[0]:
        data.estimates.setdefault(topic, Trajectory(msg.header.frame_id)).add(t, msg.pose.pose)
    elif kind == POSE_TYPES[1]:
        data.estimates.setdefault(topic, Trajectory(msg.header.frame_id)).add(t, msg.pose)
    elif kind == PATH:
        if not topic.endswith("ground_truth_path"):
            data.paths[topic] = ([p.pose.position.x for p in msg.poses], [p.pose.position.y for p in msg.poses])
    elif kind == TWIST:
        _read_twist(data, topic, t, msg)
    elif kind == TWIST_STAMPED:
        _read_twist(data, topic, t, msg.twist)
    elif kind == BRIAN_COMMANDS:
        ch = data.brian_commands.setdefault(topic, Channels())
        for c in msg.commands:
            ch.add(c.name, t, c.value)
    elif kind == BRIAN_INTROSPECTION:
        _read_introspection(data, topic, t, msg)
    elif kind == WHEEL_COMMAND:
        ch = data.wheel_commands.setdefault(topic, Channels())
        values = msg.speed if msg.mode == 0 else msg.duty
        unit = "rad/s" if msg.mode == 0 else "duty"
        for i, v in enumerate(values):
            ch.add(f"wheel {i} ({unit})", t, v)
    elif kind == WHEEL_STATE:
        ch = data.wheel_speeds.setdefault(topic, Channels())
        for i, v in enumerate(msg.speed):
            ch.add(f"wheel {i} measured", t, v)
        for i, v in enumerate(msg.setpoint):
            ch.add(f"wheel {i} set-point", t, v)
    elif kind == JOINT_STATE:
        ch = data.wheel_speeds.setdefault(topic, Channels())
        for name, v in zip(msg.name, msg.velocity):
            ch.add(name, t, v)


def read_bag(path, progress=True):
    """Reads the bag at path into a RunData. Raises rosbag.ROSBagException
    (or OSError) when the file is not a readable bag."""
    data = RunData()
    with rosbag.Bag(path) as bag:
        info = bag.get_type_and_topic_info()
        data.types = {topic: t.msg_type for topic, t in info.topics.items()}
        total = sum(t.message_count for t in info.topics.values())
        if total == 0:
            return data
        data.start = bag.get_start_time()
        data.duration = bag.get_end_time() - data.start
        bar = Progress("plot_run: reading " + path, total) if progress else None
        for n, (topic, raw, received) in enumerate(bag.read_messages(raw=True)):
            kind, payload, pytype = raw[0], raw[1], raw[4]
            rt = received.to_sec() - data.start
            timing = data.timing.setdefault(topic, Timing())
            timing.received.append(rt)
            stamp = None
            if getattr(pytype, "_has_header", False) and len(payload) >= 12:
                secs, nsecs = struct.unpack_from("<II", payload, 4)
                if secs or nsecs:
                    stamp = secs + 1e-9 * nsecs - data.start
                    timing.latency.append(rt - stamp)
            if kind in CONTENT_TYPES:
                msg = pytype()
                msg.deserialize(payload)
                _read_content(data, topic, kind, stamp if stamp is not None else rt, msg)
            if bar is not None and n % 500 == 0:
                bar.update(n)
        if bar is not None:
            bar.finish()
    return data
