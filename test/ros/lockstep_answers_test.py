#!/usr/bin/python3
"""Lockstep answers on ~lockstep_answers (LockstepAnswer), with this test as
the one listed controller of two nodes on one scene (lockstep_answers.test):

- a body wrench in an answer is held before the next step as on the body's
  wrench topic: a constant world force F and couple T on a body without
  particles give Delta p = F n dt and Delta L = T n dt over the n steps of
  a cycle, to round-off;
- an actuator command for an actuator the body does not have, and a body
  wrench for an unknown body, are rejected on their own, named and counted
  (rejected_unknown_actuator, rejected_unknown_body), and the rest of the
  answer still holds;
- a PD controller answering every cycle with body wrenches (world force,
  couple in the body's axes) and a command for the puck's lagged thruster,
  run on a quiet machine and again with every core kept busy, gives
  bit-identical states at every cycle (equal state hashes), with no
  lockstep timeout."""
import os
import subprocess
import sys
import threading
import unittest
import warnings

import numpy as np
import rospy
import rostest
from geometry_msgs.msg import Vector3, Wrench
from rigid_body_sim.msg import ActuatorCommand, BodyStateArray, BodyWrench, LockstepAnswer
from rigid_body_sim.testing import SimClient, state_hash, to_states
from sensor_msgs.msg import JointState

CYCLES = 150                                # 1.5 s of simulation at publish_rate 100 Hz
CYCLE_STEPS = 10                            # rate 1000 Hz
DT_S = 1e-3
FIRST_FORCE = np.array([1.0, 2.0, 3.0])     # N, world axes, cycle 0
FIRST_COUPLE = np.array([0.0, 0.0, 0.1])    # N m, world axes, cycle 0
TARGET = np.array([0.0, 0.0, 1.0])          # m
KP, KD, KW = 32.0, 16.0, 0.05               # N/m, N s/m, N m s/rad: critically damped at 2 kg
JET_N = 0.3                                 # N, the amplitude of the puck's thruster command


def body_wrench(body, force, torque, frame=''):
    entry = BodyWrench()
    entry.body = body
    entry.wrench.header.frame_id = frame
    entry.wrench.wrench = Wrench(force=Vector3(*force), torque=Vector3(*torque))
    return entry


def rotation_matrix(q):
    x, y, z, w = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


class Run(object):
    """The test as `node`'s controller for CYCLES + 1 cycles."""

    def __init__(self, node):
        self.node = node
        self.cycles = []  # (stamp, states, state hash) per cycle, from t_0
        self.done = threading.Event()
        # Publisher first: the node starts once both connections exist.
        with warnings.catch_warnings():
            warnings.simplefilter('ignore')  # queue_size None: publish in the callback's thread
            self.answers = rospy.Publisher(node + '/lockstep_answers', LockstepAnswer, queue_size=None,
                                           tcp_nodelay=True)
        self.bodies = rospy.Subscriber(node + '/bodies', BodyStateArray, self.on_bodies,
                                       queue_size=10, tcp_nodelay=True)
        self.jet_thrust_max = 0.0  # N, the largest |T| on the puck's actuator_states
        self.jet = rospy.Subscriber(node + '/puck/actuator_states', JointState, self.on_jet,
                                    queue_size=1000)

    def on_jet(self, msg):
        self.jet_thrust_max = max(self.jet_thrust_max, abs(msg.effort[0]))

    def on_bodies(self, msg):
        if self.done.is_set():
            return  # the node waits at this cycle until the test has read its diagnostics
        states = to_states(msg)
        self.cycles.append((msg.header.stamp, states, state_hash(msg)))
        answer = LockstepAnswer()
        answer.header.stamp = msg.header.stamp
        if len(self.cycles) == 1:
            command = ActuatorCommand(body='puck', names=['rotor_0'], commands=[1.0])
            answer.body_wrenches = [body_wrench('ghost', (1.0, 0.0, 0.0), (0.0, 0.0, 0.0)),
                                    body_wrench('puck', FIRST_FORCE, FIRST_COUPLE)]
            answer.actuators = [command]
        else:
            puck = states['puck']
            force = -KP * (puck.position - TARGET) - KD * puck.linear_velocity
            rate_body = rotation_matrix(puck.orientation).T.dot(puck.angular_velocity)
            answer.body_wrenches = [body_wrench('puck', force, -KW * rate_body, frame='puck')]
            answer.actuators = [ActuatorCommand(body='puck', names=['jet'],
                                                commands=[float(JET_N * np.sin(0.1 * len(self.cycles)))])]
        if len(self.cycles) > CYCLES:
            self.done.set()
        self.answers.publish(answer)

    def finish(self):
        """The node's diagnostics once a report has followed the run."""
        rospy.sleep(1.5)  # one report period, wall time
        diagnostics = SimClient(self.node).diagnostics()
        self.bodies.unregister()
        self.answers.unregister()
        self.jet.unregister()
        return diagnostics


class LockstepAnswers(unittest.TestCase):
    def drive(self, node):
        run = Run(node)
        self.assertTrue(run.done.wait(timeout=90.0), '%s: fewer than %d cycles' % (node, CYCLES))
        diagnostics = run.finish()
        self.assertEqual(diagnostics['lockstep_timeouts'], '0', node)
        self.assertEqual(diagnostics['rejected_unknown_actuator'], '1', node)
        self.assertEqual(diagnostics['rejected_unknown_body'], '1', node)
        self.assertEqual(diagnostics['rejected_messages'], '2', node)
        # The thruster commands were held and the thrust followed them.
        self.assertGreater(run.jet_thrust_max, 0.5 * JET_N, node)
        return run.cycles

    def check_first_cycle(self, cycles):
        (_, before, _), (_, after, _) = cycles[0], cycles[1]
        steps_s = CYCLE_STEPS * DT_S
        np.testing.assert_allclose(after['puck'].linear_momentum - before['puck'].linear_momentum,
                                   FIRST_FORCE * steps_s, rtol=0, atol=1e-14)
        np.testing.assert_allclose(after['puck'].angular_momentum - before['puck'].angular_momentum,
                                   FIRST_COUPLE * steps_s, rtol=0, atol=1e-14)

    def test_body_wrenches_in_answers_are_bit_identical_under_load(self):
        quiet = self.drive('/quiet_sim')
        self.check_first_cycle(quiet)
        busy = [subprocess.Popen([sys.executable, '-c', 'while True: pass'])
                for _ in range(os.cpu_count() or 2)]
        try:
            loaded = self.drive('/loaded_sim')
        finally:
            for process in busy:
                process.kill()
                process.wait()
        self.assertEqual(len(quiet), CYCLES + 1)
        # The controller acts: the puck is brought towards the target.
        start, end = quiet[0][1]['puck'].position, quiet[-1][1]['puck'].position
        self.assertLess(np.linalg.norm(end - TARGET), 0.5 * np.linalg.norm(start - TARGET))
        self.assertEqual([c[2] for c in quiet], [c[2] for c in loaded])


if __name__ == '__main__':
    rospy.init_node('lockstep_answers_test')
    rostest.rosrun('rigid_body_sim', 'lockstep_answers', LockstepAnswers, sys.argv)
