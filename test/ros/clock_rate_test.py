#!/usr/bin/python3
"""/clock on the ~clock_rate lattice (doc/node.md, "Time"; clock_rate.test:
rate 1000 Hz, clock_rate 250 Hz, publish_rate 100 Hz):

- running, the /clock stamps are exactly the lattice points k (k ms from time
  zero) with k a multiple of 4 (rate / clock_rate) or of 10 (a publish
  cycle), every one of them, strictly increasing;
- paused, ~step 3 sends /clock for the ~clock_rate lattice points it passes
  and for the state it reaches, which it publishes, whether on the lattice
  or not (it publishes no publish cycle it passes).
"""
import threading
import time
import unittest

import rospy
import rostest
from rigid_body_sim.srv import Step
from rigid_body_sim.testing import wait_until
from rosgraph_msgs.msg import Clock
from std_srvs.srv import SetBool

PKG = 'rigid_body_sim'
NODE = '/rigid_body_sim'
DT_NS = 1000000
CLOCK_EVERY = 4    # rate / clock_rate
PUBLISH_EVERY = 10  # rate / publish_rate


def on_clock_lattice(k):
    return k % CLOCK_EVERY == 0 or k % PUBLISH_EVERY == 0


class ClockRate(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('clock_rate_test')
        cls.lock = threading.Lock()
        cls.clocks = []
        rospy.Subscriber('/clock', Clock, cls.on_clock, queue_size=10000, tcp_nodelay=True)
        rospy.wait_for_service(NODE + '/step', timeout=30.0)
        cls.set_paused = rospy.ServiceProxy(NODE + '/set_paused', SetBool)
        cls.step = rospy.ServiceProxy(NODE + '/step', Step)

    @classmethod
    def on_clock(cls, msg):
        with cls.lock:
            cls.clocks.append(msg.clock.to_nsec())

    def received_since(self, start):
        with self.lock:
            return list(self.clocks[start:])

    def count(self):
        with self.lock:
            return len(self.clocks)

    def test_1_running_on_the_lattice_and_every_publish_cycle(self):
        wait_until(lambda: self.count() > 0, 30.0, 'no /clock (publish_clock true)')
        start = self.count()
        time.sleep(2.0)
        clocks = self.received_since(start)
        self.assertGreater(len(clocks), 500, 'fewer /clock messages than 2 s at 250 + 100 Hz')
        for stamp in clocks:
            self.assertEqual(stamp % DT_NS, 0, '/clock %d ns off the step lattice' % stamp)
        indices = [stamp // DT_NS for stamp in clocks]
        expected = [k for k in range(indices[0], indices[-1] + 1) if on_clock_lattice(k)]
        self.assertEqual(indices, expected)

    def test_2_step_sends_the_state_it_reaches(self):
        self.assertTrue(self.set_paused(True).success)
        time.sleep(0.2)  # the last /clock of the run arrives
        for steps in (3,) * 8:
            start = self.count()
            reached = rospy.Time.from_sec(self.step(steps).sim_time).to_nsec()
            k = int(round(reached / float(DT_NS)))
            wait_until(lambda: self.received_since(start)[-1:] == [k * DT_NS], 5.0,
                          'no /clock %d ns after ~step %d' % (k * DT_NS, steps))
            # ~step publishes the state it reaches only: the publish cycles
            # it passes are no published states.
            passed = [i for i in range(k - steps + 1, k) if i % CLOCK_EVERY == 0] + [k]
            self.assertEqual([stamp // DT_NS for stamp in self.received_since(start)], passed)
        self.assertTrue(self.set_paused(False).success)


if __name__ == '__main__':
    rostest.rosrun(PKG, 'clock_rate', ClockRate)
