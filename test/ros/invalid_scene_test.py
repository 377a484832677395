#!/usr/bin/python3
"""Invalid scenes and parameters stop the node (doc/node.md, "Parameters", last paragraph).

An invalid scene or parameter (`bodies` not a list, a duplicate or empty
name, a mass <= 0 or not finite, a position not of 3 finite numbers, a
non-positive rate, `publish_rate` > `rate`, a `clock_rate` that does not
divide `rate` a whole number of times, an unknown integrator, a `wind` or a
body's `drag` out of range or with an unknown key, a
`spawn_file_roots` entry that is not an absolute directory) stops the
node at start with a non-zero exit and one error line that names the offending
entry and key.

Each case sets private parameters on the master under a unique node name and
runs the node executable directly with `__name:=<that name>`, bounded by a
timeout, then checks: the process exited by itself (not killed by a signal:
an uncaught exception's abort is not a clean stop) with a code > 0, and stderr
holds exactly one error line (rosconsole "[ERROR]" / "[FATAL]") naming the key
and, for an entry of `bodies`, the entry (its name, or its index when the name
is the problem). A valid scene serves as a control: the node must still be
running after a few seconds; so must a scene without `bodies` or with an
empty list (an empty world).

Through launch/rigid_body_sim.launch (roslaunch, on the test's master), an
invalid scene file: with the default `respawn:=false` the launch ends by
itself with one FATAL line and roslaunch reporting the node's exit code 1;
with `respawn:=true` the launch keeps running and the node is retried every
0.5 s, one FATAL line each time.
"""
import os
import re
import signal
import subprocess
import tempfile
import unittest

import rosgraph
import roslib.packages
import rospy
import rostest

PKG = 'rigid_body_sim'
EXIT_TIMEOUT = 15.0  # s a node gets to exit (start-up of a roscpp node is < 1 s)
LAUNCH_TIMEOUT = 30.0  # s roslaunch gets to end (it first checks the log directory)
RESPAWN_SECONDS = 4.0  # s a respawning launch runs: several 0.5 s retries
INVALID_SCENE = """bodies:
  - name: rod
    particles:
      - {mass: 1.0, position: [0.0, 0.0, 0.0]}
      - {mass: -1.0, position: [0.2, 0.0, 0.0]}
"""


def particles(mass=1.0):
    return [{'mass': mass, 'position': [0.0, 0.0, 0.0]},
            {'mass': mass, 'position': [0.2, 0.0, 0.0]},
            {'mass': mass, 'position': [0.0, 0.3, 0.0]}]


def good_body(name='good'):
    return {'name': name, 'particles': particles(), 'position': [0.0, 0.0, 1.0]}


def bad_body(**over):
    """A second body named `badbody` (entry index 1) with one field overridden."""
    b = {'name': 'badbody', 'particles': particles(), 'position': [1.0, 0.0, 0.0]}
    b.update(over)
    return b


def with_particle(**over):
    p = particles()
    p[1] = dict(p[1], **over)
    return p


def find_node_executable():
    found = roslib.packages.find_node(PKG, 'rigid_body_sim_node')
    if not found:
        raise RuntimeError('rigid_body_sim_node not found (catkin_find / devel space)')
    return found[0]


class InvalidScene(unittest.TestCase):
    exe = None
    master = None
    counter = 0

    @classmethod
    def setUpClass(cls):
        rospy.init_node('invalid_scene_test', anonymous=True)
        cls.exe = find_node_executable()
        cls.master = rosgraph.Master('/invalid_scene_test')

    def _node_name(self, tag):
        InvalidScene.counter += 1
        return 'rbs_invalid_%d_%s' % (InvalidScene.counter, tag)

    def _set_params(self, name, params):
        ns = '/' + name
        try:
            self.master.deleteParam(ns)
        except Exception:
            pass
        for k, v in params.items():
            self.master.setParam(ns + '/' + k, v)

    def _run(self, tag, params, timeout=EXIT_TIMEOUT):
        name = self._node_name(tag)
        self._set_params(name, params)
        proc = subprocess.Popen([self.exe, '__name:=' + name],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                env=dict(os.environ, ROSCONSOLE_STDOUT_LINE_BUFFERED='1'))
        try:
            out, err = proc.communicate(timeout=timeout)
            return proc.returncode, out.decode(errors='replace'), err.decode(errors='replace')
        except subprocess.TimeoutExpired:
            proc.send_signal(signal.SIGINT)
            try:
                out, err = proc.communicate(timeout=5.0)
            except subprocess.TimeoutExpired:
                proc.kill()
                out, err = proc.communicate()
            return None, out.decode(errors='replace'), err.decode(errors='replace')

    @staticmethod
    def _error_lines(text):
        lines = [l for l in text.splitlines() if re.search(r'\[\s*(ERROR|FATAL)\s*\]', l)]
        # Drop the "[ERROR] [1700000000.123456]:" prefix so that digits of the
        # time do not count as an entry index.
        return [re.sub(r'^.*?\[\s*(ERROR|FATAL)\s*\]\s*(\[[^\]]*\]\s*)?:?\s*', '', l)
                for l in lines]

    def check_rejected(self, tag, params, key, entry=None, index=None):
        """Node must exit > 0 with one error line naming `key` (and the entry)."""
        code, out, err = self._run(tag, params)
        ctx = '\n--- case %s: exit %s\n--- stderr:\n%s\n--- stdout:\n%s' % (tag, code, err, out)
        self.assertIsNotNone(code, 'node did not exit within %.0f s%s' % (EXIT_TIMEOUT, ctx))
        self.assertGreater(code, 0, 'exit code must be non-zero (and not a signal)%s' % ctx)
        # rosconsole sends ERROR/FATAL to stderr.
        lines = self._error_lines(err)
        self.assertEqual(len(lines), 1, 'expected exactly one error line%s' % ctx)
        line = lines[0]
        self.assertIn(key, line, 'error line does not name the key %r%s' % (key, ctx))
        if entry is not None or index is not None:
            named = (entry is not None and entry in line) or (
                index is not None and re.search(r'(\[|\b)%d(\]|\b)' % index, line))
            self.assertTrue(named, 'error line does not name the entry (%r / index %r)%s'
                            % (entry, index, ctx))

    def _launch(self, args, seconds):
        """roslaunch of rigid_body_sim.launch with the invalid scene and `args`:
        (exit code or None when still running after `seconds` s, stderr)."""
        with tempfile.NamedTemporaryFile('w', suffix='.yaml') as scene:
            scene.write(INVALID_SCENE)
            scene.flush()
            proc = subprocess.Popen(
                ['roslaunch', PKG, 'rigid_body_sim.launch', 'scene:=' + scene.name] + args,
                stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True)
            try:
                _, err = proc.communicate(timeout=seconds)
                code = proc.returncode
            except subprocess.TimeoutExpired:
                code = None
                os.killpg(proc.pid, signal.SIGINT)
                try:
                    _, err = proc.communicate(timeout=15.0)
                except subprocess.TimeoutExpired:
                    os.killpg(proc.pid, signal.SIGKILL)
                    _, err = proc.communicate()
        return code, err.decode(errors='replace')

    @staticmethod
    def _fatal_lines(text):
        return [l for l in text.splitlines() if '[FATAL]' in l]

    def test_launch_stops_without_respawn(self):
        code, err = self._launch([], LAUNCH_TIMEOUT)
        ctx = '\n--- roslaunch exit %s, stderr:\n%s' % (code, err)
        self.assertIsNotNone(code, 'the launch did not end within %.0f s%s'
                             % (LAUNCH_TIMEOUT, ctx))
        fatal = self._fatal_lines(err)
        self.assertEqual(len(fatal), 1, 'expected exactly one FATAL line%s' % ctx)
        self.assertIn('mass', fatal[0], ctx)
        self.assertRegex(err, r'REQUIRED process \[rigid_body_sim-\d+\] has died', ctx)
        self.assertRegex(err, r'process has died \[pid \d+, exit code 1,', ctx)

    def test_launch_retries_with_respawn(self):
        code, err = self._launch(['respawn:=true'], RESPAWN_SECONDS)
        ctx = '\n--- roslaunch exit %s, stderr:\n%s' % (code, err)
        self.assertIsNone(code, 'with respawn:=true the launch must keep running%s' % ctx)
        fatal = self._fatal_lines(err)
        self.assertGreaterEqual(len(fatal), 2, 'expected the node retried%s' % ctx)
        self.assertTrue(all('mass' in l for l in fatal), ctx)

    # ---- control ---------------------------------------------------------

    def test_00_valid_scene_keeps_running(self):
        code, out, err = self._run('valid', {'bodies': [good_body(), bad_body()]}, timeout=4.0)
        self.assertIsNone(code, 'a valid scene must keep the node running; exit %s\n%s'
                          % (code, err))

    # ---- bodies ------------------------------------------------------------

    def test_missing_bodies_is_an_empty_world(self):
        code, out, err = self._run('missing_bodies', {'rate': 1000.0}, timeout=4.0)
        self.assertIsNone(code, 'a scene without bodies must keep the node running; exit %s\n%s'
                          % (code, err))

    def test_empty_bodies_is_an_empty_world(self):
        code, out, err = self._run('empty_bodies', {'bodies': []}, timeout=4.0)
        self.assertIsNone(code, 'an empty bodies list must keep the node running; exit %s\n%s'
                          % (code, err))

    def test_inertial_mass_negative(self):
        inertial = {'mass': -1.0, 'inertia': {'ixx': 1.0, 'ixy': 0.0, 'ixz': 0.0, 'iyy': 1.0,
                                              'iyz': 0.0, 'izz': 1.0}}
        body = {'name': 'badbody', 'inertial': inertial}
        self.check_rejected('inertial_mass_negative', {'bodies': [good_body(), body]},
                            'inertial.mass', entry='badbody')

    def test_bodies_not_a_list(self):
        self.check_rejected('bodies_not_a_list', {'bodies': 5}, 'bodies')

    def test_duplicate_name(self):
        self.check_rejected('duplicate_name', {'bodies': [good_body('twin'), good_body('twin')]},
                            'name', entry='twin')

    def test_empty_name(self):
        self.check_rejected('empty_name', {'bodies': [good_body(), bad_body(name='')]},
                            'name', index=1)

    def test_mass_zero(self):
        self.check_rejected('mass_zero',
                            {'bodies': [good_body(), bad_body(particles=with_particle(mass=0.0))]},
                            'mass', entry='badbody', index=1)

    def test_mass_negative(self):
        self.check_rejected('mass_negative',
                            {'bodies': [good_body(), bad_body(particles=with_particle(mass=-1.0))]},
                            'mass', entry='badbody', index=1)

    def test_mass_nan(self):
        self.check_rejected('mass_nan',
                            {'bodies': [good_body(),
                                        bad_body(particles=with_particle(mass=float('nan')))]},
                            'mass', entry='badbody', index=1)

    def test_mass_inf(self):
        self.check_rejected('mass_inf',
                            {'bodies': [good_body(),
                                        bad_body(particles=with_particle(mass=float('inf')))]},
                            'mass', entry='badbody', index=1)

    def test_particle_position_two_numbers(self):
        self.check_rejected('particle_position_2',
                            {'bodies': [good_body(),
                                        bad_body(particles=with_particle(position=[0.0, 1.0]))]},
                            'position', entry='badbody', index=1)

    def test_particle_position_not_finite(self):
        self.check_rejected('particle_position_inf',
                            {'bodies': [good_body(), bad_body(
                                particles=with_particle(position=[0.0, float('inf'), 0.0]))]},
                            'position', entry='badbody', index=1)

    def test_body_position_four_numbers(self):
        self.check_rejected('body_position_4',
                            {'bodies': [good_body(), bad_body(position=[1.0, 2.0, 3.0, 4.0])]},
                            'position', entry='badbody', index=1)

    def test_body_position_not_numbers(self):
        self.check_rejected('body_position_str',
                            {'bodies': [good_body(), bad_body(position='up')]},
                            'position', entry='badbody', index=1)

    # ---- node parameters ---------------------------------------------------

    def test_rate_zero(self):
        self.check_rejected('rate_zero', {'rate': 0.0, 'bodies': [good_body()]}, 'rate')

    def test_rate_negative(self):
        self.check_rejected('rate_negative', {'rate': -100.0, 'bodies': [good_body()]}, 'rate')

    def test_publish_rate_zero(self):
        self.check_rejected('publish_rate_zero',
                            {'publish_rate': 0.0, 'bodies': [good_body()]}, 'publish_rate')

    def test_publish_rate_above_rate(self):
        self.check_rejected('publish_rate_above_rate',
                            {'rate': 100.0, 'publish_rate': 200.0, 'bodies': [good_body()]},
                            'publish_rate')

    def test_clock_rate_not_dividing_rate(self):
        self.check_rejected('clock_rate_not_dividing_rate',
                            {'rate': 1000.0, 'clock_rate': 300.0, 'bodies': [good_body()]},
                            'clock_rate')

    def test_clock_rate_above_rate(self):
        self.check_rejected('clock_rate_above_rate',
                            {'rate': 1000.0, 'clock_rate': 2000.0, 'bodies': [good_body()]},
                            'clock_rate')

    def test_clock_rate_zero(self):
        self.check_rejected('clock_rate_zero',
                            {'clock_rate': 0.0, 'bodies': [good_body()]}, 'clock_rate')

    def test_start_paused_not_a_bool(self):
        self.check_rejected('start_paused_not_a_bool',
                            {'start_paused': 'yes', 'bodies': [good_body()]}, 'start_paused')

    def test_unknown_integrator(self):
        self.check_rejected('unknown_integrator',
                            {'integrator': 'no_such_scheme', 'bodies': [good_body()]},
                            'integrator')

    def test_wind_gust_time_constant_zero(self):
        self.check_rejected('wind_gust_time_constant_zero',
                            {'wind': {'gust_stddev': [1.0, 1.0, 0.0], 'gust_time_constant': 0.0},
                             'bodies': [good_body()]}, 'wind.gust_time_constant')

    def test_wind_unknown_key(self):
        self.check_rejected('wind_unknown_key',
                            {'wind': {'gusts': 1.0}, 'bodies': [good_body()]}, 'wind')

    def test_drag_negative(self):
        self.check_rejected('drag_negative',
                            {'bodies': [good_body(), bad_body(drag={'linear': [0.1, -0.1, 0.0]})]},
                            'drag.linear', entry='badbody', index=1)

    def test_status_period_negative(self):
        self.check_rejected('status_period_negative',
                            {'status_period': -1.0, 'bodies': [good_body()]}, 'status_period')

    def test_max_substeps_zero(self):
        self.check_rejected('max_substeps_zero',
                            {'max_substeps': 0, 'bodies': [good_body()]}, 'max_substeps')

    def test_max_substeps_fractional(self):
        self.check_rejected('max_substeps_fractional',
                            {'max_substeps': 2.5, 'bodies': [good_body()]}, 'max_substeps')

    def test_threads_zero(self):
        self.check_rejected('threads_zero', {'threads': 0, 'bodies': [good_body()]}, 'threads')

    def test_threads_fractional(self):
        self.check_rejected('threads_fractional',
                            {'threads': 1.5, 'bodies': [good_body()]}, 'threads')

    def test_threads_not_a_number(self):
        self.check_rejected('threads_not_a_number',
                            {'threads': 'two', 'bodies': [good_body()]}, 'threads')

    def test_lockstep_without_publishers(self):
        self.check_rejected('lockstep_without_publishers',
                            {'lockstep': True, 'bodies': [good_body()]}, 'lockstep_publishers')

    def test_lockstep_publishers_not_a_list(self):
        self.check_rejected('lockstep_publishers_not_a_list',
                            {'lockstep': True, 'lockstep_publishers': '/controller',
                             'bodies': [good_body()]}, 'lockstep_publishers')

    def test_lockstep_timeout_zero(self):
        self.check_rejected('lockstep_timeout_zero',
                            {'lockstep': True, 'lockstep_publishers': ['/controller'],
                             'lockstep_timeout': 0.0, 'bodies': [good_body()]}, 'lockstep_timeout')

    def test_spawn_file_roots_relative(self):
        self.check_rejected('spawn_file_roots_relative',
                            {'spawn_file_roots': ['urdf'], 'bodies': [good_body()]},
                            'spawn_file_roots')

    def test_spawn_file_roots_not_a_directory(self):
        self.check_rejected('spawn_file_roots_not_a_directory',
                            {'spawn_file_roots': ['/dev/null'], 'bodies': [good_body()]},
                            'spawn_file_roots')

    def test_rate_above_a_nanosecond_lattice(self):
        self.check_rejected('rate_above_1e9', {'rate': 2e9, 'publish_rate': 1.0,
                                               'bodies': [good_body()]}, 'rate')


if __name__ == '__main__':
    rostest.rosrun(PKG, 'invalid_scene', InvalidScene)
