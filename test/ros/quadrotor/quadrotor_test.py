#!/usr/bin/python3
"""The quadrotor example as a downstream test: launch/quadrotor.launch's
controller (src/examples/quadrotor_controller.h, on the C++ client's
LockstepController, commanding the four rotors through its mixer) flies the
URDF quadrotor in lockstep with the simulator (quadrotor/run.launch), its
rotors thrusters with a 20 ms lag and 8.55 N at most, its drag relative to
the wind.

- From rest to a hover at (0, 0, 1) m: after 5 s of simulated time
  base_link's origin (its odometry) is within 1 cm of the setpoint, its yaw
  within 1 mrad of 90 degrees and its z axis within 1 mrad of the vertical;
  three runs, one on a quiet machine and two with every core kept busy by
  processes this test starts and stops, reach bit-identical states at every
  cycle (equal state hashes), with no lockstep timeout: node and controller
  as programs over TCP (quiet, then loaded), and as nodelets of one manager
  (in_process:=true, loaded), the controller answering on the node's
  stepping thread.
- The same in gusts of 1 m/s standard deviation on each axis: from 5 s to
  25 s base_link's origin stays within 10 cm of the setpoint.
- A climb to 20 m asks more than the rotors give: the mixer clips, and
  actuator_states shows every rotor's thrust at 8.55 N from 0.8 s (40 motor
  time constants) to 1.4 s, when the climb is still at full thrust, and
  never above.

This test is each run's second lockstep controller: it answers each cycle
with no wrench and records the state hash, so it sees every cycle from t_0
on."""
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
from sensor_msgs.msg import JointState
from rigid_body_sim.testing import LockstepController, SimClient, state_hash

CYCLE_S = 0.01  # publish_rate 100 Hz
CYCLES = 500  # 5 s of simulation
TARGET_POSITION = np.array([0.0, 0.0, 1.0])
MAX_THRUST_N = 8.55  # config/quadrotor.yaml
TARGET_YAW = math.pi / 2.0
LAUNCH = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'run.launch')
SANITIZED = 'ASAN_OPTIONS' in os.environ


def yaw_and_tilt(q):
    """The yaw [rad] of the (x, y, z, w) quaternion q and the angle [rad]
    between its z axis and the world's."""
    x, y, z, w = q
    yaw = math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))
    return yaw, math.acos(min(1.0, 1.0 - 2.0 * (x * x + y * y)))


class Run(object):
    """One flight of `cycles` cycles in namespace `ns`, recorded cycle by
    cycle; `args` go to run.launch."""

    def __init__(self, ns, cycles=CYCLES, **args):
        self.ns = ns
        self.cycles = cycles
        self.hashes = []
        self.last_stamp = None
        self.done = threading.Event()
        self.simulator = '/%s/rigid_body_sim' % ns
        self._lock = threading.Condition()
        self._odom = {}
        self.thrusts = {}  # stamp [ns] -> the rotors' thrusts [N]
        self._subscribers = [
            rospy.Subscriber(self.simulator + '/base_link/odom', Odometry, self._on_odom,
                             queue_size=1000),
            rospy.Subscriber(self.simulator + '/base_link/actuator_states', JointState,
                             self._on_thrusts, queue_size=1000)]
        self.observer = LockstepController(self.record, self.simulator)
        self.launch = subprocess.Popen(
            ['roslaunch', LAUNCH, 'ns:=' + ns, 'observer:=' + rospy.get_name()] +
            ['%s:=%s' % item for item in args.items()],
            stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)

    def _on_odom(self, msg):
        with self._lock:
            self._odom[msg.header.stamp.to_nsec()] = msg.pose.pose
            self._lock.notify_all()

    def _on_thrusts(self, msg):
        with self._lock:
            self.thrusts[msg.header.stamp.to_nsec()] = list(msg.effort)

    def record(self, states, stamp):
        if len(self.hashes) <= self.cycles:
            self.hashes.append(state_hash(states))
            self.last_stamp = stamp.to_nsec()
        if len(self.hashes) > self.cycles:
            self.done.set()
        return []

    def poses(self):
        """base_link's pose at every recorded cycle, by stamp [ns]."""
        with self._lock:
            if not self._lock.wait_for(lambda: self.last_stamp in self._odom, 10.0):
                raise RuntimeError('%s: no odometry stamped %d ns' % (self.ns, self.last_stamp))
            return dict(self._odom)

    def last_pose(self):
        """base_link's pose at the last recorded cycle."""
        return self.poses()[self.last_stamp]

    def finish(self):
        diagnostics = SimClient(self.simulator).diagnostics(timeout=15.0)
        self.observer.stop()
        for subscriber in self._subscribers:
            subscriber.unregister()
        self.launch.send_signal(subprocess.signal.SIGINT)
        self.launch.wait(timeout=30.0)
        return diagnostics


def position_error(pose):
    p = pose.position
    return np.linalg.norm(np.array([p.x, p.y, p.z]) - TARGET_POSITION)


class Quadrotor(unittest.TestCase):
    def run_to_end(self, ns, cycles=CYCLES, **args):
        run = Run(ns, cycles, **args)
        self.assertTrue(run.done.wait(timeout=120.0), '%s: fewer than %d cycles' % (ns, cycles))
        poses = run.poses()
        diagnostics = run.finish()
        self.assertEqual(diagnostics['lockstep_timeouts'], '0', ns)
        return run, poses

    def fly(self, ns, **args):
        run, poses = self.run_to_end(ns, **args)
        pose = poses[run.last_stamp]
        q = pose.orientation
        yaw, tilt = yaw_and_tilt([q.x, q.y, q.z, q.w])
        sys.stderr.write('%s: after %d cycles position error %.3g m, yaw error %.3g rad, tilt %.3g rad, '
                         'state hash %s\n' % (ns, CYCLES, position_error(pose), yaw - TARGET_YAW, tilt,
                                               run.hashes[-1]))
        self.assertLess(position_error(pose), 1e-2, ns)
        self.assertLess(abs(yaw - TARGET_YAW), 1e-3, ns)
        self.assertLess(tilt, 1e-3, ns)
        return run.hashes

    def test_take_off_hover_and_turn_bit_identical_under_load(self):
        quiet = self.fly('quiet')
        busy = [subprocess.Popen([sys.executable, '-c', 'while True: pass'])
                for _ in range(os.cpu_count() or 2)]
        try:
            loaded = self.fly('loaded')
            # Under the sanitizers (ASAN_OPTIONS, scripts/sanitizers.sh) the
            # nodelet manager, Debian's uninstrumented program, cannot load
            # the instrumented nodelets: there the programs fly alone.
            in_process = quiet if SANITIZED else self.fly('loaded_nodelets', in_process='true')
        finally:
            for process in busy:
                process.kill()
                process.wait()
        self.assertEqual(len(quiet), CYCLES + 1)
        self.assertEqual(quiet, loaded)
        self.assertEqual(quiet, in_process)

    def test_hover_in_gusts(self):
        cycles = 2500  # 25 s
        run, poses = self.run_to_end('gusts', cycles, gust_stddev=1.0)
        start_ns = int(5.0 / CYCLE_S) * int(CYCLE_S * 1e9)
        hovering = [position_error(pose) for stamp, pose in sorted(poses.items())
                    if start_ns <= stamp <= run.last_stamp]
        sys.stderr.write('gusts: %d cycles from 5 s, position error max %.3g m, median %.3g m\n'
                         % (len(hovering), max(hovering), np.median(hovering)))
        self.assertEqual(len(hovering), cycles - int(5.0 / CYCLE_S) + 1)
        self.assertLess(max(hovering), 0.1)

    def test_saturating_climb_shows_the_clipped_thrusts(self):
        cycles = 140  # 1.4 s, climbing at full thrust towards 20 m all the while
        run, _ = self.run_to_end('climb', cycles, target_z=20.0)
        settled_ns = int(0.8e9)  # 40 motor time constants
        thrusts = sorted((stamp, rotors) for stamp, rotors in run.thrusts.items()
                         if stamp <= run.last_stamp)
        settled = [rotors for stamp, rotors in thrusts if stamp >= settled_ns]
        sys.stderr.write('climb: %d thrust samples, %d from 0.8 s; largest thrust %r N\n'
                         % (len(thrusts), len(settled), max(max(rotors) for _, rotors in thrusts)))
        self.assertGreaterEqual(len(settled), 50)
        for stamp, rotors in thrusts:
            self.assertEqual(len(rotors), 4)
            self.assertLessEqual(max(rotors), MAX_THRUST_N, stamp)
        for rotors in settled:
            for thrust in rotors:
                self.assertAlmostEqual(thrust, MAX_THRUST_N, delta=1e-9)


if __name__ == '__main__':
    rospy.init_node('quadrotor_test')
    rostest.rosrun('rigid_body_sim', 'quadrotor', Quadrotor, sys.argv)
