#!/usr/bin/python3
"""A minute of the quadrotor's lockstep flight at 1 kHz control, over TCP and in one nodelet
manager: the wall time it takes, and whether both flights pass through the same states.

Two ways to run launch/quadrotor.launch, both with rate 1000 and publish_rate 1000 (one
control cycle per step), real_time_factor 0 (as fast as the controller answers), gusts of
--gust-stddev m/s (seed 3), and neither robot_state_publisher nor /use_sim_time (nothing else
subscribes to the node):
  tcp      node and controller programs, the controller answering on roscpp's network thread
  nodelet  in_process:=true: both nodelets of one manager, the controller answering on the
           node's stepping thread
For each:
1. speed: simulated seconds per wall second between consecutive diagnostics reports over
   --window s (bench/replay_speed.py's node_speed); the flight's wall time is --seconds over
   their median;
2. states: the flight recorded (record:=BAG) until the node reports --seconds of steps, and the state hash of every recorded cycle (/record/cycles, by step); the two
   flights' hashes compared step by step up to --seconds.

Writes bench/results/flight_lockstep.md (also printed).

  bench/flight_lockstep.py [--seconds 60] [--window 5] [--gust-stddev 0.5] [--workspace PATH]
                           [--port 11397] [--out DIR]
"""

import argparse
import os
import statistics
import sys
import tempfile
import time

from node_harness import Diagnostics, Processes, add_node_bench_arguments, reexec_in_workspace, start_master
from replay_speed import launch, node_speed

# (name, quadrotor.launch arguments of the way it runs)
MODES = [("tcp", []), ("nodelet", ["in_process:=true"])]
FLIGHT = ["rate:=1000", "publish_rate:=1000", "real_time_factor:=0", "robot_state_publisher:=false",
          "use_sim_time:=false"]


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seconds", type=float, default=60.0, help="simulated seconds of flight (default 60)")
    parser.add_argument("--window", type=float, default=5.0, help="wall seconds of the speed window (default 5)")
    parser.add_argument("--gust-stddev", type=float, default=0.5, help="the gusts [m/s] (default 0.5)")
    add_node_bench_arguments(parser, 11397, "flight_lockstep.md")
    return parser.parse_args()


def wait_steps(diag, proc, steps, timeout):
    """Waits until the node reports `steps` steps or more."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline and proc.poll() is None:
        report = diag.wait_next(5, lambda: proc.poll() is None)
        if report is not None and report[1].get("steps", 0.0) >= steps:
            return
    sys.exit("the recorded flight did not reach step %d" % steps)


def recorded_hashes(bag_path, last_step):
    """The state hash of every recorded cycle up to `last_step`, by step."""
    import rosbag
    with rosbag.Bag(bag_path) as bag:
        return {msg.step: msg.state_hash for _, msg, _ in bag.read_messages(topics=["/record/cycles"])
                if msg.step <= last_step}


def main():
    args = parse_args()
    reexec_in_workspace(args.workspace, args.port)
    import rospy
    from bench_report import report_header, write_report
    os.sched_setaffinity(0, {args.bench_cpu})
    procs = Processes()
    log_dir = tempfile.mkdtemp(prefix="flight_lockstep_")
    last_step = int(round(args.seconds * 1000))
    speeds, hashes = {}, {}
    try:
        start_master(procs, args.port, args.bench_cpu, log_dir)
        rospy.init_node("flight_lockstep_bench", anonymous=True, disable_signals=True)
        diag = Diagnostics()
        for name, extra in MODES:
            diag.clear()
            speeds[name] = node_speed(procs, args, diag, log_dir, name, FLIGHT + extra)
            print("%s: %s simulated s per wall s" % (name, ", ".join("%.1f" % s for s in speeds[name])),
                  flush=True)
            bag = os.path.join(log_dir, name + ".bag")
            diag.clear()
            proc = launch(procs, args, log_dir, name + "_recorded", FLIGHT + extra + ["record:=" + bag])
            wait_steps(diag, proc, last_step, 120 + args.seconds)
            procs.stop(proc, grace_s=20.0)
            hashes[name] = recorded_hashes(bag, last_step)
            print("%s: %d cycles recorded up to step %d" % (name, len(hashes[name]), last_step), flush=True)
    finally:
        procs.stop_all()
    common = sorted(set(hashes["tcp"]) & set(hashes["nodelet"]))
    differing = [step for step in common if hashes["tcp"][step] != hashes["nodelet"][step]]
    lines = report_header("A minute of lockstep flight", "flight_lockstep.py", args.bench_cpu)
    lines += ["launch/quadrotor.launch, rate 1000, publish_rate 1000 (1 kHz control), real_time_factor 0, "
              "gusts of %g m/s (seed 3), no robot_state_publisher, use_sim_time false." % args.gust_stddev, "",
              "| way | simulated s per wall s (median) | wall time of %g s of flight | windows |" % args.seconds,
              "|---|---|---|---|"]
    for name, _ in MODES:
        speed = statistics.median(speeds[name])
        lines.append("| %s | %.1f | %.3f s | %s |" % (name, speed, args.seconds / speed,
                                                       ", ".join("%.1f" % s for s in speeds[name])))
    lines += ["", "State hashes, recorded flights: %d cycles in both up to step %d, %d differing%s." % (
        len(common), last_step, len(differing),
        "" if not differing else " (the first at step %d)" % differing[0]), ""]
    write_report(args.out, "flight_lockstep.md", lines)


if __name__ == "__main__":
    main()
