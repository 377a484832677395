#!/usr/bin/python3
"""The shards of launch/sharded.launch on hosts of their own, as a user runs
them on several machines (doc/node.md, "Shards"): four hosts on a private
network of network namespaces (network.py) that this test makes and always
removes. The master (roscore) runs on one, shard 0 and shard 1 on one each
(`roslaunch --wait rigid_body_sim sharded.launch shards:=2 index:=k
single_shard:=true pin_cores:=false`), and on the fourth a client (client_host.py) publishes
wrench arrays and records what the shards publish; every process has
ROS_MASTER_URI naming the master and ROS_IP its host's address, as ROS's
multi-machine set-up asks. The test checks that

1. every shard steps its own bodies, and no other: each body moves at its
   scene velocity between ~bodies messages;
2. a wrench array published once reaches the shard that owns each body:
   dv/dt = F/m, while the other shard counts the entry under other_shard;
3. /tf carries every body's frame, sent by the shard that owns it;
4. when shard 0's host goes away (its link cut, its processes killed, its
   namespace deleted), shard 1 keeps stepping and publishing its bodies and
   TF, and a wrench array published after the loss still reaches it.

Where network namespaces cannot be made (not root, no CAP_NET_ADMIN, no
`ip`), every check is skipped with the reason, printed."""
import json
import os
import queue
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import numpy as np
import rostest
import yaml

import network

PKG = 'rigid_body_sim'
HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, 'scene.yaml')
MASTER_PORT = 11311
HOSTS = {'master': '10.213.0.1', 'shard0': '10.213.0.10', 'shard1': '10.213.0.11',
         'client': '10.213.0.20'}
MASTER_URI = 'http://%s:%d' % (HOSTS['master'], MASTER_PORT)
SHARD_HOSTS = {'/rigid_body_sim_0': 'shard0', '/rigid_body_sim_1': 'shard1'}
PUBLISH_RATE = 50.0       # Hz
STARTUP_TIMEOUT = 30.0    # s for the master, both shards and the client to connect
DIAGNOSTICS_TIMEOUT = 5.0  # s; the node reports once a second
ANSWER_MARGIN = 10.0      # s the client may take beyond a request's own duration
FORCES = {'a0': [1.0, 0.0, 0.0], 'b1': [0.0, 2.0, 0.0], 'a2': [0.0, 0.0, 3.0],
          'b3': [4.0, 0.0, -1.0]}                                # N
FORCES_AFTER_LOSS = {'a0': [0.0, 1.0, 0.0], 'b1': [-3.0, 0.0, 0.0], 'a2': [1.0, 1.0, 1.0],
                     'b3': [0.0, 0.0, 2.0]}                      # N
TOLERANCE = 1e-9          # m/s, m/s^2: the motion is exact up to double rounding


def scene_bodies():
    """[(name, mass [kg], initial velocity [m/s], owning shard's node)] in scene order."""
    with open(SCENE) as f:
        bodies = yaml.safe_load(f)['bodies']
    nodes = sorted(SHARD_HOSTS)
    return [(b['name'], sum(p['mass'] for p in b['particles']),
             np.array(b.get('linear_velocity', [0.0, 0.0, 0.0])), nodes[i % len(nodes)])
            for i, b in enumerate(bodies)]


def host_env(host, ros_home):
    """The environment of every process on `host`: ROS's multi-machine
    variables, and nothing of the rostest graph this test runs in."""
    env = dict(os.environ)
    for key in ('ROS_HOSTNAME', 'ROS_NAMESPACE', 'ROS_LOG_DIR'):
        env.pop(key, None)
    env.update(ROS_MASTER_URI=MASTER_URI, ROS_IP=HOSTS[host], ROS_HOME=ros_home,
               PYTHONUNBUFFERED='1')
    return env


class MultiHost(unittest.TestCase):
    """The graph is started by the first check and removed after the last
    (or by the `finally` below): every check needs all of it, and a failure
    to start it must fail a check, which the XML result shows, rather than
    setUpClass, which it does not."""
    unavailable = None  # why namespaces cannot be made here ('' when they can)
    missing = None      # what is missing from the graph after waiting for it
    net = None
    tmp = None
    client = None
    answers = None

    def setUp(self):
        if MultiHost.unavailable is None:
            MultiHost.unavailable = network.unavailable_reason() or ''
            if self.unavailable:
                # Also to the terminal: the XML result has no place for a skip.
                sys.__stderr__.write('multi_host_test: SKIPPED: %s\n' % self.unavailable)
            else:
                MultiHost.missing = ['the graph: starting it failed (the first check says why)']
                self.start_graph()
                MultiHost.missing = self.ask('ready', STARTUP_TIMEOUT, shards=sorted(SHARD_HOSTS),
                                             timeout=STARTUP_TIMEOUT)['missing']
        if self.unavailable:
            self.skipTest(self.unavailable)
        if self.missing:
            self.fail('not connected across the hosts within %g s: %s\n%s'
                      % (STARTUP_TIMEOUT, self.missing, self.logs()))

    @classmethod
    def start_graph(cls):
        network.remove_stale()
        cls.tmp = tempfile.mkdtemp(prefix='rbs_multi_host_')
        cls.net = network.Network()
        for host, address in sorted(HOSTS.items()):
            cls.net.add_host(host, address)
        cls.start('master', ['roscore', '-p', str(MASTER_PORT)])
        # Unpinned: the hosts share this machine's cores, any of which may be
        # busy (a benchmark's SCHED_FIFO node, say); a real host has its own.
        for node, host in sorted(SHARD_HOSTS.items()):
            cls.start(host, ['roslaunch', '--wait', PKG, 'sharded.launch',
                             'shards:=%d' % len(SHARD_HOSTS), 'index:=%s' % node[-1],
                             'single_shard:=true', 'pin_cores:=false', 'scene:=' + SCENE,
                             'publish_rate:=%g' % PUBLISH_RATE])
        cls.client = cls.start('client', [sys.executable, os.path.join(HERE, 'client_host.py')],
                               stdin=True)
        cls.answers = queue.Queue()
        threading.Thread(target=cls.read_answers, daemon=True).start()

    @classmethod
    def start(cls, host, argv, stdin=False):
        """Runs `argv` on `host`, its output in <tmp>/<host>.log (stdout a
        pipe when it takes requests on stdin)."""
        with open(os.path.join(cls.tmp, host + '.log'), 'w') as log:
            return cls.net.popen(host, argv, env=host_env(host, cls.tmp), text=True,
                                 stdin=subprocess.PIPE if stdin else subprocess.DEVNULL,
                                 stdout=subprocess.PIPE if stdin else log, stderr=log)

    @classmethod
    def read_answers(cls):
        for line in cls.client.stdout:
            if line.startswith('{'):
                cls.answers.put(json.loads(line))

    @classmethod
    def remove_graph(cls):
        if cls.net is not None:
            cls.net.remove()
            cls.net = None
        if cls.client is not None:
            try:
                cls.client.stdin.close()
            except BrokenPipeError:
                pass  # it is gone, with a request unread
            cls.client.wait()
            cls.client = None
        if cls.tmp is not None:
            shutil.rmtree(cls.tmp, ignore_errors=True)
            cls.tmp = None

    @classmethod
    def tearDownClass(cls):
        cls.remove_graph()

    def logs(self):
        """Each host's processes and the last lines they printed, for a
        failure's message."""
        out = []
        for host in sorted(self.net.hosts if self.net else []):
            log = os.path.join(self.tmp, host + '.log')
            printed = ''
            if os.path.exists(log):
                with open(log, errors='replace') as f:
                    printed = f.read()[-1500:]
            out.append('--- %s: processes (PID, state, command) ---\n%s\n--- %s: output ---\n%s'
                       % (host, '\n'.join(self.net.processes(host)), host, printed))
        return '\n'.join(out)

    def ask(self, op, duration=0.0, **request):
        """The client's answer to one request."""
        request['op'] = op
        try:
            self.client.stdin.write(json.dumps(request) + '\n')
            self.client.stdin.flush()
        except BrokenPipeError:
            pass  # it is gone: the failure below says so
        deadline = time.monotonic() + duration + ANSWER_MARGIN
        while self.client.poll() is None and time.monotonic() < deadline:
            try:
                return self.answers.get(timeout=0.1)
            except queue.Empty:
                pass
        self.fail('the client host did not answer %s (exit code %s):\n%s'
                  % (request, self.client.poll(), self.logs()))

    def record(self, seconds):
        return self.ask('record', seconds, seconds=seconds)

    def check_motion(self, messages, node, forces, where):
        """`messages` of `node` list its bodies of the scene in scene order,
        with increasing stamps, each body moving with dv/dt = F/m (`forces`,
        none: its scene velocity) between the first and the last."""
        bodies = [b for b in scene_bodies() if b[3] == node]
        self.assertGreaterEqual(len(messages), 2, '%s: %s published %d ~bodies messages'
                                % (where, node, len(messages)))
        stamps = [stamp for stamp, _ in messages]
        self.assertEqual(stamps, sorted(set(stamps)), '%s: %s stamps do not increase'
                         % (where, node))
        for _, states in messages:
            self.assertEqual(list(states), [b[0] for b in bodies],
                             '%s: %s publishes other bodies than its own' % (where, node))
        (t1, first), (t2, last) = messages[0], messages[-1]
        dt = (t2 - t1) * 1e-9
        for name, mass, velocity, _ in bodies:
            v1, v2 = (np.array(m[name]['velocity']) for m in (first, last))
            x1, x2 = (np.array(m[name]['position']) for m in (first, last))
            if forces is None:
                np.testing.assert_allclose(v1, velocity, rtol=0, atol=TOLERANCE,
                                           err_msg='%s: %s velocity' % (where, name))
                np.testing.assert_allclose((x2 - x1) / dt, velocity, rtol=0, atol=TOLERANCE,
                                           err_msg='%s: %s dx/dt' % (where, name))
            else:
                np.testing.assert_allclose((v2 - v1) / dt, np.array(forces[name]) / mass, rtol=0,
                                           atol=TOLERANCE,
                                           err_msg='%s: %s dv/dt against F/m' % (where, name))

    def check_pushed(self, nodes, forces, other_shard_entries, where):
        """A push of `forces`: each of `nodes` moves its bodies by them (two
        messages of the recording's second half, once the array has surely
        arrived) and counts the entries for the other shard's bodies."""
        self.ask('push', forces=forces)
        recording = self.record(1.0)
        for node in nodes:
            messages = recording['bodies'].get(node, [])
            self.check_motion(messages[len(messages) // 2:], node, forces, where)
            values = self.ask('diagnostics', DIAGNOSTICS_TIMEOUT, node=node,
                              until={'other_shard': str(other_shard_entries)},
                              timeout=DIAGNOSTICS_TIMEOUT)
            self.assertEqual(values.get('other_shard'), str(other_shard_entries),
                             '%s: %s diagnostics %s' % (where, node, values))
            self.assertEqual(values.get('rejected_messages'), '0',
                             '%s: %s diagnostics %s' % (where, node, values))
        return recording

    def check_tf(self, recording, nodes, where):
        for name, _, _, owner in scene_bodies():
            if owner in nodes:
                senders = set(map(tuple, recording['tf'].get(name, [])))
                self.assertEqual(senders, {('world', owner)},
                                 '%s: /tf world -> %s sent by %s' % (where, name, senders))

    def test_1_every_shard_steps_its_bodies(self):
        recording = self.record(1.0)
        for node in SHARD_HOSTS:
            messages = recording['bodies'].get(node, [])
            self.assertGreaterEqual(len(messages), PUBLISH_RATE / 4,
                                    '%s: %d ~bodies messages in 1 s' % (node, len(messages)))
            self.check_motion(messages, node, None, 'before any push')

    def test_2_a_wrench_reaches_the_shard_that_owns_its_body(self):
        # Two entries of each array name the other shard's bodies.
        self.check_pushed(sorted(SHARD_HOSTS), FORCES, 2, 'one push')

    def test_3_tf_from_every_shard(self):
        self.check_tf(self.record(0.5), SHARD_HOSTS, 'every shard')

    def test_4_a_lost_host_leaves_the_others_running(self):
        lost, survivor = '/rigid_body_sim_0', '/rigid_body_sim_1'
        self.net.lose(SHARD_HOSTS[lost])
        where = 'after %s\'s host went away' % lost
        # The second array on the survivor: 2 + 2 entries for the lost shard's bodies.
        recording = self.check_pushed([survivor], FORCES_AFTER_LOSS, 4, where)
        self.assertEqual(len(recording['bodies'].get(lost, [])), 0,
                         '%s: it still publishes ~bodies' % where)
        messages = recording['bodies'].get(survivor, [])
        self.assertGreaterEqual(len(messages), PUBLISH_RATE / 4,
                                '%s: %s published %d ~bodies messages in 1 s'
                                % (where, survivor, len(messages)))
        self.check_tf(recording, [survivor], where)


if __name__ == '__main__':
    # rostest ends a test that overruns its time-limit with SIGINT, then
    # SIGTERM: both interrupt the run (unittest lets only KeyboardInterrupt
    # through), which removes the network in the `finally`; SIGINT too when
    # a parent started this with it ignored.
    for signum in (signal.SIGINT, signal.SIGTERM):
        signal.signal(signum, signal.default_int_handler)
    try:
        rostest.rosrun(PKG, 'multi_host', MultiHost, sys.argv)
    finally:
        MultiHost.remove_graph()
