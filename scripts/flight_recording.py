"""Records runs of the quadrotor example (launch/quadrotor.launch) into
bags, for the plotting scripts next to this file.

record() starts the launch file paused (paused:=true) on a private master,
subscribes to the topics asked for, resumes the node once the paused node's
t_0 odometry has arrived, writes every message up to the duration asked for
into a bag (the rosbag library) and stops the launch. Build first (bash
scripts/build.sh) and source the workspace's devel/setup.bash.
"""
import math
import os
import signal
import subprocess
import sys
import threading

from script_support import master_is_up, wait_until

ODOM = '/rigid_body_sim/base_link/odom'
THRUSTS = '/rigid_body_sim/base_link/actuator_states'
WIND = '/rigid_body_sim/wind'


def yaw_of(q):
    """The yaw [rad] of a geometry_msgs/Quaternion."""
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def roll_pitch_of(q):
    """The roll and pitch [rad] (z-y-x Euler angles) of a geometry_msgs/Quaternion."""
    roll = math.atan2(2.0 * (q.w * q.x + q.y * q.z), 1.0 - 2.0 * (q.x * q.x + q.y * q.y))
    pitch = math.asin(max(-1.0, min(1.0, 2.0 * (q.w * q.y - q.z * q.x))))
    return roll, pitch


def record(bag_path, topics, duration_s, launch_args=(), port=11398, real_time_factor=1.0):
    """Runs the example with `launch_args` (a list of 'name:=value') and
    writes the messages of `topics` (name -> message class; ODOM among them)
    stamped up to `duration_s` of simulated time into `bag_path`. Returns the
    controller's parameters."""
    os.environ['ROS_MASTER_URI'] = 'http://localhost:%d' % port
    launch = subprocess.Popen(
        ['roslaunch', '-p', str(port), 'rigid_body_sim', 'quadrotor.launch', 'paused:=true',
         'real_time_factor:=%g' % real_time_factor] + list(launch_args),
        stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
    try:
        import rosbag
        import rosgraph
        import rospy
        from std_srvs.srv import SetBool
        wait_until(lambda: master_is_up(rosgraph.Master('/flight_recording')), 30.0, 'ROS master')
        rospy.init_node('flight_recording', disable_signals=True, anonymous=True)
        rospy.wait_for_service('/rigid_body_sim/set_paused', 30.0)
        controller = rospy.get_param('/quadrotor_controller')
        latest = []
        # Each topic's callbacks run in a thread of their own; a bag is not
        # thread-safe, and none may write once it is closed.
        writing = threading.Lock()
        open_bag = [rosbag.Bag(bag_path, 'w')]

        def writer(topic):
            def on_message(msg):
                with writing:
                    if open_bag and msg.header.stamp.to_sec() <= duration_s:
                        open_bag[0].write(topic, msg, msg.header.stamp)
                if topic == ODOM:
                    latest[:] = [msg.header.stamp.to_sec()]
            return on_message
        try:
            subscribers = [rospy.Subscriber(topic, kind, writer(topic), queue_size=1000)
                           for topic, kind in topics.items()]
            # The paused node sends its t_0 state to a subscriber as it connects.
            wait_until(lambda: latest, 30.0, 'odometry at t_0')
            rospy.ServiceProxy('/rigid_body_sim/set_paused', SetBool)(False)
            wait_until(lambda: latest[0] >= duration_s,
                       10.0 * duration_s / real_time_factor + 30.0,
                       'odometry at %g s' % duration_s)
            for subscriber in subscribers:
                subscriber.unregister()
        finally:
            with writing:
                open_bag.pop().close()
        return controller
    finally:
        launch.send_signal(signal.SIGINT)
        launch.wait()


def read(bag_path, topic):
    """(stamp [s], message) of every `topic` message in the bag, in order."""
    import rosbag
    with rosbag.Bag(bag_path) as bag:
        out = [(msg.header.stamp.to_sec(), msg) for _, msg, _ in bag.read_messages(topics=[topic])]
    if not out:
        sys.exit('%s: no %s message in %s' % (os.path.basename(sys.argv[0]), topic, bag_path))
    return sorted(out, key=lambda item: item[0])
