#!/usr/bin/python3
"""The node under load: rigid_body_sim_node on generated scenes.

Starts its own ROS master on a private port, runs rigid_body_sim_node (pinned
to one core with taskset) on scenes of N generated bodies (shape: box,
resolution 2: 8 particles each) and measures

  1. capacity: the largest N stepped at rate 1000 with zero overruns
     (publish_rate 10, status_period 0, nobody subscribed to /tf or ~bodies; the
     node's stepping thread one SCHED_FIFO level above roscpp's), from the node's
     own /diagnostics status "simulation" (keys overruns, steps, sim_time_s,
     step_time_mean_us, step_time_max_us, real_time_factor_achieved);
  2. CPU use of the node (/proc/<pid>/stat utime+stime over a window) at 100
     and 1000 bodies with /tf and ~bodies at 100 Hz, both subscribed;
  3. particle wrenches per second taken in through ~particle_wrenches while
     the rate holds (arrays of K entries at R Hz, pre-serialised once);
  4. latency from a ParticleWrench (zero stamp) to the first ~bodies message
     whose linear momentum reflects it (wall clock, median of >= 20 trials);
  5. pushed capacity: part 1 with one held particle force on every body, sent
     once as ParticleWrenchArray messages and checked held (diagnostics key
     held_wrenches, and the z velocity of the first and last body growing at
     F/m) before the window;
  6. the cost of ~step through the node: ~step 20000 while paused on 1,000
     tumbling boxes, free and then pushed as in part 5, ns per body-step from
     a persistent service client, next to throughput_bench's
     BM_WorldStep/casimir_splitting4/free/1000 and
     BM_WorldStepLoaded/world_force/1000 on the node's core in the same run.

Writes a Markdown report (also printed) to bench/results/node_load.md and one
CSV row per run to bench/results/node_load.csv. Without part flags every part
runs; --capacity, --pushed and --step-cost run only the parts named.

  bench/node_load.py [--quick] [--capacity] [--pushed] [--step-cost] [--sizes N ...]
                     [--per-body-topics true|false] [--workspace PATH] [--port 11395]
                     [--out DIR]

The script re-executes itself with PATH/devel/setup.bash sourced (default
workspace: .build_ws in the checkout). It and the master stay on core 0, the
node runs on core 1 (--node-cpu). Everything started is stopped at the end.
"""

import argparse
import io
import json
import math
import os
import random
import statistics
import subprocess
import sys
import tempfile
import threading
import time

from node_harness import (CLK_TCK, NODE_NAME, NS, REPO, CpuWindow, Diagnostics, Processes, add_node_bench_arguments,
                          devel_program, proc_cpu_ticks, reexec_in_workspace, start_master, write_results)


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="smaller scan, under a minute")
    parser.add_argument("--sizes", type=int, nargs="+", default=None,
                        help="body counts the capacity parts scan (default 1 1000 10000; pushed: 1000 10000)")
    parser.add_argument("--capacity", action="store_true",
                        help="run the capacity part (1); with no part flag, every part runs")
    parser.add_argument("--pushed", action="store_true",
                        help="run the pushed-capacity part (5); with no part flag, every part runs")
    parser.add_argument("--step-cost", action="store_true",
                        help="run the ~step cost part (6); with no part flag, every part runs")
    parser.add_argument("--intake", action="store_true",
                        help="run the wrench intake part (3); with no part flag, every part runs")
    parser.add_argument("--per-body-topics", choices=["true", "false"], default="true",
                        help="the scenes' ~per_body_topics (default true)")
    add_node_bench_arguments(parser, 11395, "node_load.md and node_load.csv")
    parser.add_argument("--sched", choices=["normal", "nice", "fifo"], default=None,
                        help="node scheduling: normal; nice = nice -n -20 (also this script and the master); "
                             "fifo = chrt -f 10 (the script and master: nice -20). Default: fifo when root, "
                             "else normal")
    return parser.parse_args()


ARGS = parse_args()
WS = reexec_in_workspace(ARGS.workspace, ARGS.port)

# From here on: the workspace's environment, ROS's Python.
os.sched_setaffinity(0, {ARGS.bench_cpu})  # threads started later inherit it
if ARGS.sched is None:
    ARGS.sched = "fifo" if os.geteuid() == 0 else "normal"
if ARGS.sched != "normal":
    try:
        os.setpriority(os.PRIO_PROCESS, 0, -20)  # this thread; threads started later inherit it
    except PermissionError:
        sys.exit("--sched %s needs root (or CAP_SYS_NICE); use --sched normal" % ARGS.sched)
NODE_PREFIX = {"normal": [], "nice": ["nice", "-n", "-20"], "fifo": ["chrt", "-f", "10"]}[ARGS.sched]

import rospy  # noqa: E402
from rigid_body_sim.msg import BodyStateArray, ParticleWrench, ParticleWrenchArray  # noqa: E402
from rigid_body_sim.srv import Step  # noqa: E402
from std_srvs.srv import SetBool  # noqa: E402

T_START = time.monotonic()


def log(text):
    print("[%6.1f s] %s" % (time.monotonic() - T_START, text), flush=True)


PROCS = Processes()
LOG_DIR = tempfile.mkdtemp(prefix="node_load_logs_")


# ------------------------------------------------------------------- scenes

def make_scene(n_bodies, rate, publish_rate, moving=True):
    """N boxes of 2x2x2 particles (8 each) on a grid, all turning and drifting.
    No status line (status_period 0): each log message costs roscpp O(topics),
    ~3.5 ms at 10^4 bodies; the script reads /diagnostics instead."""
    bodies = []
    side = max(1, int(math.ceil(n_bodies ** (1.0 / 3.0))))
    rng = random.Random(n_bodies)
    for i in range(n_bodies):
        x, y, z = i % side, (i // side) % side, i // (side * side)
        body = {"name": "b%d" % i, "shape": "box", "mass": 1.0, "size": [0.2, 0.15, 0.1],
                "resolution": 2, "position": [0.5 * x, 0.5 * y, 0.5 * z]}
        if moving:
            body["linear_velocity"] = [0.01, 0.0, 0.0]
            body["angular_velocity"] = [rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(1, 3)]
        bodies.append(body)
    return {"rate": float(rate), "publish_rate": float(publish_rate), "real_time_factor": 1.0,
            "gravity": [0.0, 0.0, 0.0], "status_period": 0.0, "per_body_topics": ARGS.per_body_topics == "true",
            "bodies": bodies}


class NodeRun:
    """One rigid_body_sim_node process on a scene; a context manager."""

    def __init__(self, diag, scene, label):
        self.diag, self.scene, self.label = diag, scene, label
        self.proc = None
        self.startup_s = float("nan")
        self.first = None

    def alive(self):
        return self.proc is not None and self.proc.poll() is None

    def __enter__(self):
        if rospy.has_param(NS):
            rospy.delete_param(NS)
        rospy.set_param(NS, self.scene)
        self.diag.clear()
        t0 = time.monotonic()
        logfile = os.path.join(LOG_DIR, "node_%s.log" % self.label)
        self.proc = PROCS.start(NODE_PREFIX + ["taskset", "-c", str(ARGS.node_cpu), devel_program(WS, "rigid_body_sim_node"),
                                               "__name:=" + NODE_NAME],
                                logfile)
        n = len(self.scene["bodies"])
        self.first = self.diag.wait_next(60 + n / 100.0, self.alive)
        if self.first is None:
            PROCS.stop(self.proc)
            with open(logfile) as f:
                tail = f.read()[-2000:]
            raise RuntimeError("node (%s) did not report diagnostics:\n%s" % (self.label, tail))
        # The first report comes about one second after stepping starts.
        self.startup_s = self.first[0] - t0
        return self

    def __exit__(self, *exc):
        t0 = time.monotonic()
        if ARGS.sched == "fifo" and self.alive():
            # Back to SCHED_OTHER first: roscpp's shutdown can livelock with all its threads
            # SCHED_FIFO on one core (seen: > 10 s at ~95 % CPU).
            subprocess.run(["chrt", "-a", "-o", "-p", "0", str(self.proc.pid)], stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL)
        PROCS.stop(self.proc, grace_s=5.0)
        if time.monotonic() - t0 > 2.0:
            log("node (%s) took %.1f s to stop (SIGKILL after 5 s)" % (self.label, time.monotonic() - t0))
        return False

    def measure(self, warmup_s, window_s):
        """Diagnostics- and /proc-based figures over about window_s after warmup_s."""
        time.sleep(warmup_s)
        d0 = self.diag.wait_next(5, self.alive)
        if d0 is None:
            raise RuntimeError("node (%s) stopped reporting" % self.label)
        cpu = CpuWindow(self.proc.pid, ARGS.node_cpu)
        time.sleep(max(0.0, window_s - 1.0))
        d1 = self.diag.wait_next(5, self.alive)
        if d1 is None:
            raise RuntimeError("node (%s) stopped reporting" % self.label)
        result = cpu.finish()
        return self.summarise(d0, d1, result)

    def summarise(self, d0, d1, result):
        (t0, v0), (t1, v1) = d0, d1
        inside = [v for _, v in self.diag.since(t0, t1)]
        wall = t1 - t0
        result.update({
            "window_s": wall,
            "integrator": v1.get("integrator", ""),
            "overruns": int(v1["overruns"] - v0["overruns"]),
            "catch_up_limit_hits": int(v1.get("catch_up_limit_hits", 0) - v0.get("catch_up_limit_hits", 0)),
            "steps": int(v1["steps"] - v0["steps"]),
            "rtf_window": (v1["sim_time_s"] - v0["sim_time_s"]) / wall if wall > 0 else float("nan"),
            "rtf_min": min(v["real_time_factor_achieved"] for v in inside),
            "step_mean_us": statistics.mean(v["step_time_mean_us"] for v in inside),
            "step_max_us": max(v["step_time_max_us"] for v in inside),
            "rejected": v1.get("rejected_messages", 0) - v0.get("rejected_messages", 0),
            "rejected_marker": (v1.get("rejected_particle_out_of_range", 0)
                                - v0.get("rejected_particle_out_of_range", 0)),
            "loadavg1": os.getloadavg()[0],
            "startup_s": self.startup_s,
        })
        result["overruns_per_s"] = result["overruns"] / wall
        return result


# ------------------------------------------------------------------- output

ROWS = []
CSV_FIELDS = ["part", "label", "n_bodies", "rate_hz", "publish_rate_hz", "subscribers", "entries_per_msg",
              "msgs_hz", "window_s", "integrator", "startup_s", "overruns", "overruns_per_s",
              "floor_overruns", "floor_worst_us", "catch_up_limit_hits", "rtf_window", "rtf_min", "step_mean_us",
              "step_max_us", "cpu_percent",
              "core_other_percent", "loadavg1", "tf_msgs_per_s", "bodies_msgs_per_s", "rx_mbyte_per_s",
              "pub_msgs_per_s", "pub_busy_percent", "wrenches_sent_per_s", "wrenches_taken_per_s",
              "latency_median_ms", "latency_p90_ms", "latency_min_ms", "latency_max_ms",
              "stamp_lag_median_ms", "trials", "held_wrenches", "push_dv_dt_mps2", "ns_per_body_step",
              "cpu_ns_per_body_step", "core_ns_per_body_step", "node_to_core", "passed", "load_ok", "note"]


def record(**row):
    ROWS.append(row)
    return row


def fmt(value, digits=1):
    if value is None or value == "":
        return ""
    if isinstance(value, float):
        if math.isnan(value):
            return "n/a"
        return "%.*f" % (digits, value)
    return str(value)


def md_table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    lines += ["| " + " | ".join(fmt(c) if not isinstance(c, str) else c for c in r) + " |" for r in rows]
    return "\n".join(lines)


# ------------------------------------------------------- part 1: capacity

NOISE_OVERRUNS_PER_S = 1.0  # above what this (virtual, shared) machine gives a one-body node


def machine_floor(window_s, busy_us):
    """Overruns of a bare 1 kHz loop (bench/wake_jitter) on the node's core, with the node's
    scheduling and step time: what this machine alone gives."""
    probe = devel_program(WS, "wake_jitter")
    out = subprocess.run(NODE_PREFIX + ["taskset", "-c", str(ARGS.node_cpu), probe, "%.1f" % window_s,
                                        str(int(round(busy_us)))],
                         stdout=subprocess.PIPE, universal_newlines=True, check=True).stdout
    fields = dict(item.split("=") for item in out.split())
    return int(fields["late_wakeups"]), float(fields["worst_late_us"])


# Part 5's push: world z at particle 0, a corner, so each body gets a force and a torque (~3e-4 N m);
# small enough that after a minute's push no box leaves the lanes' range or needs a substep.
PUSH_FORCE_N = 0.005
# Entries per ParticleWrenchArray: the node reads at most 10,000 of one array (doc/node.md).
PUSH_ENTRIES_PER_ARRAY = 1000


def push_array(first, count):
    wrenches = []
    for i in range(first, first + count):
        w = ParticleWrench(body="b%d" % i, particle=0)  # zero stamp: from the next step; no timeout
        w.header.frame_id = "world"
        w.wrench.force.z = PUSH_FORCE_N
        wrenches.append(w)
    return ParticleWrenchArray(wrenches=wrenches)


def z_velocity_rates(bodies, span_s=1.0):
    """d(v_z)/dt of the bodies at these indices over about span_s of simulation time, from two
    ~bodies messages (the bodies' own topics may not be advertised yet in a large scene)."""
    topic = NS + "/bodies"
    first = rospy.wait_for_message(topic, BodyStateArray, timeout=10)
    time.sleep(span_s)
    last = rospy.wait_for_message(topic, BodyStateArray, timeout=10)
    dt = (last.header.stamp - first.header.stamp).to_sec()
    # Boxes of 1 kg: v_z = p_z.
    return [(last.bodies[i].linear_momentum.z - first.bodies[i].linear_momentum.z) / dt
            if dt > 0 else float("nan") for i in bodies]


def push_every_body(run, n):
    """Holds one world-axes particle force on each of the n bodies, sent once, and checks that every
    one is held (diagnostics) and acts (the first and last body speed up at F/m, boxes of 1 kg)."""
    pub = rospy.Publisher(NS + "/particle_wrenches", ParticleWrenchArray, queue_size=100)
    deadline = time.monotonic() + 10
    while pub.get_num_connections() == 0 and time.monotonic() < deadline:
        time.sleep(0.05)
    for first in range(0, n, PUSH_ENTRIES_PER_ARRAY):
        pub.publish(push_array(first, min(PUSH_ENTRIES_PER_ARRAY, n - first)))
    # While the node advertises its bodies' topics the master is busy and
    # reports can come late: keep the latest one.
    report = None
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        report = run.diag.wait_next(2, run.alive) or report
        if report is not None and report[1].get("held_wrenches", 0) >= n:
            break
    pub.unregister()
    held = int(report[1].get("held_wrenches", 0)) if report else 0
    rejected = int(report[1].get("rejected_messages", 0)) if report else -1
    if held != n or rejected != 0:
        raise RuntimeError("pushed N=%d: %d wrenches held, %d rejected" % (n, held, rejected))
    rates = z_velocity_rates([0, n - 1])
    if any(not abs(rate - PUSH_FORCE_N) <= 0.01 * PUSH_FORCE_N for rate in rates):
        raise RuntimeError("pushed N=%d: dv_z/dt %s m/s^2, expected %g" % (n, rates, PUSH_FORCE_N))
    log("pushed N=%d: %d wrenches held, dv_z/dt of the first and last body %.6f, %.6f m/s^2 (F/m = %g)"
        % (n, held, rates[0], rates[1], PUSH_FORCE_N))
    return {"held_wrenches": held, "push_dv_dt_mps2": min(rates)}


def capacity_run(diag, n, warmup, window, pushed=False):
    label = "pushed" if pushed else "capacity"
    with NodeRun(diag, make_scene(n, 1000, 10), "%s_%d" % (label, n)) as run:
        held = push_every_body(run, n) if pushed else {}
        r = run.measure(warmup, window)
    r.update(held)
    r["floor_overruns"], r["floor_worst_us"] = machine_floor(r["window_s"], r["step_mean_us"])
    passed = r["overruns"] == 0 and r["rtf_min"] >= 0.99
    # Within noise: no more than 1/s, or than twice what the bare loop got in the same time.
    load_ok = (r["overruns"] <= max(NOISE_OVERRUNS_PER_S * r["window_s"], 2 * r["floor_overruns"])
               and r["catch_up_limit_hits"] == 0 and r["rtf_min"] >= 0.99)
    log("%s N=%d: %d overruns in %.1f s (bare loop, same step time: %d), step %.1f us (max %.0f), "
        "RTF min %.3f, CPU %.0f%%, core %d other %.0f%%, load %.2f, first report %.1f s -> %s"
        % (label, n, r["overruns"], r["window_s"], r["floor_overruns"], r["step_mean_us"], r["step_max_us"],
           r["rtf_min"], r["cpu_percent"], ARGS.node_cpu, r["core_other_percent"], r["loadavg1"],
           r["startup_s"], "pass" if passed else ("pass within noise" if load_ok else "FAIL")))
    return record(part=5 if pushed else 1, label=label, n_bodies=n, rate_hz=1000, publish_rate_hz=10,
                  subscribers="none", passed=passed, load_ok=load_ok, **r)


def part_capacity(diag, quick, budget_end, pushed=False):
    """Scans N until a run fails beyond noise, then bisects. Returns
    (largest strict pass, largest pass within noise, smallest failure beyond noise)."""
    if pushed:
        scan = ARGS.sizes or ([100, 1000] if quick else [1000, 10000])
    else:
        scan = ARGS.sizes or ([1, 100, 1000] if quick else [1, 1000, 10000])
    warmup, window = (1.0, 3.0) if quick else (3.0, 10.0)
    strict = {}

    def run_n(n):
        row = capacity_run(diag, n, warmup, window, pushed)
        strict[n] = row["passed"]
        return row["load_ok"]

    best, first_fail = None, None
    for n in scan:
        if time.monotonic() > budget_end and best is not None:
            log("capacity scan stopped: time budget")
            break
        if run_n(n):
            best = n
        else:
            first_fail = n
            break
    if not quick and best is not None and first_fail is not None:
        lo, hi = best, first_fail
        for _ in range(3):
            if time.monotonic() > budget_end:
                log("capacity bisection stopped: time budget")
                break
            mid = int(float("%.2g" % math.sqrt(lo * hi)))
            if mid <= lo or mid >= hi:
                break
            if run_n(mid):
                lo = mid
            else:
                hi = mid
        best, first_fail = lo, hi
    strict_best = max([n for n, ok in strict.items() if ok and (first_fail is None or n < first_fail)],
                      default=None)
    return strict_best, best, first_fail


# ------------------------------------------------------------ part 2: CPU

class RawCounter:
    """Counts messages and bytes on a topic without deserialising them."""

    def __init__(self, topic, nodelay=False):
        self.count, self.nbytes = 0, 0
        self.lock = threading.Lock()
        self.sub = rospy.Subscriber(topic, rospy.AnyMsg, self._on_msg, queue_size=100, tcp_nodelay=nodelay)

    def _on_msg(self, msg):
        with self.lock:
            self.count += 1
            self.nbytes += len(msg._buff)

    def snapshot(self):
        with self.lock:
            return self.count, self.nbytes

    def close(self):
        self.sub.unregister()


def part_cpu(diag, quick):
    warmup, window = (1.0, 3.0) if quick else (2.0, 10.0)
    out = []
    for n in (100, 1000):
        tf = RawCounter("/tf")
        bodies = RawCounter(NS + "/bodies")
        with NodeRun(diag, make_scene(n, 1000, 100), "cpu_%d" % n) as run:
            time.sleep(1.0)  # let the subscribers connect
            c0, c1 = tf.snapshot(), bodies.snapshot()
            t0 = time.monotonic()
            r = run.measure(warmup, window)
            t1 = time.monotonic()
            c0b, c1b = tf.snapshot(), bodies.snapshot()
        tf.close()
        bodies.close()
        # counts over measure() incl. its warm-up: rates only
        r["tf_msgs_per_s"] = (c0b[0] - c0[0]) / (t1 - t0)
        r["bodies_msgs_per_s"] = (c1b[0] - c1[0]) / (t1 - t0)
        r["rx_mbyte_per_s"] = ((c0b[1] - c0[1]) + (c1b[1] - c1[1])) / (t1 - t0) / 1e6
        log("cpu N=%d: node CPU %.1f%% of one core, /tf %.0f/s, ~bodies %.0f/s (%.1f MB/s), "
            "%d overruns, step %.1f us, core other %.0f%%, load %.2f"
            % (n, r["cpu_percent"], r["tf_msgs_per_s"], r["bodies_msgs_per_s"], r["rx_mbyte_per_s"],
               r["overruns"], r["step_mean_us"], r["core_other_percent"], r["loadavg1"]))
        out.append(record(part=2, label="cpu", n_bodies=n, rate_hz=1000, publish_rate_hz=100,
                          subscribers="/tf, ~bodies", passed=r["overruns"] == 0, **r))
    return out


# --------------------------------------------------- part 3: wrench intake

class Preserialized(ParticleWrenchArray):
    """A ParticleWrenchArray serialised once; publish() then only copies bytes."""

    __slots__ = ["_bytes"]

    def __init__(self, msg):
        super().__init__()
        buff = io.BytesIO()
        msg.serialize(buff)
        self._bytes = buff.getvalue()

    def serialize(self, buff):
        buff.write(self._bytes)


def wrench_array(k, n_bodies):
    """K entries: first a marker (particle out of range, rejected: counts arrays taken),
    then K-1 valid world-axes forces spread over all bodies' particles."""
    wrenches = [ParticleWrench(body="b0", particle=999)]
    for j in range(k - 1):
        w = ParticleWrench(body="b%d" % (j % n_bodies), particle=(j // n_bodies) % 8)
        w.wrench.force.x = 1e-3 * ((j % 7) - 3)
        w.wrench.force.z = 1e-3
        wrenches.append(w)
    return Preserialized(ParticleWrenchArray(wrenches=wrenches))


def publish_at(pub, msg, hz, duration_s, stop):
    """Publishes msg at hz for duration_s; returns (sent, elapsed, busy seconds)."""
    period = 1.0 / hz
    t_start = time.monotonic()
    t_next = t_start
    sent, busy = 0, 0.0
    while not stop.is_set():
        now = time.monotonic()
        if now - t_start >= duration_s:
            break
        if now < t_next:
            time.sleep(t_next - now)
            continue
        b0 = time.monotonic()
        pub.publish(msg)
        busy += time.monotonic() - b0
        sent += 1
        t_next += period
        if t_next < time.monotonic() - 10 * period:  # far behind: do not burst
            t_next = time.monotonic()
    return sent, time.monotonic() - t_start, busy


def intake_run(diag, n_bodies, k, hz, warmup, window):
    msg = wrench_array(k, n_bodies)
    pub = rospy.Publisher(NS + "/particle_wrenches", ParticleWrenchArray, queue_size=1000, tcp_nodelay=True)
    with NodeRun(diag, make_scene(n_bodies, 1000, 100), "intake_%d_%d" % (k, int(hz))) as run:
        deadline = time.monotonic() + 10
        while pub.get_num_connections() == 0 and time.monotonic() < deadline:
            time.sleep(0.05)
        time.sleep(0.3)
        stop = threading.Event()
        stats = {}
        total = warmup + window + 2.5

        def publisher():
            stats["sent"], stats["elapsed"], stats["busy"] = publish_at(pub, msg, hz, total, stop)

        thread = threading.Thread(target=publisher, daemon=True)
        thread.start()
        try:
            r = run.measure(warmup, window)
        finally:
            stop.set()
            thread.join()
    pub.unregister()
    arrays = r["rejected_marker"]
    # every entry not taken (marker, any past the node's per-array cap) is counted as rejected
    taken = arrays * k - r["rejected"]
    r["pub_msgs_per_s"] = stats["sent"] / stats["elapsed"]
    r["pub_busy_percent"] = 100.0 * stats["busy"] / stats["elapsed"]
    r["wrenches_sent_per_s"] = r["pub_msgs_per_s"] * (k - 1)
    r["wrenches_taken_per_s"] = taken / r["window_s"]
    arrays_per_s = arrays / r["window_s"]
    kept_up = arrays_per_s >= 0.97 * r["pub_msgs_per_s"]
    all_taken = taken >= 0.99 * arrays * (k - 1)
    held = r["rtf_min"] >= 0.99 and kept_up and all_taken
    notes = []
    if not kept_up:
        notes.append("node took %.0f of %.0f arrays/s" % (arrays_per_s, r["pub_msgs_per_s"]))
    if not all_taken:
        notes.append("entries past the per-array cap rejected")
    if r["pub_msgs_per_s"] < 0.97 * hz:
        notes.append("publisher reached only %.0f of %.0f Hz" % (r["pub_msgs_per_s"], hz))
    log("intake K=%d at %.0f Hz: sent %.0f wrenches/s (publisher %.0f Hz, busy %.0f%%), node took %.0f/s, "
        "%d overruns, RTF min %.3f, step %.1f us, CPU %.0f%%, load %.2f -> %s"
        % (k, hz, r["wrenches_sent_per_s"], r["pub_msgs_per_s"], r["pub_busy_percent"],
           r["wrenches_taken_per_s"], r["overruns"], r["rtf_min"], r["step_mean_us"], r["cpu_percent"],
           r["loadavg1"], "held" if held else "NOT held"))
    return record(part=3, label="wrench intake", n_bodies=n_bodies, rate_hz=1000, publish_rate_hz=100,
                  subscribers="none", entries_per_msg=k, msgs_hz=hz, passed=held,
                  note="; ".join(notes), **r)


def part_intake(diag, quick, budget_end):
    n_bodies = 100
    warmup, window = (1.0, 3.0) if quick else (2.0, 6.0)
    plan = [(1000, 100.0), (10000, 100.0)] if quick else [(1000, 100.0), (10000, 100.0), (3000, 1000.0)]
    rows = []
    for k, hz in plan:
        if rows and time.monotonic() > budget_end:
            log("intake scan stopped: time budget")
            break
        rows.append(intake_run(diag, n_bodies, k, hz, warmup, window))
    return rows


# --------------------------------------------------------- part 4: latency

class MomentumWatcher:
    def __init__(self):
        self.cond = threading.Condition()
        self.latest = None  # (recv time, p tuple, stamp seconds)
        self.sub = rospy.Subscriber(NS + "/bodies", BodyStateArray, self._on_msg, queue_size=100,
                                    tcp_nodelay=True)

    def _on_msg(self, msg):
        now = time.time()
        p = msg.bodies[0].linear_momentum
        with self.cond:
            self.latest = (now, (p.x, p.y, p.z), msg.header.stamp.to_sec())
            self.cond.notify_all()

    def wait(self, predicate, timeout):
        deadline = time.monotonic() + timeout
        with self.cond:
            while self.latest is None or not predicate(self.latest):
                remaining = deadline - time.monotonic()
                if remaining <= 0:
                    return None
                self.cond.wait(remaining)
            return self.latest

    def close(self):
        self.sub.unregister()


def latency_run(diag, publish_rate, trials):
    scene = make_scene(1, 1000, publish_rate, moving=False)
    watcher = MomentumWatcher()
    pub = rospy.Publisher(NS + "/particle_wrench", ParticleWrench, queue_size=10, tcp_nodelay=True)
    latencies, lags = [], []
    with NodeRun(diag, scene, "latency_%d" % publish_rate) as run:
        deadline = time.monotonic() + 10
        while pub.get_num_connections() == 0 and time.monotonic() < deadline:
            time.sleep(0.05)
        if watcher.wait(lambda s: True, 10) is None:
            raise RuntimeError("no ~bodies messages")
        time.sleep(0.5)
        cpu = CpuWindow(run.proc.pid, ARGS.node_cpu)
        rng = random.Random(1)
        for i in range(trials):
            # settle: a message after the last change, then a random phase
            time.sleep(rng.uniform(0.02, 0.05))
            ref = watcher.wait(lambda s: True, 2)
            p_ref = ref[1]
            msg = ParticleWrench(body="b0", particle=0)
            msg.wrench.force.x = 1.0 if i % 2 == 0 else -1.0
            t_send = time.time()
            pub.publish(msg)

            def changed(s, t_send=t_send, p_ref=p_ref):
                return s[0] >= t_send and max(abs(a - b) for a, b in zip(s[1], p_ref)) > 1e-9

            got = watcher.wait(changed, 2.0)
            stop_msg = ParticleWrench(body="b0", particle=0)  # zero force replaces it
            pub.publish(stop_msg)
            if got is None:
                log("latency trial %d: no change seen within 2 s" % i)
                continue
            latencies.append(1e3 * (got[0] - t_send))
            lags.append(1e3 * (got[2] - t_send))
            # wait until the momentum is constant again (two consecutive equal messages)
            prev = got
            for _ in range(200):
                s = watcher.wait(lambda s, prev=prev: s[0] > prev[0], 1.0)
                if s is None or s[1] == prev[1]:
                    break
                prev = s
        cpu_r = cpu.finish()
    watcher.close()
    pub.unregister()
    latencies.sort()
    n = len(latencies)
    r = {
        "latency_median_ms": statistics.median(latencies) if n else float("nan"),
        "latency_p90_ms": latencies[min(n - 1, int(0.9 * n))] if n else float("nan"),
        "latency_min_ms": latencies[0] if n else float("nan"),
        "latency_max_ms": latencies[-1] if n else float("nan"),
        "stamp_lag_median_ms": statistics.median(lags) if n else float("nan"),
        "trials": n, "loadavg1": os.getloadavg()[0], "startup_s": run.startup_s, **cpu_r,
    }
    bound = 1e3 / publish_rate + 1.0
    log("latency publish_rate %d: median %.2f ms (p90 %.2f, min %.2f, max %.2f) over %d trials; "
        "1/publish_rate + 1/rate = %.1f ms; stamp - send median %.2f ms; load %.2f"
        % (publish_rate, r["latency_median_ms"], r["latency_p90_ms"], r["latency_min_ms"],
           r["latency_max_ms"], n, bound, r["stamp_lag_median_ms"], r["loadavg1"]))
    return record(part=4, label="latency", n_bodies=1, rate_hz=1000, publish_rate_hz=publish_rate,
                  subscribers="~bodies", passed=n >= trials * 0.9, **r)


def part_latency(diag, quick):
    rates = [1000] if quick else [100, 1000]
    trials = 20 if quick else 40
    return [latency_run(diag, rate, trials) for rate in rates]


# ---------------------------------------------------- part 6: ~step cost

STEP_COST_BODIES = 1000
STEP_COST_STEPS = 20000
# The core's counterpart of each node scene: free tumbling boxes, and boxes
# each pushed by one held world-axes particle force.
CORE_STEP_BENCHMARKS = {False: "BM_WorldStep/casimir_splitting4/free/1000",
                        True: "BM_WorldStepLoaded/world_force/1000"}


def core_ns_per_body_step(benchmark, repetitions):
    """Median ns per body-step of the core's `benchmark`, on the node's core with its scheduling."""
    out = subprocess.run(NODE_PREFIX + ["taskset", "-c", str(ARGS.node_cpu), devel_program(WS, "throughput_bench"),
                                        "--benchmark_filter=^%s$" % benchmark,
                                        "--benchmark_repetitions=%d" % repetitions,
                                        "--benchmark_report_aggregates_only=true", "--benchmark_format=json"],
                         stdout=subprocess.PIPE, universal_newlines=True, check=True).stdout
    median = next(b for b in json.loads(out)["benchmarks"] if b.get("aggregate_name") == "median")
    return 1e9 * median["per_body_step"]


def step_cost_run(diag, pushed, repetitions):
    """~step STEP_COST_STEPS on the paused node (its bodies free, or each pushed as in part 5), timed from a
    persistent client (no per-call connection set-up), and the node's own CPU time over each call; then the
    core's figure for the same kind of bodies."""
    label = "step cost, pushed" if pushed else "step cost"
    body_steps = float(STEP_COST_BODIES * STEP_COST_STEPS)
    walls, cpus = [], []
    with NodeRun(diag, make_scene(STEP_COST_BODIES, 1000, 10), label.replace(", ", "_").replace(" ", "_")) as run:
        held = push_every_body(run, STEP_COST_BODIES) if pushed else {}
        rospy.ServiceProxy(NS + "/set_paused", SetBool)(True)
        step = rospy.ServiceProxy(NS + "/step", Step, persistent=True)
        step(1000)  # warm-up: caches and first-touch page faults
        for _ in range(repetitions):
            ticks0, t0 = proc_cpu_ticks(run.proc.pid), time.monotonic()
            response = step(STEP_COST_STEPS)
            t1, ticks1 = time.monotonic(), proc_cpu_ticks(run.proc.pid)
            if not response.success:
                raise RuntimeError("~step failed: %s" % response.message)
            walls.append(1e9 * (t1 - t0) / body_steps)
            cpus.append(1e9 * (ticks1 - ticks0) / CLK_TCK / body_steps)
        step.close()
        startup_s, integrator = run.startup_s, run.first[1].get("integrator", "")
    benchmark = CORE_STEP_BENCHMARKS[pushed]
    core = core_ns_per_body_step(benchmark, repetitions)
    node = statistics.median(walls)
    r = {"ns_per_body_step": node, "cpu_ns_per_body_step": statistics.median(cpus), "core_ns_per_body_step": core,
         "node_to_core": node / core, "trials": repetitions, "loadavg1": os.getloadavg()[0],
         "startup_s": startup_s, "integrator": integrator}
    r.update(held)
    log("%s: ~step %d on %d bodies: node %.1f ns per body-step (its CPU %.1f; each call %s), core %s %.1f -> %.2fx, "
        "load %.2f" % (label, STEP_COST_STEPS, STEP_COST_BODIES, node, r["cpu_ns_per_body_step"],
                       ", ".join("%.1f" % w for w in walls), benchmark, core, r["node_to_core"], r["loadavg1"]))
    return record(part=6, label=label, n_bodies=STEP_COST_BODIES, rate_hz=1000, publish_rate_hz=10,
                  subscribers="none", passed=r["node_to_core"] <= 1.2, note=benchmark, **r)


def part_step_cost(diag, quick):
    """step_cost_run on free bodies, then on pushed ones: the node against the core for each, and pushed
    against free through the node and in the core."""
    repetitions = 3 if quick else 5
    return [step_cost_run(diag, pushed, repetitions) for pushed in (False, True)]


# ------------------------------------------------------------------ report

def git_describe():
    try:
        head = subprocess.run(["git", "-C", REPO, "rev-parse", "--short", "HEAD"], capture_output=True,
                              text=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", REPO, "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True).stdout.strip()
        return head + (" (with uncommitted changes)" if dirty else "")
    except OSError:
        return "unknown"


def capacity_summary(kind, capacity):
    strict_best, best, first_fail = capacity
    return [("%s at rate 1000 Hz, zero overruns in the window (publish_rate 10, one core)" % kind,
             "%s" % (strict_best if strict_best is not None else "none of the sizes tried")),
            ("%s at rate 1000 Hz, overruns within this machine's noise (<= %.0f/s or <= 2x a bare loop's), "
             "RTF >= 0.99" % (kind, NOISE_OVERRUNS_PER_S),
             "%s (%s)" % (best if best is not None else "none",
                          "fails at %s" % first_fail if first_fail else "no size tried failed"))]


def capacity_table(part):
    rows = [r for r in ROWS if r["part"] == part]
    return md_table(
        ["N bodies", "window s", "overruns", "bare loop overruns", "overruns per publish cycle",
         "catch-up hits",
         "step mean us", "ns per body-step", "step max us", "RTF min", "node CPU %", "core other %", "load avg",
         "first report s", "pass"],
        [[r["n_bodies"], r["window_s"], r["overruns"], r["floor_overruns"],
          "%.2f" % (r["overruns"] / (10.0 * r["window_s"])),
          r["catch_up_limit_hits"], r["step_mean_us"], 1e3 * r["step_mean_us"] / r["n_bodies"],
          r["step_max_us"], "%.3f" % r["rtf_min"], r["cpu_percent"], r["core_other_percent"],
          "%.2f" % r["loadavg1"], r["startup_s"],
          "yes" if r["passed"] else ("within noise" if r["load_ok"] else "no")] for r in rows])


def write_report(results, quick, elapsed):
    """results: what each part that ran returned, by name."""
    capacity, pushed = results.get("capacity"), results.get("pushed")
    cpu_rows, intake_rows = results.get("cpu", []), results.get("intake", [])
    latency_rows, step_cost = results.get("latency", []), results.get("step_cost")
    loads = [r["loadavg1"] for r in ROWS if "loadavg1" in r]
    cpu_model = ""
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu_model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    integrator = next((r.get("integrator") for r in ROWS if r.get("integrator")), "")
    md = ["# The node under load (`bench/node_load.py`%s)" % (" --quick" if quick else ""), ""]
    md.append("Commit %s, %s, %d cores; node pinned to core %d (`taskset`) with scheduling `%s`, this script "
              "and the master on core %d. Integrator: %s (the node's default). Scenes: N generated boxes, `resolution: 2` "
              "(8 particles each), all moving (idle bodies are skipped by the integrator). "
              "Load average (1 min) during the runs: %.2f to %.2f. Run time %.0f s."
              % (git_describe(), cpu_model or "unknown CPU", os.cpu_count(), ARGS.node_cpu, ARGS.sched, ARGS.bench_cpu,
                 integrator, min(loads) if loads else float("nan"), max(loads) if loads else float("nan"),
                 elapsed))
    md.append("")
    md.append("## Summary")
    md.append("")
    summary = capacity_summary("bodies", capacity) if capacity else []
    for r in cpu_rows:
        summary.append(("node CPU, %d bodies, /tf + ~bodies at 100 Hz subscribed" % r["n_bodies"],
                        "%.1f %% of one core" % r["cpu_percent"]))
    held = [r for r in intake_rows if r["passed"]]
    held0 = [r for r in held if r["overruns"] == 0]
    if intake_rows:
        summary.append(("particle wrenches/s taken, rate held (RTF >= 0.99, all arrays taken)",
                        "%.0f" % max(r["wrenches_taken_per_s"] for r in held) if held else "none held"))
        summary.append(("... of those with zero overruns",
                        "%.0f" % max(r["wrenches_taken_per_s"] for r in held0) if held0 else "none"))
    for r in latency_rows:
        summary.append(("wrench -> ~bodies latency, publish_rate %d (median of %d)"
                        % (r["publish_rate_hz"], r["trials"]),
                        "%.2f ms (1/publish_rate = %.1f ms)" % (r["latency_median_ms"], 1e3 / r["publish_rate_hz"])))
    if pushed:
        summary += capacity_summary("pushed bodies (one held particle force each)", pushed)
    for r in step_cost or []:
        summary.append(("~step %d while paused, %d %s bodies: node / core ns per body-step"
                        % (STEP_COST_STEPS, STEP_COST_BODIES, "pushed" if "pushed" in r["label"] else "free"),
                        "%.1f / %.1f (%.2fx)" % (r["ns_per_body_step"], r["core_ns_per_body_step"],
                                                 r["node_to_core"])))
    if step_cost and len(step_cost) == 2:
        free, pushed_cost = step_cost
        summary.append(("~step, pushed / free ns per body-step: node, core",
                        "%.2fx, %.2fx" % (pushed_cost["ns_per_body_step"] / free["ns_per_body_step"],
                                          pushed_cost["core_ns_per_body_step"] / free["core_ns_per_body_step"])))
    md.append(md_table(["figure", "value"], summary))
    md.append("")

    if capacity:
        md.append("## 1. Capacity: rate 1000 Hz, publish_rate 10, no /tf or ~bodies subscriber")
        md.append("")
        md.append("Each run: node started on a fresh scene, %s s warm-up, then the window between two "
                  "diagnostics reports. Overruns = increase of the cumulative `overruns` key (a wake-up late by "
                  "more than one step). RTF min = lowest `real_time_factor_achieved` in the window. "
                  "Pass = zero overruns and RTF min >= 0.99; \"within noise\" = at most %.0f overrun/s or at most "
                  "twice the bare loop's count, no catch-up-limit hit and RTF min >= 0.99. \"bare loop\" = "
                  "`bench/wake_jitter` right after the run, on the node's core with its scheduling: sleep to each "
                  "1 ms boundary, then busy for the run's mean step time, overruns counted as the node counts "
                  "them; it is what this shared virtual machine gives with no node at all. The scan stops at the "
                  "first size that fails beyond noise and "
                  "bisects. "
                  "\"core other\" = busy time of the node's core not used by the node (disturbance)."
                  % ("1" if quick else "3", NOISE_OVERRUNS_PER_S))
        md.append("")
        md.append(capacity_table(1))
        md.append("")

    if cpu_rows:
        md.append("## 2. CPU use: rate 1000 Hz, /tf and ~bodies at 100 Hz, both subscribed")
        md.append("")
        md.append("Node CPU = (utime + stime) from /proc/<pid>/stat over the window, per wall second, in % of one "
                  "core. The script subscribes to /tf and ~bodies as raw bytes (rospy.AnyMsg), so both messages "
                  "are built, serialised and sent.")
        md.append("")
        md.append(md_table(
            ["N bodies", "window s", "node CPU %", "step mean us", "/tf msg/s", "~bodies msg/s", "received MB/s",
             "overruns", "core other %", "load avg"],
            [[r["n_bodies"], r["window_s"], r["cpu_percent"], r["step_mean_us"], r["tf_msgs_per_s"],
              r["bodies_msgs_per_s"], "%.2f" % r["rx_mbyte_per_s"], r["overruns"], r["core_other_percent"],
              "%.2f" % r["loadavg1"]] for r in cpu_rows]))
        md.append("")

    if intake_rows:
        md.append("## 3. Particle wrench intake through ~particle_wrenches (100 bodies, 800 particles, publish_rate 100)")
        md.append("")
        md.append("Arrays of K entries published at R Hz by this script (rospy, each array serialised once and "
                  "re-sent as bytes). The first entry of each array is deliberately invalid (particle 999), so the "
                  "increase of `rejected_particle_out_of_range` counts the arrays the node processed; taken = "
                  "arrays x K - all rejected entries. Held = RTF min >= 0.99, the node processed >= 97 % of the "
                  "arrays sent and took >= 99 % of their valid entries. Publisher busy = time inside "
                  "publish() / wall time.")
        md.append("")
        md.append(md_table(
            ["K", "R Hz", "publisher Hz", "publisher busy %", "sent wrenches/s", "taken wrenches/s", "overruns",
             "RTF min", "step mean us", "node CPU %", "load avg", "held", "note"],
            [[r["entries_per_msg"], "%.0f" % r["msgs_hz"], r["pub_msgs_per_s"], r["pub_busy_percent"],
              "%.0f" % r["wrenches_sent_per_s"], "%.0f" % r["wrenches_taken_per_s"], r["overruns"],
              "%.3f" % r["rtf_min"], r["step_mean_us"], r["cpu_percent"], "%.2f" % r["loadavg1"],
              "yes" if r["passed"] else "no", r.get("note", "")] for r in intake_rows]))
        md.append("")

    if latency_rows:
        md.append("## 4. Latency: ParticleWrench (zero stamp) -> first ~bodies message reflecting it")
        md.append("")
        md.append("One box at rest, rate 1000 Hz. Each trial: wall time before publish(); the first ~bodies message "
                  "(tcp_nodelay, deserialised by rospy) whose linear momentum differs from the one before the "
                  "send; latency = wall time at its callback - send time; then a zero force replaces the push and "
                  "the next trial waits for a constant momentum plus a random 20-50 ms. Includes rospy publish "
                  "and callback overhead on both ends. Expected bound: up to one step (1 ms) until the wrench "
                  "is used, up to 1/publish_rate until the next publish cycle, plus transport. stamp - send = "
                  "the message's stamp (simulation time) minus the send time.")
        md.append("")
        md.append(md_table(
            ["publish_rate Hz", "trials", "median ms", "p90 ms", "min ms", "max ms", "1/publish_rate ms",
             "stamp - send median ms", "node CPU %", "load avg"],
            [[r["publish_rate_hz"], r["trials"], "%.2f" % r["latency_median_ms"], "%.2f" % r["latency_p90_ms"],
              "%.2f" % r["latency_min_ms"], "%.2f" % r["latency_max_ms"], 1e3 / r["publish_rate_hz"],
              "%.2f" % r["stamp_lag_median_ms"], r["cpu_percent"], "%.2f" % r["loadavg1"]] for r in latency_rows]))
        md.append("")

    if pushed:
        md.append("## 5. Pushed capacity: part 1 with one held particle force on every body")
        md.append("")
        md.append("As part 1, except that before the warm-up every body gets one held force of %g N along world "
                  "z at its particle 0 (a corner, so a torque too), sent once as ParticleWrenchArray messages of "
                  "%d entries on ~particle_wrenches (zero stamp, no `wrench_timeout`: held until replaced). "
                  "Before timing, the script waits for the diagnostics key `held_wrenches` = N with no rejected "
                  "message, and checks on two ~bodies messages that the first and last body's dv_z/dt = F/m (1 kg boxes) within "
                  "1 %%; the bodies therefore take the loaded SIMD lanes every step."
                  % (PUSH_FORCE_N, PUSH_ENTRIES_PER_ARRAY))
        md.append("")
        md.append(capacity_table(5))
        md.append("")

    if step_cost:
        md.append("## 6. ~step through the node against the core's World::Step")
        md.append("")
        md.append("The node paused on %d tumbling boxes (the part 1 scene), free, then in a second run each pushed "
                  "as in part 5; ~step %d called %d times from one persistent rospy service client after a "
                  "warm-up ~step 1000; ns per body-step = wall time of the call / (bodies x steps), median over "
                  "the calls; node CPU = the node's utime + stime over each call (10 ms ticks). Core: "
                  "`throughput_bench --benchmark_filter=^<benchmark>$` on the node's core with its scheduling "
                  "right after each run, median of as many repetitions: %s for free boxes, %s for boxes with one "
                  "held world-axes particle force each. A `rosservice call` timed from the shell would add the "
                  "command's own start-up (0.7-1.2 s on this machine, 35-60 ns per body-step at this size)."
                  % (STEP_COST_BODIES, STEP_COST_STEPS, step_cost[0]["trials"], CORE_STEP_BENCHMARKS[False],
                     CORE_STEP_BENCHMARKS[True]))
        md.append("")
        md.append(md_table(
            ["bodies", "kind", "steps per call", "calls", "node ns per body-step", "node CPU ns per body-step",
             "core ns per body-step", "node / core", "load avg"],
            [[r["n_bodies"], "pushed" if "pushed" in r["label"] else "free", STEP_COST_STEPS, r["trials"],
              r["ns_per_body_step"], r["cpu_ns_per_body_step"], r["core_ns_per_body_step"],
              "%.2f" % r["node_to_core"], "%.2f" % r["loadavg1"]] for r in step_cost]))
        md.append("")
    return "\n".join(md)


def main():
    quick = ARGS.quick
    every_part = not (ARGS.capacity or ARGS.pushed or ARGS.step_cost or ARGS.intake)
    start = time.monotonic()
    log("workspace %s, master %s, node on core %d, logs in %s"
        % (WS, os.environ["ROS_MASTER_URI"], ARGS.node_cpu, LOG_DIR))
    start_master(PROCS, ARGS.port, ARGS.bench_cpu, LOG_DIR)
    rospy.init_node("node_load_bench", anonymous=True, disable_signals=True)
    diag = Diagnostics()
    results = {}
    try:
        # Budgets (s from the start of each scan) keep the full run under about 5 minutes.
        if every_part or ARGS.capacity:
            results["capacity"] = part_capacity(diag, quick, start + (20 if quick else 140))
        if every_part:
            results["cpu"] = part_cpu(diag, quick)
        if every_part or ARGS.intake:
            results["intake"] = part_intake(diag, quick, start + (45 if quick else 250))
        if every_part:
            results["latency"] = part_latency(diag, quick)
        if every_part or ARGS.pushed:
            results["pushed"] = part_capacity(diag, quick, time.monotonic() + (20 if quick else 140), pushed=True)
        if every_part or ARGS.step_cost:
            results["step_cost"] = part_step_cost(diag, quick)
    finally:
        elapsed = time.monotonic() - start
        report = write_report(results, quick, elapsed)
        md_path, csv_path = write_results(ARGS.out, "node_load", report, CSV_FIELDS, ROWS)
        print()
        print(report)
        print("written: %s, %s" % (md_path, csv_path))
        rospy.signal_shutdown("done")
        PROCS.stop_all()


if __name__ == "__main__":
    try:
        main()
    except KeyboardInterrupt:
        PROCS.stop_all()
        sys.exit(130)
    except Exception:
        PROCS.stop_all()
        raise
