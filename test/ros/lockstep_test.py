#!/usr/bin/python3
"""Lockstep as doc/node.md specifies it, with this test as the one listed
controller: the node publishes t_0 on the publish lattice once we are
connected and does not step past a cycle until we answer it; answers act
before the next step; a future stamp is rejected, a NaN entry rejected alone,
a late answer held from the next step; a stall times out (counted, WARN) and
the node goes on; a pause during a wait stops the timeout; ~step_with_wrenches
never waits, lists rejected entries and returns the state and its hash; the
diagnostics' state_hash is the hash of the last published cycle."""
import queue
import sys
import time
import unittest

import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray
from rigid_body_sim.msg import BodyStateArray, StampedParticleWrenchArray
from rigid_body_sim.testing import SimClient, particle_wrench, state_hash, to_states

DT_NS = 1000000          # rate 1000 Hz
CYCLE_NS = 10 * DT_NS    # publish_rate 100 Hz
TIMEOUT_S = 0.5          # ~lockstep_timeout
NODE = '/rigid_body_sim'


class Lockstep(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('lockstep_test')
        cls.cycles = queue.Queue()
        cls.diagnostics = {}
        cls.levels = []
        cls.answers = rospy.Publisher(NODE + '/lockstep_wrenches', StampedParticleWrenchArray,
                                      queue_size=10, tcp_nodelay=True)
        rospy.Subscriber(NODE + '/bodies', BodyStateArray,
                         lambda msg: cls.cycles.put((time.monotonic(), msg)),
                         queue_size=100, tcp_nodelay=True)
        rospy.Subscriber('/diagnostics', DiagnosticArray, cls.on_diagnostics, queue_size=10)

    @classmethod
    def on_diagnostics(cls, msg):
        for status in msg.status:
            if status.name == NODE[1:] + ': simulation':
                cls.diagnostics = {kv.key: kv.value for kv in status.values}
                cls.levels.append(status.level)

    def next_cycle(self, timeout=5.0):
        return self.cycles.get(timeout=timeout)

    def no_cycle_for(self, seconds):
        with self.assertRaises(queue.Empty):
            self.cycles.get(timeout=seconds)

    def answer(self, stamp, wrenches=()):
        msg = StampedParticleWrenchArray()
        msg.header.stamp = stamp
        msg.wrenches = list(wrenches)
        self.answers.publish(msg)

    def diagnostic(self, key, settle_s=1.5):
        rospy.sleep(settle_s)  # one report period, wall time
        return self.diagnostics[key]

    def puck(self, msg):
        return to_states(msg)['puck']

    def test_lockstep(self):
        # t_0: published once we are connected, on the publish lattice.
        _, first = self.next_cycle(timeout=30.0)
        t0 = first.header.stamp
        self.assertEqual(t0.to_nsec() % CYCLE_NS, 0)
        self.no_cycle_for(0.25)  # it waits for our answer

        # An answer acts before the next step: 1 N for the 10 steps of a cycle.
        self.answer(t0, [particle_wrench('puck', force=(1.0, 0.0, 0.0))])
        _, c1 = self.next_cycle()
        self.assertEqual(c1.header.stamp.to_nsec(), t0.to_nsec() + CYCLE_NS)
        self.assertAlmostEqual(self.puck(c1).linear_momentum[0], 0.01, delta=1e-15)

        # A future stamp is rejected (entries not held) and answers nothing.
        self.answer(c1.header.stamp + rospy.Duration(1.0), [particle_wrench('puck', force=(0, 5.0, 0))])
        self.no_cycle_for(0.25)
        # A NaN entry is rejected alone; the message still answers.
        sent = time.monotonic()
        self.answer(c1.header.stamp, [particle_wrench('puck', force=(float('nan'), 0, 0)),
                                      particle_wrench('puck', force=(-1.0, 0.0, 0.0))])
        arrived, c2 = self.next_cycle()
        self.assertLess(arrived - sent, TIMEOUT_S)
        self.assertEqual(c2.header.stamp.to_nsec(), t0.to_nsec() + 2 * CYCLE_NS)
        self.assertEqual(self.puck(c2).linear_momentum[1], 0.0)
        self.assertAlmostEqual(self.puck(c2).linear_momentum[0], 0.0, delta=1e-15)

        # A stall: no answer to c2. The node steps on after the timeout.
        sent = time.monotonic()
        arrived, c3 = self.next_cycle()
        self.assertGreaterEqual(arrived - sent, TIMEOUT_S - 0.05)
        self.assertEqual(c3.header.stamp.to_nsec(), t0.to_nsec() + 3 * CYCLE_NS)
        # The late answer to c2 is held from the next step, as is ours to c3.
        self.answer(c2.header.stamp, [particle_wrench('puck', force=(0.0, 0.0, 2.0))])
        self.answer(c3.header.stamp)
        _, c4 = self.next_cycle()
        self.assertAlmostEqual(self.puck(c4).linear_momentum[2], 0.02, delta=1e-15)

        # A pause during a wait: no timeout while paused; ~step_with_wrenches
        # does not wait, lists the rejected entry and returns the state.
        sim = SimClient(NODE)
        sim.pause()
        rospy.sleep(2 * TIMEOUT_S)
        result = sim.step_with_wrenches([particle_wrench('puck', force=(0.0, 0.0, -2.0)),
                                         particle_wrench('ghost', force=(1.0, 0.0, 0.0))], steps=3)
        self.assertIn('wrenches[1]: unknown_body', result.message)
        # sim_time is a float64 of ~1.8e9 s: 2.4e-7 s resolution.
        self.assertAlmostEqual(result.sim_time, (c4.header.stamp.to_nsec() + 3 * DT_NS) * 1e-9, delta=5e-7)
        # -2 N replaces the held +2 N on the same particle: 0.02 - 2 * 0.003.
        self.assertAlmostEqual(result.states['puck'].linear_momentum[2], 0.014, delta=1e-15)
        _, stepped = self.next_cycle()
        self.assertEqual(stepped.header.stamp.to_nsec(), c4.header.stamp.to_nsec() + 3 * DT_NS)
        self.assertEqual(result.state_hash, state_hash(stepped))
        # Paused, the diagnostics report the hash of that last published state.
        self.assertEqual(self.diagnostic('state_hash'), state_hash(stepped))
        stamp = stepped.header.stamp
        self.assertEqual(self.diagnostics['state_hash_stamp'], '%d.%09d' % (stamp.secs, stamp.nsecs))
        self.assertEqual(self.diagnostics['lockstep_timeouts'], '1')
        self.assertEqual(self.diagnostics['lockstep_late_answers'], '1')
        self.assertEqual(self.diagnostics['lockstep_future_stamp'], '1')
        self.assertEqual(self.diagnostics['rejected_lockstep_future_stamp'], '1')
        self.assertEqual(self.diagnostics['rejected_non_finite'], '1')
        self.assertIn(1, self.levels)  # WARN after the timeout

        # Resumed, it waits for the answer to the stepped state, then goes on
        # to the next cycle of the lattice, 7 steps on, -2 N still held.
        sim.resume()
        self.no_cycle_for(0.25)
        self.answer(stamp)
        _, c5 = self.next_cycle()
        self.assertEqual(c5.header.stamp.to_nsec(), c4.header.stamp.to_nsec() + CYCLE_NS)
        self.assertAlmostEqual(self.puck(c5).linear_momentum[2], 0.0, delta=1e-15)

    # Runs after test_lockstep (unittest sorts by name), which must not see
    # the timeouts /rigid_body_sim counts while nobody answers it here.
    def test_z_a_controller_that_never_comes_never_hangs_the_node(self):
        stamps = queue.Queue()
        rospy.Subscriber('/orphan/bodies', BodyStateArray, lambda msg: stamps.put(msg.header.stamp),
                         queue_size=100)
        received = [stamps.get(timeout=10.0) for _ in range(4)]
        for earlier, later in zip(received, received[1:]):
            self.assertEqual((later - earlier).to_nsec(), CYCLE_NS)
        diagnostics = SimClient('/orphan').diagnostics()
        # One for the start, one per cycle since.
        self.assertGreaterEqual(int(diagnostics['lockstep_timeouts']), 4)


if __name__ == '__main__':
    rostest.rosrun('rigid_body_sim', 'lockstep', Lockstep, sys.argv)
