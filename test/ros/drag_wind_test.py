#!/usr/bin/python3
"""Drag and wind through the node (doc/node.md, "Drag and wind";
drag_wind.test: two nodes, /rigid_body_sim and /twin, of drag_wind_scene.yaml,
started paused, rate 100 Hz):

- linear drag along body x: after n steps of ~step, v_x = v0 e^(-c t/m) to
  round-off (the drag's half-flows are exact; each rounds a few times per
  step, n * 16 eps of v0 bounds them) and v_y = v_z = 0 exactly, whatever
  the gusts along y and z do;
- ~wind after each ~step 1: the same series bit for bit in both nodes (the
  gusts are a function of their key and the step), x exactly the mean (no
  gust along x), y and z moving;
- wind_x reconfigured: from the next published state on, x is the new mean
  and y, z go on as the twin's;
- ~reset: the gusts restart at lattice step 0, so the series repeats.
"""
import math
import sys
import threading
import time
import unittest

import dynamic_reconfigure.client
import rospy
import rostest
from geometry_msgs.msg import Vector3Stamped
from rigid_body_sim.msg import BodyStateArray
from rigid_body_sim.srv import Step
from std_srvs.srv import Empty

PKG = 'rigid_body_sim'
NODES = ('/rigid_body_sim', '/twin')
DT = 0.01
MASS = 2.0
DRAG = 0.6
V0 = 1.5
EPS = sys.float_info.epsilon
SERIES = 50


class DragWind(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('drag_wind_test')
        cls.lock = threading.Lock()
        cls.winds = {node: [] for node in NODES}
        cls.bodies = []
        cls.subscribers = [
            rospy.Subscriber(node + '/wind', Vector3Stamped, cls.on_wind, callback_args=node,
                             queue_size=1000, tcp_nodelay=True) for node in NODES]
        cls.subscribers.append(rospy.Subscriber(NODES[0] + '/bodies', BodyStateArray,
                                                cls.on_bodies, queue_size=1000))
        cls.step = {}
        cls.reset = {}
        for node in NODES:
            rospy.wait_for_service(node + '/step', timeout=30.0)
            cls.step[node] = rospy.ServiceProxy(node + '/step', Step)
            cls.reset[node] = rospy.ServiceProxy(node + '/reset', Empty)

    @classmethod
    def on_wind(cls, msg, node):
        with cls.lock:
            cls.winds[node].append(msg)

    @classmethod
    def on_bodies(cls, msg):
        with cls.lock:
            cls.bodies.append(msg)

    @staticmethod
    def at(messages, sim_time):
        """The last of `messages` stamped `sim_time` (a service's seconds)."""
        found = [m for m in messages if abs(m.header.stamp.to_sec() - sim_time) < DT / 2]
        return found[-1] if found else None

    def wait_for(self, predicate, what, timeout=10.0):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            with self.lock:
                if predicate():
                    return
            time.sleep(0.005)
        self.fail(what)

    def step_once(self, node):
        """~step 1 on `node`; returns the ~wind message of the state reached."""
        with self.lock:
            count = len(self.winds[node])
        response = self.step[node](1)
        self.assertTrue(response.success, response.message)
        self.wait_for(lambda: self.at(self.winds[node][count:], response.sim_time) is not None,
                      'no ~wind from %s at %.3f s' % (node, response.sim_time))
        with self.lock:
            return self.at(self.winds[node][count:], response.sim_time).vector

    def series(self, node, length):
        return [self.step_once(node) for _ in range(length)]

    def assert_same_bits(self, a, b, axes='xyz'):
        self.assertEqual(len(a), len(b))
        for k, (u, v) in enumerate(zip(a, b)):
            for axis in axes:
                self.assertEqual(getattr(u, axis).hex(), getattr(v, axis).hex(),
                                 'step %d, %s' % (k + 1, axis))

    def test_1_linear_drag_is_the_exponential(self):
        for node in NODES:
            self.wait_for(lambda node=node: len(self.winds[node]) > 0,
                          'no ~wind from %s at t_0' % node, 30.0)
        with self.lock:
            count = len(self.bodies)
        steps = 100
        response = self.step[NODES[0]](steps)
        self.assertTrue(response.success, response.message)
        self.wait_for(lambda: self.at(self.bodies[count:], response.sim_time) is not None,
                      'no ~bodies at %.3f s' % response.sim_time)
        with self.lock:
            state = self.at(self.bodies[count:], response.sim_time)
        glider = [b for b in state.bodies if b.name == 'glider'][0]
        t = steps * DT
        expected = V0 * math.exp(-DRAG * t / MASS)
        self.assertAlmostEqual(glider.twist.linear.x, expected, delta=steps * 16 * EPS * V0)
        self.assertEqual(glider.twist.linear.y, 0.0)
        self.assertEqual(glider.twist.linear.z, 0.0)
        # The twin steps as far, so that both winds stand at the same step.
        self.assertTrue(self.step[NODES[1]](steps).success)

    def test_2_wind_series_repeats_in_two_nodes(self):
        first = self.series(NODES[0], SERIES)
        twin = self.series(NODES[1], SERIES)
        self.assert_same_bits(first, twin)
        for wind in first:
            self.assertEqual(wind.x, 0.0)  # no gust along x: the mean
        self.assertGreater(len(set(w.y for w in first)), SERIES // 2)
        self.assertGreater(len(set(w.z for w in first)), SERIES // 2)

    def test_3_reconfigured_wind_x_moves_the_mean_alone(self):
        client = dynamic_reconfigure.client.Client(NODES[0], timeout=30.0)
        client.update_configuration({'wind_x': 2.0})
        moved = self.series(NODES[0], SERIES)
        twin = self.series(NODES[1], SERIES)
        for wind in moved:
            self.assertEqual(wind.x, 2.0)
        self.assert_same_bits(moved, twin, axes='yz')

    def test_4_reset_restarts_the_gusts(self):
        for node in NODES:
            self.reset[node]()
        first = self.series(NODES[0], SERIES)
        twin = self.series(NODES[1], SERIES)
        self.assert_same_bits(first, twin, axes='yz')
        for node in NODES:
            self.reset[node]()
        again = self.series(NODES[0], SERIES)
        self.assert_same_bits(first, again)


if __name__ == '__main__':
    rostest.rosrun(PKG, 'drag_wind_test', DragWind)
