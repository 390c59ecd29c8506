#!/usr/bin/env python3
"""Kill each stateless node of the Roby loop mid-route; roslaunch respawns it.

For brian, sonar_crisp and brian_cmd_vel in turn: once the robot drives
(wheel speed x radius > 0.15 m/s), the node is killed; the robot must stop
(speed < 0.05 m/s within 5 s of sim time: the simulator's 0.5 s command
timeout, as the AIRBoard's watchdog on the robot), then drive again once
roslaunch has respawned the node (within 30 s of sim time), and the route
must be completed (all 6 points). A stop can outlast a leg's timeout
(15 s + 4 s per metre, mrt_roby/config/tasks.yaml): the task then fails and
the sequencer re-plans from where the robot stands, as designed; so at most
one failed task per kill, each followed by a re-plan, and never `gave_up`.
"""
import sys
import time
import unittest

import rosnode
import rospy
import rostest
from mrt_msgs.msg import TaskStatus, WheelState


class Respawn(unittest.TestCase):
    def setUp(self):
        self.speed = 0.0
        self.events = []
        rospy.Subscriber('wheel_state', WheelState, self.on_wheels)
        rospy.Subscriber('task_status', TaskStatus, self.on_status)

    def on_wheels(self, m):
        # The simulator's wheel speeds (rad/s, P3-AT wheel radius 0.11 m):
        # the body speed of the faster side. (Debian ships no Python
        # nav_msgs, so not the ground truth's twist.)
        self.speed = 0.11 * max((abs(w) for w in m.speed), default=0.0)

    def on_status(self, m):
        if m.event:
            self.events.append(m.event)

    def wait_sim(self, pred, seconds):
        """Waits up to `seconds` of sim time (and 4x that of wall time)."""
        t_end = rospy.Time.now() + rospy.Duration(seconds)
        wall_deadline = time.time() + 4 * seconds + 10
        while not rospy.is_shutdown() and time.time() < wall_deadline:
            if pred():
                return True
            if rospy.Time.now() > t_end:
                return False
            time.sleep(0.02)
        return pred()

    def test_kill_and_respawn(self):
        ns = rospy.get_namespace().rstrip('/')
        for node in ('brian', 'sonar_crisp', 'brian_cmd_vel'):
            self.assertTrue(self.wait_sim(lambda: self.speed > 0.15, 60.0), 'not driving before killing ' + node)
            killed = rosnode.kill_nodes([ns + '/' + node])[0]
            self.assertEqual(killed, [ns + '/' + node], 'could not kill ' + node)
            stopped_at = rospy.Time.now()
            self.assertTrue(self.wait_sim(lambda: self.speed < 0.05, 5.0),
                            'the robot did not stop after %s died (%.2f m/s)' % (node, self.speed))
            rospy.loginfo('respawn: %s killed, stopped within %.2f s of sim time', node,
                          (rospy.Time.now() - stopped_at).to_sec())
            self.assertTrue(self.wait_sim(lambda: self.speed > 0.15, 30.0),
                            'the robot did not resume after %s was respawned' % node)
        self.assertTrue(self.wait_sim(lambda: 'route_completed' in self.events, 220.0), 'route not completed')
        failed = self.events.count('task_failed')
        self.assertLessEqual(failed, 3, 'tasks failed: %d (events %s)' % (failed, self.events))
        self.assertGreaterEqual(self.events.count('replan_requested'), failed, 'a failed task was not re-planned')
        self.assertNotIn('gave_up', self.events)
        rospy.loginfo('respawn: events %s', sorted(set(self.events)))


if __name__ == '__main__':
    rospy.init_node('roby_respawn_test')
    rostest.rosrun('mrt_roby', 'roby_respawn', Respawn, sys.argv)
