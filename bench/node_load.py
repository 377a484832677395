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
     BM_WorldStepLoaded/world_force/1000 on the node's core in the same run;
  7. the cost of ~record: the quadrotor of config/quadrotor.yaml and 1,000 pushed boxes at rate 1000
     with publish_rate 100, each without and with ~record to a bag: the real-time factor, overruns,
     the bag's size and the diagnostics keys record_dropped and record_error.

Writes a Markdown report (also printed) to bench/results/node_load.md and one
CSV row per run to bench/results/node_load.csv. Without part flags every part
runs; --capacity, --pushed, --intake, --step-cost and --record run only the parts named.

  bench/node_load.py [--quick] [--capacity] [--pushed] [--intake] [--step-cost] [--record] [--sizes N ...]
                     [--per-body-topics true|false] [--workspace PATH] [--port 11395]
                     [--out DIR]

The script re-executes itself with PATH/devel/setup.bash sourced (default
workspace: .build_ws in the checkout). It and the master stay on core 0, the
node runs on core 1 (--node-cpu). Everything started is stopped at the end.
"""

import argparse
import os
import sys
import tempfile
import time

from node_harness import (Diagnostics, Processes, add_node_bench_arguments, reexec_in_workspace, start_master,
                          write_results)


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
    parser.add_argument("--record", action="store_true",
                        help="run the ~record cost part (7); with no part flag, every part runs")
    parser.add_argument("--per-body-topics", choices=["true", "false"], default="true",
                        help="the scenes' ~per_body_topics (default true)")
    add_node_bench_arguments(parser, 11395, "node_load.md and node_load.csv")
    parser.add_argument("--sched", choices=["normal", "nice", "fifo"], default=None,
                        help="node scheduling: normal; nice = nice -n -20 (also this script and the master); "
                             "fifo = chrt -f 10 (the script and master: nice -20). Default: fifo when root, "
                             "else normal")
    return parser.parse_args()


def set_scheduling(args):
    """Pins this script (and the threads it starts later) to --bench-cpu, raises its priority unless
    --sched is normal, and returns the command prefix that starts the node with --sched."""
    os.sched_setaffinity(0, {args.bench_cpu})
    if args.sched is None:
        args.sched = "fifo" if os.geteuid() == 0 else "normal"
    if args.sched != "normal":
        try:
            os.setpriority(os.PRIO_PROCESS, 0, -20)
        except PermissionError:
            sys.exit("--sched %s needs root (or CAP_SYS_NICE); use --sched normal" % args.sched)
    return {"normal": [], "nice": ["nice", "-n", "-20"], "fifo": ["chrt", "-f", "10"]}[args.sched]


def run_parts(bench):
    """The parts the arguments ask for, then the report, written and printed even when a part fails."""
    # These import rospy and the package's messages: the script runs in the workspace's environment now.
    import rospy
    from node_load_capacity import part_capacity
    from node_load_cpu import part_cpu
    from node_load_intake import part_intake
    from node_load_latency import part_latency
    from node_load_record import part_record
    from node_load_report import CSV_FIELDS, write_report
    from node_load_step_cost import part_step_cost

    args = bench.args
    quick = args.quick
    every_part = not (args.capacity or args.pushed or args.step_cost or args.intake or args.record)
    start = time.monotonic()
    bench.log("workspace %s, master %s, node on core %d, logs in %s"
              % (bench.workspace, os.environ["ROS_MASTER_URI"], args.node_cpu, bench.log_dir))
    start_master(bench.procs, args.port, args.bench_cpu, bench.log_dir)
    rospy.init_node("node_load_bench", anonymous=True, disable_signals=True)
    bench.diag = Diagnostics()
    results = {}
    try:
        # Budgets (s from the start of each scan) keep the full run under about 5 minutes.
        if every_part or args.capacity:
            results["capacity"] = part_capacity(bench, quick, start + (20 if quick else 140))
        if every_part:
            results["cpu"] = part_cpu(bench, quick)
        if every_part or args.intake:
            results["intake"] = part_intake(bench, quick, start + (45 if quick else 250))
        if every_part:
            results["latency"] = part_latency(bench, quick)
        if every_part or args.pushed:
            results["pushed"] = part_capacity(bench, quick, time.monotonic() + (20 if quick else 140), pushed=True)
        if every_part or args.step_cost:
            results["step_cost"] = part_step_cost(bench, quick)
        if every_part or args.record:
            results["record"] = part_record(bench, quick)
    finally:
        elapsed = time.monotonic() - start
        report = write_report(bench, results, quick, elapsed)
        md_path, csv_path = write_results(args.out, "node_load", report, CSV_FIELDS, bench.rows)
        print()
        print(report)
        print("written: %s, %s" % (md_path, csv_path))
        rospy.signal_shutdown("done")
        bench.procs.stop_all()


def main():
    args = parse_args()
    workspace = reexec_in_workspace(args.workspace, args.port)
    from node_load_run import Bench  # imports rospy: in the workspace's environment
    node_prefix = set_scheduling(args)
    procs = Processes()
    try:
        run_parts(Bench(args, workspace, node_prefix, procs, tempfile.mkdtemp(prefix="node_load_logs_")))
    except KeyboardInterrupt:
        procs.stop_all()
        sys.exit(130)
    except Exception:
        procs.stop_all()
        raise


if __name__ == "__main__":
    main()
