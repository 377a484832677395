#!/usr/bin/python3
"""Records a flight of the quadrotor example and plots it: base_link's
height and yaw (from its odometry) against simulated time, with the
controller's setpoints.

    /usr/bin/python3 scripts/plot_flight.py                    # record, then plot
    /usr/bin/python3 scripts/plot_flight.py --bag FLIGHT.bag   # plot a recorded run

Recording starts launch/quadrotor.launch paused (paused:=true) on a private
master (--port), subscribes to /rigid_body_sim/base_link/odom, resumes the
node once the paused node's t_0 message has arrived, writes every message
into a bag (the rosbag library) and stops after --duration simulated
seconds. The bag is kept (--keep-bag, default
/tmp/quadrotor_flight.bag); the plot goes to --out (default
doc/quadrotor_flight.png). Build first (bash scripts/build.sh) and source
the workspace's devel/setup.bash.
"""
import argparse
import math
import os
import signal
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ODOM = '/rigid_body_sim/base_link/odom'


def yaw_of(q):
    """The yaw [rad] of a geometry_msgs/Quaternion."""
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def wait_until(predicate, timeout_s, what):
    deadline = time.monotonic() + timeout_s
    while not predicate():
        if time.monotonic() > deadline:
            sys.exit('plot_flight: no %s within %g s' % (what, timeout_s))
        time.sleep(0.05)


def record(args):
    """Runs the example and records its odometry into args.keep_bag; returns
    the controller's setpoints (height [m], yaw [rad])."""
    os.environ['ROS_MASTER_URI'] = 'http://localhost:%d' % args.port
    launch = subprocess.Popen(
        ['roslaunch', '-p', str(args.port), 'rigid_body_sim', 'quadrotor.launch', 'paused:=true',
         'real_time_factor:=%g' % args.real_time_factor],
        stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
    try:
        import rosbag
        import rosgraph
        import rospy
        from nav_msgs.msg import Odometry
        from std_srvs.srv import SetBool
        wait_until(lambda: _is_up(rosgraph.Master('/plot_flight')), 30.0, 'ROS master')
        rospy.init_node('plot_flight', disable_signals=True)
        rospy.wait_for_service('/rigid_body_sim/set_paused', 30.0)
        target = rospy.get_param('/quadrotor_controller/target_position')[2]
        target_yaw = rospy.get_param('/quadrotor_controller/target_yaw')
        latest = []
        with rosbag.Bag(args.keep_bag, 'w') as bag:
            def on_odom(msg):
                if not latest or msg.header.stamp.to_sec() <= args.duration:
                    bag.write(ODOM, msg, msg.header.stamp)
                latest[:] = [msg.header.stamp.to_sec()]
            subscriber = rospy.Subscriber(ODOM, Odometry, on_odom, queue_size=1000)
            # The paused node sends its t_0 state to a subscriber as it connects.
            wait_until(lambda: latest, 30.0, 'odometry at t_0')
            rospy.ServiceProxy('/rigid_body_sim/set_paused', SetBool)(False)
            wait_until(lambda: latest[0] >= args.duration,
                       10.0 * args.duration / args.real_time_factor + 30.0,
                       'odometry at %g s' % args.duration)
            subscriber.unregister()
        return target, target_yaw
    finally:
        launch.send_signal(signal.SIGINT)
        launch.wait()


def _is_up(master):
    try:
        master.getPid()
        return True
    except Exception:  # the master is not up yet
        return False


def plot(bag_path, target, target_yaw, duration, out):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    import rosbag
    t, z, yaw = [], [], []
    with rosbag.Bag(bag_path) as bag:
        for _, msg, _ in bag.read_messages(topics=[ODOM]):
            stamp = msg.header.stamp.to_sec()
            if stamp > duration:
                break
            t.append(stamp)
            z.append(msg.pose.pose.position.z)
            yaw.append(math.degrees(yaw_of(msg.pose.pose.orientation)))
    if not t:
        sys.exit('plot_flight: no %s message in %s' % (ODOM, bag_path))
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
        target, target_yaw = record(args)
        bag_path = args.keep_bag
    plot(bag_path, target, target_yaw, args.duration, args.out)


if __name__ == '__main__':
    main()
