"""Part 4 of bench/node_load.py: the latency from a ParticleWrench to the first ~bodies message that
reflects it."""

import os
import random
import statistics
import threading
import time

import rospy
from rigid_body_sim.msg import BodyStateArray, ParticleWrench

from generated_scene import make_scene
from node_harness import NS, CpuWindow
from node_load_run import NodeRun


class MomentumWatcher:
    def __init__(self):
        self.cond = threading.Condition()
        self.latest = None  # (recv time, p tuple, stamp seconds)
        self.sub = rospy.Subscriber(NS + "/bodies", BodyStateArray, self._on_msg, queue_size=100,
                                    tcp_nodelay=True)

    def _on_msg(self, msg):
        now = time.time()
        p = msg.bodies[0].linear_momentum
        with self.cond:
            self.latest = (now, (p.x, p.y, p.z), msg.header.stamp.to_sec())
            self.cond.notify_all()

    def wait(self, predicate, timeout):
        deadline = time.monotonic() + timeout
        with self.cond:
            while self.latest is None or not predicate(self.latest):
                remaining = deadline - time.monotonic()
                if remaining <= 0:
                    return None
                self.cond.wait(remaining)
            return self.latest

    def close(self):
        self.sub.unregister()


def latency_run(bench, publish_rate, trials):
    scene = make_scene(1, 1000, publish_rate, bench.per_body_topics, moving=False)
    watcher = MomentumWatcher()
    pub = rospy.Publisher(NS + "/particle_wrench", ParticleWrench, queue_size=10, tcp_nodelay=True)
    latencies, lags = [], []
    with NodeRun(bench, scene, "latency_%d" % publish_rate) as run:
        deadline = time.monotonic() + 10
        while pub.get_num_connections() == 0 and time.monotonic() < deadline:
            time.sleep(0.05)
        if watcher.wait(lambda s: True, 10) is None:
            raise RuntimeError("no ~bodies messages")
        time.sleep(0.5)
        cpu = CpuWindow(run.proc.pid, bench.args.node_cpu)
        rng = random.Random(1)
        for i in range(trials):
            # settle: a message after the last change, then a random phase
            time.sleep(rng.uniform(0.02, 0.05))
            ref = watcher.wait(lambda s: True, 2)
            p_ref = ref[1]
            msg = ParticleWrench(body="b0", particle=0)
            msg.wrench.force.x = 1.0 if i % 2 == 0 else -1.0
            t_send = time.time()
            pub.publish(msg)

            def changed(s, t_send=t_send, p_ref=p_ref):
                return s[0] >= t_send and max(abs(a - b) for a, b in zip(s[1], p_ref)) > 1e-9

            got = watcher.wait(changed, 2.0)
            stop_msg = ParticleWrench(body="b0", particle=0)  # zero force replaces it
            pub.publish(stop_msg)
            if got is None:
                bench.log("latency trial %d: no change seen within 2 s" % i)
                continue
            latencies.append(1e3 * (got[0] - t_send))
            lags.append(1e3 * (got[2] - t_send))
            # wait until the momentum is constant again (two consecutive equal messages)
            prev = got
            for _ in range(200):
                s = watcher.wait(lambda s, prev=prev: s[0] > prev[0], 1.0)
                if s is None or s[1] == prev[1]:
                    break
                prev = s
        cpu_r = cpu.finish()
    watcher.close()
    pub.unregister()
    latencies.sort()
    n = len(latencies)
    r = {
        "latency_median_ms": statistics.median(latencies) if n else float("nan"),
        "latency_p90_ms": latencies[min(n - 1, int(0.9 * n))] if n else float("nan"),
        "latency_min_ms": latencies[0] if n else float("nan"),
        "latency_max_ms": latencies[-1] if n else float("nan"),
        "stamp_lag_median_ms": statistics.median(lags) if n else float("nan"),
        "trials": n, "loadavg1": os.getloadavg()[0], "startup_s": run.startup_s, **cpu_r,
    }
    bound = 1e3 / publish_rate + 1.0
    bench.log("latency publish_rate %d: median %.2f ms (p90 %.2f, min %.2f, max %.2f) over %d trials; "
              "1/publish_rate + 1/rate = %.1f ms; stamp - send median %.2f ms; load %.2f"
              % (publish_rate, r["latency_median_ms"], r["latency_p90_ms"], r["latency_min_ms"],
                 r["latency_max_ms"], n, bound, r["stamp_lag_median_ms"], r["loadavg1"]))
    return bench.record(part=4, label="latency", n_bodies=1, rate_hz=1000, publish_rate_hz=publish_rate,
                        subscribers="~bodies", passed=n >= trials * 0.9, **r)


def part_latency(bench, quick):
    rates = [1000] if quick else [100, 1000]
    trials = 20 if quick else 40
    return [latency_run(bench, rate, trials) for rate in rates]
