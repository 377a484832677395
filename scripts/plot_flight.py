#!/usr/bin/python3
"""Records a flight of the quadrotor example and plots it: base_link's
height and yaw (from its odometry) against simulated time, with the
controller's setpoints.

    /usr/bin/python3 scripts/plot_flight.py                    # record, then plot
    /usr/bin/python3 scripts/plot_flight.py --bag FLIGHT.bag   # plot a recorded run

Recording (flight_recording.py) starts launch/quadrotor.launch paused on a
private master (--port), records /rigid_body_sim/base_link/odom into a bag
and stops after --duration simulated seconds. The bag is kept (--keep-bag, default
/tmp/quadrotor_flight.bag); the plot goes to --out (default
doc/quadrotor_flight.png). Build first (bash scripts/build.sh) and source
the workspace's devel/setup.bash.
"""
import argparse
import math
import os

from flight_recording import ODOM, read, record, yaw_of

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def plot(bag_path, target, target_yaw, duration, out):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    t, z, yaw = [], [], []
    for stamp, msg in read(bag_path, ODOM):
        if stamp > duration:
            break
        t.append(stamp)
        z.append(msg.pose.pose.position.z)
        yaw.append(math.degrees(yaw_of(msg.pose.pose.orientation)))
    figure, (height_axes, yaw_axes) = plt.subplots(2, 1, sharex=True, figsize=(6.4, 4.8))
    height_axes.plot(t, z, label='base_link height')
    height_axes.axhline(target, color='gray', linestyle='--', label='setpoint')
    height_axes.set_ylabel('height [m]')
    height_axes.legend(loc='lower right')
    yaw_axes.plot(t, yaw, label='base_link yaw')
    yaw_axes.axhline(math.degrees(target_yaw), color='gray', linestyle='--', label='setpoint')
    yaw_axes.set_ylabel('yaw [deg]')
    yaw_axes.set_xlabel('simulated time [s]')
    yaw_axes.legend(loc='lower right')
    height_axes.set_title('quadrotor example: take-off from rest, lockstep, 100 Hz control')
    figure.tight_layout()
    figure.savefig(out, dpi=100)
    print('plot_flight: %d samples from %s to %s' % (len(t), bag_path, out))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--bag', help='plot this recorded run instead of recording one')
    parser.add_argument('--keep-bag', default='/tmp/quadrotor_flight.bag',
                        help='where a recorded run goes')
    parser.add_argument('--duration', type=float, default=6.0, help='simulated seconds')
    parser.add_argument('--real-time-factor', type=float, default=1.0)
    parser.add_argument('--port', type=int, default=11398, help='the private master port')
    parser.add_argument('--target-height', type=float, default=1.0,
                        help='setpoint [m] drawn for a --bag run (a recording reads it)')
    parser.add_argument('--target-yaw', type=float, default=math.pi / 2.0,
                        help='setpoint [rad] drawn for a --bag run (a recording reads it)')
    parser.add_argument('--out', default=os.path.join(REPO, 'doc', 'quadrotor_flight.png'))
    args = parser.parse_args()
    if args.bag:
        target, target_yaw, bag_path = args.target_height, args.target_yaw, args.bag
    else:
        from nav_msgs.msg import Odometry
        controller = record(args.keep_bag, {ODOM: Odometry}, args.duration, port=args.port,
                            real_time_factor=args.real_time_factor)
        target, target_yaw = controller['target_position'][2], controller['target_yaw']
        bag_path = args.keep_bag
    plot(bag_path, target, target_yaw, args.duration, args.out)


if __name__ == '__main__':
    main()
