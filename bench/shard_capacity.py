#!/usr/bin/python3
"""How many bodies one node, and K shards of one scene, hold at 1 kHz.

For 1 process and for --shards K processes (shard_count K, shard_index k,
each pinned to core k with chrt -f 10, as launch/sharded.launch pins them),
finds the largest N of generated boxes (8 particles each, torque-free,
publish_rate 10, per_body_topics false, nobody subscribed) at rate 1000 with
every process's overruns within the machine's floor — node_load.py's rule:
at most 1 overrun a second, or twice what a bare 1 kHz loop (wake_jitter)
with the same step time gets on the same core right after, no catch-up limit
hit, real-time factor >= 0.99 — by doubling from --start, then bisecting
until the bracket is within --resolution (10 %). The bare loops run at the
same time on the same cores as the run's processes, so the floor of the
sharded case has every core busy too.

One node runs on --node-cpu with this script and the master on the other
core; K shards take every core, so the script and the master share them.
Writes bench/results/shard_capacity.md (also printed) and
bench/results/shard_capacity.csv (one row per process per run).

  bench/shard_capacity.py [--shards 2] [--start 10000] [--window 10] [--workspace PATH] [--out DIR]
"""

import argparse
import math
import os
import subprocess
import tempfile
import time

from node_harness import (Diagnostics, Processes, add_node_bench_arguments, devel_program,
                          reexec_in_workspace, start_master, write_results)


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--shards", type=int, default=2, help="shard processes in the sharded case (default 2)")
    parser.add_argument("--start", type=int, default=10000, help="first N tried (default 10000)")
    parser.add_argument("--one-node", type=int, default=None,
                        help="one node's capacity from an earlier run, instead of measuring it again")
    parser.add_argument("--one-node-failed", type=int, default=None, help=argparse.SUPPRESS)
    parser.add_argument("--resolution", type=float, default=0.1,
                        help="bisect until the failing N is within this fraction of the passing one")
    parser.add_argument("--warmup", type=float, default=3.0, help="seconds before the window")
    parser.add_argument("--window", type=float, default=10.0, help="measuring window [s] (default 10)")
    add_node_bench_arguments(parser, 11399, "shard_capacity.md and .csv")
    return parser.parse_args()


ARGS = parse_args()
WS = reexec_in_workspace(ARGS.workspace, ARGS.port)
CORES = os.cpu_count() or 1
LOG_DIR = tempfile.mkdtemp(prefix="shard_capacity_")
NOISE_OVERRUNS_PER_S = 1.0
ROWS = []


def log(text):
    print(text, flush=True)


def scene(n, shards, index):
    bodies = [{"name": "b%d" % i, "shape": "box", "mass": 1.0, "size": [0.2, 0.15, 0.1], "resolution": 2,
               "position": [0.5 * (i % 50), 0.5 * ((i // 50) % 50), 0.5 * (i // 2500)],
               "linear_velocity": [0.01, 0.0, 0.0], "angular_velocity": [0.3, -0.2, 1.0 + (i % 7) * 0.3]}
              for i in range(n)]
    return {"rate": 1000.0, "publish_rate": 10.0, "real_time_factor": 1.0, "status_period": 0.0,
            "per_body_topics": False, "shard_count": shards, "shard_index": index, "bodies": bodies}


def floor_overruns(rows):
    """Late wake-ups of bare 1 kHz loops (wake_jitter), one per process of the
    run on its core with its step time, all at once: the machine's floor with
    the same cores busy."""
    probes = [subprocess.Popen(["chrt", "-f", "10", "taskset", "-c", str(r["cpu"]),
                                devel_program(WS, "wake_jitter"), "%.1f" % r["window_s"],
                                str(int(round(r["step_mean_us"])))],
                               stdout=subprocess.PIPE, universal_newlines=True) for r in rows]
    return [int(dict(item.split("=") for item in probe.communicate()[0].split())["late_wakeups"])
            for probe in probes]


def run(n, shards):
    """Every process of one run: (passed, rows)."""
    import rospy  # importable once the script runs in the workspace's environment
    procs = Processes()
    names = ["rigid_body_sim"] if shards == 1 else ["rigid_body_sim_%d" % k for k in range(shards)]
    cpus = [ARGS.node_cpu] if shards == 1 else [k % CORES for k in range(shards)]
    diags = [Diagnostics(name) for name in names]
    nodes = []
    for k, (name, cpu) in enumerate(zip(names, cpus)):
        rospy.set_param("/" + name, scene(n, shards, k))
        nodes.append(procs.start(["chrt", "-f", "10", "taskset", "-c", str(cpu),
                                  devel_program(WS, "rigid_body_sim_node"), "__name:=" + name],
                                 os.path.join(LOG_DIR, "%s_%d.log" % (name, n))))
    rows = []
    try:

        def alive():
            return all(p.poll() is None for p in nodes)

        # A node whose steps take longer than dt starves roscpp's threads
        # (its stepping thread outranks them under SCHED_FIFO): no report
        # comes, and N is too large.
        if any(diag.wait_next(30 + n / 2000.0, alive) is None for diag in diags):
            log("%d process(es), N=%d: no diagnostics (overloaded) -> FAIL" % (shards, n))
            return False
        time.sleep(ARGS.warmup)
        first = [diag.wait_next(5, alive) for diag in diags]
        time.sleep(ARGS.window - 1.0)
        last = [diag.wait_next(5, alive) for diag in diags]
        if None in first or None in last:
            log("%d process(es), N=%d: a process stopped reporting (overloaded) -> FAIL" % (shards, n))
            return False
        for name, cpu, diag, (t0, v0), (t1, v1) in zip(names, cpus, diags, first, last):
            inside = [v for _, v in diag.since(t0, t1)]
            rows.append({"processes": shards, "n_bodies": n, "node": name, "cpu": cpu,
                         "bodies_here": int(v1["bodies"]), "window_s": t1 - t0,
                         "overruns": int(v1["overruns"] - v0["overruns"]),
                         "catch_up_limit_hits": int(v1["catch_up_limit_hits"] - v0["catch_up_limit_hits"]),
                         "rtf_min": min(v["real_time_factor_achieved"] for v in inside),
                         "step_mean_us": sum(v["step_time_mean_us"] for v in inside) / len(inside),
                         "step_max_us": max(v["step_time_max_us"] for v in inside)})
    finally:
        for node in nodes:  # back to SCHED_OTHER first: roscpp's shutdown livelocks under FIFO
            subprocess.run(["chrt", "-a", "-o", "-p", "0", str(node.pid)], stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL)
        procs.stop_all()
        for diag in diags:
            diag.close()
    passed = True
    for r, floor in zip(rows, floor_overruns(rows)):
        r["floor_overruns"] = floor
        r["passed"] = (r["overruns"] <= max(NOISE_OVERRUNS_PER_S * r["window_s"], 2 * r["floor_overruns"])
                       and r["catch_up_limit_hits"] == 0 and r["rtf_min"] >= 0.99)
        passed = passed and r["passed"]
        log("  %s (core %d, %d bodies): %d overruns in %.1f s (bare loop %d), step %.0f us (max %.0f), "
            "RTF min %.3f -> %s" % (r["node"], r["cpu"], r["bodies_here"], r["overruns"], r["window_s"],
                                    r["floor_overruns"], r["step_mean_us"], r["step_max_us"], r["rtf_min"],
                                    "pass" if r["passed"] else "FAIL"))
    ROWS.extend(rows)
    log("%d process(es), N=%d: %s" % (shards, n, "pass" if passed else "FAIL"))
    return passed


def capacity(shards):
    """(largest passing N, smallest failing N) with the failing one within the resolution."""
    lo, hi = None, None
    n = ARGS.start
    while lo is None or hi is None:  # a bracket: doubling up from a pass, halving down from a failure
        if run(n, shards):
            lo = n
            n *= 2
        else:
            hi = n
            n //= 2
            if n < 100:
                return None, hi
        if lo is not None and hi is not None and lo > hi:
            lo = None
    while hi > lo * (1.0 + ARGS.resolution):
        mid = int(round(math.sqrt(lo * hi), -2))
        if mid <= lo or mid >= hi:
            break
        if run(mid, shards):
            lo = mid
        else:
            hi = mid
    return lo, hi


def main():
    import rospy
    os.sched_setaffinity(0, {ARGS.bench_cpu})
    procs = Processes()
    start = time.monotonic()
    try:
        start_master(procs, ARGS.port, ARGS.bench_cpu, LOG_DIR)
        rospy.init_node("shard_capacity_bench", disable_signals=True)
        os.sched_setaffinity(0, set(range(CORES)))  # the sharded runs leave no core to itself
        one = (ARGS.one_node, ARGS.one_node_failed) if ARGS.one_node else capacity(1)
        sharded = capacity(ARGS.shards)
    finally:
        procs.stop_all()
    ratio = sharded[0] / one[0] if one[0] and sharded[0] else float("nan")
    text = ("Capacity at rate 1000 Hz (boxes of 8 particles, torque-free, publish_rate 10, nobody "
            "subscribed; overruns within the machine's floor), %d cores, run took %.0f s:\n\n"
            "| processes | largest N held | smallest N failed |\n|---|---|---|\n"
            "| 1 node (core %d; script and master on core %d) | %s | %s |\n"
            "| %d shards (one per core; script and master share them) | %s | %s |\n\n"
            "Sharded / one node: %.2f\n" % (CORES, time.monotonic() - start, ARGS.node_cpu, ARGS.bench_cpu,
                                           one[0], one[1], ARGS.shards, sharded[0], sharded[1], ratio))
    print(text)
    write_results(ARGS.out, "shard_capacity", text, list(ROWS[0].keys()), ROWS)


if __name__ == "__main__":
    main()
