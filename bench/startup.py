#!/usr/bin/python3
"""Start-up of rigid_body_sim_node at 10,000 bodies.

For ~per_body_topics true and false, --trials times each, on a scene of N
generated boxes (resolution 2: 8 particles each; rate 1000, publish_rate 100,
real_time_factor 1, status_period 0), measures from the node process's start
(t0 = time.monotonic() just before Popen):

  1. the time to the first ~bodies message and to the first /tf message,
     both subscribed (as raw bytes, rospy.AnyMsg) before the node starts,
     and the node's RSS (VmRSS, /proc/<pid>/status) at the first ~bodies;
  2. the time until the node's "simulation" status on /diagnostics shows
     bodies_with_topics == bodies (every per-body topic advertised; true
     only; bounded by --max-wait), the RSS then, and the overruns and largest
     step_time_max_us the status reports over that advertising phase;
  3. overruns and step_time_max_us over a --steady-window after (1) and (2):
     the same node with nothing left to advertise, for comparison.

The two subscribers stay connected for the whole trial, as a user's would:
at 10,000 bodies each /tf and ~bodies message is about 1 MB, 100 of each
per second, which the node builds and sends.

Each trial runs in a fresh process of this script (--one-trial) with a fresh
private master on --port, so no trial sees another's 60,000 registrations.
The trial's process and the master run on core 0, the node on core 1
(taskset) with normal scheduling, as a user starts it (--sched fifo: chrt -f
10, as bench/node_load.py's capacity runs). A trial stops waiting once the
node's RSS passes --rss-limit-mb. The node is killed at the end of a trial
(a clean shutdown would unregister every topic with the master).

Writes bench/results/startup.md (medians; also printed) and one CSV row per
trial to bench/results/startup.csv.

  bench/startup.py [--bodies 10000] [--trials 3] [--workspace PATH] [--port 11397] [--out DIR]

With --launch FILE (a launch file of the package, e.g. quadrotor.launch) it
times that launch instead, as a user starts it: from just before
`roslaunch rigid_body_sim FILE` (on a fresh private master, subscribed to
~bodies before) to the first ~bodies message, --trials times; writes
bench/results/startup_<FILE without .launch>.md and .csv.

  bench/startup.py --launch quadrotor.launch [--trials 5] [--workspace PATH]
"""

import argparse
import json
import math
import os
import re
import shlex
import statistics
import subprocess
import sys
import tempfile
import threading
import time

from bench_report import cpu_model, fmt, git_head, md_table
from generated_scene import make_scene
from node_harness import NODE_NAME, NS, Processes, add_node_bench_arguments, devel_program, rss_kib, write_results


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bodies", type=int, default=10000, help="number of generated boxes (default 10000)")
    parser.add_argument("--publish-rate", type=float, default=100.0,
                        help="the scene's publish_rate [Hz] (default 100)")
    parser.add_argument("--trials", type=int, default=3, help="trials per per_body_topics value (default 3)")
    add_node_bench_arguments(parser, 11397, "startup.md and startup.csv")
    parser.add_argument("--sched", choices=["normal", "fifo"], default="normal",
                        help="node scheduling: normal (default, as a user starts it), or fifo = chrt -f 10 "
                             "(see the README: at 10,000 bodies with both subscribers it starves roscpp's threads)")
    parser.add_argument("--rss-limit-mb", type=float, default=4000.0,
                        help="a trial stops waiting once the node's RSS exceeds this [MB] (default 4000)")
    parser.add_argument("--max-wait", type=float, default=600.0,
                        help="longest wait for every per-body topic to be advertised [s] (default 600)")
    parser.add_argument("--steady-window", type=float, default=10.0,
                        help="window after the start-up for overruns with nothing left to advertise [s]")
    parser.add_argument("--only", choices=["true", "false"], default=None,
                        help="run only this per_body_topics value")
    parser.add_argument("--launch", default=None,
                        help="time `roslaunch rigid_body_sim LAUNCH` to its first ~bodies instead (e.g. quadrotor.launch)")
    parser.add_argument("--one-trial", choices=["true", "false", "launch"], default=None, help=argparse.SUPPRESS)
    parser.add_argument("--log-dir", default=None, help=argparse.SUPPRESS)
    return parser.parse_args()


ARGS = parse_args()
NODE_PREFIX = {"normal": [], "fifo": ["chrt", "-f", "10"]}[ARGS.sched]
T_START = time.monotonic()


def log(text):
    print("[%6.1f s] %s" % (time.monotonic() - T_START, text), file=sys.stderr, flush=True)


# ------------------------------------------------------------- one trial

def run_one_trial():
    """Runs in the workspace's environment (re-executed); prints one JSON object on stdout."""
    from node_harness import Diagnostics, start_master
    os.sched_setaffinity(0, {ARGS.bench_cpu})
    per_body_topics = ARGS.one_trial == "true"
    log_dir = ARGS.log_dir or tempfile.mkdtemp(prefix="startup_logs_")
    label = "topics_%s" % ARGS.one_trial
    procs = Processes()
    try:
        start_master(procs, ARGS.port, ARGS.bench_cpu, log_dir)
        import rospy
        rospy.init_node("startup_bench", anonymous=True, disable_signals=True)
        diag = Diagnostics()
        n = ARGS.bodies
        rospy.set_param(NS, make_scene(n, 1000, ARGS.publish_rate, per_body_topics))

        first = {}
        lock = threading.Lock()
        got_both = threading.Event()
        state = {"pid": None}
        counts = {"tf": 0, "bodies": 0}

        def on_msg(key):
            def callback(msg):
                now = time.monotonic()
                with lock:
                    counts[key] += 1
                    if key in first:
                        return
                    entry = {"t": now, "bytes": len(msg._buff)}
                    if state["pid"] is not None:
                        try:
                            entry["rss_kib"] = rss_kib(state["pid"])
                        except (OSError, StopIteration):
                            pass
                    first[key] = entry
                    if len(first) == 2:
                        got_both.set()
            return callback

        subs = [rospy.Subscriber(NS + "/bodies", rospy.AnyMsg, on_msg("bodies"), queue_size=2),
                rospy.Subscriber("/tf", rospy.AnyMsg, on_msg("tf"), queue_size=2)]
        time.sleep(0.5)
        node_log = os.path.join(log_dir, "node_%s.log" % label)
        argv = NODE_PREFIX + ["taskset", "-c", str(ARGS.node_cpu), devel_program(os.environ["RBS_BENCH_WS"],
                                                                               "rigid_body_sim_node"),
                              "__name:=" + NODE_NAME]
        os.environ["ROSCONSOLE_STDOUT_LINE_BUFFERED"] = "1"  # the log survives the SIGKILL at the end
        wall0 = time.time()
        t0 = time.monotonic()
        node = procs.start(argv, node_log)
        state["pid"] = node.pid

        def alive():
            return node.poll() is None

        if not got_both.wait(120.0) or not alive():
            raise RuntimeError("no first ~bodies and /tf within 120 s (node log %s)" % node_log)
        r = {"per_body_topics": per_body_topics, "bodies": n, "log_dir": log_dir, "rss_limit_hit": 0}
        r["first_bodies_s"] = first["bodies"]["t"] - t0
        r["first_tf_s"] = first["tf"]["t"] - t0
        r["rss_first_mb"] = first["bodies"].get("rss_kib", float("nan")) / 1024.0
        r["bodies_msg_mb"] = first["bodies"]["bytes"] / 1e6
        r["tf_msg_mb"] = first["tf"]["bytes"] / 1e6
        log("%s: first ~bodies %.2f s, first /tf %.2f s, RSS %.0f MB"
            % (label, r["first_bodies_s"], r["first_tf_s"], r["rss_first_mb"]))

        # The advertising phase, from the status reports.
        done_t, done_report = None, None
        deadline = t0 + ARGS.max_wait
        last = None
        while time.monotonic() < deadline and alive():
            if rss_kib(node.pid) / 1024.0 > ARGS.rss_limit_mb:
                r["rss_limit_hit"] = 1
                log("%s: RSS above %.0f MB: stopped waiting" % (label, ARGS.rss_limit_mb))
                break
            rep = diag.wait_next(5.0, alive)
            if rep is None:
                continue
            last = rep
            if rep[1].get("bodies_with_topics", 0) >= rep[1].get("bodies", n) or not per_body_topics:
                done_t, done_report = rep[0], rep
                break
        if last is None:
            raise RuntimeError("no diagnostics from the node (log %s)" % node_log)
        reports = diag.since(0.0, time.monotonic())
        r["first_report_s"] = reports[0][0] - t0
        r["topics_reached"] = int(last[1].get("bodies_with_topics", 0))
        if per_body_topics:
            if done_t is not None:
                r["all_topics_s"] = done_t - t0
                r["rss_all_mb"] = rss_kib(node.pid) / 1024.0
            else:
                r["all_topics_s"] = float("nan")
                r["rss_all_mb"] = rss_kib(node.pid) / 1024.0 if alive() else float("nan")
            phase = reports if done_report is None else [x for x in reports if x[0] <= done_report[0]]
            end = phase[-1][1]
            r["adv_overruns"] = int(end["overruns"])
            r["adv_steps"] = int(end["steps"])
            r["adv_step_max_us"] = max(x[1]["step_time_max_us"] for x in phase)
            r["adv_catch_up_hits"] = int(end.get("catch_up_limit_hits", 0))
            r["adv_rtf_min"] = min(x[1]["real_time_factor_achieved"] for x in phase[1:] or phase)
            # Advertising rate over the reports (topics per second of wall time).
            with_topics = [(x[0], x[1]["bodies_with_topics"]) for x in phase]
            if len(with_topics) >= 2 and with_topics[-1][0] > with_topics[0][0]:
                r["topics_per_s"] = (6.0 * (with_topics[-1][1] - with_topics[0][1])
                                     / (with_topics[-1][0] - with_topics[0][0]))
            else:
                r["topics_per_s"] = float("nan")
            log("%s: %d/%d bodies with topics at %.1f s, RSS %.0f MB, %d overruns in %d steps, step max %.0f us"
                % (label, r["topics_reached"], n, r.get("all_topics_s", float("nan")), r["rss_all_mb"],
                   r["adv_overruns"], r["adv_steps"], r["adv_step_max_us"]))
        # Steady window: from the next report on, --steady-window seconds.
        d0 = diag.wait_next(5.0, alive)
        steady_end = time.monotonic() + max(0.0, ARGS.steady_window - 1.0)
        while time.monotonic() < steady_end and rss_kib(node.pid) / 1024.0 <= ARGS.rss_limit_mb:
            time.sleep(0.2)
        if rss_kib(node.pid) / 1024.0 > ARGS.rss_limit_mb:
            r["rss_limit_hit"] = 1
        d1 = diag.wait_next(5.0, alive)
        if d0 is None or d1 is None:
            raise RuntimeError("the node stopped reporting (log %s)" % node_log)
        inside = [x[1] for x in diag.since(d0[0], d1[0])]
        r["steady_window_s"] = d1[0] - d0[0]
        r["steady_overruns"] = int(d1[1]["overruns"] - d0[1]["overruns"])
        r["steady_step_max_us"] = max(v["step_time_max_us"] for v in inside)
        r["steady_step_mean_us"] = statistics.mean(v["step_time_mean_us"] for v in inside)
        r["steady_rtf_min"] = min(v["real_time_factor_achieved"] for v in inside)
        r["rss_end_mb"] = rss_kib(node.pid) / 1024.0
        with lock:
            r["tf_msgs"], r["bodies_msgs"] = counts["tf"], counts["bodies"]
        r["loadavg1"] = os.getloadavg()[0]
        log("%s: steady %.1f s: %d overruns, step mean %.0f us, max %.0f us, RSS %.0f MB"
            % (label, r["steady_window_s"], r["steady_overruns"], r["steady_step_mean_us"],
               r["steady_step_max_us"], r["rss_end_mb"]))
        for s in subs:
            s.unregister()
        # Kill the node (SIGKILL): a clean shutdown would unregister every topic with the master.
        import signal
        try:
            os.killpg(node.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        node.wait()
        r["run_s"] = run_log_seconds(node_log, wall0)
        print(json.dumps(r), flush=True)
    finally:
        try:
            import rospy
            rospy.signal_shutdown("done")
        except Exception:
            pass
        procs.stop_all()


def run_launch_trial():
    """One start of --launch; prints {"first_bodies_s": ...} on stdout."""
    import rospy
    from node_harness import start_master
    os.sched_setaffinity(0, {ARGS.bench_cpu})
    log_dir = ARGS.log_dir or tempfile.mkdtemp(prefix="startup_logs_")
    procs = Processes()
    try:
        start_master(procs, ARGS.port, ARGS.bench_cpu, log_dir)
        rospy.init_node("startup_bench", anonymous=True, disable_signals=True)
        first = threading.Event()
        times = []

        def on_bodies(_msg):
            if not times:
                times.append(time.monotonic())
                first.set()

        sub = rospy.Subscriber(NS + "/bodies", rospy.AnyMsg, on_bodies, queue_size=2)
        time.sleep(0.5)
        launch_log = os.path.join(log_dir, "launch.log")
        t0 = time.monotonic()
        launch = procs.start(["roslaunch", "rigid_body_sim", ARGS.launch], launch_log)
        if not first.wait(60.0) or launch.poll() is not None:
            raise RuntimeError("no first ~bodies within 60 s (log %s)" % launch_log)
        sub.unregister()
        print(json.dumps({"first_bodies_s": times[0] - t0, "log_dir": log_dir,
                          "loadavg1": os.getloadavg()[0]}), flush=True)
    finally:
        rospy.signal_shutdown("done")
        procs.stop_all()


def run_log_seconds(node_log, wall0):
    """Seconds from the start to the node's "<n> bodies, integrator ..." line (Run() entered: scene
    read, World built, topics of the node advertised), from the wall stamp roscpp puts on it."""
    try:
        with open(node_log) as f:
            for line in f:
                m = re.search(r"\[ INFO\] \[(\d+\.\d+)\]: .*bodies, integrator", line)
                if m:
                    return float(m.group(1)) - wall0
    except OSError:
        pass
    return float("nan")


# --------------------------------------------------------------- driver

CSV_FIELDS = ["per_body_topics", "trial", "bodies", "run_s", "first_bodies_s", "first_tf_s", "first_report_s",
              "rss_first_mb", "all_topics_s", "topics_reached", "topics_per_s", "rss_all_mb", "adv_overruns",
              "adv_steps", "adv_step_max_us", "adv_catch_up_hits", "adv_rtf_min", "steady_window_s",
              "steady_overruns", "steady_step_mean_us", "steady_step_max_us", "steady_rtf_min", "rss_end_mb",
              "bodies_msg_mb", "tf_msg_mb", "rss_limit_hit", "loadavg1", "trial_wall_s"]


def median(rows, key):
    values = [r[key] for r in rows if key in r and isinstance(r[key], (int, float)) and not math.isnan(r[key])]
    return statistics.median(values) if values else float("nan")


def write_report(rows, elapsed, command):
    n = ARGS.bodies
    md = ["# Start-up at %d bodies (`bench/startup.py`)" % n, ""]
    md.append("Command: `%s`. Commit %s, %s, %d cores; the node pinned to core %d (`taskset`), scheduling `%s`; "
              "the script and a private master (port %d, a fresh one per trial) on core %d. Run time %.0f s; "
              "load average (1 min) at the trials' ends %s."
              % (command, git_head(), cpu_model(), os.cpu_count(), ARGS.node_cpu, ARGS.sched, ARGS.port,
                 ARGS.bench_cpu, elapsed,
                 ", ".join("%.2f" % r["loadavg1"] for r in rows if "loadavg1" in r) or "n/a"))
    md.append("")
    md.append("Scene: %d boxes of 8 particles (`resolution: 2`), all moving, `rate` 1000, `publish_rate` %g, "
              "`real_time_factor` 1, `status_period` 0, set on the parameter server before the node starts. "
              "The script subscribes to `/rigid_body_sim/bodies` and `/tf` (raw bytes) before it starts the "
              "node and stays subscribed, as a user would: each message is about %.1f MB (~bodies) and %.1f MB "
              "(/tf) at this size, %g of each per second, which costs the node CPU. Times are from "
              "`time.monotonic()` just before the node's `Popen`. Each figure is the median of %d trial(s) per "
              "row; every trial is a row of `startup.csv`."
              % (n, ARGS.publish_rate, median(rows, "bodies_msg_mb"), median(rows, "tf_msg_mb"),
                 ARGS.publish_rate, ARGS.trials))
    md.append("")
    header = ["`per_body_topics`", "trials", "Run() entered s", "first ~bodies s", "first /tf s",
              "RSS at first ~bodies MB", "all per-body topics up s", "bodies with topics", "topics/s",
              "RSS with all topics MB", "overruns while advertising", "steps while advertising",
              "step max while advertising us", "RTF min while advertising", "steady overruns (window s)",
              "steady step mean / max us", "RSS at end MB"]
    table = []
    for value in (True, False):
        sel = [r for r in rows if r["per_body_topics"] == value]
        if not sel:
            continue
        adv = value
        table.append([
            "true" if value else "false", str(len(sel)),
            fmt(median(sel, "run_s"), 2), fmt(median(sel, "first_bodies_s"), 2), fmt(median(sel, "first_tf_s"), 2),
            fmt(median(sel, "rss_first_mb"), 0),
            fmt(median(sel, "all_topics_s"), 1) if adv else "-",
            ("%d / %d" % (median(sel, "topics_reached"), ARGS.bodies)) if adv else "0 (off)",
            fmt(median(sel, "topics_per_s"), 0) if adv else "-",
            fmt(median(sel, "rss_all_mb"), 0) if adv else "-",
            fmt(median(sel, "adv_overruns"), 0) if adv else "-",
            fmt(median(sel, "adv_steps"), 0) if adv else "-",
            fmt(median(sel, "adv_step_max_us"), 0) if adv else "-",
            fmt(median(sel, "adv_rtf_min"), 3) if adv else "-",
            "%s (%s)" % (fmt(median(sel, "steady_overruns"), 0), fmt(median(sel, "steady_window_s"), 0)),
            "%s / %s" % (fmt(median(sel, "steady_step_mean_us"), 0), fmt(median(sel, "steady_step_max_us"), 0)),
            fmt(median(sel, "rss_end_mb"), 0)])
    md.append(md_table(header, table))
    md.append("")
    md.append("Columns: *Run() entered* = the wall stamp of the node's start line (\"N bodies, integrator ...\", "
              "logged when the scene is read, the World built and the node's own topics advertised) minus the "
              "start. *all per-body topics up* = receive time of the first status on /diagnostics with "
              "`bodies_with_topics` = `bodies` (statuses come once a second, so up to 1 s late); 6 topics per "
              "body (5 published, 1 subscribed), %d in all; *topics/s* = 6 x the increase of "
              "`bodies_with_topics` per second between the first and that status. *Overruns while "
              "advertising* = the cumulative `overruns` key at that status (from the node's start: the whole "
              "advertising phase), *steps* = `steps` then; *step max* = the largest `step_time_max_us` "
              "(per-second window) of the statuses up to then; *RTF min* = the lowest "
              "`real_time_factor_achieved` of them, the first excepted. *Steady* = the same node for "
              "--steady-window seconds after (nothing left to advertise): overruns, and the mean and largest "
              "step time. RSS = VmRSS of the node from /proc/<pid>/status; at the first ~bodies it is read in "
              "the script's callback." % (6 * ARGS.bodies))
    md.append("")
    return "\n".join(md)


def time_launch():
    """--launch: the trials, each in a fresh process, and their report."""
    command = "bench/startup.py " + " ".join(shlex.quote(a) for a in sys.argv[1:])
    argv = [sys.executable if os.path.exists(sys.executable) else "/usr/bin/python3", os.path.abspath(__file__),
            "--launch", ARGS.launch, "--workspace", os.path.abspath(ARGS.workspace), "--port", str(ARGS.port),
            "--bench-cpu", str(ARGS.bench_cpu), "--one-trial", "launch"]
    rows = []
    for trial in range(1, ARGS.trials + 1):
        log_dir = tempfile.mkdtemp(prefix="startup_launch_%d_" % trial)
        out = subprocess.run(argv + ["--log-dir", log_dir], stdout=subprocess.PIPE, universal_newlines=True)
        lines = [l for l in out.stdout.splitlines() if l.startswith("{")]
        if out.returncode != 0 or not lines:
            log("trial %d failed (exit %d); logs in %s" % (trial, out.returncode, log_dir))
            continue
        row = json.loads(lines[-1])
        row["trial"] = trial
        rows.append(row)
        log("trial %d: first ~bodies %.2f s" % (trial, row["first_bodies_s"]))
    times = ", ".join("%.2f" % r["first_bodies_s"] for r in rows)
    report = "\n".join([
        "# Start-up of `%s` (`bench/startup.py --launch`)" % ARGS.launch, "",
        "Command: `%s`. Commit %s, %s, %d cores; load average (1 min) at the trials' ends %s." % (
            command, git_head(), cpu_model(), os.cpu_count(),
            ", ".join("%.2f" % r["loadavg1"] for r in rows) or "n/a"), "",
        "From just before `roslaunch rigid_body_sim %s` (a fresh private master per trial, this script "
        "subscribed to `/rigid_body_sim/bodies` before) to the first `~bodies` message: median %s s over %d "
        "trial(s) (%s s)." % (ARGS.launch, fmt(median(rows, "first_bodies_s"), 2), len(rows), times), ""])
    stem = os.path.splitext(os.path.basename(ARGS.launch))[0]
    md_path, csv_path = write_results(ARGS.out, "startup_" + stem, report,
                                      ["trial", "first_bodies_s", "loadavg1"], rows)
    print(report)
    print("written: %s, %s" % (md_path, csv_path))
    if len(rows) < ARGS.trials:
        sys.exit(1)


def main():
    from node_harness import reexec_in_workspace
    if ARGS.one_trial:
        reexec_in_workspace(ARGS.workspace, ARGS.port)
        if ARGS.one_trial == "launch":
            run_launch_trial()
        else:
            run_one_trial()
        return
    if ARGS.launch:
        time_launch()
        return
    ws = os.path.abspath(ARGS.workspace)
    devel_program(ws, "rigid_body_sim_node")
    command = "bench/startup.py " + " ".join(shlex.quote(a) for a in sys.argv[1:])
    start = time.monotonic()
    rows = []
    values = [ARGS.only == "true"] if ARGS.only else [True, False]
    base = [sys.executable if os.path.exists(sys.executable) else "/usr/bin/python3", os.path.abspath(__file__),
            "--bodies", str(ARGS.bodies), "--workspace", ws, "--port", str(ARGS.port), "--node-cpu",
            str(ARGS.node_cpu), "--bench-cpu", str(ARGS.bench_cpu), "--sched", ARGS.sched, "--max-wait",
            str(ARGS.max_wait), "--rss-limit-mb", str(ARGS.rss_limit_mb), "--steady-window", str(ARGS.steady_window)]
    # Alternate true and false, so a slow period of the shared machine does not hit one value only.
    for trial in range(1, ARGS.trials + 1):
        for value in values:
            label = "true" if value else "false"
            log_dir = tempfile.mkdtemp(prefix="startup_%s_%d_" % (label, trial))
            log("trial %d, per_body_topics %s (logs in %s)" % (trial, label, log_dir))
            t = time.monotonic()
            out = subprocess.run(base + ["--one-trial", label, "--log-dir", log_dir], stdout=subprocess.PIPE,
                                 universal_newlines=True)
            lines = [l for l in out.stdout.splitlines() if l.startswith("{")]
            if out.returncode != 0 or not lines:
                log("trial %d (%s) failed (exit %d); logs in %s" % (trial, label, out.returncode, log_dir))
                continue
            row = json.loads(lines[-1])
            row["trial"] = trial
            row["trial_wall_s"] = time.monotonic() - t
            rows.append(row)
    elapsed = time.monotonic() - start
    report = write_report(rows, elapsed, command)
    md_path, csv_path = write_results(ARGS.out, "startup", report, CSV_FIELDS, rows)
    print(report)
    print("written: %s, %s" % (md_path, csv_path))
    if len(rows) < len(values) * ARGS.trials:
        sys.exit(1)


if __name__ == "__main__":
    main()
