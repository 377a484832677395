#!/usr/bin/python3
"""Soak test, in one of two modes.

Wrenches (the default): the node on the default scene at rate 1000 for
DURATION s (default 1 h) under random wrenches, valid and invalid (NaN,
infinite, unknown body, particle out of range, unknown frame), on every body
but `t_handle`, which stays torque-free so its |L| and energy drift stay
measurable. Every minute: node RSS, overruns, rejected messages, t_handle's
drift (from /diagnostics) and the worst |q| − 1 seen on ~bodies. Fails if the
node dies, if RSS grows by more than MAX_GROWTH KiB after the first minute, or
if a published quaternion is off unit length by more than 1e-12.

Spawn and delete (--spawn-delete): the node on the default scene (with
~per_body_topics as given) takes CYCLES ~spawn_body + ~delete_body pairs of a
small box, back to back over two persistent service connections, each cycle's
body named anew (soak_<k>); node RSS every SAMPLE_EVERY cycles and once more
SETTLE s after the last. Prints the first, last and after RSS and the growth
per cycle; fails if the node dies, a call is refused, or RSS after the cycles
exceeds the first sample (before any cycle) by more than MAX_GROWTH KiB.
--node-prefix runs the node under a tool, e.g. "heaptrack -o /tmp/sd".

usage: soak.py [--workspace WS] [--duration 3600] [--rate 200] [--max-growth 1024]
       soak.py --spawn-delete [--cycles 100000] [--sample-every 1000] [--settle 10]
               [--per-body-topics true|false] [--node-prefix CMD] [--max-growth 1024]

The script runs itself again in the workspace's environment (devel/setup.bash
sourced, bench/node_harness.py); roslaunch (wrenches) or the script (spawn and
delete) starts the master on --port.
"""
import argparse
import math
import os
import random
import shlex
import sys
import tempfile
import time

import yaml

from node_harness import (NODE_NAME, NS, REPO, Diagnostics, Processes, add_workspace_argument, devel_program,
                          launch_default_scene, node_pid, reexec_in_workspace, rss_kib, start_master, stop_launch,
                          wait_for_scene)

parser = argparse.ArgumentParser()
add_workspace_argument(parser)
parser.add_argument("--duration", type=float, default=3600.0)
parser.add_argument("--rate", type=float, default=200.0, help="wrench messages per second")
parser.add_argument("--spawn-delete", action="store_true", help="spawn and delete bodies instead of wrenches")
parser.add_argument("--cycles", type=int, default=100000, help="spawn + delete pairs (--spawn-delete)")
parser.add_argument("--sample-every", type=int, default=1000, help="cycles between RSS samples (--spawn-delete)")
parser.add_argument("--settle", type=float, default=10.0,
                    help="s from the last cycle to the after sample (--spawn-delete)")
parser.add_argument("--per-body-topics", choices=["true", "false"], default="true",
                    help="the node's ~per_body_topics (--spawn-delete)")
parser.add_argument("--node-prefix", default="", help="words before the node's command (--spawn-delete)")
parser.add_argument("--max-growth", type=int, default=1024, help="RSS growth [KiB] that fails the soak")
parser.add_argument("--port", type=int, default=11431)
parser.add_argument("--out", default=None,
                    help="report (default bench/results/soak.md, or soak_spawn_delete.md with --spawn-delete)")
args = parser.parse_args()
workspace = reexec_in_workspace(args.workspace, args.port)
if args.out is None:
    args.out = os.path.join(REPO, "bench", "results", "soak_spawn_delete.md" if args.spawn_delete else "soak.md")


SMALL_BOX = ("{name: %s, shape: box, mass: 1.0, size: [0.1, 0.1, 0.1], resolution: 2, "
             "position: [0.0, 0.0, 2.0]}")


def write_report(text):
    print(text)
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    open(args.out, "w").write(text)


def spawn_delete_soak():
    """Spawns and deletes a small box --cycles times; fails on RSS growth."""
    # The package's messages import once the script runs in the workspace's environment.
    import rospy
    from rigid_body_sim.srv import DeleteBody, SpawnBody

    procs = Processes()
    log_dir = tempfile.mkdtemp(prefix="soak_logs_")
    try:
        start_master(procs, args.port, 0, log_dir)
        rospy.init_node("soak_driver", anonymous=True)
        scene = yaml.safe_load(open(os.path.join(REPO, "config", "default_scene.yaml")))
        scene["per_body_topics"] = args.per_body_topics == "true"
        rospy.set_param(NS, scene)
        node = procs.start(shlex.split(args.node_prefix) +
                           [devel_program(workspace, "rigid_body_sim_node"), "__name:=" + NODE_NAME],
                           os.path.join(log_dir, "node.log"))
        rospy.wait_for_service(NS + "/spawn_body", timeout=60)
        rospy.wait_for_service(NS + "/delete_body", timeout=10)
        pid = node_pid()
        spawn = rospy.ServiceProxy(NS + "/spawn_body", SpawnBody, persistent=True)
        delete = rospy.ServiceProxy(NS + "/delete_body", DeleteBody, persistent=True)
        rows = [(0, time.monotonic(), rss_kib(pid))]
        print("%8d cycles  RSS %d KiB" % (0, rows[0][2]), flush=True)
        for k in range(1, args.cycles + 1):
            name = "soak_%d" % k
            for call, request in ((spawn, SMALL_BOX % name), (delete, name)):
                response = call(request)
                if not response.success:
                    sys.exit("cycle %d: %s" % (k, response.message))
            if k % args.sample_every == 0 or k == args.cycles:
                rows.append((k, time.monotonic(), rss_kib(pid)))
                print("%8d cycles  RSS %d KiB  %.2f ms/cycle" % (
                    k, rows[-1][2], 1e3 * (rows[-1][1] - rows[-2][1]) / (k - rows[-2][0])), flush=True)
        spawn.close()
        delete.close()
        time.sleep(args.settle)
        if node.poll() is not None:
            sys.exit("the node died (log: %s)" % log_dir)
        after = rss_kib(pid)
        first, last = rows[0][2], rows[-1][2]
        growth = after - first
        lines = ["| cycles | RSS [KiB] |", "|---|---|"]
        lines += ["| %d | %d |" % (r[0], r[2]) for r in rows]
        lines.append("| %.0f s after | %d |" % (args.settle, after))
        lines.append("")
        lines.append("%d spawn + delete cycles of a small box (per_body_topics %s), %.2f ms a cycle; RSS first %d, "
                     "last %d, %.0f s after %d KiB: %+d KiB, %.1f bytes a cycle; load average at the end: %s" % (
                         args.cycles, args.per_body_topics, 1e3 * (rows[-1][1] - rows[0][1]) / args.cycles,
                         first, last, args.settle, after, growth, 1024.0 * (last - first) / args.cycles,
                         open("/proc/loadavg").read().split()[0]))
        write_report("\n".join(lines) + "\n")
        return 0 if growth <= args.max_growth else 1
    finally:
        procs.stop_all()


def wrench_soak():
    """Sends random (partly invalid) wrenches to the default scene for --duration s; fails on RSS growth or
    a quaternion off unit length."""
    import rospy
    from rigid_body_sim.msg import BodyStateArray, ParticleWrench

    launch = launch_default_scene(args.port)
    try:
        rospy.init_node("soak_driver", anonymous=True)
        diagnostics = Diagnostics()
        latest = diagnostics.latest  # the node's newest "simulation" status
        worst_norm = [0.0]

        def on_bodies(message):
            for body in message.bodies:
                q = body.pose.orientation
                worst_norm[0] = max(worst_norm[0], abs(math.sqrt(q.x**2 + q.y**2 + q.z**2 + q.w**2) - 1.0))
        rospy.Subscriber("/rigid_body_sim/bodies", BodyStateArray, on_bodies)
        names, counts = wait_for_scene()
        pushed = [n for n in names if n != "t_handle"]
        pid = node_pid()
        publisher = rospy.Publisher("/rigid_body_sim/particle_wrench", ParticleWrench, queue_size=1000)
        rng = random.Random(20261122)

        def random_wrench():
            message = ParticleWrench()
            message.body = rng.choice(pushed)
            message.particle = rng.randrange(counts[message.body])
            message.header.frame_id = rng.choice(["", "world", message.body])
            f = message.wrench.force
            f.x, f.y, f.z = (rng.uniform(-1, 1) for _ in range(3))
            kind = rng.random()
            if kind < 0.05:
                f.x = float("nan")
            elif kind < 0.10:
                f.y = float("inf")
            elif kind < 0.15:
                message.body = "no_such_body"
            elif kind < 0.20:
                message.particle = counts[message.body] + rng.randrange(100)
            elif kind < 0.25:
                message.header.frame_id = "no_such_frame"
            elif kind < 0.30:
                f.x = f.y = f.z = 0.0  # release: keeps the bodies from spinning up forever
            return message

        start = time.time()
        next_report = start + 60.0
        rows = []
        period = 1.0 / args.rate
        sent = 0
        while time.time() - start < args.duration:
            if launch.poll() is not None or not os.path.exists("/proc/%d" % pid):
                print("node died after %.0f s" % (time.time() - start))
                sys.exit(1)
            publisher.publish(random_wrench())
            sent += 1
            time.sleep(period)
            if time.time() >= next_report:
                next_report += 60.0
                rows.append((time.time() - start, rss_kib(pid), latest.get("overruns", "?"),
                             latest.get("rejected_messages", "?"),
                             latest.get("t_handle/angular_momentum_drift", "?"),
                             latest.get("t_handle/rotational_energy_drift", "?"), worst_norm[0]))
                print("%6.0f s  RSS %d KiB  overruns %s  rejected %s  t_handle |L| drift %s  energy drift %s  "
                      "worst | |q|-1 | %.1e" % rows[-1], flush=True)
        growth = max(r[1] for r in rows[1:]) - rows[0][1] if len(rows) > 1 else 0
        lines = ["| minute | RSS [KiB] | overruns | rejected | t_handle \\|L\\| drift | energy drift "
                 "| worst \\| \\|q\\| − 1 \\| |",
                 "|---|---|---|---|---|---|---|"]
        lines += ["| %.0f | %d | %s | %s | %s | %s | %.1e |" % ((r[0] / 60.0,) + r[1:]) for r in rows]
        lines.append("")
        lines.append("%d wrench messages sent (%.0f/s, ~25 %% invalid); RSS growth after the first minute: %d KiB; "
                     "load average at the end: %s" % (sent, args.rate, growth, open("/proc/loadavg").read().split()[0]))
        write_report("\n".join(lines) + "\n")
        sys.exit(0 if growth <= args.max_growth and worst_norm[0] <= 1e-12 else 1)
    finally:
        stop_launch(launch)


if __name__ == "__main__":
    sys.exit(spawn_delete_soak() if args.spawn_delete else wrench_soak())
