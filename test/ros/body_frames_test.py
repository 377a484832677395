#!/usr/bin/python3
"""A body's frames in the outputs (doc/node.md, "Frames of a body";
body_frames.test):

- `lever` (`frame: reference`, O at r = A(−x̄_CM) from the COM, isotropic,
  no gravity): a job in its frame at a point p from O, and then the applied
  wrench it reads sent back on ~lever/wrench with its frame_id, each give
  Δp = A f dt and ΔL = A(c + r_p × f) dt over their step (r_p from the COM,
  to the body's turn within the step), and read back about O; after
  ~set_body_state of O's pose and twist, one torque-free step later ~bodies,
  ~lever/pose and ~lever/twist are the closed-form rotation of that state;
- `arm` (`frame: reference`, x̄_CM = (0.3, 0, 0), spinning at 2 rad/s about
  z under gravity): /tf, ~arm/pose and ~arm/odom give the reference origin,
  x + A(−x̄_CM), ~arm/twist and ~arm/odom its velocity v + ω × A(−x̄_CM)
  (world axes, and body axes for the odometry); ~arm/imu reads the specific force of that origin (its finite
  difference across the step; about the centripetal −ω² r, as free fall
  cancels g); ~arm/applied_wrench gives gravity's torque about the origin,
  x̄_CM × F in body axes;
- its sites are on /tf_static, children of sim/arm, placed from the
  reference origin; a spawned body's sites join them and leave with it;
- `quad` (from config/quadrotor.urdf): its TF frame is its root link,
  sim/base_link; its links are not on /tf_static; ~joint_states names its
  four rotor joints at 0, stamped as ~bodies, and so does its own
  /uav1/joint_states; with `namespace: /uav1` its topics are /uav1/pose,
  /uav1/odom, ... and /uav1/wrench pushes it; a spawned body may not take
  that namespace, and takes a free one.
"""
import math
import threading
import time
import unittest

import numpy as np
import rospy
import rostest
from geometry_msgs.msg import PoseStamped, TwistStamped, WrenchStamped
from nav_msgs.msg import Odometry
from rigid_body_sim.msg import BodyStateArray
from rigid_body_sim.testing import SimClient, body_wrench
from sensor_msgs.msg import Imu, JointState
from tf2_msgs.msg import TFMessage

PKG = 'rigid_body_sim'
NODE = '/rigid_body_sim'
G = np.array([0.0, 0.0, -9.81])
MASS = 4.0
COM = np.array([0.3, 0.0, 0.0])  # x̄_CM, reference coordinates
HALF = math.sqrt(0.5)
ROTORS = ['rotor_0_joint', 'rotor_1_joint', 'rotor_2_joint', 'rotor_3_joint']
LEVER_COM = np.array([0.4, 0.2, -0.1])  # x̄_CM of `lever`, reference coordinates
# The impulse of a held body-axes wrench over a step is A f dt to the body's
# turn within the step and since it started to turn (a few 1e-6 rad).
TURN = 1e-5
# Position round-off of a rotated 0.3 m offset; velocities of ~1 m/s.
TIGHT = 1e-12
# An IMU's finite difference of velocities ~1 m/s over dt = 1e-3 s.
DIFFERENCE = 1e-9
SPAWNED = """
name: tool
particles: [{mass: 1.0, position: [0.0, 0.0, 0.0]}, {mass: 1.0, position: [0.2, 0.0, 0.0]}]
sites: [{name: tool_grip, position: [0.2, 0.0, 0.0]}]
position: [0.0, -3.0, 0.0]
gravity_scale: 0.0
"""


def rotate(q, v):
    """v turned by the unit quaternion q = (x, y, z, w)."""
    u, w = np.asarray(q[:3]), q[3]
    return v + 2.0 * np.cross(u, np.cross(u, v) + w * v)


def xyz(msg):
    return np.array([msg.x, msg.y, msg.z])


def xyzw(msg):
    return np.array([msg.x, msg.y, msg.z, msg.w])


def quaternion_multiply(a, b):
    """a * b for (x, y, z, w) quaternions."""
    av, aw, bv, bw = np.asarray(a[:3]), a[3], np.asarray(b[:3]), b[3]
    return np.concatenate([aw * bv + bw * av + np.cross(av, bv), [aw * bw - av.dot(bv)]])


def inverse(q):
    return np.asarray(q) * [-1, -1, -1, 1]


class BodyFrames(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('body_frames_test')
        cls.lock = threading.Lock()
        cls.messages = {name: [] for name in (
            'bodies', 'tf', 'tf_static', 'pose', 'odom', 'imu', 'wrench', 'joints', 'uav1_odom',
            'uav1_applied', 'uav2_pose', 'twist', 'uav1_joints', 'lever_pose', 'lever_twist',
            'lever_applied')}
        for name, topic, msg_type in (
                ('bodies', NODE + '/bodies', BodyStateArray), ('tf', '/tf', TFMessage),
                ('tf_static', '/tf_static', TFMessage), ('pose', NODE + '/arm/pose', PoseStamped),
                ('odom', NODE + '/arm/odom', Odometry), ('imu', NODE + '/arm/imu', Imu),
                ('wrench', NODE + '/arm/applied_wrench', WrenchStamped),
                ('joints', NODE + '/joint_states', JointState),
                ('uav1_odom', '/uav1/odom', Odometry),
                ('uav1_applied', '/uav1/applied_wrench', WrenchStamped),
                ('uav2_pose', '/uav2/pose', PoseStamped),
                ('twist', NODE + '/arm/twist', TwistStamped),
                ('uav1_joints', '/uav1/joint_states', JointState),
                ('lever_pose', NODE + '/lever/pose', PoseStamped),
                ('lever_twist', NODE + '/lever/twist', TwistStamped),
                ('lever_applied', NODE + '/lever/applied_wrench', WrenchStamped)):
            rospy.Subscriber(topic, msg_type, cls.on(cls.messages[name]), queue_size=1000)
        cls.sim = SimClient(NODE)

    @classmethod
    def on(cls, messages):
        def callback(msg):
            with cls.lock:
                messages.append(msg)
        return callback

    def wait_for(self, name, predicate, what, timeout=20.0, since=0):
        """The last message on `name`, from the `since`-th on, that meets
        `predicate`."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            with self.lock:
                found = [m for m in self.messages[name][since:] if predicate(m)]
            if found:
                return found[-1]
            time.sleep(0.02)
        self.fail('no %s within %g s' % (what, timeout))

    def at(self, name, stamp):
        return self.wait_for(name, lambda m: self.stamp_of(m) == stamp,
                             '%s at %d ns' % (name, stamp))

    @staticmethod
    def stamp_of(msg):
        if isinstance(msg, TFMessage):
            return msg.transforms[0].header.stamp.to_nsec() if msg.transforms else None
        return msg.header.stamp.to_nsec()

    @staticmethod
    def static_frames(msg):
        return {t.child_frame_id: t for t in msg.transforms}

    def expect_impulse(self, before, after, force, torque):
        """`lever`'s Δp and ΔL from `before` to `after` (BodyStates a step
        apart) are those of `force` at its COM and `torque` about it, body
        axes of `before`, over dt."""
        dt = self.sim.dt
        for change, body_axes in ((after.linear_momentum - before.linear_momentum, force),
                                  (after.angular_momentum - before.angular_momentum, torque)):
            expected = rotate(before.orientation, body_axes) * dt
            np.testing.assert_allclose(change, expected, atol=TURN * np.linalg.norm(expected))

    def expect_applied(self, reading, before, after, force, torque):
        """`reading` (~lever/applied_wrench) is `force` at the COM and `torque`
        about it, body axes of `before` (the step's start), read about O in
        the body axes of `after`: Aₐᵀ A_b f and Aₐᵀ A_b τ − (−x̄_CM) × that."""
        def to_after(v):
            return rotate(inverse(after.orientation), rotate(before.orientation, v))
        self.assertEqual(reading.header.frame_id, 'sim/lever')
        f = to_after(force)
        np.testing.assert_allclose(xyz(reading.wrench.force), f, atol=TIGHT)
        np.testing.assert_allclose(xyz(reading.wrench.torque),
                                   to_after(torque) - np.cross(-LEVER_COM, f), atol=TIGHT)

    def wait_for_outputs(self):
        """Every output the tests step and read flows (their topics are
        advertised after start), before the first test pauses the node."""
        for name in ('pose', 'twist', 'odom', 'imu', 'wrench', 'joints', 'uav1_joints',
                     'lever_pose', 'lever_twist', 'lever_applied'):
            self.wait_for(name, lambda m: True, 'message on ' + name)

    def test_a_reference_body_pushed_in_its_frame_and_set_at_its_origin(self):
        self.wait_for_outputs()
        self.sim.pause()
        start = self.sim.step(1).states['lever']

        # A job in the lever's frame for one step: f at p (from O, body axes), couple c.
        f, c, p = np.array([0.3, -0.2, 0.5]), np.array([0.02, 0.01, -0.03]), np.array([0.1, -0.3, 0.2])
        pushed = self.sim.step(1, [body_wrench('lever', force=f, torque=c, point=p, frame='lever')])
        torque = c + np.cross(p - LEVER_COM, f)  # about the COM: r_p = p − x̄_CM
        self.expect_impulse(start, pushed.states['lever'], f, torque)
        applied = self.at('lever_applied', pushed.stamp.to_nsec())
        self.expect_applied(applied, start, pushed.states['lever'], f, torque)

        # The reading sent back on ~lever/wrench (frame_id sim/lever, its force
        # at O): the same impulse, in the body axes of its step.
        echo = rospy.Publisher(NODE + '/lever/wrench', WrenchStamped, queue_size=1, latch=True)
        echo.publish(applied)
        before = pushed
        for _ in range(200):  # until the node holds it: a step whose reading is not zero
            after = self.sim.step(1)
            reading = self.at('lever_applied', after.stamp.to_nsec())
            if any(xyz(reading.wrench.force)):
                break
            before = after
        else:
            self.fail('the wrench sent back did not act within 200 steps')
        echoed_force = xyz(applied.wrench.force)
        echoed_torque = xyz(applied.wrench.torque) + np.cross(-LEVER_COM, echoed_force)
        self.expect_impulse(before.states['lever'], after.states['lever'], f, torque)
        self.expect_applied(reading, before.states['lever'], after.states['lever'], echoed_force,
                            echoed_torque)
        self.sim.clear_body_wrenches('lever')
        echo.unregister()

        # ~set_body_state: O at `origin`, moving at `velocity`, turning at ω.
        # One torque-free step of the isotropic lever turns it by exp(ω dt)
        # and moves its COM at a constant v = v_O − ω × r.
        origin, velocity = np.array([-4.0, 1.0, 2.0]), np.array([0.5, -0.3, 0.2])
        omega = np.array([0.4, -0.7, 1.1])
        q0 = np.array([0.1, 0.3, -0.2, 0.9]) / np.linalg.norm([0.1, 0.3, -0.2, 0.9])
        self.sim.set_body_state('lever', origin, q0, velocity, omega)
        stepped = self.sim.step(1)
        dt = self.sim.dt
        angle = np.linalg.norm(omega) * dt
        turn = np.concatenate([math.sin(angle / 2) * omega / np.linalg.norm(omega),
                               [math.cos(angle / 2)]])
        q1 = quaternion_multiply(turn, q0)
        r0, r1 = rotate(q0, -LEVER_COM), rotate(q1, -LEVER_COM)
        com_velocity = velocity - np.cross(omega, r0)
        com = origin - r0 + com_velocity * dt
        lever = stepped.states['lever']
        np.testing.assert_allclose(lever.position, com, atol=TIGHT)
        np.testing.assert_allclose(lever.linear_velocity, com_velocity, atol=TIGHT)
        np.testing.assert_allclose(lever.angular_velocity, omega, atol=TIGHT)
        pose = self.at('lever_pose', stepped.stamp.to_nsec())
        np.testing.assert_allclose(xyz(pose.pose.position), com + r1, atol=TIGHT)
        q = xyzw(pose.pose.orientation)
        np.testing.assert_allclose(q * np.sign(q.dot(q1)), q1, atol=TIGHT)
        twist = self.at('lever_twist', stepped.stamp.to_nsec())
        self.assertEqual(twist.header.frame_id, 'world')
        np.testing.assert_allclose(xyz(twist.twist.linear), com_velocity + np.cross(omega, r1),
                                   atol=TIGHT)
        np.testing.assert_allclose(xyz(twist.twist.angular), omega, atol=TIGHT)

    def test_reference_frame_sites_and_joints(self):
        self.wait_for_outputs()
        self.sim.pause()
        previous = self.sim.step(1)
        current = self.sim.step(1)
        stamp = current.stamp.to_nsec()
        arm, before = current.states['arm'], previous.states['arm']
        r = rotate(arm.orientation, -COM)  # COM → reference origin, world
        origin = arm.position + r
        velocity = arm.linear_velocity + np.cross(arm.angular_velocity, r)
        to_body = lambda v: rotate(arm.orientation * [-1, -1, -1, 1], v)

        tf = {t.child_frame_id: t for t in self.at('tf', stamp).transforms}
        self.assertEqual(tf['sim/arm'].header.frame_id, 'world')
        np.testing.assert_allclose(xyz(tf['sim/arm'].transform.translation), origin, atol=TIGHT)
        np.testing.assert_array_equal(xyzw(tf['sim/arm'].transform.rotation), arm.orientation)
        self.assertIn('sim/base_link', tf, 'a URDF body is its root link')
        self.assertNotIn('sim/quad', tf)

        pose = self.at('pose', stamp)
        np.testing.assert_allclose(xyz(pose.pose.position), origin, atol=TIGHT)
        twist = self.at('twist', stamp)
        self.assertEqual(twist.header.frame_id, 'world')
        np.testing.assert_allclose(xyz(twist.twist.linear), velocity, atol=TIGHT)
        np.testing.assert_array_equal(xyz(twist.twist.angular), arm.angular_velocity)
        odom = self.at('odom', stamp)
        self.assertEqual(odom.child_frame_id, 'sim/arm')
        np.testing.assert_allclose(xyz(odom.pose.pose.position), origin, atol=TIGHT)
        np.testing.assert_allclose(xyz(odom.twist.twist.linear), to_body(velocity), atol=TIGHT)
        np.testing.assert_allclose(xyz(odom.twist.twist.angular),
                                   to_body(arm.angular_velocity), atol=TIGHT)

        # The IMU: the origin's velocity across the step, less g.
        r_before = rotate(before.orientation, -COM)
        v_before = before.linear_velocity + np.cross(before.angular_velocity, r_before)
        specific_force = to_body((velocity - v_before) / self.sim.dt - G)
        imu = self.at('imu', stamp)
        self.assertEqual(imu.header.frame_id, 'sim/arm')
        np.testing.assert_allclose(xyz(imu.linear_acceleration), specific_force, atol=DIFFERENCE)
        # About the centripetal −ω² r = (1.2, 0, 0) in body axes, to ~ω·dt of it.
        np.testing.assert_allclose(xyz(imu.linear_acceleration), [1.2, 0.0, 0.0], atol=3e-3)

        # Gravity's torque about the origin: x̄_CM × M Aᵀg.
        wrench = self.at('wrench', stamp)
        self.assertEqual(wrench.header.frame_id, 'sim/arm')
        force = to_body(MASS * G)
        np.testing.assert_allclose(xyz(wrench.wrench.force), force, atol=TIGHT)
        np.testing.assert_allclose(xyz(wrench.wrench.torque), np.cross(COM, force), atol=TIGHT)

        joints = self.at('joints', stamp)
        self.assertEqual(sorted(joints.name), ROTORS)
        self.assertEqual(list(joints.position), [0.0] * 4)
        self.assertEqual(list(joints.velocity), [0.0] * 4)
        # The URDF body with a namespace has its own.
        own = self.at('uav1_joints', stamp)
        self.assertEqual(sorted(own.name), ROTORS)
        self.assertEqual(list(own.position), [0.0] * 4)
        self.assertEqual(list(own.velocity), [0.0] * 4)

        # The sites, from the reference origin; the URDF links are not there.
        static = self.static_frames(self.wait_for(
            'tf_static', lambda m: 'sim/arm_tip' in self.static_frames(m), 'the sites'))
        self.assertEqual(sorted(static), ['sim/arm_mount', 'sim/arm_tip'])
        tip, mount = static['sim/arm_tip'], static['sim/arm_mount']
        self.assertEqual(tip.header.frame_id, 'sim/arm')
        np.testing.assert_array_equal(xyz(tip.transform.translation), [0.5, 0.0, 0.0])
        # The reader normalises the orientation: to round-off.
        np.testing.assert_allclose(xyzw(tip.transform.rotation), [0.0, 0.0, HALF, HALF],
                                   atol=1e-15)
        self.assertEqual(mount.header.frame_id, 'sim/arm')
        np.testing.assert_array_equal(xyz(mount.transform.translation), [0.0, 0.1, 0.0])
        np.testing.assert_array_equal(xyzw(mount.transform.rotation), [0.0, 0.0, 0.0, 1.0])

        # A spawned body's site joins the set (from its COM, (0.1, 0, 0)), and leaves with it.
        self.sim.spawn(SPAWNED)
        static = self.static_frames(self.wait_for(
            'tf_static', lambda m: 'sim/tool_grip' in self.static_frames(m), 'the spawned site'))
        self.assertEqual(sorted(static), ['sim/arm_mount', 'sim/arm_tip', 'sim/tool_grip'])
        self.assertEqual(static['sim/tool_grip'].header.frame_id, 'sim/tool')
        np.testing.assert_allclose(xyz(static['sim/tool_grip'].transform.translation),
                                   [0.1, 0.0, 0.0], atol=1e-15)
        with self.lock:
            sent = len(self.messages['tf_static'])
        self.sim.delete('tool')
        static = self.static_frames(self.wait_for(
            'tf_static', lambda m: 'sim/tool_grip' not in self.static_frames(m),
            'the set without it', since=sent))
        self.assertEqual(sorted(static), ['sim/arm_mount', 'sim/arm_tip'])

    def test_topics_in_the_bodys_namespace(self):
        self.sim.resume()  # the other test leaves it paused
        odom = self.wait_for('uav1_odom', lambda m: True, 'odometry on /uav1/odom')
        self.assertEqual(odom.child_frame_id, 'sim/base_link')
        self.assertEqual(odom.pose.pose.position.y, 5.0)
        published = set(topic for topic, _ in rospy.get_published_topics())
        self.assertNotIn(NODE + '/quad/odom', published)
        # A force on /uav1/wrench is what /uav1/applied_wrench reads back.
        self.wait_for('uav1_applied', lambda m: True, 'a message on /uav1/applied_wrench')
        push = rospy.Publisher('/uav1/wrench', WrenchStamped, queue_size=1, latch=True)
        msg = WrenchStamped()
        msg.wrench.force.z = 3.0
        push.publish(msg)
        self.wait_for('uav1_applied', lambda m: m.wrench.force.z == 3.0,
                      'the force of /uav1/wrench on /uav1/applied_wrench')

        with self.assertRaisesRegex(RuntimeError, "namespace '/uav1' is the topic namespace "
                                                  "of body 'quad'"):
            self.sim.spawn(SPAWNED.replace('tool', 'intruder') + 'namespace: /uav1\n')
        self.sim.spawn(SPAWNED.replace('tool', 'uav2') + 'namespace: /uav2\n')
        pose = self.wait_for('uav2_pose', lambda m: True, 'a pose on /uav2/pose')
        self.assertEqual(pose.pose.position.y, -3.0)
        self.sim.delete('uav2')


if __name__ == '__main__':
    rostest.rosrun(PKG, 'body_frames_test', BodyFrames)
