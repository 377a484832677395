"""Running rigid_body_sim_node for the bench scripts (node_load.py, flood.py,
soak.py): starting it (under roslaunch, or bare next to a private master),
finding its process through the master, reading its "simulation" status from
/diagnostics, and its memory and CPU time from /proc.

Only the standard library is imported here at load time: the scripts set up
the workspace and ROS_MASTER_URI first; the parts that need rospy import it
when they are called.
"""

import csv
import os
import shlex
import signal
import subprocess
import sys
import tempfile
import threading
import time
import xmlrpc.client

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_WORKSPACE = os.path.join(REPO, ".build_ws")
NODE_NAME = "rigid_body_sim"
NS = "/" + NODE_NAME
WORKSPACE_MARK = "RBS_BENCH_WS"  # set once the script runs in the workspace's environment
CLK_TCK = os.sysconf("SC_CLK_TCK")


# --------------------------------------------------------------- workspace

def add_workspace_argument(parser):
    parser.add_argument("--workspace", default=DEFAULT_WORKSPACE,
                        help="catkin workspace whose devel/setup.bash is sourced (default: .build_ws in the repo)")


def add_node_bench_arguments(parser, port, results):
    """The options of the benches that run a node on one core and themselves on another: --workspace,
    --port (each bench its own default, so that they can run side by side), --node-cpu, --bench-cpu and
    --out, the directory for `results`."""
    add_workspace_argument(parser)
    parser.add_argument("--port", type=int, default=port, help="port of the private ROS master")
    parser.add_argument("--node-cpu", type=int, default=1, help="core the node is pinned to (taskset -c)")
    parser.add_argument("--bench-cpu", type=int, default=0, help="core of this script and the master")
    parser.add_argument("--out", default=os.path.join(REPO, "bench", "results"), help="directory for " + results)


def write_results(out_dir, name, report, fields, rows):
    """Writes report to <out_dir>/<name>.md and one CSV row per dict in rows to <name>.csv (floats to
    6 significant digits, booleans as true/false); returns the two paths."""
    os.makedirs(out_dir, exist_ok=True)
    md_path, csv_path = (os.path.join(out_dir, name + ext) for ext in (".md", ".csv"))
    with open(md_path, "w") as f:
        f.write(report + "\n")
    with open(csv_path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        writer.writeheader()
        for row in rows:
            writer.writerow({k: (("%.6g" % v) if isinstance(v, float) else
                                 ("true" if v is True else "false" if v is False else v)) for k, v in row.items()})
    return md_path, csv_path


def reexec_in_workspace(workspace, port):
    """Runs the calling script again (same arguments) with the workspace's
    devel/setup.bash sourced, ROS's Python, ROS_MASTER_URI on 127.0.0.1:port (the
    master the script starts, or roslaunch does) and a ROS_HOME of its own, unless
    it already runs so. Returns the workspace's absolute path."""
    ws = os.path.abspath(workspace)
    if os.environ.get(WORKSPACE_MARK) == ws:
        return ws
    setup = os.path.join(ws, "devel", "setup.bash")
    if not os.path.exists(setup):
        sys.exit("no %s: build first, e.g. RBS_WS=%s bash scripts/build.sh" % (setup, ws))
    env = dict(os.environ)
    env[WORKSPACE_MARK] = ws
    env["PATH"] = "/usr/bin:" + env.get("PATH", "")
    env["ROS_MASTER_URI"] = "http://127.0.0.1:%d" % port
    env["ROS_IP"] = "127.0.0.1"
    env.pop("ROS_HOSTNAME", None)
    ros_home = tempfile.mkdtemp(prefix="rbs_bench_ros_")
    env["ROS_HOME"] = ros_home
    env["ROS_LOG_DIR"] = os.path.join(ros_home, "log")
    command = "source %s && exec /usr/bin/python3 %s %s" % (
        shlex.quote(setup), shlex.quote(os.path.abspath(sys.argv[0])),
        " ".join(shlex.quote(a) for a in sys.argv[1:]))
    os.execve("/bin/bash", ["/bin/bash", "-c", command], env)


def devel_program(workspace, name):
    """A program of this package in the workspace's devel space; exits if it is not there."""
    path = os.path.join(workspace, "devel", "lib", "rigid_body_sim", name)
    if not os.access(path, os.X_OK):
        sys.exit("no %s executable at %s" % (name, path))
    return path


# ---------------------------------------------------------------- processes

class Processes:
    """Children started here, each leading a process group of its own; all stopped at exit."""

    def __init__(self):
        self.children = []

    def start(self, argv, logfile):
        out = open(logfile, "w")
        proc = subprocess.Popen(argv, stdout=out, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                start_new_session=True)
        out.close()
        self.children.append(proc)
        return proc

    def stop(self, proc, grace_s=5.0):
        if proc.poll() is None:
            try:
                os.killpg(proc.pid, signal.SIGINT)
            except ProcessLookupError:
                pass
            try:
                proc.wait(grace_s)
            except subprocess.TimeoutExpired:
                try:
                    os.killpg(proc.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                proc.wait()
        if proc in self.children:
            self.children.remove(proc)

    def stop_all(self):
        for proc in list(reversed(self.children)):
            self.stop(proc, grace_s=3.0)


def start_master(procs, port, cpu, log_dir):
    """rosmaster --core on port, pinned to cpu; waits until it answers."""
    import rosgraph
    if rosgraph.is_master_online():
        sys.exit("a master already answers on %s: pick another --port" % os.environ["ROS_MASTER_URI"])
    master = procs.start(["taskset", "-c", str(cpu), "rosmaster", "--core", "-p", str(port)],
                         os.path.join(log_dir, "master.log"))
    deadline = time.monotonic() + 20
    while not rosgraph.is_master_online():
        if master.poll() is not None or time.monotonic() > deadline:
            sys.exit("the master did not start (log: %s)" % log_dir)
        time.sleep(0.1)
    return master


def launch_default_scene(port):
    """roslaunch of the run command's launch file (default scene) with its own
    master on port, output discarded, leading a process group of its own."""
    return subprocess.Popen(["roslaunch", "-p", str(port), "rigid_body_sim", "rigid_body_sim.launch"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)


def stop_launch(launch):
    os.killpg(launch.pid, signal.SIGINT)
    launch.wait(timeout=20)


def wait_for_scene():
    """Waits for the node's first ~particles and ~bodies messages; returns the body
    names in the node's order and each body's particle count by name."""
    import rospy
    from rigid_body_sim.msg import BodyStateArray
    from visualization_msgs.msg import MarkerArray
    markers = rospy.wait_for_message(NS + "/particles", MarkerArray, timeout=30)
    names = [b.name for b in rospy.wait_for_message(NS + "/bodies", BodyStateArray, timeout=10).bodies]
    return names, {names[m.id]: len(m.points) for m in markers.markers}


def node_pid(node=NS):
    """The pid of the node registered as `node` with this process's master: this
    launch's node, not any other rigid_body_sim_node on the machine."""
    import rosgraph
    import rospy
    node_api = rosgraph.Master(rospy.get_name()).lookupNode(node)
    return xmlrpc.client.ServerProxy(node_api).getPid(rospy.get_name())[2]


# --------------------------------------------------------------------- /proc

def rss_kib(pid):
    """Resident memory of the process [KiB] (VmRSS)."""
    with open("/proc/%d/status" % pid) as status:
        return next(int(line.split()[1]) for line in status if line.startswith("VmRSS"))


def proc_cpu_ticks(pid):
    with open("/proc/%d/stat" % pid) as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return int(fields[11]) + int(fields[12])  # utime + stime (fields 14, 15)


def core_busy_ticks(cpu):
    with open("/proc/stat") as f:
        for line in f:
            if line.startswith("cpu%d " % cpu):
                v = [int(x) for x in line.split()[1:]]
                idle = v[3] + v[4]
                return sum(v[:8]) - idle
    return 0


class CpuWindow:
    """CPU time of a process, and of the core it runs on, from now until finish()."""

    def __init__(self, pid, cpu):
        self.pid, self.cpu = pid, cpu
        self.t0 = time.monotonic()
        self.node0 = proc_cpu_ticks(pid)
        self.core0 = core_busy_ticks(cpu)

    def finish(self):
        wall = time.monotonic() - self.t0
        node = (proc_cpu_ticks(self.pid) - self.node0) / CLK_TCK
        core = (core_busy_ticks(self.cpu) - self.core0) / CLK_TCK
        return {"cpu_percent": 100.0 * node / wall,
                "core_other_percent": max(0.0, 100.0 * (core - node) / wall)}


# -------------------------------------------------------------- diagnostics

class Diagnostics:
    """The status "<node_name>: simulation" from /diagnostics, as received.

    latest: every key of the newest status (per-body keys such as
    "t_handle/angular_momentum_drift" too), values as the node wrote them.
    reports: (wall receive time, dict) per status, scalar keys only, numbers as
    floats, plus "level" and "message"."""

    def __init__(self, node_name=NODE_NAME):
        import rospy
        from diagnostic_msgs.msg import DiagnosticArray
        self.status_name = node_name + ": simulation"
        self.cond = threading.Condition()
        self.latest = {}
        self.reports = []
        self._sub = rospy.Subscriber("/diagnostics", DiagnosticArray, self._on_msg, queue_size=20)

    def close(self):
        self._sub.unregister()

    def _on_msg(self, msg):
        now = time.monotonic()
        for status in msg.status:
            if status.name != self.status_name:
                continue
            values = {"level": status.level, "message": status.message}
            for kv in status.values:
                if "/" in kv.key:
                    continue  # per-body keys
                try:
                    values[kv.key] = float(kv.value)
                except ValueError:
                    values[kv.key] = kv.value
            with self.cond:
                self.latest.update({kv.key: kv.value for kv in status.values})
                self.reports.append((now, values))
                self.cond.notify_all()

    def clear(self):
        with self.cond:
            self.reports = []

    def wait_next(self, timeout, alive=lambda: True):
        """Waits for a report newer than the latest one seen; returns it or None."""
        deadline = time.monotonic() + timeout
        with self.cond:
            count = len(self.reports)
            while len(self.reports) == count:
                remaining = deadline - time.monotonic()
                if remaining <= 0 or not alive():
                    return None
                self.cond.wait(min(remaining, 0.5))
            return self.reports[-1]

    def since(self, t0, t1):
        with self.cond:
            return [r for r in self.reports if t0 < r[0] <= t1]
