"""Part 2 of bench/node_load.py: the node's CPU use with /tf and ~bodies at 100 Hz, both subscribed."""

import threading
import time

import rospy

from generated_scene import make_scene
from node_harness import NS
from node_load_run import NodeRun


class RawCounter:
    """Counts messages and bytes on a topic without deserialising them."""

    def __init__(self, topic, nodelay=False):
        self.count, self.nbytes = 0, 0
        self.lock = threading.Lock()
        self.sub = rospy.Subscriber(topic, rospy.AnyMsg, self._on_msg, queue_size=100, tcp_nodelay=nodelay)

    def _on_msg(self, msg):
        with self.lock:
            self.count += 1
            self.nbytes += len(msg._buff)

    def snapshot(self):
        with self.lock:
            return self.count, self.nbytes

    def close(self):
        self.sub.unregister()


def part_cpu(bench, quick):
    warmup, window = (1.0, 3.0) if quick else (2.0, 10.0)
    out = []
    for n in (100, 1000):
        tf = RawCounter("/tf")
        bodies = RawCounter(NS + "/bodies")
        with NodeRun(bench, make_scene(n, 1000, 100, bench.per_body_topics), "cpu_%d" % n) as run:
            time.sleep(1.0)  # let the subscribers connect
            c0, c1 = tf.snapshot(), bodies.snapshot()
            t0 = time.monotonic()
            r = run.measure(warmup, window)
            t1 = time.monotonic()
            c0b, c1b = tf.snapshot(), bodies.snapshot()
        tf.close()
        bodies.close()
        # counts over measure() incl. its warm-up: rates only
        r["tf_msgs_per_s"] = (c0b[0] - c0[0]) / (t1 - t0)
        r["bodies_msgs_per_s"] = (c1b[0] - c1[0]) / (t1 - t0)
        r["rx_mbyte_per_s"] = ((c0b[1] - c0[1]) + (c1b[1] - c1[1])) / (t1 - t0) / 1e6
        bench.log("cpu N=%d: node CPU %.1f%% of one core, /tf %.0f/s, ~bodies %.0f/s (%.1f MB/s), "
                  "%d overruns, step %.1f us, core other %.0f%%, load %.2f"
                  % (n, r["cpu_percent"], r["tf_msgs_per_s"], r["bodies_msgs_per_s"], r["rx_mbyte_per_s"],
                     r["overruns"], r["step_mean_us"], r["core_other_percent"], r["loadavg1"]))
        out.append(bench.record(part=2, label="cpu", n_bodies=n, rate_hz=1000, publish_rate_hz=100,
                                subscribers="/tf, ~bodies", passed=r["overruns"] == 0, **r))
    return out
