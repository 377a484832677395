#!/usr/bin/python3
"""Frame names as robot_state_publisher makes them (tf_prefix.test): with
`tf_prefix: robot1` set for the namespace robot1 (not for either node), the
node broadcasts the URDF body's frame as robot1/base_link (joined with '/',
as tf::resolve joins) and robot_state_publisher, fed by the body's own
/robot1/joint_states, hangs robot1/rotor_0 (a continuous joint, /tf) and
robot1/arm_0 (a fixed one, /tf_static) from that same frame; so rotor_0's
joint origin (0.17, 0.17, 0.05) m from base_link is at (0.17, 0.17, 1.05) m
in the world for the body at rest at (0, 0, 1)."""
import threading
import time
import unittest

import numpy as np
import rospy
import rostest
from sensor_msgs.msg import JointState
from tf2_msgs.msg import TFMessage

PKG = 'rigid_body_sim'
ROTORS = ['rotor_0_joint', 'rotor_1_joint', 'rotor_2_joint', 'rotor_3_joint']


def xyz(msg):
    return np.array([msg.x, msg.y, msg.z])


class TfPrefix(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('tf_prefix_test')
        cls.lock = threading.Lock()
        cls.transforms = {}  # (parent, child) -> the latest transform, /tf and /tf_static
        cls.joint_states = []
        for topic in ('/tf', '/tf_static'):
            rospy.Subscriber(topic, TFMessage, cls.on_tf, queue_size=100)
        rospy.Subscriber('/robot1/joint_states', JointState, cls.on_joints, queue_size=100)

    @classmethod
    def on_tf(cls, msg):
        with cls.lock:
            for t in msg.transforms:
                cls.transforms[(t.header.frame_id, t.child_frame_id)] = t

    @classmethod
    def on_joints(cls, msg):
        with cls.lock:
            cls.joint_states.append(msg)

    def transform(self, parent, child, timeout=20.0):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            with self.lock:
                found = self.transforms.get((parent, child))
            if found is not None:
                return found
            time.sleep(0.05)
        with self.lock:
            known = sorted(self.transforms)
        self.fail('no transform %s -> %s within %g s; seen: %s' % (parent, child, timeout, known))

    def test_the_node_and_robot_state_publisher_name_the_same_frames(self):
        self.assertFalse(rospy.has_param('/robot1/rigid_body_sim/tf_prefix'))
        base = self.transform('world', 'robot1/base_link')
        np.testing.assert_allclose(xyz(base.transform.translation), [0.0, 0.0, 1.0], atol=1e-12)
        rotor = self.transform('robot1/base_link', 'robot1/rotor_0')
        self.transform('robot1/base_link', 'robot1/arm_0')
        # The body is at rest with identity orientation: rotor_0 in the world.
        np.testing.assert_allclose(
            xyz(base.transform.translation) + xyz(rotor.transform.translation),
            [0.17, 0.17, 1.05], atol=1e-12)
        with self.lock:
            parents = set(parent for parent, _ in self.transforms)
            children = set(child for _, child in self.transforms)
        self.assertNotIn('robot1base_link', parents | children)
        self.assertNotIn('base_link', parents | children)

        with self.lock:
            joints = self.joint_states[-1] if self.joint_states else None
        self.assertIsNotNone(joints, 'nothing on /robot1/joint_states')
        self.assertEqual(sorted(joints.name), ROTORS)
        self.assertEqual(list(joints.position), [0.0] * 4)


if __name__ == '__main__':
    rostest.rosrun(PKG, 'tf_prefix_test', TfPrefix)
