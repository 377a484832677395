"""What every part of bench/node_load.py runs on: the run's settings and rows (Bench), one node
process on a scene and its measured window (NodeRun), and what this machine gives a bare loop with
the node's scheduling (machine_floor)."""

import os
import statistics
import subprocess
import time

import rospy

from node_harness import NODE_NAME, NS, CpuWindow, devel_program

# Overruns per second above what this (virtual, shared) machine gives a one-body node.
NOISE_OVERRUNS_PER_S = 1.0


class Bench:
    """The run's settings (the parsed arguments, the workspace, the node's scheduling prefix), the
    processes it started, its log directory, the log, the diagnostics subscription and the rows of
    the CSV."""

    def __init__(self, args, workspace, node_prefix, procs, log_dir):
        self.args, self.workspace, self.node_prefix = args, workspace, node_prefix
        self.procs, self.log_dir = procs, log_dir
        self.per_body_topics = args.per_body_topics == "true"
        self.diag = None  # the Diagnostics, once the script is a ROS node
        self.rows = []
        self.t_start = time.monotonic()

    def log(self, text):
        print("[%6.1f s] %s" % (time.monotonic() - self.t_start, text), flush=True)

    def record(self, **row):
        self.rows.append(row)
        return row


class NodeRun:
    """One rigid_body_sim_node process on a scene; a context manager."""

    def __init__(self, bench, scene, label):
        self.bench, self.diag, self.scene, self.label = bench, bench.diag, scene, label
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
        bench = self.bench
        logfile = os.path.join(bench.log_dir, "node_%s.log" % self.label)
        node = devel_program(bench.workspace, "rigid_body_sim_node")
        self.proc = bench.procs.start(bench.node_prefix + ["taskset", "-c", str(bench.args.node_cpu), node,
                                                           "__name:=" + NODE_NAME],
                                      logfile)
        n = len(self.scene["bodies"])
        self.first = self.diag.wait_next(60 + n / 100.0, self.alive)
        if self.first is None:
            bench.procs.stop(self.proc)
            with open(logfile) as f:
                tail = f.read()[-2000:]
            raise RuntimeError("node (%s) did not report diagnostics:\n%s" % (self.label, tail))
        # The first report comes about one second after stepping starts.
        self.startup_s = self.first[0] - t0
        return self

    def __exit__(self, *exc):
        t0 = time.monotonic()
        if self.bench.args.sched == "fifo" and self.alive():
            # Back to SCHED_OTHER first: roscpp's shutdown can livelock with all its threads
            # SCHED_FIFO on one core.
            subprocess.run(["chrt", "-a", "-o", "-p", "0", str(self.proc.pid)], stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL)
        self.bench.procs.stop(self.proc, grace_s=5.0)
        if time.monotonic() - t0 > 2.0:
            self.bench.log("node (%s) took %.1f s to stop (SIGKILL after 5 s)"
                           % (self.label, time.monotonic() - t0))
        return False

    def measure(self, warmup_s, window_s):
        """Diagnostics- and /proc-based figures over about window_s after warmup_s."""
        time.sleep(warmup_s)
        d0 = self.diag.wait_next(5, self.alive)
        if d0 is None:
            raise RuntimeError("node (%s) stopped reporting" % self.label)
        cpu = CpuWindow(self.proc.pid, self.bench.args.node_cpu)
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


def machine_floor(bench, window_s, busy_us):
    """Overruns of a bare 1 kHz loop (bench/wake_jitter) on the node's core, with the node's
    scheduling and step time: what this machine alone gives."""
    probe = devel_program(bench.workspace, "wake_jitter")
    out = subprocess.run(bench.node_prefix + ["taskset", "-c", str(bench.args.node_cpu), probe,
                                              "%.1f" % window_s, str(int(round(busy_us)))],
                         stdout=subprocess.PIPE, universal_newlines=True, check=True).stdout
    fields = dict(item.split("=") for item in out.split())
    return int(fields["late_wakeups"]), float(fields["worst_late_us"])
