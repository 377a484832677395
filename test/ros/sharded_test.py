#!/usr/bin/python3
"""Two shards of one scene (launch/sharded.launch): each publishes its own
bodies; one ParticleWrenchArray on /rigid_body_sim/particle_wrenches pushes
every body through the shard that owns it (dp/dt = F exactly) while the
other shard counts the entry under other_shard, not as rejected; an unknown
body is rejected by both; only shard 0 publishes /clock; a service call for
another shard's body fails naming that shard; both shards stamp on the same
lattice; ~spawn_body is refused."""
import sys
import threading
import time
import unittest

import rosgraph
import rospy
import rostest
from rigid_body_sim.msg import BodyStateArray, ParticleWrenchArray
from rigid_body_sim.srv import SpawnBody
from rigid_body_sim.testing import SimClient, particle_wrench

SHARDS = {'/rigid_body_sim_0': ['a0', 'a2'], '/rigid_body_sim_1': ['b1', 'b3']}
FORCES = {'a0': 1.0, 'b1': 2.0, 'a2': 3.0, 'b3': 4.0}  # N along x


class Sharded(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('sharded_test')
        cls.clients = {node: SimClient(node) for node in SHARDS}
        cls.messages = {node: [] for node in SHARDS}
        cls.lock = threading.Lock()
        for node in SHARDS:
            rospy.Subscriber(node + '/bodies', BodyStateArray,
                             lambda msg, node=node: cls.on_bodies(node, msg), queue_size=100)

    @classmethod
    def on_bodies(cls, node, msg):
        with cls.lock:
            cls.messages[node].append(msg)

    def wait_messages(self, node, count, timeout=10.0):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            with self.lock:
                if len(self.messages[node]) >= count:
                    return list(self.messages[node])
            time.sleep(0.05)
        self.fail('%s: fewer than %d ~bodies messages' % (node, count))

    def test_shards(self):
        for node, names in SHARDS.items():
            self.assertEqual([b.name for b in self.wait_messages(node, 1)[-1].bodies], names)
        # Same lattice: both shards publish the same stamps.
        stamps = [set(m.header.stamp.to_nsec() for m in self.wait_messages(node, 20)) for node in SHARDS]
        self.assertTrue(stamps[0] & stamps[1])

        pub = rospy.Publisher('/rigid_body_sim/particle_wrenches', ParticleWrenchArray,
                              queue_size=1, latch=True)
        entries = [particle_wrench(name, force=(force, 0.0, 0.0)) for name, force in FORCES.items()]
        entries.append(particle_wrench('ghost', force=(1.0, 0.0, 0.0)))
        pub.publish(ParticleWrenchArray(wrenches=entries))
        time.sleep(1.0)
        for node, names in SHARDS.items():
            with self.lock:
                count = len(self.messages[node])
            m1, m2 = self.wait_messages(node, count + 2)[-2:]
            dt = (m2.header.stamp - m1.header.stamp).to_sec()
            for b1, b2 in zip(m1.bodies, m2.bodies):
                rate = (b2.linear_momentum.x - b1.linear_momentum.x) / dt
                self.assertAlmostEqual(rate, FORCES[b1.name], delta=1e-9, msg=b1.name)
            # Diagnostics come once a second: wait for a report after the push.
            deadline = time.monotonic() + 5.0
            diagnostics = self.clients[node].diagnostics()
            while diagnostics.get('other_shard') == '0' and time.monotonic() < deadline:
                time.sleep(0.2)
                diagnostics = self.clients[node].diagnostics()
            self.assertEqual(diagnostics['other_shard'], '2', node)
            self.assertEqual(diagnostics['rejected_unknown_body'], '1', node)
            self.assertEqual(diagnostics['rejected_messages'], '1', node)

        publishers = dict(rosgraph.Master('/sharded_test').getSystemState()[0])
        self.assertEqual(publishers.get('/clock'), ['/rigid_body_sim_0'])

        with self.assertRaisesRegex(RuntimeError, "'b1' is simulated by shard 1 of 2"):
            self.clients['/rigid_body_sim_0'].clear_body_wrenches('b1')
        spawn = rospy.ServiceProxy('/rigid_body_sim_1/spawn_body', SpawnBody)
        response = spawn('{name: c4, particles: [{mass: 1.0, position: [0, 0, 0]}]}')
        self.assertFalse(response.success)
        self.assertIn('shard', response.message)


if __name__ == '__main__':
    rostest.rosrun('rigid_body_sim', 'sharded', Sharded, sys.argv)
