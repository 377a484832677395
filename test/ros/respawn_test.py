#!/usr/bin/python3
"""Respawn: launched with `respawn:=true`, the node comes back after `kill -9`.

The node is started by launch/rigid_body_sim.launch (respawn.test). ROUNDS
times: the node's PID is read over its XML-RPC API (master lookupNode, then
getPid); it is killed with SIGKILL; then
- the node registers again under the same name with a different PID;
- a `~bodies` message and a `/tf` message carrying a state of the new process
  arrive within MAX_GAP s (wall clock) of the kill. A state of the new process
  is one stamped after the kill (+ 10 ms): without sim time its t0 is ros::Time::now()
  at its start, and the killed process cannot have published a state stamped
  later than its death (simulation time never runs ahead of the wall clock
  at real_time_factor 1);
- its first stamp is later than the last stamp received before the kill, and
  stamps increase from there on.
"""
import os
import signal
import threading
import time
import unittest
from xmlrpc.client import ServerProxy

import rosgraph
import rosnode
import rospy
import rostest

from rigid_body_sim.msg import BodyStateArray
from rigid_body_sim.testing import wait_until
from tf2_msgs.msg import TFMessage

PKG = 'rigid_body_sim'
NODE = '/rigid_body_sim'
CALLER = '/respawn_test'
MAX_GAP = 2.0          # s from kill -9 to the first message of the new process
ROUNDS = 3
STARTUP_TIMEOUT = 30.0
KILL_MARGIN = 0.01     # s: a stamp later than kill + this is from the new process
SETTLE = 1.0           # s of messages from a new process before killing it again


class Respawn(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rospy.init_node('respawn_test', anonymous=False)
        cls.lock = threading.Lock()
        cls.msgs = {'bodies': [], 'tf': []}   # (receipt wall time, stamp)
        rospy.Subscriber(NODE + '/bodies', BodyStateArray, cls._on_bodies, queue_size=1000)
        rospy.Subscriber('/tf', TFMessage, cls._on_tf, queue_size=1000)

    @classmethod
    def _record(cls, topic, stamp):
        with cls.lock:
            cls.msgs[topic].append((time.time(), stamp))

    @classmethod
    def _on_bodies(cls, msg):
        cls._record('bodies', msg.header.stamp)

    @classmethod
    def _on_tf(cls, msg):
        # Only the node's transforms (one message per publish cycle).
        if msg.transforms:
            cls._record('tf', msg.transforms[0].header.stamp)

    def snapshot(self, topic):
        with self.lock:
            return list(self.msgs[topic])

    def node_pid(self):
        """PID of the process registered as NODE, or None."""
        uri = rosnode.get_api_uri(rosgraph.Master(CALLER), NODE, skip_cache=True)
        if not uri:
            return None
        try:
            code, _, pid = ServerProxy(uri).getPid(CALLER)
        except OSError:        # registered, but that process is gone
            return None
        return pid if code == 1 else None

    def test_respawn_after_kill9(self):
        wait_until(lambda: self.snapshot('bodies') and self.snapshot('tf'),
                      STARTUP_TIMEOUT, 'no ~bodies and /tf message from the node')
        pid = wait_until(self.node_pid, 10.0, 'no PID from %s' % NODE)
        gaps = []
        for round_ in range(1, ROUNDS + 1):
            # Settle: the current process publishes, and we are connected to it.
            time.sleep(SETTLE)
            last_before = {t: self.snapshot(t)[-1][1] for t in ('bodies', 'tf')}
            n_before = {t: len(self.snapshot(t)) for t in ('bodies', 'tf')}
            os.kill(pid, signal.SIGKILL)
            t_kill = time.time()
            # States of the killed process are stamped at most about a step
            # ahead of the wall clock; the new one starts > 0.1 s after the kill
            # (roslaunch polls every 0.1 s).
            kill_stamp = rospy.Time.from_sec(t_kill + KILL_MARGIN)

            def first_new(topic):
                for received, stamp in self.snapshot(topic)[n_before[topic]:]:
                    if stamp > kill_stamp:
                        return received, stamp
                return None

            got = {}
            for topic in ('bodies', 'tf'):
                got[topic] = wait_until(
                    lambda: first_new(topic), MAX_GAP + 5.0,
                    'round %d: no %s message from a new process' % (round_, topic))
            new_pid = wait_until(lambda: (lambda p: p if p and p != pid else None)(
                self.node_pid()), 5.0, 'round %d: no new process registered' % round_)
            self.assertNotEqual(new_pid, pid)
            for topic in ('bodies', 'tf'):
                received, stamp = got[topic]
                gap = received - t_kill
                rospy.loginfo('round %d: %s back %.3f s after kill -9 of PID %d (new PID %d)',
                              round_, topic, gap, pid, new_pid)
                self.assertLessEqual(gap, MAX_GAP, 'round %d: first %s message of the new '
                                     'process %.3f s after kill -9, more than %.1f s'
                                     % (round_, topic, gap, MAX_GAP))
                self.assertGreater(stamp, last_before[topic],
                                   'round %d: %s stamp %s after the restart is not later than '
                                   'the last one before it (%s)'
                                   % (round_, topic, stamp, last_before[topic]))
                if topic == 'bodies':
                    gaps.append(gap)
            time.sleep(0.5)
            after = [s for _, s in self.snapshot('bodies')[n_before['bodies']:]
                     if s > kill_stamp]
            self.assertTrue(all(b > a for a, b in zip(after, after[1:])),
                            'round %d: ~bodies stamps of the new process not increasing'
                            % round_)
            pid = new_pid
        rospy.loginfo('~bodies back after kill -9: %s s', ', '.join('%.3f' % g for g in gaps))


if __name__ == '__main__':
    rostest.rosrun(PKG, 'respawn', Respawn)
