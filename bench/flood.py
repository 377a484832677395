#!/usr/bin/python3
"""Flood test: the node on the default scene at
rate 1000 takes ARRAYS wrenches/s in ParticleWrenchArray messages and
SINGLES/s single ParticleWrench messages from another process (bench's
wrench_flood) for DURATION s. Reports the rate held (overruns and achieved
real-time factor from /diagnostics), the node's memory over time, and checks
that each particle holds the last wrench sent to it.

usage: flood.py [--workspace WS] [--arrays 100000] [--singles 20000] [--duration 30]

The script runs itself again in the workspace's environment (devel/setup.bash
sourced, bench/node_harness.py); roslaunch starts the master on --port.
"""
import argparse
import os
import subprocess
import sys
import time

from node_harness import (REPO, Diagnostics, add_workspace_argument, devel_program, launch_default_scene,
                          node_pid, reexec_in_workspace, rss_kib, stop_launch, wait_for_scene)

parser = argparse.ArgumentParser()
add_workspace_argument(parser)
parser.add_argument("--arrays", type=float, default=100000, help="wrenches/s sent in arrays")
parser.add_argument("--entries", type=int, default=100, help="entries per array")
parser.add_argument("--singles", type=float, default=20000, help="single messages/s")
parser.add_argument("--duration", type=float, default=30.0)
parser.add_argument("--port", type=int, default=11421)
parser.add_argument("--out", default=os.path.join(REPO, "bench", "results", "flood.md"))
args = parser.parse_args()
workspace = reexec_in_workspace(args.workspace, args.port)


def main():
    """Floods the node, checks the held wrenches and writes the report."""
    # The package's messages import once the script runs in the workspace's environment.
    import rospy
    from rigid_body_sim.msg import BodyStateArray
    from rigid_body_sim.srv import Step
    from std_srvs.srv import SetBool

    wrench_flood = devel_program(workspace, "wrench_flood")
    launch = launch_default_scene(args.port)
    try:
        rospy.init_node("flood_driver", anonymous=True)
        diagnostics = Diagnostics()
        latest = diagnostics.latest  # the node's newest "simulation" status
        names, counts = wait_for_scene()
        pid = node_pid()

        while "overruns" not in latest:
            time.sleep(0.2)
        overruns_before = int(latest["overruns"])
        rate_per_array = args.arrays / args.entries
        flood = subprocess.Popen([wrench_flood, "top", str(counts["top"]),
                                  str(rate_per_array), str(args.entries), "box", str(counts["box"]),
                                  str(args.singles), str(args.duration)],
                                 stdout=subprocess.PIPE, text=True)
        rss, factors = [], []
        while flood.poll() is None:
            time.sleep(1.0)
            rss.append(rss_kib(pid))
            factors.append(float(latest.get("real_time_factor_achieved", "nan")))
        report = flood.stdout.read().splitlines()
        sent_line = report[0]
        last = {}
        for line in report[1:]:
            _, body, particle, force = line.split()
            last.setdefault(body, 0.0)
            last[body] += float(force)
        time.sleep(2.0)
        overruns = int(latest["overruns"]) - overruns_before

        # Each body's held force is the sum of the last force.x per particle (world
        # x): the momentum change between two single steps, over dt.
        published = {}
        rospy.Subscriber("/rigid_body_sim/bodies", BodyStateArray,
                         lambda m: published.update({round(m.header.stamp.to_sec(), 6): m}))
        time.sleep(1.0)
        rospy.ServiceProxy("/rigid_body_sim/set_paused", SetBool)(True)
        step = rospy.ServiceProxy("/rigid_body_sim/step", Step)

        def stepped_state():
            stamp = round(step(1).sim_time, 6)
            deadline = time.time() + 5.0
            while stamp not in published and time.time() < deadline:
                time.sleep(0.01)
            return published[stamp]

        before = stepped_state()
        after = stepped_state()
        dt = 1e-3
        checks = []
        for body in ("top", "box"):
            i = names.index(body)
            held = (after.bodies[i].linear_momentum.x - before.bodies[i].linear_momentum.x) / dt
            checks.append((body, last[body], held, abs(held - last[body]) <= 1e-9 * max(1.0, abs(last[body]))))

        half = len(rss) // 2
        lines = [
            "| figure | value |", "|---|---|",
            "| load sent | %s |" % sent_line,
            "| overruns during the flood | %d |" % overruns,
            "| achieved real-time factor (min, median over 1 s windows) | %.3f, %.3f |" % (
                min(factors), sorted(factors)[len(factors) // 2]),
            "| node RSS first half max / second half max [KiB] | %d / %d |" % (max(rss[:half]), max(rss[half:])),
            "| node RSS start / end [KiB] | %d / %d |" % (rss[0], rss[-1]),
        ]
        for body, expected, held, ok in checks:
            lines.append("| `%s` held force x, last sent / measured [N] | %.9g / %.9g (%s) |" % (
                body, expected, held, "ok" if ok else "MISMATCH"))
        lines.append("| load average at the end | %s |" % open("/proc/loadavg").read().split()[0])
        text = "\n".join(lines) + "\n"
        print(text)
        os.makedirs(os.path.dirname(args.out), exist_ok=True)
        open(args.out, "w").write(text)
        sys.exit(0 if all(c[3] for c in checks) else 1)
    finally:
        stop_launch(launch)


if __name__ == "__main__":
    main()
