#!/usr/bin/python3
"""A downstream-style closed-loop test: pd_controller.py brings the puck to
its target pose in lockstep with the simulator (closed_loop/run.launch), and
two runs, one on a quiet machine and one with every core kept busy by
processes this test starts and stops, reach bit-identical states at every
cycle (equal state hashes), with no lockstep timeout in either.

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
from rigid_body_sim.testing import LockstepController, SimClient, state_hash

CYCLES = 300  # 3 s of simulation at publish_rate 100 Hz
TARGET_POSITION = np.array([0.0, 0.0, 1.0])
LAUNCH = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'run.launch')


def angle_to_identity(q):
    return 2.0 * math.atan2(np.linalg.norm(q[:3]), abs(q[3]))


class Run(object):
    """One closed loop in namespace `ns`, recorded cycle by cycle."""

    def __init__(self, ns):
        self.ns = ns
        self.hashes = []
        self.last_states = None
        self.done = threading.Event()
        self.simulator = '/%s/rigid_body_sim' % ns
        self.observer = LockstepController(self.record, self.simulator)
        self.launch = subprocess.Popen(
            ['roslaunch', LAUNCH, 'ns:=' + ns, 'observer:=' + rospy.get_name()],
            stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)

    def record(self, states, _stamp):
        if len(self.hashes) <= CYCLES:
            self.hashes.append(state_hash(states))
            self.last_states = states
        if len(self.hashes) > CYCLES:
            self.done.set()
        return []

    def finish(self):
        diagnostics = SimClient(self.simulator).diagnostics(timeout=15.0)
        self.observer.stop()
        self.launch.send_signal(subprocess.signal.SIGINT)
        self.launch.wait(timeout=30.0)
        return diagnostics


class ClosedLoop(unittest.TestCase):
    def run_loop(self, ns):
        run = Run(ns)
        self.assertTrue(run.done.wait(timeout=120.0), '%s: fewer than %d cycles' % (ns, CYCLES))
        diagnostics = run.finish()
        self.assertEqual(diagnostics['lockstep_timeouts'], '0', ns)
        puck = run.last_states['puck']
        self.assertLess(np.linalg.norm(puck.position - TARGET_POSITION), 1e-3, ns)
        self.assertLess(angle_to_identity(puck.orientation), 1e-3, ns)
        return run.hashes

    def test_two_runs_one_of_them_loaded_are_bit_identical(self):
        quiet = self.run_loop('quiet')
        busy = [subprocess.Popen([sys.executable, '-c', 'while True: pass'])
                for _ in range(os.cpu_count() or 2)]
        try:
            loaded = self.run_loop('loaded')
        finally:
            for process in busy:
                process.kill()
                process.wait()
        self.assertEqual(len(quiet), CYCLES + 1)
        self.assertEqual(len(set(quiet)), len(quiet))  # the state moves every cycle
        self.assertEqual(quiet, loaded)


if __name__ == '__main__':
    rospy.init_node('closed_loop_test')
    rostest.rosrun('rigid_body_sim', 'closed_loop', ClosedLoop, sys.argv)
