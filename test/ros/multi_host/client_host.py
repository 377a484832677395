#!/usr/bin/python3
"""The client host of multi_host_test.py: a ROS node on a machine of its own
that publishes wrench arrays on /rigid_body_sim/particle_wrenches, as a
controller would, and records what the shards publish. It does what the test
asks, one JSON request a line on stdin, and answers each with one JSON line
on stdout (anything else it prints starts with another character than '{'):

  {"op": "ready", "shards": [NODE, ...], "timeout": S}
      waits until every shard's ~bodies has arrived and every shard has
      subscribed to the wrench array; {"missing": [what is still missing]}
  {"op": "record", "seconds": S}
      {"bodies": {NODE: [[stamp_ns, {BODY: {"position": [x, y, z],
      "velocity": [vx, vy, vz]}}], ...]}, "tf": {CHILD: [[PARENT, NODE], ...]}}:
      every ~bodies message (and /tf transform) that arrives in the next S s
  {"op": "push", "forces": {BODY: [fx, fy, fz]}}
      one ParticleWrenchArray, each force on particle 0 of its body; {}
  {"op": "diagnostics", "node": NODE, "until": {KEY: VALUE}, "timeout": S}
      the node's diagnostics values once they hold `until`, or its last ones
      after S s; {} when none came
"""
import json
import sys
import threading
import time

import rospy
from diagnostic_msgs.msg import DiagnosticArray
from rigid_body_sim.msg import BodyStateArray, ParticleWrenchArray
from rigid_body_sim.testing import particle_wrench
from tf2_msgs.msg import TFMessage

WRENCH_TOPIC = '/rigid_body_sim/particle_wrenches'


def xyz(vector):
    return [vector.x, vector.y, vector.z]


class Client(object):
    def __init__(self):
        self.lock = threading.Lock()
        self.seen = set()         # shards whose ~bodies arrived
        self.recording = None     # what `record` collects while it runs
        self.diagnostics = {}     # node -> its last values
        self.subscribers = {}
        self.wrenches = rospy.Publisher(WRENCH_TOPIC, ParticleWrenchArray, queue_size=10)
        rospy.Subscriber('/tf', TFMessage, self.on_tf, queue_size=1000)
        rospy.Subscriber('/diagnostics', DiagnosticArray, self.on_diagnostics, queue_size=100)

    def subscribe(self, node):
        if node not in self.subscribers:
            self.subscribers[node] = rospy.Subscriber(
                node + '/bodies', BodyStateArray, lambda msg: self.on_bodies(node, msg),
                queue_size=1000)

    def on_bodies(self, node, msg):
        bodies = {b.name: {'position': xyz(b.pose.position), 'velocity': xyz(b.twist.linear)}
                  for b in msg.bodies}
        with self.lock:
            self.seen.add(node)
            if self.recording is not None:
                self.recording['bodies'].setdefault(node, []).append(
                    [msg.header.stamp.to_nsec(), bodies])

    def on_tf(self, msg):
        node = msg._connection_header['callerid']
        with self.lock:
            if self.recording is not None:
                for t in msg.transforms:
                    self.recording['tf'].setdefault(t.child_frame_id, []).append(
                        [t.header.frame_id, node])

    def on_diagnostics(self, msg):
        with self.lock:
            for status in msg.status:
                if status.name.endswith(': simulation'):
                    node = '/' + status.name[:-len(': simulation')]
                    self.diagnostics[node] = {kv.key: kv.value for kv in status.values}

    def ready(self, shards, timeout):
        for node in shards:
            self.subscribe(node)
        deadline = time.monotonic() + timeout
        while True:
            with self.lock:
                missing = ['%s/bodies' % n for n in shards if n not in self.seen]
            subscribed = self.wrenches.get_num_connections()
            if subscribed < len(shards):
                missing.append('%s: %d of %d shards subscribed' % (WRENCH_TOPIC, subscribed,
                                                                    len(shards)))
            if not missing or time.monotonic() >= deadline:
                return {'missing': missing}
            time.sleep(0.05)

    def record(self, seconds):
        with self.lock:
            self.recording = {'bodies': {}, 'tf': {}}
        time.sleep(seconds)
        with self.lock:
            recording, self.recording = self.recording, None
        return recording

    def push(self, forces):
        self.wrenches.publish(ParticleWrenchArray(wrenches=[
            particle_wrench(body, force=force) for body, force in sorted(forces.items())]))
        return {}

    def wait_diagnostics(self, node, until, timeout):
        deadline = time.monotonic() + timeout
        while True:
            with self.lock:
                values = dict(self.diagnostics.get(node, {}))
            if all(values.get(k) == v for k, v in until.items()) or time.monotonic() >= deadline:
                return values
            time.sleep(0.05)

    def serve(self, requests, answers):
        for line in requests:
            request = json.loads(line)
            op = request.pop('op')
            if op == 'ready':
                answer = self.ready(**request)
            elif op == 'record':
                answer = self.record(**request)
            elif op == 'push':
                answer = self.push(**request)
            elif op == 'diagnostics':
                answer = self.wait_diagnostics(**request)
            else:
                answer = {'error': 'unknown op %r' % op}
            answers.write(json.dumps(answer) + '\n')
            answers.flush()


if __name__ == '__main__':
    rospy.init_node('multi_host_client', disable_signals=True)
    Client().serve(sys.stdin, sys.stdout)
