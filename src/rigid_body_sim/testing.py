"""A client of the rigid_body_sim node for downstream tests (doc/testing.md).

    from rigid_body_sim.testing import SimClient
    sim = SimClient()              # waits for /rigid_body_sim
    sim.pause()
    result = sim.step(100)         # 100 steps; the state reached
    result.states['box'].position  # numpy array, world [m]
    result.stamp                   # rospy.Time of that state, on the lattice

Everything goes through the node's public topics and services; nothing here
knows its internals. States come as `BodyState` tuples of numpy arrays, keyed
by body name in scene order.
"""
import collections
import struct
import threading
import time
import warnings

import numpy as np
import rospy
import yaml
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import Point, Pose, Quaternion, Twist, Vector3, Wrench
from rigid_body_sim.msg import BodyStateArray
from rigid_body_sim.msg import BodyWrench as BodyWrenchMsg
from rigid_body_sim.msg import ActuatorCommand, LockstepAnswer, ParticleWrench
from rigid_body_sim.srv import (ApplyBodyWrench, ClearBodyWrenches, DeleteBody,
                                SetBodyState, SpawnBody, StepWithWrenches)
from std_srvs.srv import Empty, SetBool

# One body as ~bodies carries it: numpy arrays in world axes (SI units);
# orientation is (x, y, z, w).
BodyState = collections.namedtuple('BodyState', [
    'name', 'position', 'orientation', 'linear_velocity', 'angular_velocity',
    'linear_momentum', 'angular_momentum', 'kinetic_energy'])

# What a step returns: the stamp of the state reached, the states, the node's
# state hash of them and its message. `stamp` is that rospy.Time exactly, as
# the node stamps it on the time lattice; `sim_time` is the service's float
# seconds of it, not exact: a double at 1.8e9 s resolves only 2.4e-7 s.
StepResult = collections.namedtuple('StepResult', ['sim_time', 'states', 'state_hash', 'message',
                                                   'stamp'])

# A wrench on a whole body for the steps of one call or one lockstep cycle
# (see body_wrench()).
BodyWrench = collections.namedtuple('BodyWrench', ['body', 'force', 'torque', 'point', 'frame'])

_FNV_OFFSET_BASIS = 0xcbf29ce484222325
_FNV_PRIME = 0x100000001b3


def _xyz(vector):
    return np.array([vector.x, vector.y, vector.z])


def to_states(msg):
    """A BodyStateArray as an ordered dict: body name -> BodyState."""
    states = collections.OrderedDict()
    for body in msg.bodies:
        pose, twist = body.pose, body.twist
        states[body.name] = BodyState(
            body.name, _xyz(pose.position),
            np.array([pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w]),
            _xyz(twist.linear), _xyz(twist.angular), _xyz(body.linear_momentum),
            _xyz(body.angular_momentum), body.kinetic_energy)
    return states


def state_hash(states):
    """The state hash of a BodyStateArray (or of its to_states()), as the node
    computes it: FNV-1a 64 over the little-endian doubles position,
    orientation (x, y, z, w), linear and angular momentum of every body in
    order, as 16 lower-case hex digits."""
    if isinstance(states, BodyStateArray):
        states = to_states(states)
    values = []
    for body in states.values():
        for array in (body.position, body.orientation, body.linear_momentum, body.angular_momentum):
            values += [float(v) for v in array]
    h = _FNV_OFFSET_BASIS
    for byte in struct.pack('<%dd' % len(values), *values):
        h = ((h ^ byte) * _FNV_PRIME) & 0xffffffffffffffff
    return '%016x' % h


def particle_wrench(body, particle=0, force=(0, 0, 0), torque=(0, 0, 0), frame='', start=None):
    """A ParticleWrench: `force` [N] at particle `particle` of `body`, `torque`
    [N m] a pure couple; axes of `frame` ('' = world, the body's name = its own
    axes); from `start` (rospy.Time), or from the next step when None."""
    msg = ParticleWrench()
    msg.header.frame_id = frame
    if start is not None:
        msg.header.stamp = start
    msg.body = body
    msg.particle = particle
    msg.wrench = Wrench(force=Vector3(*force), torque=Vector3(*torque))
    return msg


def body_wrench(body, force=(0, 0, 0), torque=(0, 0, 0), point=(0, 0, 0), frame=''):
    """A BodyWrench for SimClient.step() or a LockstepController's answer:
    `force` [N] at `point` of `body` (body frame [m], (0, 0, 0) = its origin:
    the COM, or the reference origin with `frame: reference`; step() only), `torque` [N m] a pure couple; axes of `frame` ('' = world,
    the body's name = its own axes)."""
    return BodyWrench(body, tuple(force), tuple(torque), tuple(point), frame)


def _body_wrench_msg(wrench):
    """A BodyWrench as the message a lockstep answer carries: held as on the
    body's wrench topic, from the next step."""
    if any(wrench.point):
        raise ValueError('body_wrench(%r, point=%r): a lockstep answer\'s body wrench acts at the '
                         'origin of its frame; name a site of the body as its frame instead'
                         % (wrench.body, wrench.point))
    msg = BodyWrenchMsg()
    msg.body = wrench.body
    msg.wrench.header.frame_id = wrench.frame
    msg.wrench.wrench = Wrench(force=Vector3(*wrench.force), torque=Vector3(*wrench.torque))
    return msg


def wait_until(predicate, timeout, what):
    """Polls `predicate()` every 10 ms (wall time) until it returns something
    true, and returns that; AssertionError naming `what` after `timeout` s."""
    deadline = time.monotonic() + timeout
    while True:
        value = predicate()
        if value:
            return value
        if time.monotonic() >= deadline:
            raise AssertionError('%s within %g s' % (what, timeout))
        time.sleep(0.01)


def _stamp(msg_stamp):
    """A message's stamp as a rospy.Time, exact."""
    return rospy.Time(msg_stamp.secs, msg_stamp.nsecs)


class SimClient(object):
    """The node `node` (default /rigid_body_sim) seen from a test. Waits for
    its services (at most `timeout` s) and keeps the latest ~bodies message.
    `rate` is the node's ~rate [Hz] and `dt` = 1 / rate its step [s]."""

    def __init__(self, node='/rigid_body_sim', timeout=30.0):
        self.node = rospy.resolve_name(node)
        self._lock = threading.Condition()
        self._latest = None
        self._diagnostics = {}
        self.wait_for_node(timeout)
        self.rate = rospy.get_param(self._name('rate'), 1000)  # the node's default
        self.dt = 1.0 / self.rate
        self._services = {}
        for name, srv in (('set_paused', SetBool), ('step_with_wrenches', StepWithWrenches),
                          ('reset', Empty), ('clear_wrenches', Empty),
                          ('apply_body_wrench', ApplyBodyWrench),
                          ('clear_body_wrenches', ClearBodyWrenches),
                          ('set_body_state', SetBodyState), ('spawn_body', SpawnBody),
                          ('delete_body', DeleteBody)):
            self._services[name] = rospy.ServiceProxy(self._name(name), srv)
        self._bodies_sub = rospy.Subscriber(self._name('bodies'), BodyStateArray, self._on_bodies,
                                            queue_size=10, tcp_nodelay=True)
        self._diagnostics_sub = rospy.Subscriber('/diagnostics', DiagnosticArray,
                                                 self._on_diagnostics, queue_size=10)

    def _name(self, relative):
        return self.node + '/' + relative

    def wait_for_node(self, timeout=30.0):
        """Blocks until the node serves ~step_with_wrenches; rospy's
        ROSException after `timeout` s."""
        rospy.wait_for_service(self._name('step_with_wrenches'), timeout)

    def _call(self, service, *args):
        return self._check(self._services[service](*args), service)

    def _check(self, response, service):
        if hasattr(response, 'success') and not response.success:
            raise RuntimeError('%s: %s' % (self._name(service), response.message))
        return response

    def pause(self):
        self._call('set_paused', True)

    def resume(self):
        self._call('set_paused', False)

    def step(self, steps=1, body_wrenches=()):
        """`steps` steps while paused; a StepResult. `body_wrenches`
        (BodyWrench, see body_wrench()) act on exactly these steps."""
        return self.step_with_wrenches([], steps, body_wrenches)

    def step_with_wrenches(self, wrenches, steps=1, body_wrenches=()):
        """Holds `wrenches` (ParticleWrench messages, see particle_wrench())
        as one array, then `steps` steps while paused; a StepResult. Rejected
        entries are named in its message; RuntimeError if no step was taken.

        Each of `body_wrenches` (BodyWrench, see body_wrench()) becomes a
        ~apply_body_wrench job from the next step over (steps - 1/2) dt: the
        window ends half a step clear of the step after these, so it acts on
        exactly these steps. The jobs are added before the steps: when the node refuses
        one (RuntimeError with its message), no step is taken but the jobs
        before it stay; when it refuses the steps (not paused), all of them
        stay. A body wrench held across calls is push() (until cleared, or
        for a duration) or a message on ~<body>/wrench."""
        if steps < 1:
            raise ValueError('steps must be >= 1, got %r' % (steps,))
        window = rospy.Duration.from_sec((steps - 0.5) * self.dt)
        for wrench in body_wrenches:
            self._call('apply_body_wrench', wrench.body, wrench.frame, Point(*wrench.point),
                       Wrench(force=Vector3(*wrench.force), torque=Vector3(*wrench.torque)),
                       rospy.Time(), window)
        response = self._call('step_with_wrenches', list(wrenches), steps)
        return StepResult(response.sim_time, to_states(response.states), response.state_hash,
                          response.message, _stamp(response.states.header.stamp))

    def push(self, body, force, point=(0, 0, 0), frame='', torque=(0, 0, 0), duration=-1.0,
             start=None):
        """A wrench job (~apply_body_wrench): `force` [N] at `point` (body
        frame [m]) and the couple `torque` [N m], in the axes of `frame`, for
        `duration` s (< 0: until cleared) from `start` (None: the next step)."""
        self._call('apply_body_wrench', body, frame, Point(*point),
                   Wrench(force=Vector3(*force), torque=Vector3(*torque)),
                   start if start is not None else rospy.Time(),
                   rospy.Duration.from_sec(duration))

    def set_body_state(self, body, position=(0, 0, 0), orientation=(0, 0, 0, 1),
                       linear_velocity=(0, 0, 0), angular_velocity=(0, 0, 0)):
        """~set_body_state: the body frame origin's `position` [m] (the COM,
        or the reference origin with `frame: reference`), `orientation` (x, y,
        z, w; normalised by the node), `linear_velocity` [m/s] and
        `angular_velocity` [rad/s], world axes. RuntimeError with the node's
        message when refused."""
        self._call('set_body_state', body,
                   Pose(position=Point(*position), orientation=Quaternion(*orientation)),
                   Twist(linear=Vector3(*linear_velocity), angular=Vector3(*angular_velocity)))

    def clear_wrenches(self):
        """~clear_wrenches: drops every held wrench and job."""
        self._call('clear_wrenches')

    def clear_body_wrenches(self, body=''):
        """~clear_body_wrenches: drops the wrenches and jobs of `body` ('' =
        every body)."""
        self._call('clear_body_wrenches', body)

    def reset(self):
        self._call('reset')

    def spawn(self, body):
        """Adds a body: a scene entry as a dict or as YAML text."""
        text = body if isinstance(body, str) else yaml.safe_dump(body)
        self._call('spawn_body', text)

    def delete(self, body):
        self._call('delete_body', body)

    def _on_bodies(self, msg):
        with self._lock:
            self._latest = msg
            self._lock.notify_all()

    def _on_diagnostics(self, msg):
        for status in msg.status:
            if status.name == self.node[1:] + ': simulation':
                with self._lock:
                    self._diagnostics = {kv.key: kv.value for kv in status.values}
                    self._lock.notify_all()

    def latest(self, timeout=10.0):
        """The last ~bodies message (waits for the first one)."""
        with self._lock:
            if not self._lock.wait_for(lambda: self._latest is not None, timeout):
                raise RuntimeError('no message on %s within %g s' % (self._name('bodies'), timeout))
            return self._latest

    def stamp(self, timeout=10.0):
        """The stamp of the last ~bodies message, an exact rospy.Time."""
        return _stamp(self.latest(timeout).header.stamp)

    def states(self, timeout=10.0):
        """The last published states: body name -> BodyState."""
        return to_states(self.latest(timeout))

    def state(self, body, timeout=10.0):
        """The last published state of `body`."""
        return self.states(timeout)[body]

    def diagnostics(self, timeout=10.0):
        """The node's last diagnostics values (key -> string), e.g.
        'state_hash', 'lockstep_timeouts'."""
        with self._lock:
            if not self._lock.wait_for(lambda: bool(self._diagnostics), timeout):
                raise RuntimeError('no diagnostics from %s within %g s' % (self.node, timeout))
            return dict(self._diagnostics)


class LockstepController(object):
    """Answers every cycle of a node running with ~lockstep: `control(states,
    stamp)` gets each ~bodies message's states (body name -> BodyState) and
    its stamp and returns what to apply (an empty list or None: nothing):
    ParticleWrench messages (see particle_wrench()), held as on
    ~particle_wrenches, BodyWrench tuples (see body_wrench(), at the origin
    of their frame), each the command of one cycle, and ActuatorCommand
    messages (rigid_body_sim.msg), held as on the body's actuators topic.
    All go in one LockstepAnswer on ~lockstep_answers, held before the next
    step, so a run repeats bit for bit. The node holds a body wrench as on the body's wrench
    topic, until the next one for that body: a body named in one answer and
    not in the next gets a zero wrench there, and an answer that comes after
    the node's ~lockstep_timeout leaves the previous command acting meanwhile.
    List this node's name (rospy.get_name()) in the simulator's
    ~lockstep_publishers."""

    def __init__(self, control, node='/rigid_body_sim'):
        self.node = rospy.resolve_name(node)
        self._control = control
        self._pushed = []  # bodies with a body wrench in the last answer, in order
        # stop() waits for an answer being sent, so none goes to a closed topic.
        self._sending = threading.Lock()
        self._stopped = False
        # Publisher first: the simulator starts once both connections exist.
        # queue_size None publishes in the callback's thread, without the
        # hand-over to a queue thread that would add to every cycle (rospy
        # warns about it as if it were an oversight).
        with warnings.catch_warnings():
            warnings.simplefilter('ignore')
            self._answers = rospy.Publisher(self.node + '/lockstep_answers', LockstepAnswer,
                                            queue_size=None, tcp_nodelay=True)
        self._bodies = rospy.Subscriber(self.node + '/bodies', BodyStateArray, self._on_bodies,
                                        queue_size=10, tcp_nodelay=True)

    def _on_bodies(self, msg):
        answer = LockstepAnswer()
        answer.header.stamp = msg.header.stamp
        for item in self._control(to_states(msg), msg.header.stamp) or []:
            if isinstance(item, BodyWrench):
                answer.body_wrenches.append(_body_wrench_msg(item))
            elif isinstance(item, ActuatorCommand):
                answer.actuators.append(item)
            else:
                answer.wrenches.append(item)
        pushed = [entry.body for entry in answer.body_wrenches]
        answer.body_wrenches += [_body_wrench_msg(body_wrench(body)) for body in self._pushed
                                 if body not in pushed]
        self._pushed = list(collections.OrderedDict.fromkeys(pushed))
        with self._sending:
            if not self._stopped:
                self._answers.publish(answer)

    def stop(self):
        self._bodies.unregister()
        with self._sending:
            self._stopped = True
        self._answers.unregister()
