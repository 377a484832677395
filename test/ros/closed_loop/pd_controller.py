#!/usr/bin/python3
"""A PD controller as a downstream package would write it, with only the
public client (rigid_body_sim.testing): each cycle it answers the state of
~body with a force at particle 0 (the body's centre of mass in the scene) and
a couple, both in world axes, that pull it to ~target_position and
~target_orientation."""
import numpy as np
import rospy
from rigid_body_sim.testing import LockstepController, particle_wrench


def quaternion_multiply(a, b):
    """a * b for (x, y, z, w) quaternions."""
    av, aw, bv, bw = a[:3], a[3], b[:3], b[3]
    return np.concatenate([aw * bv + bw * av + np.cross(av, bv), [aw * bw - av.dot(bv)]])


def rotation_vector(q):
    """The rotation vector [rad] of the unit quaternion q, angle in [0, pi]."""
    if q[3] < 0.0:
        q = -q
    sin_half = np.linalg.norm(q[:3])
    if sin_half == 0.0:
        return np.zeros(3)
    return 2.0 * np.arctan2(sin_half, q[3]) * q[:3] / sin_half


def main():
    rospy.init_node('pd_controller')
    body = rospy.get_param('~body')
    target_position = np.array(rospy.get_param('~target_position'))
    target_orientation = np.array(rospy.get_param('~target_orientation'))
    kp, kd = rospy.get_param('~position_gains')
    kp_rot, kd_rot = rospy.get_param('~orientation_gains')
    simulator = rospy.resolve_name(rospy.get_param('~simulator', 'rigid_body_sim'))

    def control(states, _stamp):
        state = states[body]
        force = kp * (target_position - state.position) - kd * state.linear_velocity
        inverse = state.orientation * np.array([-1.0, -1.0, -1.0, 1.0])
        error = rotation_vector(quaternion_multiply(target_orientation, inverse))
        torque = kp_rot * error - kd_rot * state.angular_velocity
        return [particle_wrench(body, 0, force=force, torque=torque)]

    LockstepController(control, simulator)
    rospy.spin()


if __name__ == '__main__':
    main()
