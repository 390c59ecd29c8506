#!/usr/bin/python3
"""team_markers: each robot's SCARE job and role, drawn where it thinks it is.

For every robot of ~robots (list of namespaces) subscribes <robot>/scare/job
(std_msgs/String, the slot: "BringBall", "PassageToMate.passer", "" waiting)
and <robot>/pose (geometry_msgs/PoseWithCovarianceStamped, MUREA's estimate)
and publishes `team_markers` (visualization_msgs/MarkerArray, ~frame) at
~rate Hz: a text "robotN / Job / role" above the estimated pose and a
cylinder around it in the job's colour (grey while waiting or not localized).
"""
import colorsys
import zlib

import rospy
from geometry_msgs.msg import PoseWithCovarianceStamped
from std_msgs.msg import String
from visualization_msgs.msg import Marker, MarkerArray


def job_color(job):
    """A stable colour per activity name (crc32 of the name as the hue)."""
    if not job:
        return (0.6, 0.6, 0.6)
    return colorsys.hsv_to_rgb((zlib.crc32(job.encode()) % 360) / 360.0, 0.8, 1.0)


class TeamMarkers:
    def __init__(self):
        self.robots = rospy.get_param("~robots", ["robot1", "robot2", "robot3", "robot4"])
        self.frame = rospy.get_param("~frame", "map")
        rate = float(rospy.get_param("~rate", 5.0))
        if not rate > 0.0:
            raise ValueError("~rate: expected a number > 0, got %r" % rate)
        self.jobs = {r: "" for r in self.robots}
        self.poses = {}
        for r in self.robots:
            rospy.Subscriber("/%s/scare/job" % r, String, self.on_job, r, queue_size=5)
            rospy.Subscriber("/%s/pose" % r, PoseWithCovarianceStamped, self.on_pose, r, queue_size=5)
        self.pub = rospy.Publisher("team_markers", MarkerArray, queue_size=2)
        rospy.Timer(rospy.Duration(1.0 / rate), self.publish)

    def on_job(self, msg, robot):
        self.jobs[robot] = msg.data

    def on_pose(self, msg, robot):
        self.poses[robot] = msg.pose.pose.position

    def publish(self, _event):
        out = MarkerArray()
        for i, r in enumerate(self.robots):
            p = self.poses.get(r)
            if p is None:
                continue
            job, _, role = self.jobs[r].partition(".")
            color = job_color(job)
            text = Marker()
            text.header.frame_id = self.frame
            text.header.stamp = rospy.Time.now()
            text.ns, text.id = "job", i
            text.type, text.action = Marker.TEXT_VIEW_FACING, Marker.ADD
            text.pose.position.x, text.pose.position.y, text.pose.position.z = p.x, p.y + 0.6, 1.0
            text.pose.orientation.w = 1.0
            text.scale.z = 0.35
            text.color.r, text.color.g, text.color.b, text.color.a = color[0], color[1], color[2], 1.0
            text.text = "%s: %s%s" % (r, job or "(waiting)", " / " + role if role else "")
            ring = Marker()
            ring.header = text.header
            ring.ns, ring.id = "estimate", i
            ring.type, ring.action = Marker.CYLINDER, Marker.ADD
            ring.pose.position.x, ring.pose.position.y, ring.pose.position.z = p.x, p.y, 0.02
            ring.pose.orientation.w = 1.0
            ring.scale.x = ring.scale.y = 0.7
            ring.scale.z = 0.03
            ring.color.r, ring.color.g, ring.color.b, ring.color.a = color[0], color[1], color[2], 0.6
            out.markers += [text, ring]
        self.pub.publish(out)


if __name__ == "__main__":
    rospy.init_node("team_markers")
    try:
        TeamMarkers()
    except ValueError as e:
        rospy.logfatal(str(e))
        raise SystemExit(1)
    rospy.spin()
