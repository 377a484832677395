#!/usr/bin/python3
"""~start_paused (doc/node.md, "Starting paused"; start_paused.test:
launch/quadrotor.launch paused:=true publish_clock:=true, no controller):

- the node sends its initial state once, stamped t_0, on /clock and ~bodies,
  and then nothing for a second: it does not step;
- a subscriber that connects a second later receives /tf, the body's pose,
  twist and odom, ~particles and ~joint_states, each once, stamped t_0, with
  the state ~bodies carried; the IMU and the applied wrench, which need a
  step, send nothing;
- ~step 1 reaches t_0 + dt and publishes it, /clock first among its stamp.
"""
import threading
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import PoseStamped, TwistStamped, WrenchStamped
from nav_msgs.msg import Odometry
from rigid_body_sim.msg import BodyStateArray
from rigid_body_sim.srv import Step
from rigid_body_sim.testing import wait_until
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import Imu, JointState
from tf2_msgs.msg import TFMessage
from visualization_msgs.msg import MarkerArray

PKG = 'rigid_body_sim'
NODE = '/rigid_body_sim'
BODY = 'base_link'
DT_NS = 1000000  # quadrotor.launch: rate 1000 Hz
QUIET_S = 1.0    # wall seconds in which a paused node sends nothing


def stamp_of(topic, msg):
    if topic == 'clock':
        return msg.clock.to_nsec()
    if topic == 'tf':
        return msg.transforms[0].header.stamp.to_nsec()
    if topic == 'particles':
        return msg.markers[0].header.stamp.to_nsec()
    return msg.header.stamp.to_nsec()


class StartPaused(unittest.TestCase):
    t0 = None  # ns, from the first /clock
    @classmethod
    def setUpClass(cls):
        rospy.init_node('start_paused_test')
        cls.lock = threading.Lock()
        cls.messages = {}
        cls.subscribers = []
        # Subscribed at once: they connect while the node waits at t_0, or
        # just before it does.
        cls.subscribe('clock', '/clock', Clock)
        cls.subscribe('bodies', NODE + '/bodies', BodyStateArray)

    @classmethod
    def subscribe(cls, topic, name, msg_type):
        cls.messages[topic] = []

        def callback(msg):
            # /tf: the node's transform only (robot_state_publisher's too go there).
            if topic == 'tf' and not [t for t in msg.transforms if t.child_frame_id == BODY]:
                return
            with cls.lock:
                cls.messages[topic].append(msg)
        cls.subscribers.append(rospy.Subscriber(name, msg_type, callback, queue_size=1000,
                                                tcp_nodelay=True))

    def received(self, topic):
        with self.lock:
            return list(self.messages[topic])

    def test_1_sends_t0_once_and_waits_there(self):
        for topic in ('clock', 'bodies'):
            wait_until(lambda: self.received(topic), 30.0, 'no %s at t_0' % topic)
        time.sleep(QUIET_S)
        StartPaused.t0 = stamp_of('clock', self.received('clock')[0])
        self.assertEqual(self.t0 % DT_NS, 0, 't_0 off the step lattice')
        for topic in ('clock', 'bodies'):
            self.assertEqual([stamp_of(topic, m) for m in self.received(topic)], [self.t0],
                             '%s: not one message stamped t_0' % topic)

    def test_2_late_subscriber_receives_t0(self):
        time.sleep(QUIET_S)  # well after t_0 was published
        late = {'tf': ('/tf', TFMessage), 'pose': (NODE + '/%s/pose' % BODY, PoseStamped),
                'twist': (NODE + '/%s/twist' % BODY, TwistStamped),
                'odom': (NODE + '/%s/odom' % BODY, Odometry),
                'particles': (NODE + '/particles', MarkerArray),
                'joint_states': (NODE + '/joint_states', JointState),
                'imu': (NODE + '/%s/imu' % BODY, Imu),
                'applied_wrench': (NODE + '/%s/applied_wrench' % BODY, WrenchStamped)}
        for topic, (name, msg_type) in late.items():
            self.subscribe(topic, name, msg_type)
        sent = ('tf', 'pose', 'twist', 'odom', 'particles', 'joint_states')
        for topic in sent:
            wait_until(lambda: self.received(topic), 10.0,
                          '%s: nothing for a subscriber that connected at t_0' % topic)
        time.sleep(QUIET_S)
        for topic in sent:
            self.assertEqual([stamp_of(topic, m) for m in self.received(topic)], [self.t0],
                             '%s: not one message stamped t_0' % topic)
        for topic in ('imu', 'applied_wrench'):
            self.assertEqual(self.received(topic), [], '%s before any step' % topic)
        pose = self.received('pose')[0].pose
        self.assertEqual(self.received('odom')[0].pose.pose, pose)
        transform = [t for t in self.received('tf')[0].transforms if t.child_frame_id == BODY][0]
        self.assertEqual([transform.transform.translation.x, transform.transform.translation.y,
                          transform.transform.translation.z],
                         [pose.position.x, pose.position.y, pose.position.z])
        self.assertEqual(self.received('twist')[0].twist, self.received('bodies')[0].bodies[0].twist)

    def test_3_step_advances(self):
        step = rospy.ServiceProxy(NODE + '/step', Step)
        step.wait_for_service(timeout=30.0)
        response = step(1)
        self.assertTrue(response.success, response.message)
        t1 = self.t0 + DT_NS
        # sim_time is float64 seconds: ns to a few hundred (an ulp at 1.7e9 s).
        self.assertLess(abs(rospy.Time.from_sec(response.sim_time).to_nsec() - t1), 1000)
        for topic in ('clock', 'bodies', 'pose', 'odom', 'imu', 'applied_wrench'):
            wait_until(lambda: self.received(topic) and
                          stamp_of(topic, self.received(topic)[-1]) == t1, 5.0,
                          '%s: nothing stamped t_0 + dt after ~step 1' % topic)
        self.assertEqual([stamp_of('clock', m) for m in self.received('clock')], [self.t0, t1])


if __name__ == '__main__':
    rostest.rosrun(PKG, 'start_paused', StartPaused)
