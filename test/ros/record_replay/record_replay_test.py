#!/usr/bin/python3
"""~record and `rosrun rigid_body_sim replay` (doc/node.md, "Record and
replay"; record_replay.test):

- the quadrotor flies in lockstep with its controller (actuator commands),
  in gusts, while this test pushes it (~base_link/wrench, a wrench job and
  its clearing), spawns and deletes a body, reconfigures the node (gravity,
  wind, integrator), pauses, steps and resumes it, resets it and sets the
  body's state, at whatever steps they land; the node records to a bag;
- the replay, with no controller, matches every recorded state hash: exit 0;
- one recorded actuator command altered by one bit: the replay names the
  first publish cycle after it, exit 1;
- a truncated copy and a bag of other topics are refused, exit 2, with a
  message naming what is wrong.
"""
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import unittest

import rosbag
import rospy
import rostest
from dynamic_reconfigure.client import Client as ReconfigureClient
from geometry_msgs.msg import Vector3, WrenchStamped
from rigid_body_sim.msg import RecordedInput
from rigid_body_sim.testing import SimClient, wait_until
from std_msgs.msg import String

LAUNCH = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'run.launch')
NODE = '/rigid_body_sim'
BALL = """
name: ball
inertial:
  mass: 0.5
  inertia: {ixx: 0.002, ixy: 0.0, ixz: 0.0, iyy: 0.002, iyz: 0.0, izz: 0.002}
position: [2.0, 0.0, 3.0]
"""
ALTERED_BIT = 44  # of the 52 mantissa bits: a change of 2^-8 relative


def replay(bag):
    """The replay's exit code, stdout and stderr."""
    done = subprocess.run(['rosrun', 'rigid_body_sim', 'replay', bag], capture_output=True,
                          text=True, timeout=120)
    sys.stderr.write('exit %d: %s%s' % (done.returncode, done.stdout, done.stderr))
    return done.returncode, done.stdout, done.stderr


def flip_bit(value, bit):
    (bits,) = struct.unpack('<Q', struct.pack('<d', value))
    (flipped,) = struct.unpack('<d', struct.pack('<Q', bits ^ (1 << bit)))
    return flipped


class RecordReplay(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('record_replay_test')
        cls.dir = tempfile.mkdtemp(prefix='record_replay_test')
        cls.bag = os.path.join(cls.dir, 'flight.bag')
        launch = subprocess.Popen(['roslaunch', LAUNCH, 'bag:=' + cls.bag],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
        try:
            cls.fly()
        finally:
            launch.send_signal(subprocess.signal.SIGINT)
            launch.wait(timeout=60.0)

    @classmethod
    def fly(cls):
        sim = SimClient(NODE, timeout=60.0)
        sim.latest(timeout=30.0)
        wrench = rospy.Publisher(NODE + '/base_link/wrench', WrenchStamped, queue_size=10)
        wait_until(lambda: wrench.get_num_connections() > 0, 10.0, 'no subscriber to the wrench')
        time.sleep(0.5)
        for i in range(5):
            msg = WrenchStamped()
            msg.header.frame_id = 'world'
            msg.wrench.force = Vector3(0.3 * i, -0.2, 0.1)
            wrench.publish(msg)
            time.sleep(0.05)
        sim.spawn(BALL)
        time.sleep(0.2)
        ReconfigureClient(NODE, timeout=10.0).update_configuration(
            {'gravity_z': -9.7, 'wind_x': 1.0, 'integrator': 'rk4'})
        time.sleep(0.2)
        sim.delete('ball')
        time.sleep(0.2)
        sim.push('base_link', (0.0, 0.5, 0.0), point=(0.1, 0.0, 0.0), duration=0.3)
        time.sleep(0.1)
        sim.clear_body_wrenches('base_link')
        sim.pause()
        sim.step(7)
        sim.resume()
        sim.reset()
        sim.set_body_state('base_link', position=(0.0, 0.0, 0.5))
        time.sleep(0.5)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def test_1_every_input_kind_is_recorded(self):
        kinds = set()
        with rosbag.Bag(self.bag) as bag:
            for _, msg, _ in bag.read_messages(topics=['/record/inputs']):
                kinds.add(msg.kind)
            self.assertGreater(bag.get_message_count('/record/cycles'), 100)
            self.assertEqual(bag.get_message_count('/record/cycles'),
                             bag.get_message_count('/record/bodies'))
        for kind in ('BODY_WRENCH', 'ACTUATOR_COMMANDS', 'WRENCH_JOB', 'CLEAR_BODY_WRENCHES',
                     'SPAWN', 'DELETE', 'RESET', 'RECONFIGURE', 'BODY_STATE', 'PAUSE', 'STEP',
                     'RESUME', 'END'):
            self.assertIn(getattr(RecordedInput, kind), kinds, kind)

    def test_2_replay_matches_every_cycle(self):
        code, out, err = replay(self.bag)
        self.assertEqual(code, 0, out + err)
        self.assertIn('state hashes match', out)

    def test_3_one_bit_changed_is_found_at_its_cycle(self):
        altered = os.path.join(self.dir, 'altered.bag')
        cycle_steps = []
        target = None
        with rosbag.Bag(self.bag) as bag, rosbag.Bag(altered, 'w') as out:
            for topic, msg, t in bag.read_messages():
                if topic == '/record/cycles':
                    cycle_steps.append(msg.step)
                if (target is None and topic == '/record/inputs' and
                        msg.kind == RecordedInput.ACTUATOR_COMMANDS and msg.step > 200 and
                        msg.values[0] != 0.0):
                    values = list(msg.values)
                    values[0] = flip_bit(values[0], ALTERED_BIT)
                    msg.values = values
                    target = msg.step
                out.write(topic, msg, t)
        self.assertIsNotNone(target, 'no actuator command after step 200')
        first_after = min(step for step in cycle_steps if step > target)
        code, out, err = replay(altered)
        self.assertEqual(code, 1, out + err)
        self.assertIn('(step %d,' % first_after, out)

    def test_4_truncated_bag_is_refused(self):
        half = os.path.join(self.dir, 'half.bag')
        with open(self.bag, 'rb') as whole, open(half, 'wb') as part:
            part.write(whole.read(os.path.getsize(self.bag) // 2))
        code, out, err = replay(half)
        self.assertEqual(code, 2, out + err)
        self.assertIn('is truncated or damaged: its index cannot be read', err)
        # Cut after its last input: the bag is whole, the recording is not.
        unended = os.path.join(self.dir, 'unended.bag')
        with rosbag.Bag(self.bag) as bag, rosbag.Bag(unended, 'w') as out_bag:
            for topic, msg, t in bag.read_messages():
                if topic != '/record/inputs' or msg.kind != RecordedInput.END:
                    out_bag.write(topic, msg, t)
        code, out, err = replay(unended)
        self.assertEqual(code, 2, out + err)
        self.assertIn('is truncated: it ends after', err)
        # And one that is not a bag at all.
        text = os.path.join(self.dir, 'text.bag')
        with open(text, 'w') as not_a_bag:
            not_a_bag.write('hello\n')
        code, out, err = replay(text)
        self.assertEqual(code, 2, out + err)
        self.assertIn('is not a bag', err)

    def test_5_bag_of_other_topics_is_refused(self):
        other = os.path.join(self.dir, 'other.bag')
        with rosbag.Bag(other, 'w') as bag:
            bag.write('/chatter', String(data='hello'), rospy.Time(1))
        code, out, err = replay(other)
        self.assertEqual(code, 2, out + err)
        self.assertIn('not a recording', err)
        self.assertIn('/chatter', err)


if __name__ == '__main__':
    rostest.rosrun('rigid_body_sim', 'record_replay_test', RecordReplay)
