#!/usr/bin/python3
"""The client rigid_body_sim.testing against the node of client.test, each
call checked against a closed form (no gravity, no damping; the box's
orientation turns body x, y, z into world y, z, x exactly):

- a body wrench in step(n) acts on exactly those n steps: a constant force
  at the COM, in world or body axes, gives Delta p = F n dt and a world
  couple Delta L = T n dt, to round-off, and step n + 1 sees none of it;
- a force at a point of the body gives the torque r x f: Delta L over one
  step is (r x f) dt within the dt^3 term of the exact flow;
- set_body_state, then step: the body moved by v dt, spinning about a
  principal axis by omega dt; refusals raise RuntimeError with the node's
  message;
- clear_wrenches() drops held particle wrenches and jobs on every body,
  clear_body_wrenches(body) on that body alone;
- StepResult.stamp and SimClient.stamp() are the published header's stamp
  exactly, on the time lattice; sim_time is its to_sec();
- the client snippets of README.md and doc/testing.md run as written;
- a body wrench in a LockstepController's answer acts on exactly the steps
  up to the next cycle; an actuator command in one is held: the puck's jet
  (no lag, along world z) pushes on through the cycles after it.
"""
import os
import re
import subprocess
import sys
import time
import unittest

import numpy as np
import rospkg
import rospy
import rostest
from rigid_body_sim.msg import ActuatorCommand
from rigid_body_sim.testing import (LockstepController, SimClient, body_wrench, particle_wrench,
                                    state_hash)

PKG = 'rigid_body_sim'
NODE = '/rigid_body_sim'
RATE_HZ = 300                     # ~rate of client.test
LOCKSTEP_NODE = '/lockstep_sim'   # 1 kHz, publishing at 100 Hz
LOCKSTEP_CYCLE_NS = 10000000
EPS = np.finfo(float).eps
BOX_MASS = 2.0                    # the box of client.test
BOX_SIZE = np.array([0.3, 0.2, 0.1])
# Resolution 2: eight masses m/8 at (+-a/4, +-b/4, +-c/4), principal axes the
# body axes, I_x = m ((b/4)^2 + (c/4)^2) and so on.
BOX_MOMENTS = BOX_MASS * np.array([
    (BOX_SIZE[1] / 4) ** 2 + (BOX_SIZE[2] / 4) ** 2,
    (BOX_SIZE[0] / 4) ** 2 + (BOX_SIZE[2] / 4) ** 2,
    (BOX_SIZE[0] / 4) ** 2 + (BOX_SIZE[1] / 4) ** 2])
BOX_ORIENTATION = np.array([0.5, 0.5, 0.5, 0.5])  # x, y, z, w
SNIPPET_TIMEOUT = 60.0            # s


def quaternion_multiply(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return np.array([aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw,
                     aw * bw - ax * bx - ay * by - az * bz])


def rotate(q, v):
    """v turned by the unit quaternion q = (x, y, z, w)."""
    conjugate = q * np.array([-1.0, -1.0, -1.0, 1.0])
    return quaternion_multiply(quaternion_multiply(q, np.append(v, 0.0)), conjugate)[:3]


def lattice_ns(k):
    """t_k = round(k 1e9 / rate) ns, half up, in integers."""
    return (2 * k * 10 ** 9 + RATE_HZ) // (2 * RATE_HZ)


def python_blocks(text):
    return re.findall(r'(?ms)^```python\n(.*?)^```', text)


def answer_until(control, done, timeout_s=20.0):
    """Answers lockstep_sim's cycles with a LockstepController on `control`
    until done() or timeout_s of wall time."""
    controller = LockstepController(control, LOCKSTEP_NODE)
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline and not done():
        time.sleep(0.05)
    controller.stop()


class Client(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('client_test')
        cls.sim = SimClient(NODE)

    def setUp(self):
        self.sim.pause()
        self.sim.reset()

    def assertClose(self, actual, expected, tolerance, msg=None):
        error = np.max(np.abs(np.asarray(actual) - np.asarray(expected)))
        self.assertLessEqual(error, tolerance, '%s: %r != %r (error %.3g > %.3g)'
                             % (msg, actual, expected, error, tolerance))

    def test_rate_and_dt(self):
        self.assertEqual(self.sim.rate, RATE_HZ)
        self.assertEqual(self.sim.dt, 1.0 / RATE_HZ)

    def check_constant_wrench(self, wrench, force_world, couple_world, steps):
        """A body wrench on the box at rest for `steps` steps, then one more
        step without it."""
        dt = self.sim.dt
        before = self.sim.step(1).states['box']
        after = self.sim.step(steps, body_wrenches=[wrench]).states['box']
        impulse = np.asarray(force_world) * steps * dt
        # Each step adds to p in a few kicks, each rounding once.
        self.assertClose(after.linear_momentum - before.linear_momentum, impulse,
                         8 * steps * EPS * np.linalg.norm(impulse), 'Delta p')
        angular_impulse = np.asarray(couple_world) * steps * dt
        self.assertClose(after.angular_momentum - before.angular_momentum, angular_impulse,
                         8 * steps * EPS * np.linalg.norm(angular_impulse), 'Delta L')
        following = self.sim.step(1).states['box']
        self.assertEqual(list(following.linear_momentum), list(after.linear_momentum))
        # Torque-free, L is constant in world axes up to the rotations' round-off.
        self.assertClose(following.angular_momentum, after.angular_momentum,
                         8 * EPS * np.linalg.norm(after.angular_momentum), 'L on step n + 1')

    def test_body_wrench_world_axes_acts_on_exactly_its_steps(self):
        for steps in (1, 7, 30):
            self.check_constant_wrench(
                body_wrench('box', force=(0.7, -1.3, 2.1), torque=(0.02, 0.05, -0.03)),
                (0.7, -1.3, 2.1), (0.02, 0.05, -0.03), steps)

    def test_body_wrench_body_axes_at_the_com(self):
        # At the COM the force turns nothing, so its world direction stays.
        force_body = np.array([0.7, -1.3, 2.1])
        force_world = rotate(BOX_ORIENTATION, force_body)
        self.assertClose(force_world, [2.1, 0.7, -1.3], 4 * EPS, 'the box turns x, y, z into y, z, x')
        for steps in (1, 7, 30):
            self.check_constant_wrench(body_wrench('box', force=force_body, frame='box'),
                                       force_world, (0.0, 0.0, 0.0), steps)
        self.assertClose(self.sim.step(1).states['box'].orientation, BOX_ORIENTATION, 4 * EPS,
                         'orientation')

    def test_force_at_a_point_gives_the_torque_r_cross_f(self):
        dt = self.sim.dt
        point = np.array([0.15, 0.0, 0.0])          # body frame: an end of the box
        force = np.array([0.4, 1.0, 0.5])           # world axes
        lever = rotate(BOX_ORIENTATION, point)
        torque = np.cross(lever, force)
        before = self.sim.step(1).states['box']
        after = self.sim.step(1, body_wrenches=[body_wrench('box', force=force, point=point)])
        box = after.states['box']
        self.assertClose(box.linear_momentum - before.linear_momentum, force * dt,
                         8 * EPS * np.linalg.norm(force * dt), 'Delta p')
        # From rest the lever turns by theta(t) = alpha t^2 / 2, alpha = I^-1
        # tau, so the exact Delta L is tau dt + ((alpha x r) x f) dt^3 / 6 +
        # O(dt^5); the scheme's own error, O(dt^5) at order 4, is far below.
        alpha_bound = np.linalg.norm(torque) / BOX_MOMENTS.min()
        tolerance = 2 * alpha_bound * np.linalg.norm(point) * np.linalg.norm(force) * dt ** 3 / 6
        self.assertLess(tolerance, 1e-3 * np.linalg.norm(torque) * dt)  # a check with teeth
        self.assertClose(box.angular_momentum - before.angular_momentum, torque * dt, tolerance,
                         'Delta L')

    def test_set_body_state_then_step(self):
        dt = self.sim.dt
        position = np.array([0.25, -1.5, 3.0])
        velocity = np.array([0.8, 0.3, -1.1])
        self.sim.set_body_state('puck', position=position, linear_velocity=velocity)
        puck = self.sim.step(1).states['puck']
        self.assertClose(puck.position, position + velocity * dt, 4 * EPS * np.linalg.norm(position),
                         'puck position')
        self.assertClose(puck.linear_velocity, velocity, 4 * EPS * np.linalg.norm(velocity),
                         'puck velocity')

        # About a principal axis (body z) a free body turns steadily.
        orientation = np.array([0.0, 0.0, np.sin(0.3), np.cos(0.3)])
        axis = rotate(orientation, [0.0, 0.0, 1.0])
        spin = 2.0
        self.sim.set_body_state('box', position=position, orientation=orientation,
                                linear_velocity=velocity, angular_velocity=spin * axis)
        box = self.sim.step(1).states['box']
        self.assertClose(box.position, position + velocity * dt, 4 * EPS * np.linalg.norm(position),
                         'box position')
        turn = np.append(axis * np.sin(spin * dt / 2), np.cos(spin * dt / 2))
        self.assertClose(box.orientation, quaternion_multiply(turn, orientation), 64 * EPS,
                         'box orientation')
        self.assertClose(box.angular_velocity, spin * axis, 64 * EPS * spin, 'box angular velocity')

        # Defaults: at the origin, identity, at rest.
        self.sim.set_body_state('box')
        box = self.sim.step(1).states['box']
        self.assertEqual(list(box.position), [0.0, 0.0, 0.0])
        self.assertEqual(list(box.orientation), [0.0, 0.0, 0.0, 1.0])
        self.assertEqual(list(box.linear_momentum) + list(box.angular_momentum), [0.0] * 6)

        with self.assertRaisesRegex(RuntimeError, "set_body_state: .*'ghost'"):
            self.sim.set_body_state('ghost')
        with self.assertRaisesRegex(RuntimeError, 'set_body_state: pose.orientation must be'):
            self.sim.set_body_state('box', orientation=(0, 0, 0, 0))

    def test_a_refused_body_wrench_takes_no_step(self):
        stamp = self.sim.step(1).stamp
        with self.assertRaisesRegex(RuntimeError, 'apply_body_wrench: reference_frame: '):
            self.sim.step(3, body_wrenches=[body_wrench('box', force=(1, 0, 0), frame='nowhere')])
        with self.assertRaises(ValueError):
            self.sim.step(0, body_wrenches=[body_wrench('box', force=(1, 0, 0))])
        self.assertEqual(self.sim.step(1).stamp.to_nsec() - stamp.to_nsec(),
                         lattice_ns(self.lattice_index(stamp) + 1) - stamp.to_nsec())

    def test_clear_wrenches(self):
        dt = self.sim.dt
        force = np.array([0.0, 0.0, 2.0])
        self.sim.push('box', force=(1.0, 0.0, 0.0))  # a job until cleared
        before = self.sim.step(1).states
        held = self.sim.step_with_wrenches([particle_wrench('puck', force=force)], 2).states
        self.assertClose(held['puck'].linear_momentum - before['puck'].linear_momentum,
                         2 * force * dt, 8 * EPS, 'held particle wrench')
        self.assertClose(held['box'].linear_momentum - before['box'].linear_momentum,
                         [2 * dt, 0.0, 0.0], 8 * EPS, 'held job')
        self.sim.clear_wrenches()
        cleared = self.sim.step(3).states
        for body in ('puck', 'box'):
            self.assertEqual(list(cleared[body].linear_momentum), list(held[body].linear_momentum),
                             body)

        # One body's only.
        self.sim.push('box', force=(1.0, 0.0, 0.0))
        self.sim.step_with_wrenches([particle_wrench('puck', force=force)], 1)
        self.sim.clear_body_wrenches('puck')
        before = self.sim.step(1).states
        after = self.sim.step(2).states
        self.assertEqual(list(after['puck'].linear_momentum), list(before['puck'].linear_momentum))
        self.assertClose(after['box'].linear_momentum - before['box'].linear_momentum,
                         [2 * dt, 0.0, 0.0], 8 * EPS, 'the box keeps its job')
        self.sim.clear_body_wrenches()
        last = self.sim.step(2).states
        self.assertEqual(list(last['box'].linear_momentum), list(after['box'].linear_momentum))
        with self.assertRaisesRegex(RuntimeError, "clear_body_wrenches: body: .*'ghost'"):
            self.sim.clear_body_wrenches('ghost')

    def lattice_index(self, stamp):
        """k with t_k = stamp, failing when the stamp is off the lattice."""
        k = (stamp.to_nsec() * RATE_HZ + 5 * 10 ** 8) // 10 ** 9
        self.assertEqual(lattice_ns(k), stamp.to_nsec(), 'off the lattice')
        return k

    def published(self, result, timeout=5.0):
        """The ~bodies message the step of `result` published."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            msg = self.sim.latest()
            if state_hash(msg) == result.state_hash:
                return msg
            time.sleep(0.01)
        self.fail('no ~bodies message with the state of the step')

    def test_stamps_are_exact_and_on_the_lattice(self):
        # Moving, so that every step's state (and hash) is new.
        self.sim.set_body_state('puck', linear_velocity=(1.0, 0.0, 0.0))
        first = self.sim.step(1)
        k = self.lattice_index(first.stamp)
        for steps in (1, 2, 5, 7):
            result = self.sim.step(steps)
            self.assertIsInstance(result.stamp, rospy.Time)
            k += steps
            self.assertEqual(result.stamp.to_nsec(), lattice_ns(k))
            header = self.published(result).header.stamp
            self.assertEqual(result.stamp, rospy.Time(header.secs, header.nsecs))
            self.assertEqual(self.sim.stamp(), result.stamp)
            self.assertIsInstance(self.sim.stamp(), rospy.Time)
            self.assertEqual(result.sim_time, result.stamp.to_sec())

    def test_documented_snippets_run(self):
        """Every python block of README.md and doc/testing.md that imports the
        client runs as a script against this node, in order and without a
        reset between them, as a reader would run them; one without its own
        rospy.init_node gets one first."""
        root = rospkg.RosPack().get_path(PKG)
        blocks = []
        for document in ('README.md', os.path.join('doc', 'testing.md')):
            with open(os.path.join(root, document)) as f:
                blocks += [(document, block) for block in python_blocks(f.read())
                           if 'rigid_body_sim.testing import' in block]
        self.assertGreaterEqual(len(blocks), 3)
        for document, block in blocks:
            if 'rospy.init_node' not in block:
                block = "import rospy\nrospy.init_node('snippet', anonymous=True)\n" + block
            run = subprocess.run([sys.executable, '-c', block], stdout=subprocess.PIPE,
                                 stderr=subprocess.PIPE, universal_newlines=True,
                                 timeout=SNIPPET_TIMEOUT)
            self.assertEqual(run.returncode, 0, '%s:\n%s\n%s' % (document, block, run.stderr))


    def test_a_body_wrench_in_a_lockstep_answer_acts_until_the_next_cycle(self):
        momentum = {}  # stamp [ns] -> lockstep_sim's puck's p_y
        pushed_at = []

        def control(states, stamp):
            momentum[stamp.to_nsec()] = states['puck'].linear_momentum[1]
            if not pushed_at and len(momentum) >= 3:
                pushed_at.append(stamp.to_nsec())
                return [body_wrench('puck', force=(0.0, 3.0, 0.0))]
            return []

        answer_until(control, lambda: pushed_at and pushed_at[0] + 2 * LOCKSTEP_CYCLE_NS in momentum)
        self.assertTrue(pushed_at, 'no cycle reached the controller')
        start = pushed_at[0]
        self.assertIn(start + 2 * LOCKSTEP_CYCLE_NS, momentum, 'the cycles after the push did not come')
        # 3 N on the 10 steps of that cycle, none on the next.
        self.assertAlmostEqual(momentum[start + LOCKSTEP_CYCLE_NS] - momentum[start], 3.0 * 10 * 1e-3,
                               delta=1e-15)
        self.assertEqual(momentum[start + 2 * LOCKSTEP_CYCLE_NS], momentum[start + LOCKSTEP_CYCLE_NS])

    def test_an_actuator_command_in_a_lockstep_answer_is_held(self):
        momentum = {}  # stamp [ns] -> lockstep_sim's puck's p_z
        commanded_at = []

        def control(states, stamp):
            momentum[stamp.to_nsec()] = states['puck'].linear_momentum[2]
            if not commanded_at and len(momentum) >= 3:
                commanded_at.append(stamp.to_nsec())
                return [ActuatorCommand(body='puck', names=['jet'], commands=[2.0])]
            return []

        answer_until(control, lambda: commanded_at and commanded_at[0] + 2 * LOCKSTEP_CYCLE_NS in momentum)
        self.assertTrue(commanded_at, 'no cycle reached the controller')
        start = commanded_at[0]
        self.assertIn(start + 2 * LOCKSTEP_CYCLE_NS, momentum, 'the cycles after the command did not come')
        # 2 N on the 10 steps of that cycle and, held, on the next 10.
        for cycle in (1, 2):
            self.assertAlmostEqual(momentum[start + cycle * LOCKSTEP_CYCLE_NS] -
                                   momentum[start + (cycle - 1) * LOCKSTEP_CYCLE_NS], 2.0 * 10 * 1e-3,
                                   delta=1e-15)


if __name__ == '__main__':
    rostest.rosrun(PKG, 'client', Client, sys.argv)
