#!/usr/bin/python3
"""How fast `rosrun rigid_body_sim replay` replays a recorded quadrotor flight, against the node
stepping the same scene with no controller.

1. Records a flight: launch/quadrotor.launch (rate 1000, publish_rate 100, the controller in
   lockstep, its four rotors, gusts of --gust-stddev m/s with seed 3) with `record:=BAG`, at
   real_time_factor --record-rtf, stopped once the node's diagnostics report --seconds of
   simulated time.
2. Replays BAG --replays times (`replay`, pinned to --node-cpu): the replay's own time (its
   line's "in T s": reading the bag, rebuilding the world, every input and step, every hash
   compared) and the whole command's wall time; the median of each, over the recorded
   simulated time.
3. The node on the same scene with no controller and no lockstep (`controller:=false`,
   real_time_factor 0: as fast as it steps; the launch pinned to --node-cpu): simulated
   seconds per wall second from its diagnostics (`sim_time_s` between consecutive reports),
   the median over --window s.

Writes bench/results/replay_speed.md (also printed).

  bench/replay_speed.py [--seconds 60] [--replays 5] [--window 10] [--record-rtf 4]
                        [--gust-stddev 0.5] [--workspace PATH] [--port 11399] [--out DIR]
"""

import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

from node_harness import (Diagnostics, Processes, add_node_bench_arguments, devel_program, reexec_in_workspace,
                          start_master)


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seconds", type=float, default=60.0, help="simulated seconds recorded (default 60)")
    parser.add_argument("--replays", type=int, default=5, help="replays of the bag (default 5)")
    parser.add_argument("--window", type=float, default=10.0,
                        help="wall seconds the node without controller is measured (default 10)")
    parser.add_argument("--record-rtf", type=float, default=4.0,
                        help="real_time_factor of the recorded flight (default 4)")
    parser.add_argument("--gust-stddev", type=float, default=0.5, help="the gusts [m/s] (default 0.5)")
    add_node_bench_arguments(parser, 11399, "replay_speed.md")
    return parser.parse_args()


def launch(procs, args, log_dir, label, extra, cpu=None):
    argv = ["roslaunch", "rigid_body_sim", "quadrotor.launch",
            "gust_stddev:=%g" % args.gust_stddev, "wind_seed:=3"] + extra
    if cpu is not None:
        argv = ["taskset", "-c", str(cpu)] + argv
    return procs.start(argv, os.path.join(log_dir, label + ".log"))


def wait_sim_time(diag, proc, seconds, timeout):
    """The latest report once the node's sim_time_s reaches `seconds`."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        report = diag.wait_next(5, lambda: proc.poll() is None)
        if report is not None and report[1].get("sim_time_s", 0.0) >= seconds:
            return report
        if proc.poll() is not None:
            break
    sys.exit("the recorded flight did not reach %g s of simulated time" % seconds)


def record_flight(procs, args, diag, log_dir, bag):
    proc = launch(procs, args, log_dir, "record", ["record:=" + bag, "real_time_factor:=%g" % args.record_rtf])
    report = wait_sim_time(diag, proc, args.seconds, 60 + 2 * args.seconds / args.record_rtf)
    procs.stop(proc, grace_s=20.0)
    return report[1]


def recorded_span(bag_path):
    """Simulated seconds from the first to the last recorded cycle, and the counts of cycles and inputs."""
    import rosbag
    with rosbag.Bag(bag_path) as bag:
        stamps = [msg.header.stamp.to_sec() for _, msg, _ in bag.read_messages(topics=["/record/cycles"])]
        inputs = bag.get_message_count("/record/inputs")
    return stamps[-1] - stamps[0], len(stamps), inputs


def replay_once(args, workspace, bag):
    t0 = time.monotonic()
    done = subprocess.run(["taskset", "-c", str(args.node_cpu), devel_program(workspace, "replay"), bag],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    wall = time.monotonic() - t0
    found = re.search(r"all (\d+) state hashes match .* in ([0-9.]+) s\)", done.stdout)
    if done.returncode != 0 or not found:
        sys.exit("replay failed (exit %d): %s" % (done.returncode, done.stdout))
    return float(found.group(2)), wall, int(found.group(1))


def node_speed(procs, args, diag, log_dir, label, extra, cpu=None):
    """Simulated seconds per wall second of each consecutive pair of reports over the window, of
    launch/quadrotor.launch with `extra` arguments."""
    proc = launch(procs, args, log_dir, label, extra, cpu=cpu)
    if diag.wait_next(60, lambda: proc.poll() is None) is None:
        sys.exit("%s: the node did not report" % label)
    diag.wait_next(5)  # past the start-up
    reports = []
    deadline = time.monotonic() + args.window
    while time.monotonic() < deadline:
        report = diag.wait_next(5, lambda: proc.poll() is None)
        if report is None:
            break
        reports.append(report)
    procs.stop(proc, grace_s=20.0)
    speeds = [(b[1]["sim_time_s"] - a[1]["sim_time_s"]) / (b[0] - a[0]) for a, b in zip(reports, reports[1:])]
    if not speeds:
        sys.exit("%s: the node gave no window" % label)
    return speeds


def main():
    args = parse_args()
    workspace = reexec_in_workspace(args.workspace, args.port)
    import rospy
    from bench_report import report_header, write_report
    os.sched_setaffinity(0, {args.bench_cpu})
    procs = Processes()
    log_dir = tempfile.mkdtemp(prefix="replay_speed_")
    bag = os.path.join(log_dir, "flight.bag")
    try:
        start_master(procs, args.port, args.bench_cpu, log_dir)
        rospy.init_node("replay_speed_bench", anonymous=True, disable_signals=True)
        diag = Diagnostics()
        last = record_flight(procs, args, diag, log_dir, bag)
        span_s, cycles, inputs = recorded_span(bag)
        print("recorded %.2f s of simulated time (%d cycles, %d inputs, %.1f MB); node reported %.2f s"
              % (span_s, cycles, inputs, os.path.getsize(bag) / 1e6, last["sim_time_s"]), flush=True)
        replays = []
        for i in range(args.replays):
            replays.append(replay_once(args, workspace, bag))
            print("replay %d: %.3f s inside, %.3f s the command, %d hashes matched" % ((i + 1,) + replays[-1]),
                  flush=True)
        diag.clear()
        speeds = node_speed(procs, args, diag, log_dir, "free", ["controller:=false", "real_time_factor:=0"],
                            cpu=args.node_cpu)
        print("node without controller: %s simulated s per wall s" % ", ".join("%.1f" % s for s in speeds),
              flush=True)
    finally:
        procs.stop_all()
    inside = statistics.median(r[0] for r in replays)
    command = statistics.median(r[1] for r in replays)
    speed = statistics.median(speeds)
    md = report_header("Replay speed", "replay_speed.py", args.bench_cpu,
                       pinned="replay and the node without controller pinned to core %d, " % args.node_cpu)
    md += ["Recorded: launch/quadrotor.launch in lockstep with its controller, gusts of %g m/s (seed 3), "
           "real_time_factor %g: %.2f s of simulated time, %d cycles, %d inputs, bag of %.1f MB."
           % (args.gust_stddev, args.record_rtf, span_s, cycles, inputs, os.path.getsize(bag) / 1e6), "",
           "| figure | median | runs |", "|---|---|---|",
           "| replay, its own time (bag read, world rebuilt, every input and step, every hash) | %.3f s = %.4f of "
           "real time (%.0fx) | %s |" % (inside, inside / span_s, span_s / inside,
                                         ", ".join("%.3f" % r[0] for r in replays)),
           "| replay, the whole command (process start-up and master too) | %.3f s = %.4f of real time (%.0fx) | %s |"
           % (command, command / span_s, span_s / command, ", ".join("%.3f" % r[1] for r in replays)),
           "| node, same scene, no controller, real_time_factor 0: simulated s per wall s | %.1f (%.2f s for the "
           "flight, %.4f of real time) | %s |" % (speed, span_s / speed, 1.0 / speed,
                                                  ", ".join("%.1f" % s for s in speeds)),
           "| replay's own time / the node's time for the flight | %.2f | |" % (inside / (span_s / speed)), ""]
    write_report(args.out, "replay_speed.md", md)


if __name__ == "__main__":
    main()
