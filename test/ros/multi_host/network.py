"""Hosts on a private network of Linux network namespaces, for tests that need
several machines. Each host is a namespace whose interface eth0 is one end of
a veth pair; the other end is a port of a bridge in a switch namespace, so
every host reaches every other at its own address and nothing else. The
caller's namespace gets no interface, address or route: only the
namespaces' names, which carry the creating process's PID
(rbs_mh<pid>_<host>), so parallel runs cannot collide and remove_stale()
can tell the leftovers of a run that was killed."""
import os
import re
import signal
import subprocess
import time

PREFIX = 'rbs_mh'
SUBNET_BITS = 24  # every host's address is on one /24


class IpError(RuntimeError):
    pass


def _ip(*args):
    """Runs `ip ARGS`; IpError with ip's message on failure."""
    done = subprocess.run(('ip',) + args, capture_output=True, text=True)
    if done.returncode != 0:
        raise IpError('`ip %s` failed: %s' % (' '.join(args), done.stderr.strip()))
    return done.stdout


def _namespaces():
    return [line.split()[0] for line in _ip('netns', 'list').splitlines() if line.strip()]


def _kill_all_in(namespace, timeout=5.0):
    """SIGKILLs every process in `namespace` and waits for them to be gone."""
    deadline = time.monotonic() + timeout
    while True:
        try:
            pids = [int(p) for p in _ip('netns', 'pids', namespace).split()]
        except IpError:
            return  # no such namespace
        if not pids or time.monotonic() >= deadline:
            return
        for pid in pids:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        time.sleep(0.05)


def _delete(namespace):
    _kill_all_in(namespace)
    subprocess.run(['ip', 'netns', 'delete', namespace], capture_output=True)


def unavailable_reason():
    """Why namespaces, a bridge and veth pairs cannot be made here (no `ip`,
    not root, no CAP_NET_ADMIN, a kernel without them, ...), or None."""
    try:
        _ip('-V')
    except FileNotFoundError:
        return 'no `ip` command (package iproute2)'
    probe = '%s%d_probe' % (PREFIX, os.getpid())
    try:
        _ip('netns', 'add', probe)
    except IpError as e:
        return 'cannot make a network namespace (root with CAP_NET_ADMIN and CAP_SYS_ADMIN ' \
               'is needed): %s' % e
    try:
        _ip('-n', probe, 'link', 'add', 'name', 'br0', 'type', 'bridge')
        _ip('-n', probe, 'link', 'add', 'name', 'v0', 'type', 'veth', 'peer', 'name', 'v1')
        _ip('netns', 'exec', probe, 'true')
    except IpError as e:
        return 'cannot make a bridge, a veth pair or run a process in a network namespace: ' \
               '%s' % e
    finally:
        _delete(probe)
    return None


def remove_stale():
    """Deletes the namespaces of runs whose process is gone (killed before it
    could remove them), with every process still in them."""
    for namespace in _namespaces():
        match = re.match(r'^%s(\d+)_' % PREFIX, namespace)
        if not match:
            continue
        try:
            os.kill(int(match.group(1)), 0)
        except ProcessLookupError:
            _delete(namespace)
        except PermissionError:
            pass  # alive, someone else's


class Network(object):
    """A switch and the hosts added to it. remove() deletes everything, and
    may be called any number of times."""

    def __init__(self):
        self._tag = '%s%d_' % (PREFIX, os.getpid())
        self._switch = self._tag + 'switch'
        self.hosts = {}  # host name -> its address
        self._namespaces = [self._switch]
        try:
            _ip('netns', 'add', self._switch)
            _ip('-n', self._switch, 'link', 'add', 'name', 'br0', 'type', 'bridge')
            _ip('-n', self._switch, 'link', 'set', 'dev', 'br0', 'up')
        except IpError:
            self.remove()
            raise

    def namespace(self, host):
        return self._tag + host

    def add_host(self, host, address):
        """A namespace for `host` (at most 15 characters: it names the
        switch's port) with loopback and eth0 at `address` up."""
        namespace = self.namespace(host)
        _ip('netns', 'add', namespace)
        self._namespaces.append(namespace)
        _ip('-n', self._switch, 'link', 'add', 'name', host, 'type', 'veth',
            'peer', 'name', 'eth0', 'netns', namespace)
        _ip('-n', self._switch, 'link', 'set', 'dev', host, 'master', 'br0', 'up')
        _ip('-n', namespace, 'address', 'add', '%s/%d' % (address, SUBNET_BITS), 'dev', 'eth0')
        _ip('-n', namespace, 'link', 'set', 'dev', 'eth0', 'up')
        _ip('-n', namespace, 'link', 'set', 'dev', 'lo', 'up')
        self.hosts[host] = address

    def popen(self, host, argv, **kwargs):
        """subprocess.Popen of `argv` on `host`."""
        return subprocess.Popen(['ip', 'netns', 'exec', self.namespace(host)] + list(argv),
                                **kwargs)

    def processes(self, host):
        """'PID STATE COMMAND' of every process on `host`, from /proc."""
        out = []
        for pid in _ip('netns', 'pids', self.namespace(host)).split():
            try:
                with open('/proc/%s/stat' % pid) as f:
                    state = f.read().rsplit(')', 1)[1].split()[0]
                with open('/proc/%s/cmdline' % pid) as f:
                    command = f.read().replace('\0', ' ').strip()
            except OSError:
                continue  # gone meanwhile
            out.append('%s %s %s' % (pid, state, command))
        return out

    def lose(self, host):
        """The host goes away as a machine does when its cable is pulled and
        it powers off: its switch port goes down first, so no peer hears of
        it (no FIN, no RST), then every process on it is killed and its
        namespace deleted."""
        _ip('-n', self._switch, 'link', 'set', 'dev', host, 'down')
        namespace = self.namespace(host)
        _delete(namespace)
        self._namespaces.remove(namespace)
        del self.hosts[host]

    def remove(self):
        for namespace in reversed(self._namespaces):
            _delete(namespace)
        self._namespaces = []
        self.hosts = {}
