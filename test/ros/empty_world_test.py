#!/usr/bin/python3
"""An empty world (doc/node.md, "An empty world"; empty_world.test, no
`bodies` in the scene):

- the node starts and steps: ~bodies arrives with zero entries and stamps
  that advance, and /clock advances;
- ~spawn_body takes an `inertial` body, which then appears in ~bodies;
- paused, N steps of dt under gravity g take it from rest at z0 to
  z0 - g t^2 / 2 with velocity -g t, t = N dt, to round-off (the splitting
  integrators are exact for a constant force); x, y and the orientation stay;
- a ParticleWrench for it is rejected as `unknown_particle` and changes
  nothing; ~particles shows its COM as its one point.
"""
import threading
import time
import unittest

import numpy as np
import rospy
import rostest
from rigid_body_sim.msg import BodyStateArray
from rigid_body_sim.testing import SimClient, particle_wrench
from rosgraph_msgs.msg import Clock
from visualization_msgs.msg import MarkerArray

PKG = 'rigid_body_sim'
NODE = '/rigid_body_sim'
G = 9.81
Z0 = 10.0
STEPS = 200
EPS = np.finfo(float).eps
PUCK = """
name: puck
inertial:
  mass: 1.5
  origin: {xyz: [0.0, 0.0, 0.02], rpy: [0.0, 0.0, 0.3]}
  inertia: {ixx: 0.03, ixy: 0.001, ixz: 0.0, iyy: 0.03, iyz: 0.0, izz: 0.05}
position: [1.0, -2.0, %r]
""" % Z0


class EmptyWorld(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('empty_world_test')
        cls.lock = threading.Lock()
        cls.bodies = []
        cls.clocks = []
        cls.markers = []
        rospy.Subscriber(NODE + '/bodies', BodyStateArray, cls.on(cls.bodies), queue_size=100)
        rospy.Subscriber('/clock', Clock, cls.on(cls.clocks), queue_size=100)
        rospy.Subscriber(NODE + '/particles', MarkerArray, cls.on(cls.markers), queue_size=100)
        cls.sim = SimClient(NODE)

    @classmethod
    def on(cls, messages):
        def callback(msg):
            with cls.lock:
                messages.append(msg)
        return callback

    def wait_for(self, messages, predicate, what, timeout=10.0):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            with self.lock:
                found = [m for m in messages if predicate(m)]
            if found:
                return found
            time.sleep(0.02)
        self.fail('no %s within %g s' % (what, timeout))

    def test_empty_world_steps_and_takes_an_inertial_body(self):
        # Running with no bodies: ~bodies empty, stamps and /clock advance.
        self.wait_for(self.bodies, lambda m: True, 'message on ~bodies')
        time.sleep(0.3)
        with self.lock:
            empty = list(self.bodies)
        self.assertGreaterEqual(len(empty), 3)
        self.assertTrue(all(len(m.bodies) == 0 for m in empty))
        stamps = [m.header.stamp.to_nsec() for m in empty]
        self.assertTrue(all(b > a for a, b in zip(stamps, stamps[1:])), stamps)
        self.wait_for(self.clocks, lambda m: True, '/clock')
        time.sleep(0.2)
        with self.lock:
            clocks = [m.clock.to_nsec() for m in self.clocks]
        self.assertGreaterEqual(len(clocks), 2)
        self.assertGreater(clocks[-1], clocks[0])

        # A spawned inertial body, paused: it falls as F/M says.
        self.sim.pause()
        self.sim.spawn(PUCK)
        before = self.sim.step(1)  # t = dt: z0 - g dt^2 / 2
        self.assertEqual(list(before.states), ['puck'])
        rejected = self.sim.step_with_wrenches(
            [particle_wrench('puck', 0, force=(0.0, 0.0, 100.0))], STEPS - 1)
        self.assertIn('unknown_particle', rejected.message)
        t = STEPS * self.sim.dt
        puck = rejected.states['puck']
        tolerance = 8 * STEPS * EPS * Z0
        np.testing.assert_allclose(puck.position, [1.0, -2.0, Z0 - 0.5 * G * t * t],
                                   rtol=0, atol=tolerance)
        np.testing.assert_allclose(puck.linear_velocity, [0.0, 0.0, -G * t],
                                   rtol=0, atol=8 * STEPS * EPS * G * t)
        np.testing.assert_allclose(puck.linear_momentum, [0.0, 0.0, -1.5 * G * t],
                                   rtol=0, atol=8 * STEPS * EPS * 1.5 * G * t)
        np.testing.assert_allclose(puck.angular_velocity, [0.0, 0.0, 0.0], atol=1e-15)
        np.testing.assert_allclose(puck.orientation, [0.0, 0.0, 0.0, 1.0], atol=1e-15)

        # ~bodies carries it, and ~particles shows its COM as its one point.
        stamp = rejected.stamp.to_nsec()
        published = self.wait_for(
            self.bodies, lambda m: m.header.stamp.to_nsec() == stamp, '~bodies of the step')[-1]
        self.assertEqual([b.name for b in published.bodies], ['puck'])
        markers = self.wait_for(
            self.markers, lambda m: any(k.header.stamp.to_nsec() == stamp and k.points
                                        for k in m.markers), '~particles of the step')[-1]
        points = [k.points for k in markers.markers if k.points]
        self.assertEqual(len(points), 1)
        self.assertEqual(len(points[0]), 1)
        point = points[0][0]
        np.testing.assert_array_equal([point.x, point.y, point.z], puck.position)

        # Running again, it keeps falling.
        self.sim.resume()
        time.sleep(0.3)
        self.assertLess(self.sim.state('puck').position[2], puck.position[2])


if __name__ == '__main__':
    rostest.rosrun(PKG, 'empty_world_test', EmptyWorld)
