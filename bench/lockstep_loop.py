#!/usr/bin/python3
"""The cost of lockstep: a node in lockstep with a trivial Python controller
(rigid_body_sim.testing.LockstepController answering every cycle with no
wrench) at real_time_factor 0, against the same node running free.

Scene: --bodies generated boxes (8 particles each), rate 1000 Hz. Cases:

  free_every_step      no lockstep, publish_rate 1000, ~bodies subscribed by
                       this script (the same messages as the lockstep case)
  lockstep_every_step  lockstep, publish_rate 1000: one step per cycle
  lockstep_every_10    lockstep, publish_rate 100: ten steps per cycle

For each: steps per second of simulation from the node's diagnostics
(`steps` over --window seconds of wall time), cycles per second, wall µs per
cycle, and the lockstep overhead per cycle = µs per cycle in lockstep − µs
per step free (both publishing every step). The node runs on --node-cpu, this
script (controller) and a private master on --bench-cpu.

Writes bench/results/lockstep_loop.md (also printed).

  bench/lockstep_loop.py [--bodies 1] [--window 5] [--workspace PATH] [--port 11398] [--out DIR]
"""

import argparse
import os
import sys
import tempfile
import time

from node_harness import NODE_NAME, NS, Processes, add_node_bench_arguments, devel_program


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bodies", type=int, default=1, help="generated boxes in the scene (default 1)")
    parser.add_argument("--window", type=float, default=5.0, help="measuring window [s] (default 5)")
    add_node_bench_arguments(parser, 11398, "lockstep_loop.md")
    return parser.parse_args()


ARGS = parse_args()
CASES = [("free_every_step", False, 1000.0), ("lockstep_every_step", True, 1000.0),
         ("lockstep_every_10", True, 100.0)]


def scene(lockstep, publish_rate, controller):
    bodies = [{"name": "b%d" % i, "shape": "box", "mass": 1.0, "size": [0.2, 0.15, 0.1], "resolution": 2,
               "position": [0.5 * i, 0.0, 0.0], "angular_velocity": [0.3, 2.0, -0.1]}
              for i in range(ARGS.bodies)]
    params = {"rate": 1000.0, "publish_rate": publish_rate, "real_time_factor": 0.0, "status_period": 0.0,
              "per_body_topics": False, "bodies": bodies}
    if lockstep:
        params.update({"lockstep": True, "lockstep_publishers": [controller], "lockstep_timeout": 5.0})
    return params


def measure(procs, log_dir, name, lockstep, publish_rate):
    import rospy
    from node_harness import Diagnostics
    from rigid_body_sim.testing import LockstepController
    rospy.set_param(NS, scene(lockstep, publish_rate, rospy.get_name()))
    diag = Diagnostics()
    cycles = [0]

    def count(msg_or_states, _stamp=None):
        cycles[0] += 1
        return []

    if lockstep:
        helper = LockstepController(count, NS)
    else:
        helper = rospy.Subscriber(NS + "/bodies", rospy.AnyMsg, count, queue_size=100, tcp_nodelay=True)
    node = procs.start(["taskset", "-c", str(ARGS.node_cpu),
                        devel_program(os.environ["RBS_BENCH_WS"], "rigid_body_sim_node"),
                        "__name:=" + NODE_NAME], os.path.join(log_dir, name + ".log"))

    def alive():
        return node.poll() is None

    first = diag.wait_next(30.0, alive)  # the first report: the node steps
    start = diag.wait_next(10.0, alive)
    cycles0 = cycles[0]
    time.sleep(ARGS.window)
    end = diag.wait_next(10.0, alive)
    cycles1 = cycles[0]
    if first is None or start is None or end is None:
        sys.exit("%s: no diagnostics from the node (log in %s)" % (name, log_dir))
    wall = end[0] - start[0]
    steps_per_s = (end[1]["steps"] - start[1]["steps"]) / wall
    cycles_per_s = (cycles1 - cycles0) / wall
    procs.stop(node)
    if lockstep:
        helper.stop()
    else:
        helper.unregister()
    return {"case": name, "steps_per_s": steps_per_s, "cycles_per_s": cycles_per_s,
            "us_per_cycle": 1e6 / cycles_per_s if cycles_per_s > 0 else float("inf"),
            "timeouts": end[1].get("lockstep_timeouts", 0.0)}


def main():
    from node_harness import reexec_in_workspace, start_master
    reexec_in_workspace(ARGS.workspace, ARGS.port)
    os.sched_setaffinity(0, {ARGS.bench_cpu})
    log_dir = tempfile.mkdtemp(prefix="lockstep_loop_")
    procs = Processes()
    try:
        start_master(procs, ARGS.port, ARGS.bench_cpu, log_dir)
        import rospy
        rospy.init_node("lockstep_bench", disable_signals=True)
        rows = [measure(procs, log_dir, *case) for case in CASES]
    finally:
        procs.stop_all()
    free = rows[0]
    lines = ["| case | steps/s | cycles/s | µs per cycle | lockstep timeouts |", "|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %.0f | %.0f | %.1f | %d |" % (r["case"], r["steps_per_s"], r["cycles_per_s"],
                                                         r["us_per_cycle"], r["timeouts"]))
    overhead = rows[1]["us_per_cycle"] - 1e6 / free["steps_per_s"]
    text = ("Lockstep at real_time_factor 0, %d bodies of 8 particles, rate 1000 Hz, window %.0f s, "
            "node on core %d, controller (Python) and master on core %d.\n\n%s\n\n"
            "Lockstep overhead per cycle: %.1f µs (µs per cycle in lockstep_every_step − µs per step "
            "in free_every_step).\n" % (ARGS.bodies, ARGS.window, ARGS.node_cpu, ARGS.bench_cpu,
                                        "\n".join(lines), overhead))
    print(text)
    os.makedirs(ARGS.out, exist_ok=True)
    with open(os.path.join(ARGS.out, "lockstep_loop.md"), "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
