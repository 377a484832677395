#!/usr/bin/python3
"""The ROS commands of the documents, checked so that they cannot rot.

Read at test time: README.md, every doc/*.md and bench/README.md, in that
order (doc/ sorted by name). Every ```bash fenced block is split into commands
(joining `\\` continuations and quoted strings that span lines, leading
`VAR=value` words dropped). A command is

- `rostopic ...` / `rosservice ...`: run, in document order, with `/bin/bash -c`
  against the node started by readme_examples.test (launch/rigid_body_sim.launch
  with its defaults: node `/rigid_body_sim`, the default scene), and its effect
  checked (below);
- `rosrun dynamic_reconfigure dynparam set <node> <key> <value>`: run against
  the node like the above; afterwards the parameter `<node>/<key>` holds the
  value (the server writes what it applied back);
- `roslaunch [options] <package> <file> [name:=value ...]`, or
  `bash scripts/run.sh [name:=value ...]` (which runs
  `roslaunch rigid_body_sim rigid_body_sim.launch "$@"`, checked in the script):
  not started (a second node would clash with the one under test) but
  resolved: `roslaunch --nodes` with the same file and arguments must succeed,
  every `name` must be an argument the launch file declares
  (`roslaunch --ros-args`), and an `integrator:=` value must be a name of the
  integrator table in doc/physics.md;
- `rostest [options] <package> <file>`: the file must exist in the package,
  exactly once, and `roslaunch --nodes` must load it;
- a command that reads a recorded bag (`rosbag info BAG`, `rostopic echo -b
  BAG ...`, `rosrun rigid_body_sim replay BAG`): not run (record_replay.test
  runs recording and replay) but checked: an earlier command of the same
  document records BAG (`record:=BAG`), and the tool exists;
- anything else that names a ROS command-line tool (`rosrun`, `rosparam`, a
  `roslaunch` after `&&`, ...): a failure, so that no such command goes
  unchecked; a ROS command in a fenced block that is not ```bash fails too;
- any other command (build and shell set-up lines): not run.

For each command run against the node:
- it exits with code 0 within COMMAND_TIMEOUT s; a command that runs until
  interrupted (`rostopic echo/hz/bw/delay` without `-n`, `rostopic pub`
  without `-1`) runs for STREAM_SECONDS s, is interrupted and must have
  printed at least one message;
- `rostopic echo -n N` printed a message (`---`);
- `rosservice call`: when the service's response has a `success` field, the
  output says `success: True`;
- effects, checked on `~bodies` (read with rospy all along):
  * `rostopic pub` of a ParticleWrench / ParticleWrenchArray, a
    WrenchStamped on `~<body>/wrench`, or an ActuatorCommand on
    `~<body>/actuators` of a body spawned earlier from `inertial` with
    `sites` and `actuators` (each thrust T, clipped, along its site's z at
    the site, with the couple torque_coefficient * T, held once ten time
    constants have passed): every body the message pushes with a
    non-zero wrench changed its momentum or angular momentum, and, for every
    body, dp/dt and dL/dt measured between two consecutive `~bodies` messages
    equal the force and torque of the wrenches held (a model of them kept by
    this test across all documents: world or body axes per frame_id, a later
    wrench for the same (body, particle) or on the same `~<body>/wrench`
    replaces an earlier one, a zero one removes it; torque = sum of r_i x f_i
    plus couples, with r_i from `~particles`, or 0 at the COM);
  * `~apply_body_wrench`: a job until cleared (duration < 0) joins the model
    with r_i its reference_point; a job with a duration is waited out (at
    the real-time factor 1 of the documents) before the rates are checked;
  * `~clear_wrenches`: the model is emptied, so every dp/dt and dL/dt is 0;
    `~clear_body_wrenches` empties it for the body named (all for "");
  * `~spawn_body` / `~delete_body`: the body is in / out of the next
    `~bodies` message (bodies are matched by name throughout);
  * `~reset`: every body's p, L and kinetic energy equal those published at
    start (invariants of the torque-free motion), stamps still increase;
  * `~set_paused true`: no `~bodies` message for 1 s; `~step N`: exactly one
    message whose stamp is the response's `sim_time`, N to N + k - 1 steps
    after the last one before pausing (k = rate / publish_rate);
    `~step_with_wrenches`: its entries join the model as an array on
    `~particle_wrenches` would, then as `~step`, and its `state_hash` is
    the hash of that message; `false`: messages flow again with later stamps;
  * `~set_body_state`: the body's next state has the requested position,
    orientation, linear and angular velocity.
- the node's PID is the same at the end as at the start (under
  `respawn:=true` a crash would otherwise go unnoticed).

A failure names the document, the line number and the command.
"""
import math
import os
import re
import shlex
import signal
import shutil
import subprocess
import threading
import time
import unittest

import rosgraph
import rosnode
import rospkg
import rospy
import rosservice
import rostest
import yaml
from xmlrpc.client import ServerProxy

from rigid_body_sim.msg import BodyStateArray
from rigid_body_sim.testing import state_hash
from visualization_msgs.msg import MarkerArray

PKG = 'rigid_body_sim'
NODE = '/rigid_body_sim'
COMMAND_TIMEOUT = 20.0   # s; `rostopic pub -1` takes about 3 s
STREAM_SECONDS = 4.0     # s a never-ending command runs before it is interrupted
STARTUP_TIMEOUT = 30.0   # s to wait for the node's first ~bodies message
RUN_COMMANDS = ('rostopic', 'rosservice')
DYNPARAM_SET = ['rosrun', 'dynamic_reconfigure', 'dynparam', 'set']
# A command that names one of these anywhere but as handled below fails the test.
ROS_TOOLS = ('rostopic', 'rosservice', 'roslaunch', 'rostest', 'rosrun', 'rosparam', 'rosnode',
             'rosmsg', 'rossrv', 'roscore', 'rosbag', 'rosbash', 'roswtf', 'rviz', 'rqt')
RUN_SCRIPT = 'scripts/run.sh'           # `bash scripts/run.sh ARGS` = roslaunch of ...
RUN_SCRIPT_LAUNCH = ['rigid_body_sim', 'rigid_body_sim.launch']   # ... this file with ARGS
# roslaunch / rostest options that take a value.
OPTIONS_WITH_VALUE = {
    'roslaunch': ('-c', '--child', '-u', '--server_uri', '--run_id', '-p', '--port', '--pid', '-w',
                  '--numworkers', '-t', '--timeout', '--master-logger-level', '--sigint-timeout',
                  '--sigterm-timeout', '--args', '--find-node'),
    'rostest': ('--pkgdir', '--package', '--results-filename', '--results-base-dir'),
}
STREAMING_ECHO = ('echo', 'hz', 'bw', 'delay')
REL_TOL = 0.05           # dp/dt, dL/dt vs. the held wrenches (bodies spin up to ~20 rad/s)
ABS_TOL = 2e-3           # N, N m
KEEP_MSGS = 3000         # ~bodies messages kept (30 s at 100 Hz); count() counts them all


# ---- the documents ----------------------------------------------------------

def package_dir():
    return rospkg.RosPack().get_path(PKG)


def documents():
    """[(path relative to the package, absolute path)] in the order they are run."""
    root = package_dir()
    docs = ['README.md']
    doc_dir = os.path.join(root, 'doc')
    if os.path.isdir(doc_dir):
        docs += sorted(os.path.join('doc', f) for f in os.listdir(doc_dir) if f.endswith('.md'))
    if os.path.isfile(os.path.join(root, 'bench', 'README.md')):
        docs.append(os.path.join('bench', 'README.md'))
    return [(d, os.path.join(root, d)) for d in docs]


def bash_commands(text, name):
    """[(line number, command text)] of every ```bash block, in order. A line of
    another fenced block that starts with a ROS tool raises ValueError."""
    commands = []
    in_bash = in_other = False
    buf, buf_line = [], None
    for lineno, line in enumerate(text.split('\n'), 1):
        stripped = line.strip()
        if stripped.startswith('```'):
            if in_bash and buf:
                raise ValueError('%s line %d: unterminated command at the end of a '
                                 'bash block: %r' % (name, buf_line, '\n'.join(buf)))
            if in_bash or in_other:
                in_bash = in_other = False
            elif stripped == '```bash':
                in_bash = True
            else:
                in_other = True
            buf, buf_line = [], None
            continue
        if in_other:
            first = stripped.lstrip('$ ').split(' ', 1)[0]
            if os.path.basename(first) in ROS_TOOLS or RUN_SCRIPT in stripped.split(' ', 2)[:2]:
                raise ValueError('%s line %d: a ROS command outside a ```bash block, where '
                                 'readme_examples_test.py does not check it: %r'
                                 % (name, lineno, stripped))
            continue
        if not in_bash:
            continue
        if not buf and (not stripped or stripped.startswith('#')):
            continue
        if not buf:
            buf_line = lineno
        buf.append(line)
        command = '\n'.join(buf)
        if command.rstrip().endswith('\\'):
            continue
        try:
            shlex.split(command, comments=True)
        except ValueError:       # a quoted string goes on over the next line
            continue
        commands.append((buf_line, command))
        buf, buf_line = [], None
    return commands


def all_commands():
    """[(document, line number, command)] of every document, in order."""
    out = []
    for name, path in documents():
        with open(path) as f:
            out += [(name, lineno, c) for lineno, c in bash_commands(f.read(), name)]
    return out


def words(command):
    """The command's words, without leading `VAR=value` assignments."""
    w = shlex.split(command.replace('\\\n', ' '), comments=True)
    while w and re.match(r'^[A-Za-z_][A-Za-z0-9_]*=', w[0]):
        w = w[1:]
    return w


def bag_read(w):
    """The bag that the command of words `w` reads, for the commands that read
    a recorded bag (`rosbag info BAG`, `rostopic echo -b BAG ...`, `rosrun
    rigid_body_sim replay BAG`); None for any other command."""
    if w[:2] == ['rosbag', 'info'] and len(w) == 3:
        return w[2]
    if w[:2] == ['rostopic', 'echo'] and '-b' in w[:-1]:
        return w[w.index('-b') + 1]
    if w[:3] == ['rosrun', 'rigid_body_sim', 'replay'] and len(w) == 4:
        return w[3]
    return None


def classify(command):
    """'run', 'stream' (runs until interrupted), 'launch', 'rostest', 'bag' (reads
    a recorded bag) or 'skip' (no ROS tool in it); None: a ROS tool used in a
    way this test does not check."""
    w = words(command)
    if w and bag_read(w):
        kind, rest = 'bag', w[1:]
    elif w and w[0] == 'bash' and len(w) > 1 and w[1] == RUN_SCRIPT:
        kind = 'launch'
        rest = w[2:]
    elif w and w[0] in RUN_COMMANDS:
        kind = 'run'
        rest = w[1:]
        if w[0] == 'rostopic' and len(w) > 1:
            if w[1] in STREAMING_ECHO and not any(a == '-n' or a.startswith('-n') for a in w[2:]):
                kind = 'stream'
            if w[1] == 'pub' and not any(a in ('-1', '--once') or a.startswith('-f')
                                         for a in w[2:]):
                kind = 'stream'
    elif w[:4] == DYNPARAM_SET:
        kind, rest = 'run', w[4:]
    elif w and w[0] == 'roslaunch':
        kind, rest = 'launch', w[1:]
    elif w and w[0] == 'rostest':
        kind, rest = 'rostest', w[1:]
    else:
        kind, rest = 'skip', w
    # Another command chained on (`&&`, `;`, `|`) or a ROS tool in a non-ROS line.
    tools = [a for a in rest if os.path.basename(a) in ROS_TOOLS or a.endswith(RUN_SCRIPT)]
    if tools or (kind != 'skip' and any(a in ('&&', '||', ';', '|', '&') for a in rest)):
        return None
    if kind == 'skip' and (RUN_SCRIPT in command or re.search(
            r'(?<![\w.-])(%s)(?![\w.-])' % '|'.join(ROS_TOOLS), command)):
        return None  # e.g. `source x&&roslaunch ...`
    return kind


def split_launch_args(tool, args):
    """(files, [(name, value)]) of the arguments of a roslaunch/rostest command line."""
    files, launch_args, skip = [], [], False
    for a in args:
        if skip:
            skip = False
            continue
        if a.startswith('-'):
            skip = a in OPTIONS_WITH_VALUE[tool]
            continue
        if ':=' in a:
            name, value = a.split(':=', 1)
            launch_args.append((name, value))
        else:
            files.append(a)
    return files, launch_args


def integrator_names():
    """The names of the integrator table in doc/physics.md (`| name | order |`)."""
    path = os.path.join(package_dir(), 'doc', 'physics.md')
    names, in_table = [], False
    with open(path) as f:
        for line in f:
            if re.match(r'^\|\s*name\s*\|\s*order\s*\|', line):
                in_table = True
                continue
            if in_table:
                m = re.match(r'^\|\s*`([a-z0-9_]+)`\s*\|', line)
                if m:
                    names.append(m.group(1))
                elif not line.startswith('|'):
                    break
    return names


def load_launch(files, argv, args_only=False):
    """(loader, error) of roslaunch's own load of a launch file, as `roslaunch --nodes FILES
    ARGV` (or, with args_only, `roslaunch --ros-args FILES`) does it, in this process: the
    files resolve to exactly one path each and every substitution with these arguments
    (name:=value) resolves; error is None, or what roslaunch would print."""
    import roslaunch.config
    import roslaunch.core
    import roslaunch.rlutil
    import roslaunch.xmlloader
    loader = roslaunch.xmlloader.XmlLoader(resolve_anon=False, args_only=args_only)
    loader.ignore_unset_args = False
    try:
        for path in roslaunch.rlutil.resolve_launch_arguments(files):
            loader.load(path, roslaunch.config.ROSLaunchConfig(), argv=['roslaunch'] + argv,
                        verbose=False)
    except roslaunch.core.RLException as e:
        return loader, str(e)
    return loader, None


def declared_launch_args(files):
    loader, error = load_launch(files, [], args_only=True)
    if error is not None:
        return None, error
    return set(loader.root_context.resolve_dict.get('arg_doc', {})), None


def positional(args):
    """Positional arguments after the sub-command, options (and -n's value) dropped."""
    out, skip = [], False
    for a in args:
        if skip:
            skip = False
            continue
        if a in ('-n', '-r', '--rate', '-s', '--filter', '-w', '--window'):
            skip = True
            continue
        if a.startswith('-'):
            continue
        out.append(a)
    return out


# ---- small vector algebra (no numpy in Debian's ROS python here) ------------

def vec(v):
    return (v.x, v.y, v.z)


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def scale(s, a):
    return tuple(s * x for x in a)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(sum(x * x for x in a))


def rot(q):
    """Rotation matrix (rows) of a geometry_msgs quaternion, normalised."""
    x, y, z, w = q.x, q.y, q.z, q.w
    n = math.sqrt(x * x + y * y + z * z + w * w)
    x, y, z, w = x / n, y / n, z / n, w / n
    return ((1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)),
            (2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)),
            (2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)))


def mul(m, v):
    return tuple(sum(m[i][j] * v[j] for j in range(3)) for i in range(3))


def mul_t(m, v):
    return tuple(sum(m[j][i] * v[j] for j in range(3)) for i in range(3))


def get3(d, key):
    d = (d or {}).get(key) or {}
    return (float(d.get('x', 0.0)), float(d.get('y', 0.0)), float(d.get('z', 0.0)))


# ---- the test ---------------------------------------------------------------

class ReadmeExamples(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rospy.init_node('readme_examples_test', anonymous=True)
        cls.lock = threading.Lock()
        cls.bodies_msgs = []      # (receipt wall time, BodyStateArray), the last KEEP_MSGS
        cls.bodies_total = 0      # ~bodies messages received since the start
        cls.particles = {}        # stamp ns -> MarkerArray (recent only)
        rospy.Subscriber(NODE + '/bodies', BodyStateArray, cls._on_bodies, queue_size=1000)
        rospy.Subscriber(NODE + '/particles', MarkerArray, cls._on_particles, queue_size=1000)

    @classmethod
    def _on_bodies(cls, msg):
        with cls.lock:
            cls.bodies_msgs.append((time.time(), msg))
            cls.bodies_total += 1
            del cls.bodies_msgs[:-KEEP_MSGS]

    @classmethod
    def _on_particles(cls, msg):
        if not msg.markers:
            return
        with cls.lock:
            cls.particles[msg.markers[0].header.stamp.to_nsec()] = msg
            if len(cls.particles) > 3000:
                for k in sorted(cls.particles)[:-3000]:
                    del cls.particles[k]

    # -- helpers --------------------------------------------------------------

    def count(self):
        with self.lock:
            return self.bodies_total

    def last(self):
        with self.lock:
            return self.bodies_msgs[-1][1] if self.bodies_msgs else None

    def since(self, n):
        with self.lock:
            first = self.bodies_total - len(self.bodies_msgs)   # index of bodies_msgs[0]
            return [m for _, m in self.bodies_msgs[max(0, n - first):]]

    def wait_new(self, n0, count, timeout, where):
        deadline = time.time() + timeout
        while time.time() < deadline and self.count() - n0 < count:
            time.sleep(0.01)
        msgs = self.since(n0)
        self.assertGreaterEqual(len(msgs), count, '%s: %d ~bodies message(s) within %.1f s, '
                                'expected %d' % (where, len(msgs), timeout, count))
        return msgs

    def node_pid(self):
        uri = rosnode.get_api_uri(rosgraph.Master('/readme_examples_test'), NODE,
                                  skip_cache=True)
        self.assertTrue(uri, 'node %s not registered' % NODE)
        code, _, pid = ServerProxy(uri).getPid('/readme_examples_test')
        self.assertEqual(code, 1)
        return pid

    def run_command(self, where, command, kind):
        proc = subprocess.Popen(['/bin/bash', '-c', command], stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, start_new_session=True)
        limit = STREAM_SECONDS if kind == 'stream' else COMMAND_TIMEOUT
        timed_out = False
        try:
            out, err = proc.communicate(timeout=limit)
        except subprocess.TimeoutExpired:
            timed_out = True
            os.killpg(proc.pid, signal.SIGINT)
            try:
                out, err = proc.communicate(timeout=5.0)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
                out, err = proc.communicate()
        out, err = out.decode(errors='replace'), err.decode(errors='replace')
        ctx = '%s\n--- exit %s\n--- stdout:\n%s\n--- stderr:\n%s' % (
            where, proc.returncode, out[-3000:], err[-3000:])
        if kind == 'stream':
            self.assertTrue(timed_out, '%s: expected to run until interrupted\n%s'
                            % (where, ctx))
            self.assertIn('---', out, '%s: printed no message in %.0f s\n%s'
                          % (where, STREAM_SECONDS, ctx))
        else:
            self.assertFalse(timed_out, '%s: did not finish within %.0f s\n%s'
                             % (where, COMMAND_TIMEOUT, ctx))
            self.assertEqual(proc.returncode, 0, 'documented command failed: %s' % ctx)
        return out, ctx

    # -- the wrench model and the momentum rates --------------------------------

    def reference_offsets(self):
        """body name -> particle offsets r̄_i in body axes, from matching
        ~bodies and ~particles messages."""
        deadline = time.time() + 10.0
        while time.time() < deadline:
            with self.lock:
                pairs = [(m, self.particles.get(m.header.stamp.to_nsec()))
                         for _, m in self.bodies_msgs[-50:]]
            pairs = [(b, p) for b, p in pairs if p is not None]
            if pairs:
                bodies, markers = pairs[-1]
                offsets = {}
                for b, marker in zip(bodies.bodies, markers.markers):
                    a = rot(b.pose.orientation)
                    c = vec(b.pose.position)
                    offsets[b.name] = [mul_t(a, sub(vec(p), c)) for p in marker.points]
                return offsets
            time.sleep(0.05)
        self.fail('no ~particles message with the stamp of a ~bodies message in 10 s')

    def predicted(self, state):
        """(dp/dt, dL/dt) of one body from the wrenches held in the model."""
        a = rot(state.pose.orientation)
        force, torque = (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)
        for (body, _), (in_body_axes, f, t, offset) in self.held.items():
            if body != state.name:
                continue
            if in_body_axes:
                f, t = mul(a, f), mul(a, t)
            r = mul(a, offset)
            force = add(force, f)
            torque = add(torque, add(cross(r, f), t))
        return force, torque

    def check_rates(self, where, pairs=2):
        """dp/dt and dL/dt between consecutive ~bodies messages = the held wrenches."""
        n0 = self.count()
        msgs = self.wait_new(n0, pairs + 1, 5.0, where)
        checked = 0
        for m1, m2 in zip(msgs, msgs[1:]):
            dt = (m2.header.stamp - m1.header.stamp).to_sec()
            self.assertGreater(dt, 0.0, '%s: ~bodies stamps not increasing' % where)
            later = {b.name: b for b in m2.bodies}
            for b1 in m1.bodies:
                b2 = later.get(b1.name)
                if b2 is None:
                    continue   # deleted in between
                f1, t1 = self.predicted(b1)
                f2, t2 = self.predicted(b2)
                f, t = scale(0.5, add(f1, f2)), scale(0.5, add(t1, t2))
                dp = scale(1.0 / dt, sub(vec(b2.linear_momentum), vec(b1.linear_momentum)))
                dl = scale(1.0 / dt, sub(vec(b2.angular_momentum), vec(b1.angular_momentum)))
                for name, got, want in (('dp/dt', dp, f), ('dL/dt', dl, t)):
                    self.assertLessEqual(
                        norm(sub(got, want)), REL_TOL * norm(want) + ABS_TOL,
                        '%s: body %s: %s = (%.4g, %.4g, %.4g) over [%s, %s], expected '
                        '(%.4g, %.4g, %.4g) from the held wrenches %r'
                        % (where, b1.name, name, got[0], got[1], got[2], m1.header.stamp,
                           m2.header.stamp, want[0], want[1], want[2], self.held))
            checked += 1
        self.assertGreaterEqual(checked, 1)

    def apply_push(self, where, args, before):
        """Update the held-wrench model from a documented `rostopic pub`."""
        pos = positional(args[2:])
        self.assertGreaterEqual(len(pos), 3, '%s: expected topic, type and message' % where)
        topic, msg_type, text = pos[0], pos[1], ' '.join(pos[2:])
        data = yaml.safe_load(text)
        names = [b.name for b in before.bodies]
        if topic.endswith('/wrench') and msg_type.endswith('WrenchStamped'):
            body = topic.rstrip('/').split('/')[-2]
            self.assertIn(body, names, '%s: unknown body %r in the example' % (where, body))
            return self.hold(where, body, 'com', data, (0.0, 0.0, 0.0))
        if topic.endswith('/actuators') and msg_type.endswith('ActuatorCommand'):
            return self.hold_thrusts(where, topic.rstrip('/').split('/')[-2], data)
        if topic.endswith('/particle_wrench') and msg_type.endswith('ParticleWrench'):
            entries = [data]
        elif topic.endswith('/particle_wrenches') and msg_type.endswith('ParticleWrenchArray'):
            entries = data.get('wrenches', [])
        else:
            return None   # not a push: no model to update
        return self.hold_entries(where, entries, names)

    def hold_entries(self, where, entries, names):
        """Holds ParticleWrench entries in the model; the bodies they push."""
        pushed = set()
        for e in entries:
            body = e.get('body')
            particle = int(e.get('particle', 0))
            self.assertIn(body, names, '%s: unknown body %r in the example' % (where, body))
            self.assertLess(particle, len(self.offsets[body]),
                            '%s: particle %d out of range for %s' % (where, particle, body))
            pushed |= self.hold(where, body, particle, e, self.offsets[body][particle])
        return pushed

    def hold_thrusts(self, where, body, command):
        """Holds each commanded thrust of an ActuatorCommand in the model, once
        its lag has settled; {body} if one pushes."""
        self.assertIn(body, self.thrusters, '%s: %s was not spawned with actuators in the '
                      'documents before' % (where, body))
        thrusters = self.thrusters[body]
        names = command.get('names') or list(thrusters)
        pushed = set()
        settle = 0.0
        for name, u in zip(names, command.get('commands') or []):
            offset, axis, coefficient, low, high, tau = thrusters[name]
            thrust = min(max(float(u), low), high)
            self.held[(body, 'actuator ' + name)] = (True, scale(thrust, axis),
                                                    scale(coefficient * thrust, axis), offset)
            pushed |= {body} if thrust != 0.0 else set()
            settle = max(settle, 10.0 * tau)
        time.sleep(settle)   # at real-time factor 1: T is u to 5e-5 after ten time constants
        return pushed

    def remember_thrusters(self, where, entry):
        """The thrusters of a spawned `inertial` entry: name -> (site from the
        COM, site z, torque coefficient, min, max, time constant), body axes."""
        if not entry.get('actuators'):
            return
        self.assertIn('inertial', entry, '%s: the model knows the COM of inertial '
                      'entries only' % where)
        origin = entry['inertial'].get('origin') or {}
        com = tuple(float(x) for x in origin.get('xyz', [0.0, 0.0, 0.0]))
        sites = {}
        for site in entry.get('sites', []):
            q = site.get('orientation', [0.0, 0.0, 0.0, 1.0])
            orientation = type('Q', (), dict(zip('xyzw', (float(x) for x in q))))
            sites[site['name']] = (sub(tuple(float(x) for x in site.get('position', [0.0] * 3)),
                                       com), mul(rot(orientation), (0.0, 0.0, 1.0)))
        self.thrusters[entry['name']] = {
            a['name']: sites[a['site']] + (float(a.get('torque_coefficient', 0.0)),
                                            float(a.get('min_thrust', 0.0)),
                                            float(a['max_thrust']),
                                            float(a.get('time_constant', 0.0)))
            for a in entry['actuators']}

    def hold(self, where, body, key, message, offset):
        """Holds the wrench of a ParticleWrench entry or a WrenchStamped in the
        model under (body, key), force at `offset` (body axes); {body} if it
        pushes."""
        header = message.get('header') or {}
        stamp = header.get('stamp') or {}
        if isinstance(stamp, dict) and (stamp.get('secs') or stamp.get('nsecs')):
            self.skipTest('%s: a stamped wrench; the model handles zero stamps only' % where)
        frame = str(header.get('frame_id', '') or '').lstrip('/')
        self.assertIn(frame, ('', 'world', body),
                      '%s: frame_id %r: neither world nor the body' % (where, frame))
        wrench = message.get('wrench') or {}
        f, t = get3(wrench, 'force'), get3(wrench, 'torque')
        if norm(f) == 0.0 and norm(t) == 0.0:
            self.held.pop((body, key), None)
            return set()
        self.held[(body, key)] = (frame == body, f, t, offset)
        return {body}

    # -- the tests --------------------------------------------------------------

    def classified(self):
        """[(document, line, command, kind)] of every document; fails on a command
        that uses a ROS tool in a way this test does not check."""
        try:
            commands = all_commands()
        except ValueError as e:
            self.fail(str(e))
        kinds = [(doc, l, c, classify(c)) for doc, l, c in commands]
        unknown = ['%s line %d: %s' % (d, l, c) for d, l, c, k in kinds if k is None]
        self.assertFalse(unknown, 'documented commands that use a ROS tool in a way this test '
                         'does not check (write one plain rostopic, rosservice, roslaunch or '
                         'rostest command per line, or extend readme_examples_test.py):\n'
                         + '\n'.join(unknown))
        return kinds

    def test_bag_commands(self):
        """Every command that reads a recorded bag reads one that an earlier
        command of its document records (`record:=BAG`), with a tool that
        exists: the bag is the reader's, so these are checked, not run
        (record_replay.test runs the recording and the replay)."""
        import roslib.packages
        recorded = {}
        checked = 0
        for doc, lineno, command, kind in self.classified():
            w = words(command)
            recorded.setdefault(doc, set()).update(
                a.split(':=', 1)[1] for a in w if a.startswith('record:='))
            if kind != 'bag':
                continue
            where = '%s line %d: `%s`' % (doc, lineno, ' '.join(w))
            self.assertIn(bag_read(w), recorded[doc], '%s: no earlier command of %s records '
                          'that bag (record:=)' % (where, doc))
            if w[0] == 'rosrun':
                self.assertTrue(roslib.packages.find_node(w[1], w[2]),
                                '%s: package %s has no executable %s' % (where, w[1], w[2]))
            else:
                self.assertIsNotNone(shutil.which(w[0]), '%s: no %s on PATH' % (where, w[0]))
            checked += 1
        self.assertGreater(checked, 0, 'no documented command reads a recorded bag')

    def test_launch_and_rostest_lines(self):
        """Every roslaunch (and `bash scripts/run.sh`) line resolves its launch file
        with its arguments; every rostest line names a test file of the package."""
        import roslib.packages
        checked = 0
        integrators = None
        for doc, lineno, command, kind in self.classified():
            if kind not in ('launch', 'rostest'):
                continue
            w = words(command)
            where = '%s line %d: `%s`' % (doc, lineno, ' '.join(w))
            rospy.loginfo('checking %s', where)
            if w[0] == 'bash':
                with open(os.path.join(package_dir(), RUN_SCRIPT)) as f:
                    script = f.read()
                self.assertIn('roslaunch %s "$@"' % ' '.join(RUN_SCRIPT_LAUNCH), script,
                              '%s: %s no longer runs roslaunch %s with its arguments; update '
                              'RUN_SCRIPT_LAUNCH in readme_examples_test.py'
                              % (where, RUN_SCRIPT, ' '.join(RUN_SCRIPT_LAUNCH)))
                files, launch_args = split_launch_args('roslaunch', w[2:])
                files = RUN_SCRIPT_LAUNCH + files
            else:
                files, launch_args = split_launch_args(w[0], w[1:])
            self.assertIn(len(files), (1, 2), '%s: expected <package> <file> or a path, got %r'
                          % (where, files))
            if kind == 'rostest':
                if len(files) == 2:
                    found = roslib.packages.find_resource(files[0], files[1])
                    self.assertEqual(len(found), 1, '%s: %s in package %s: found %r, expected '
                                     'exactly one file' % (where, files[1], files[0], found))
                else:
                    self.assertTrue(os.path.isfile(files[0]), '%s: no file %s'
                                    % (where, files[0]))
            argv = ['%s:=%s' % a for a in launch_args]
            _, error = load_launch(files, argv)
            self.assertIsNone(error, '%s: roslaunch cannot load %s:\n%s'
                              % (where, ' '.join(files + argv), error))
            if launch_args:
                declared, report = declared_launch_args(files)
                self.assertIsNotNone(declared, '%s: roslaunch cannot read the arguments of %s:\n%s'
                                     % (where, ' '.join(files), report))
                undeclared = [n for n, _ in launch_args if n not in declared]
                self.assertFalse(undeclared, '%s: argument(s) %s not declared by the launch file '
                                 '(it declares %s)' % (where, ', '.join(undeclared),
                                                       ', '.join(sorted(declared))))
            for name, value in launch_args:
                if name == 'integrator' and value:
                    if integrators is None:
                        integrators = integrator_names()
                    self.assertIn(value, integrators, '%s: integrator %r is not in the table of '
                                  'doc/physics.md %r' % (where, value, integrators))
            checked += 1
        self.assertGreaterEqual(checked, 1, 'no roslaunch line found in the documents')

    def test_topic_and_service_commands(self):
        kinds = self.classified()
        to_run = [(d, l, c, k) for d, l, c, k in kinds if k in ('run', 'stream')]
        self.assertTrue(any(words(c)[:2] == ['rostopic', 'pub'] for _, _, c, _ in to_run),
                        'no `rostopic pub` example found in the documents')
        self.assertTrue(any(words(c)[0] == 'rosservice' for _, _, c, _ in to_run),
                        'no `rosservice` example found in the documents')

        # The node is up, the scene is torque-free (default scene: no gravity).
        self.wait_new(0, 1, STARTUP_TIMEOUT, 'start-up')
        gravity = rospy.get_param(NODE + '/gravity', [0.0, 0.0, 0.0])
        self.assertEqual(norm(gravity), 0.0, 'the test expects the default scene (no gravity)')
        rate = float(rospy.get_param(NODE + '/rate', 1000.0))
        publish_rate = float(rospy.get_param(NODE + '/publish_rate', 100.0))
        dt, k = 1.0 / rate, int(round(rate / publish_rate))
        pid = self.node_pid()
        self.offsets = self.reference_offsets()
        initial = self.last()
        self.held = {}
        self.thrusters = {}   # body -> its thrusters, from the spawns of the documents
        self.jobs = 0
        paused = False
        last_before_pause = None

        for doc, lineno, command, kind in to_run:
            where = '%s line %d: `%s`' % (doc, lineno, ' '.join(words(command)))
            rospy.loginfo('running %s', where)
            args = words(command)
            before = self.last()
            n_before = self.count()
            if kind == 'stream':
                self.run_command(where, command, kind)
                continue
            out, ctx = self.run_command(where, command, kind)

            if args[:4] == DYNPARAM_SET:
                self.check_dynparam_set(where, args[4:])
            elif args[0] == 'rostopic' and args[1] == 'echo':
                self.assertIn('---', out, '%s: printed no message\n%s' % (where, ctx))
            elif args[0] == 'rostopic' and args[1] == 'pub':
                pushed = self.apply_push(where, args, before)
                if pushed is not None and not paused:
                    after = self.wait_new(self.count(), 1, 5.0, where)[-1]
                    for b0, b1 in zip(before.bodies, after.bodies):
                        if b0.name in pushed:
                            change = (norm(sub(vec(b1.linear_momentum), vec(b0.linear_momentum)))
                                      + norm(sub(vec(b1.angular_momentum),
                                                 vec(b0.angular_momentum))))
                            self.assertGreater(change, 1e-3, '%s: body %s pushed but its p and '
                                               'L did not change' % (where, b0.name))
            elif args[0] == 'rosservice' and args[1] == 'call':
                pos = positional(args[2:])
                service = pos[0]
                request = yaml.safe_load(' '.join(pos[1:])) if len(pos) > 1 else None
                cls = rosservice.get_service_class_by_name(service)
                if 'success' in cls._response_class.__slots__:
                    self.assertRegex(out, r'(?m)^success: True$',
                                     '%s: the response is not a success\n%s' % (where, ctx))
                name = service.rstrip('/').split('/')[-1]
                if name == 'clear_wrenches':
                    self.held = {}
                elif name == 'clear_body_wrenches':
                    body = request['body']
                    self.held = {k: v for k, v in self.held.items() if body and k[0] != body}
                elif name == 'apply_body_wrench':
                    self.apply_job(where, request, paused)
                elif name == 'spawn_body':
                    entry = yaml.safe_load(request['body_yaml'])
                    self.remember_thrusters(where, entry)
                    spawned = entry['name']
                    msgs = self.wait_new(self.count(), 1, 5.0, where)
                    self.assertIn(spawned, [b.name for b in msgs[-1].bodies],
                                  '%s: %s not in ~bodies after the spawn' % (where, spawned))
                elif name == 'delete_body':
                    gone = request['body']
                    self.held = {k: v for k, v in self.held.items() if k[0] != gone}
                    time.sleep(0.1)   # a message already on its way may still have it
                    msgs = self.wait_new(self.count(), 1, 5.0, where)
                    self.assertNotIn(gone, [b.name for b in msgs[-1].bodies],
                                     '%s: %s still in ~bodies after the delete' % (where, gone))
                elif name == 'reset':
                    self.held = {}
                    self.check_reset(where, initial, before)
                elif name == 'set_paused':
                    paused = bool(request['data'])
                    if paused:
                        time.sleep(0.2)   # a message already on its way may still arrive
                        last_before_pause = self.last()
                        n = self.count()
                        time.sleep(1.0)
                        self.assertEqual(self.count(), n, '%s: ~bodies still published '
                                         'while paused' % where)
                    else:
                        msgs = self.wait_new(n_before, 1, 2.0, where + ' (resumed)')
                        self.assertGreater(msgs[0].header.stamp, before.header.stamp,
                                           '%s: stamps went back after resuming' % where)
                elif name in ('step', 'step_with_wrenches'):
                    if name == 'step_with_wrenches':
                        self.hold_entries(where, request.get('wrenches', []),
                                          [b.name for b in before.bodies])
                    steps = int(request['steps'])
                    m = re.search(r'(?m)^sim_time: (\S+)$', out)
                    self.assertIsNotNone(m, '%s: no sim_time in the response\n%s' % (where, ctx))
                    sim_time = float(m.group(1))
                    time.sleep(0.3)
                    msgs = self.since(n_before)
                    self.assertEqual(len(msgs), 1, '%s: expected exactly one ~bodies message '
                                     'after the step, got %d' % (where, len(msgs)))
                    stamp = msgs[0].header.stamp.to_sec()
                    self.assertAlmostEqual(stamp, sim_time, delta=1e-6,
                                           msg='%s: published stamp %.9f != sim_time %.9f'
                                           % (where, stamp, sim_time))
                    advance = (msgs[0].header.stamp - last_before_pause.header.stamp).to_sec()
                    self.assertTrue(steps * dt - 1e-7 <= advance <= (steps + k - 1) * dt + 1e-7,
                                    '%s: the state advanced %.6f s since the last message '
                                    'before pausing; expected %d to %d steps of %g s'
                                    % (where, advance, steps, steps + k - 1, dt))
                    last_before_pause = msgs[0]
                    if name == 'step_with_wrenches':
                        m = re.search(r'(?m)^state_hash: "?([0-9a-f]{16})"?$', out)
                        self.assertIsNotNone(m, '%s: no state_hash in the response\n%s' % (where, ctx))
                        self.assertEqual(m.group(1), state_hash(msgs[0]),
                                         '%s: state_hash is not the hash of the published state'
                                         % where)
                elif name == 'set_body_state':
                    self.check_set_body_state(where, request, n_before)
            if not paused:
                self.check_rates(where)

        self.assertEqual(self.node_pid(), pid, 'the node restarted during the documented '
                         'examples (it crashed and was respawned)')

    def apply_job(self, where, request, paused):
        """A job until cleared joins the model; one with a duration is waited out."""
        body = request['body']
        duration = request.get('duration') or {}
        seconds = float(duration.get('secs', 0)) + 1e-9 * float(duration.get('nsecs', 0))
        frame = str(request.get('reference_frame', '') or '').lstrip('/')
        point = request.get('reference_point') or {}
        offset = tuple(float(point.get(k, 0.0)) for k in ('x', 'y', 'z'))
        if seconds < 0.0:
            self.jobs += 1
            self.hold(where, body, ('job', self.jobs),
                      {'header': {'frame_id': frame}, 'wrench': request.get('wrench') or {}}, offset)
        else:
            self.assertFalse(paused, '%s: a job with a duration while paused is not modelled'
                             % where)
            time.sleep(seconds + 0.3)

    def check_dynparam_set(self, where, args):
        self.assertEqual(len(args), 3, '%s: expected `dynparam set <node> <key> <value>`' % where)
        node, key, value = args
        self.assertNotIn('gravity', key, '%s: the test expects the default scene (no gravity)'
                         % where)
        self.assertEqual(rospy.get_param(node.rstrip('/') + '/' + key), yaml.safe_load(value),
                         '%s: the node did not apply it' % where)

    def check_reset(self, where, initial, before):
        after = self.wait_new(self.count(), 1, 5.0, where)[-1]
        self.assertGreater(after.header.stamp, before.header.stamp,
                           '%s: stamps went back after reset' % where)
        now = {b.name: b for b in after.bodies}
        for b0 in initial.bodies:
            b1 = now.get(b0.name)
            if b1 is None:
                continue   # deleted
            for name, x0, x1 in (('p', vec(b0.linear_momentum), vec(b1.linear_momentum)),
                                 ('L', vec(b0.angular_momentum), vec(b1.angular_momentum))):
                self.assertLessEqual(norm(sub(x1, x0)), 1e-6 * norm(x0) + 1e-9,
                                     '%s: body %s: %s = %r after reset, %r at start'
                                     % (where, b0.name, name, x1, x0))
            self.assertAlmostEqual(b1.kinetic_energy, b0.kinetic_energy,
                                   delta=1e-4 * b0.kinetic_energy + 1e-9,
                                   msg='%s: body %s: kinetic energy %.9g after reset, %.9g at '
                                   'start' % (where, b0.name, b1.kinetic_energy,
                                              b0.kinetic_energy))

    def check_set_body_state(self, where, request, n_before):
        """One of the ~bodies messages since the call started carries the requested
        state, up to one publish period (plus a step) of motion after it was set."""
        body = request['body']
        pose = request.get('pose') or {}
        twist = request.get('twist') or {}
        position = get3(pose, 'position')
        o = pose.get('orientation') or {}
        q = [float(o.get(c, 0.0)) for c in 'xyzw']
        qn = norm(q)
        q = [c / qn for c in q]
        v, w = get3(twist, 'linear'), get3(twist, 'angular')
        slack = 0.02   # s: a publish period (10 ms) and a step, with margin

        def errors(s):
            got_q = [s.pose.orientation.x, s.pose.orientation.y, s.pose.orientation.z,
                     s.pose.orientation.w]
            dot = abs(sum(a * b for a, b in zip(q, got_q)))
            return (
                ('position', norm(sub(vec(s.pose.position), position)), norm(v) * slack + 1e-6),
                ('orientation (angle)', 2.0 * math.acos(min(1.0, dot)), norm(w) * slack + 1e-6),
                ('linear velocity', norm(sub(vec(s.twist.linear), v)), 1e-6),
                ('angular velocity', norm(sub(vec(s.twist.angular), w)), 0.02 * norm(w) + 1e-6))

        msgs = self.wait_new(n_before, 1, 5.0, where)
        time.sleep(0.1)
        msgs = self.since(n_before)
        report = []
        for msg in msgs:
            states = [b for b in msg.bodies if b.name == body]
            self.assertEqual(len(states), 1, '%s: body %s not in ~bodies' % (where, body))
            errs = errors(states[0])
            if all(err <= tol for _, err, tol in errs):
                return
            report.append('%s: %s' % (msg.header.stamp, ', '.join(
                '%s off by %.3g (tol %.3g)' % e for e in errs)))
        self.fail('%s: no ~bodies message after the call has body %s in the requested state; '
                  'last ones:\n%s' % (where, body, '\n'.join(report[-5:])))


if __name__ == '__main__':
    rostest.rosrun(PKG, 'readme_examples', ReadmeExamples)
