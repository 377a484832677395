#!/usr/bin/python3
"""A quadrotor's position and attitude controller as a downstream package
would write it, in lockstep with the simulator (rigid_body_sim.testing).

Each cycle it reads the body's odometry (~<body>/odom: base_link's origin,
velocity in body axes) and IMU (~<body>/imu: orientation and angular
velocity, body axes) of that cycle's stamp and answers with what a mixer
would make of four rotors: a thrust along the body's z axis and a torque in
body axes, both at the centre of mass (a body wrench in the body's frame).

- Position (world axes, base_link's origin): the acceleration wanted is a
  critically damped PD, a = w_p^2 (target - p) - 2 w_p v; the force wanted is
  mass (a - gravity); the thrust is its component along the body's z axis.
- Attitude: the orientation wanted has its z axis along that force and its
  yaw at ~target_yaw; the error is the rotation vector e of q^-1 q_wanted
  (body axes), and the torque a critically damped PD on it,
  J (w_a^2 e - 2 w_a w) + w x J w, with J the principal moments.

The node publishes an IMU only once the body has taken a step, so on the
first cycle the attitude comes from the odometry, which carries the same
orientation and angular velocity."""
import threading

import numpy as np
import rospy
from nav_msgs.msg import Odometry
from rigid_body_sim.testing import LockstepController, body_wrench
from sensor_msgs.msg import Imu

WAIT_S = 10.0  # the longest wait [s] for a cycle's odometry and IMU


def quaternion_multiply(a, b):
    """a * b for (x, y, z, w) quaternions."""
    av, aw, bv, bw = a[:3], a[3], b[:3], b[3]
    return np.concatenate([aw * bv + bw * av + np.cross(av, bv), [aw * bw - av.dot(bv)]])


def rotation_matrix(q):
    """The rotation matrix of the unit quaternion q = (x, y, z, w)."""
    x, y, z, w = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def quaternion_from_matrix(r):
    """The unit quaternion (x, y, z, w) of the rotation matrix r (Shepperd's
    method: from the largest of the four diagonal combinations)."""
    diagonal = [r[0, 0] + r[1, 1] + r[2, 2], r[0, 0], r[1, 1], r[2, 2]]
    i = int(np.argmax(diagonal))
    if i == 0:
        s = 2.0 * np.sqrt(1.0 + diagonal[0])
        q = [(r[2, 1] - r[1, 2]) / s, (r[0, 2] - r[2, 0]) / s, (r[1, 0] - r[0, 1]) / s, s / 4.0]
    elif i == 1:
        s = 2.0 * np.sqrt(1.0 + r[0, 0] - r[1, 1] - r[2, 2])
        q = [s / 4.0, (r[0, 1] + r[1, 0]) / s, (r[0, 2] + r[2, 0]) / s, (r[2, 1] - r[1, 2]) / s]
    elif i == 2:
        s = 2.0 * np.sqrt(1.0 - r[0, 0] + r[1, 1] - r[2, 2])
        q = [(r[0, 1] + r[1, 0]) / s, s / 4.0, (r[1, 2] + r[2, 1]) / s, (r[0, 2] - r[2, 0]) / s]
    else:
        s = 2.0 * np.sqrt(1.0 - r[0, 0] - r[1, 1] + r[2, 2])
        q = [(r[0, 2] + r[2, 0]) / s, (r[1, 2] + r[2, 1]) / s, s / 4.0, (r[1, 0] - r[0, 1]) / s]
    return np.array(q)


def rotation_vector(q):
    """The rotation vector [rad] of the unit quaternion q, angle in [0, pi]."""
    if q[3] < 0.0:
        q = -q
    sin_half = np.linalg.norm(q[:3])
    if sin_half == 0.0:
        return np.zeros(3)
    return 2.0 * np.arctan2(sin_half, q[3]) * q[:3] / sin_half


def xyz(vector):
    return np.array([vector.x, vector.y, vector.z])


def xyzw(quaternion):
    return np.array([quaternion.x, quaternion.y, quaternion.z, quaternion.w])


class Sensors(object):
    """The latest odometry and IMU messages, and a wait for those of a stamp."""

    def __init__(self, simulator, body):
        self._lock = threading.Condition()
        self._latest = {'odom': None, 'imu': None}
        self._subscribers = [
            rospy.Subscriber('%s/%s/%s' % (simulator, body, topic), msg_type, self._on_message,
                             callback_args=topic, queue_size=10, tcp_nodelay=True)
            for topic, msg_type in (('odom', Odometry), ('imu', Imu))]

    def _on_message(self, msg, topic):
        with self._lock:
            self._latest[topic] = msg
            self._lock.notify_all()

    def wait_for_publishers(self):
        """Blocks until both topics are connected, so that the node, which
        starts once the lockstep controller is connected, sends the first
        cycle's odometry here."""
        while not rospy.is_shutdown() and not all(s.get_num_connections() for s in self._subscribers):
            rospy.rostime.wallsleep(0.05)  # under use_sim_time no time passes before the first cycle

    def at(self, stamp, topics):
        """The messages of `topics` stamped `stamp` (waits for them)."""
        def arrived():
            return all(self._latest[t] is not None and self._latest[t].header.stamp == stamp for t in topics)
        with self._lock:
            if not self._lock.wait_for(arrived, WAIT_S):
                raise RuntimeError('no %s stamped %s within %g s' % (' and '.join(topics), stamp, WAIT_S))
            return [self._latest[t] for t in topics]


class Controller(object):
    """The control law, from the parameters of a controller node."""

    def __init__(self, mass, inertia, gravity, target_position, target_yaw, w_p, w_a):
        self.mass, self.inertia, self.gravity = mass, np.array(inertia), np.array(gravity)
        self.target_position, self.w_p, self.w_a = np.array(target_position), w_p, w_a
        self.heading = np.array([np.cos(target_yaw), np.sin(target_yaw), 0.0])

    def command(self, position, velocity, orientation, rate):
        """The thrust [N] along body z and the torque [N m] in body axes for
        base_link's origin at `position` with `velocity` (world axes [m],
        [m/s]), the body at `orientation` (x, y, z, w) turning at `rate`
        (body axes [rad/s])."""
        w_p, w_a, inertia = self.w_p, self.w_a, self.inertia
        acceleration = w_p * w_p * (self.target_position - position) - 2.0 * w_p * velocity
        force = self.mass * (acceleration - self.gravity)
        thrust = force.dot(rotation_matrix(orientation)[:, 2])

        z_wanted = force / np.linalg.norm(force)
        y_wanted = np.cross(z_wanted, self.heading)
        y_wanted /= np.linalg.norm(y_wanted)
        wanted = quaternion_from_matrix(np.column_stack([np.cross(y_wanted, z_wanted), y_wanted, z_wanted]))
        inverse = orientation * np.array([-1.0, -1.0, -1.0, 1.0])
        error = rotation_vector(quaternion_multiply(inverse, wanted))
        torque = inertia * (w_a * w_a * error - 2.0 * w_a * rate) + np.cross(rate, inertia * rate)
        return thrust, torque


def main():
    rospy.init_node('quadrotor_controller')
    body = rospy.get_param('~body')
    simulator = rospy.resolve_name(rospy.get_param('~simulator', 'rigid_body_sim'))
    controller = Controller(rospy.get_param('~mass'), rospy.get_param('~inertia'),
                            rospy.get_param(simulator + '/gravity'), rospy.get_param('~target_position'),
                            rospy.get_param('~target_yaw'), rospy.get_param('~position_frequency'),
                            rospy.get_param('~attitude_frequency'))
    sensors = Sensors(simulator, body)
    first_cycle = [True]

    def control(_states, stamp):
        if first_cycle[0]:
            odom, = sensors.at(stamp, ['odom'])
            orientation, rate = xyzw(odom.pose.pose.orientation), xyz(odom.twist.twist.angular)
            first_cycle[0] = False
        else:
            odom, imu = sensors.at(stamp, ['odom', 'imu'])
            orientation, rate = xyzw(imu.orientation), xyz(imu.angular_velocity)
        pose, twist = odom.pose.pose, odom.twist.twist
        velocity = rotation_matrix(xyzw(pose.orientation)).dot(xyz(twist.linear))
        thrust, torque = controller.command(xyz(pose.position), velocity, orientation, rate)
        return [body_wrench(body, force=(0.0, 0.0, thrust), torque=torque, frame=body)]

    sensors.wait_for_publishers()
    LockstepController(control, simulator)
    rospy.spin()


if __name__ == '__main__':
    main()
