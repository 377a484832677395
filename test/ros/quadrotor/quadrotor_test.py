#!/usr/bin/python3
"""The quadrotor example as a downstream test: launch/quadrotor.launch's
controller (src/examples/quadrotor_controller.cpp, on the C++ client's
LockstepController, answering with body wrenches) takes the URDF quadrotor off from rest
under gravity in lockstep with the simulator (quadrotor/run.launch). After
5 s of simulated time base_link's origin (its odometry) is within 1 cm of
(0, 0, 1) m, its yaw within 1 mrad of 90 degrees and its z axis within
1 mrad of the vertical; two runs, one on a quiet machine and one with every
core kept busy by processes this test starts and stops, reach bit-identical
states at every cycle (equal state hashes), with no lockstep timeout.

This test is the run's second lockstep controller: it answers each cycle with
no wrench and records the state hash, so it sees every cycle from t_0 on."""
import math
import os
import subprocess
import sys
import threading
import unittest

import numpy as np
import rospy
import rostest
from nav_msgs.msg import Odometry
from rigid_body_sim.testing import LockstepController, SimClient, state_hash

CYCLES = 500  # 5 s of simulation at publish_rate 100 Hz
TARGET_POSITION = np.array([0.0, 0.0, 1.0])
TARGET_YAW = math.pi / 2.0
LAUNCH = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'run.launch')


def yaw_and_tilt(q):
    """The yaw [rad] of the (x, y, z, w) quaternion q and the angle [rad]
    between its z axis and the world's."""
    x, y, z, w = q
    yaw = math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))
    return yaw, math.acos(min(1.0, 1.0 - 2.0 * (x * x + y * y)))


class Run(object):
    """One flight in namespace `ns`, recorded cycle by cycle."""

    def __init__(self, ns):
        self.ns = ns
        self.hashes = []
        self.last_stamp = None
        self.done = threading.Event()
        self.simulator = '/%s/rigid_body_sim' % ns
        self._odom = {}
        self._odom_lock = threading.Condition()
        self._odom_sub = rospy.Subscriber(self.simulator + '/base_link/odom', Odometry, self._on_odom,
                                          queue_size=100)
        self.observer = LockstepController(self.record, self.simulator)
        self.launch = subprocess.Popen(
            ['roslaunch', LAUNCH, 'ns:=' + ns, 'observer:=' + rospy.get_name()],
            stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)

    def _on_odom(self, msg):
        with self._odom_lock:
            self._odom[msg.header.stamp.to_nsec()] = msg.pose.pose
            self._odom_lock.notify_all()

    def record(self, states, stamp):
        if len(self.hashes) <= CYCLES:
            self.hashes.append(state_hash(states))
            self.last_stamp = stamp.to_nsec()
        if len(self.hashes) > CYCLES:
            self.done.set()
        return []

    def last_pose(self):
        """base_link's pose at the last recorded cycle."""
        with self._odom_lock:
            if not self._odom_lock.wait_for(lambda: self.last_stamp in self._odom, 10.0):
                raise RuntimeError('%s: no odometry stamped %d ns' % (self.ns, self.last_stamp))
            return self._odom[self.last_stamp]

    def finish(self):
        diagnostics = SimClient(self.simulator).diagnostics(timeout=15.0)
        self.observer.stop()
        self._odom_sub.unregister()
        self.launch.send_signal(subprocess.signal.SIGINT)
        self.launch.wait(timeout=30.0)
        return diagnostics


class Quadrotor(unittest.TestCase):
    def fly(self, ns):
        run = Run(ns)
        self.assertTrue(run.done.wait(timeout=120.0), '%s: fewer than %d cycles' % (ns, CYCLES))
        pose = run.last_pose()
        diagnostics = run.finish()
        self.assertEqual(diagnostics['lockstep_timeouts'], '0', ns)
        p, q = pose.position, pose.orientation
        position_error = np.linalg.norm(np.array([p.x, p.y, p.z]) - TARGET_POSITION)
        yaw, tilt = yaw_and_tilt([q.x, q.y, q.z, q.w])
        sys.stderr.write('%s: after %d cycles position error %.3g m, yaw error %.3g rad, tilt %.3g rad, '
                         'state hash %s\n' % (ns, CYCLES, position_error, yaw - TARGET_YAW, tilt, run.hashes[-1]))
        self.assertLess(position_error, 1e-2, ns)
        self.assertLess(abs(yaw - TARGET_YAW), 1e-3, ns)
        self.assertLess(tilt, 1e-3, ns)
        return run.hashes

    def test_take_off_hover_and_turn_bit_identical_under_load(self):
        quiet = self.fly('quiet')
        busy = [subprocess.Popen([sys.executable, '-c', 'while True: pass'])
                for _ in range(os.cpu_count() or 2)]
        try:
            loaded = self.fly('loaded')
        finally:
            for process in busy:
                process.kill()
                process.wait()
        self.assertEqual(len(quiet), CYCLES + 1)
        self.assertEqual(quiet, loaded)


if __name__ == '__main__':
    rospy.init_node('quadrotor_test')
    rostest.rosrun('rigid_body_sim', 'quadrotor', Quadrotor, sys.argv)
