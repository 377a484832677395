#!/usr/bin/python3
"""Soak test: the node on the default scene at
rate 1000 for DURATION s (default 1 h) under random wrenches, valid and
invalid (NaN, infinite, unknown body, particle out of range, unknown frame),
on every body but `t_handle`, which stays torque-free so its |L| and energy
drift stay measurable. Every minute: node RSS, overruns, rejected messages,
t_handle's drift (from /diagnostics) and the worst |q| − 1 seen on ~bodies.
Fails if the node dies, if RSS grows by more than 1 MiB after the first
minute, or if a published quaternion is off unit length by more than 1e-12.

usage: soak.py [--workspace WS] [--duration 3600] [--rate 200]

The script runs itself again in the workspace's environment (devel/setup.bash
sourced, bench/node_harness.py); roslaunch starts the master on --port.
"""
import argparse
import math
import os
import random
import sys
import time

from node_harness import (REPO, Diagnostics, add_workspace_argument, launch_default_scene, node_pid,
                          reexec_in_workspace, rss_kib, stop_launch, wait_for_scene)

parser = argparse.ArgumentParser()
add_workspace_argument(parser)
parser.add_argument("--duration", type=float, default=3600.0)
parser.add_argument("--rate", type=float, default=200.0, help="wrench messages per second")
parser.add_argument("--port", type=int, default=11431)
parser.add_argument("--out", default=os.path.join(REPO, "bench", "results", "soak.md"))
args = parser.parse_args()
reexec_in_workspace(args.workspace, args.port)

import rospy  # noqa: E402  (in the workspace's environment)
from rigid_body_sim.msg import BodyStateArray, ParticleWrench  # noqa: E402

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
    lines = ["| minute | RSS [KiB] | overruns | rejected | t_handle \\|L\\| drift | energy drift | worst \\| \\|q\\| − 1 \\| |",
             "|---|---|---|---|---|---|---|"]
    lines += ["| %.0f | %d | %s | %s | %s | %s | %.1e |" % ((r[0] / 60.0,) + r[1:]) for r in rows]
    lines.append("")
    lines.append("%d wrench messages sent (%.0f/s, ~25 %% invalid); RSS growth after the first minute: %d KiB; "
                 "load average at the end: %s" % (sent, args.rate, growth, open("/proc/loadavg").read().split()[0]))
    text = "\n".join(lines) + "\n"
    print(text)
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    open(args.out, "w").write(text)
    sys.exit(0 if growth <= 1024 and worst_norm[0] <= 1e-12 else 1)
finally:
    stop_launch(launch)
