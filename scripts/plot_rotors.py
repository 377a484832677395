#!/usr/bin/python3
"""Records the quadrotor example on its rotors and plots what the plant does
to its controller:

- doc/quadrotor_step_response.png: the take-off to the 1 m setpoint with the
  scene's 20 ms motor lag and without it (every time_constant 0): height and
  the four rotors' thrusts against time;
- doc/quadrotor_gusty_hover.png: 25 s of the same flight in gusts of 1 m/s
  standard deviation per axis (gust_stddev:=1.0): base_link's distance from
  the setpoint, roll, pitch and yaw error, the rotors' thrusts and the wind.

    /usr/bin/python3 scripts/plot_rotors.py                 # record, then plot
    /usr/bin/python3 scripts/plot_rotors.py --bags DIR      # plot recorded runs again

Each run (flight_recording.py) records base_link's odometry, its
actuator_states and ~wind into DIR (default /tmp/quadrotor_rotors): lag.bag,
no_lag.bag, gusts.bag. Build first (bash scripts/build.sh) and source the
workspace's devel/setup.bash; at real time (--real-time-factor 1) it takes
about 45 s.
"""
import argparse
import math
import multiprocessing
import os
import sys

import yaml

from flight_recording import ODOM, THRUSTS, WIND, read, record, roll_pitch_of, yaw_of

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(REPO, 'config', 'quadrotor.yaml')
STEP_S = 2.0
GUSTS_S = 25.0
GUST_STDDEV = 1.0
TARGET = (0.0, 0.0, 1.0)
TARGET_YAW = math.pi / 2.0


def record_all(directory, args):
    from geometry_msgs.msg import Vector3Stamped
    from nav_msgs.msg import Odometry
    from sensor_msgs.msg import JointState
    topics = {ODOM: Odometry, THRUSTS: JointState, WIND: Vector3Stamped}
    os.makedirs(directory, exist_ok=True)
    with open(SCENE) as source:
        scene = yaml.safe_load(source)
    for actuator in scene['bodies'][0]['actuators']:
        actuator['time_constant'] = 0.0
    no_lag_scene = os.path.join(directory, 'no_lag.yaml')
    with open(no_lag_scene, 'w') as out:
        yaml.safe_dump(scene, out)
    runs = [('lag.bag', STEP_S, []),
            ('no_lag.bag', STEP_S, ['scene:=' + no_lag_scene]),
            ('gusts.bag', GUSTS_S, ['gust_stddev:=%g' % GUST_STDDEV, 'wind_seed:=7'])]
    # rospy joins one master once per process: each run records in a child.
    for name, duration, launch_args in runs:
        child = multiprocessing.get_context('fork').Process(
            target=record, args=(os.path.join(directory, name), topics, duration, launch_args,
                                 args.port, args.real_time_factor))
        child.start()
        child.join()
        if child.exitcode != 0:
            sys.exit('plot_rotors: recording %s failed' % name)


def series(bag_path, topic, value):
    stamps, values = [], []
    for stamp, msg in read(bag_path, topic):
        stamps.append(stamp)
        values.append(value(msg))
    return stamps, values


def plot_step_response(directory, out, plt):
    figure, (height_axes, thrust_axes) = plt.subplots(2, 1, sharex=True, figsize=(6.4, 5.2))
    for name, label, style in (('lag.bag', 'motor lag 20 ms', '-'),
                               ('no_lag.bag', 'no motor lag', '--')):
        bag_path = os.path.join(directory, name)
        t, z = series(bag_path, ODOM, lambda msg: msg.pose.pose.position.z)
        height_axes.plot(t, z, style, color='black', label=label)
        # rotor_2 and rotor_3 follow rotor_0 and rotor_1 (the diagonals).
        t, thrusts = series(bag_path, THRUSTS, lambda msg: list(msg.effort))
        for k, color in ((0, 'tab:blue'), (1, 'tab:red')):
            thrust_axes.plot(t, [row[k] for row in thrusts], style, color=color, linewidth=1.2,
                             label='%s, rotor_%d' % (label, k))
    height_axes.axhline(TARGET[2], color='gray', linestyle=':', label='setpoint')
    height_axes.set_ylabel('height [m]')
    height_axes.legend(loc='lower right')
    height_axes.set_title('quadrotor on its rotors: take-off to 1 m, 100 Hz control')
    thrust_axes.axhline(8.55, color='gray', linestyle=':', label='max_thrust')
    thrust_axes.set_ylabel('rotor thrust [N]')
    thrust_axes.set_xlabel('simulated time [s]')
    thrust_axes.legend(loc='center right', fontsize='small')
    figure.tight_layout()
    figure.savefig(out, dpi=100)
    print('plot_rotors: %s' % out)


def distance_from_target(msg):
    p = msg.pose.pose.position
    return math.sqrt((p.x - TARGET[0])**2 + (p.y - TARGET[1])**2 + (p.z - TARGET[2])**2)


def attitude_mrad(msg):
    q = msg.pose.pose.orientation
    roll, pitch = roll_pitch_of(q)
    yaw_error = math.remainder(yaw_of(q) - TARGET_YAW, 2.0 * math.pi)
    return [1e3 * roll, 1e3 * pitch, 1e3 * yaw_error]


def visible(t, rows, start_s):
    """The rows of series (t, rows) from start_s on, flattened."""
    return [value for stamp, row in zip(t, rows) if stamp >= start_s
            for value in (row if isinstance(row, list) else [row])]


def plot_gusty_hover(directory, out, plt):
    bag_path = os.path.join(directory, 'gusts.bag')
    # From 2 s: the take-off is the step response's figure.
    start_s = 2.0
    figure, axes = plt.subplots(4, 1, sharex=True, figsize=(6.4, 8.0))
    t, distance = series(bag_path, ODOM, distance_from_target)
    axes[0].plot(t, [100.0 * d for d in distance])
    axes[0].set_ylabel('from setpoint [cm]')
    axes[0].set_ylim(0.0, 1.2e2 * max(visible(t, distance, start_s)))
    axes[0].set_title('quadrotor hovering at 1 m in gusts of %g m/s std' % GUST_STDDEV)
    t, attitude = series(bag_path, ODOM, attitude_mrad)
    for k, label in enumerate(('roll', 'pitch', 'yaw error')):
        axes[1].plot(t, [row[k] for row in attitude], linewidth=1.0, label=label)
    bound = 1.2 * max(abs(value) for value in visible(t, attitude, start_s))
    axes[1].set_ylim(-bound, bound)
    axes[1].set_ylabel('attitude [mrad]')
    axes[1].legend(loc='upper right', fontsize='small', ncol=3)
    t, thrusts = series(bag_path, THRUSTS, lambda msg: list(msg.effort))
    for k in range(len(thrusts[0])):
        axes[2].plot(t, [row[k] for row in thrusts], linewidth=1.0, label='rotor_%d' % k)
    shown = visible(t, thrusts, start_s)
    margin = 0.2 * (max(shown) - min(shown))
    axes[2].set_ylim(min(shown) - margin, max(shown) + 2.0 * margin)
    axes[2].set_ylabel('rotor thrust [N]')
    axes[2].legend(loc='upper right', fontsize='small', ncol=4)
    t, wind = series(bag_path, WIND, lambda msg: [msg.vector.x, msg.vector.y, msg.vector.z])
    for k, label in enumerate('xyz'):
        axes[3].plot(t, [row[k] for row in wind], linewidth=1.0, label=label)
    axes[3].set_ylabel('wind [m/s]')
    axes[3].set_xlabel('simulated time [s]')
    axes[3].legend(loc='upper right', fontsize='small', ncol=3)
    axes[0].set_xlim(start_s, GUSTS_S)
    figure.tight_layout()
    figure.savefig(out, dpi=100)
    print('plot_rotors: %s' % out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--bags', help='plot the runs recorded in this directory')
    parser.add_argument('--keep-bags', default='/tmp/quadrotor_rotors',
                        help='where recorded runs go')
    parser.add_argument('--real-time-factor', type=float, default=1.0)
    parser.add_argument('--port', type=int, default=11398, help='the private master port')
    parser.add_argument('--out-dir', default=os.path.join(REPO, 'doc'))
    args = parser.parse_args()
    directory = args.bags
    if not directory:
        directory = args.keep_bags
        record_all(directory, args)
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    plot_step_response(directory, os.path.join(args.out_dir, 'quadrotor_step_response.png'), plt)
    plot_gusty_hover(directory, os.path.join(args.out_dir, 'quadrotor_gusty_hover.png'), plt)


if __name__ == '__main__':
    main()
