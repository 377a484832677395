#!/usr/bin/python3
"""Records a simulated IMU at rest and plots its Allan deviation against the
lines its parameters draw (doc/imu_allan_deviation.png): the white noise's
sigma/sqrt(tau) and the bias random walk's sigma_b*sqrt(tau/3), for the
gyroscope and the accelerometer, the lines a user compares with a datasheet.

    /usr/bin/python3 scripts/plot_allan.py                  # record, then plot
    /usr/bin/python3 scripts/plot_allan.py --samples FILE   # plot a recording again

The node (launch/rigid_body_sim.launch, paused, on a private master) steps a
body at rest without gravity, so each sample of its IMU is the IMU's error
alone; ~step advances it 50 steps per call and every sample is kept
(numpy's .npy in FILE, default /tmp/imu_allan.npy). Build first (bash
scripts/build.sh) and source the workspace's devel/setup.bash; 4,000 s of
simulated time at 100 Hz take under a minute.
"""
import argparse
import os
import signal
import subprocess
import tempfile
import threading

import numpy
import yaml

from script_support import master_is_up, wait_until

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUTPUT = os.path.join(REPO, 'doc', 'imu_allan_deviation.png')
RATE_HZ = 100.0
STEPS_PER_CALL = 50  # below the sensor's queue of 100
# A tactical-grade MEMS IMU's datasheet figures.
IMU = {'type': 'imu', 'name': 'imu_raw', 'rate': RATE_HZ, 'seed': 1,
       'gyro_noise_density': 1.7e-4, 'gyro_random_walk': 1.9e-5,
       'accel_noise_density': 2.0e-3, 'accel_random_walk': 3.0e-3}
TOPIC = '/rigid_body_sim/resting/imu_raw'


def scene():
    return {'gravity': [0.0, 0.0, 0.0],
            'bodies': [{'name': 'resting', 'shape': 'sphere', 'mass': 1.0, 'radius': 0.1,
                        'sensors': [IMU]}]}


def record(duration_s, port):
    """The IMU's samples over `duration_s` of simulated time: an array of rows
    (gyro x, y, z [rad/s], accel x, y, z [m/s^2])."""
    os.environ['ROS_MASTER_URI'] = 'http://localhost:%d' % port
    with tempfile.NamedTemporaryFile('w', suffix='.yaml', delete=False) as out:
        yaml.safe_dump(scene(), out)
    launch = subprocess.Popen(
        ['roslaunch', '-p', str(port), 'rigid_body_sim', 'rigid_body_sim.launch',
         'scene:=' + out.name, 'paused:=true', 'rate:=%g' % RATE_HZ,
         'publish_rate:=%g' % RATE_HZ, 'use_sim_time:=false'],
        stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
    try:
        import rosgraph
        import rospy
        from rigid_body_sim.srv import Step
        from sensor_msgs.msg import Imu
        wait_until(lambda: master_is_up(rosgraph.Master('/plot_allan')), 30.0, 'ROS master')
        rospy.init_node('plot_allan', disable_signals=True, anonymous=True)
        rospy.wait_for_service('/rigid_body_sim/step', 30.0)
        samples = []
        lock = threading.Lock()

        def on_imu(msg):
            w, f = msg.angular_velocity, msg.linear_acceleration
            with lock:
                samples.append((w.x, w.y, w.z, f.x, f.y, f.z))
        subscriber = rospy.Subscriber(TOPIC, Imu, on_imu, queue_size=100000)
        wait_until(lambda: subscriber.get_num_connections() > 0, 30.0, 'connection to ' + TOPIC)
        step = rospy.ServiceProxy('/rigid_body_sim/step', Step, persistent=True)
        calls = int(round(duration_s * RATE_HZ / STEPS_PER_CALL))
        for call in range(1, calls + 1):
            step(STEPS_PER_CALL)
            # Each call's samples are in before the next: none overflows a queue.
            wait_until(lambda: len(samples) >= call * STEPS_PER_CALL, 10.0, 'samples', 0.001)
        subscriber.unregister()
        return numpy.array(samples)
    finally:
        launch.send_signal(signal.SIGINT)
        launch.wait()
        os.unlink(out.name)


def allan_deviation(rates, rate_hz, taus_s):
    """Overlapping Allan deviation of `rates` (one column) at each tau."""
    phase = numpy.concatenate(([0.0], numpy.cumsum(rates))) / rate_hz
    out = []
    for tau in taus_s:
        m = int(round(tau * rate_hz))
        d = phase[2 * m:] - 2.0 * phase[m:-m] + phase[:-2 * m]
        out.append(numpy.sqrt(numpy.mean(d * d) / (2.0 * tau * tau)))
    return numpy.array(out)


def plot(samples, path):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    duration_s = len(samples) / RATE_HZ
    taus = numpy.logspace(numpy.log10(2.0 / RATE_HZ), numpy.log10(duration_s / 9.0), 40)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, first, kind, unit in ((axes[0], 0, 'gyro', 'rad/s'), (axes[1], 3, 'accel', 'm/s²')):
        density = IMU[kind + '_noise_density']
        walk = IMU[kind + '_random_walk']
        for axis, name in enumerate('xyz'):
            ax.loglog(taus, allan_deviation(samples[:, first + axis], RATE_HZ, taus), '.-',
                      label='simulated, ' + name, alpha=0.8)
        ax.loglog(taus, density / numpy.sqrt(taus), 'k--',
                  label='noise density σ/√τ, σ = %g' % density)
        ax.loglog(taus, walk * numpy.sqrt(taus / 3.0), 'k:',
                  label='random walk σ_b√(τ/3), σ_b = %g' % walk)
        ax.set_xlabel('τ [s]')
        ax.set_ylabel('Allan deviation [%s]' % unit)
        ax.set_title('%s, %g Hz, %.0f s' % (kind, RATE_HZ, duration_s))
        ax.grid(True, which='both', alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print('wrote', path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--samples', help='a recording (.npy) to plot again')
    parser.add_argument('--out', default='/tmp/imu_allan.npy', help='where to keep the recording')
    parser.add_argument('--duration', type=float, default=4000.0, help='simulated seconds')
    parser.add_argument('--port', type=int, default=11399, help="the private master's port")
    args = parser.parse_args()
    if args.samples:
        samples = numpy.load(args.samples)
    else:
        samples = record(args.duration, args.port)
        numpy.save(args.out, samples)
    plot(samples, OUTPUT)


if __name__ == '__main__':
    main()
