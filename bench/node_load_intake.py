"""Part 3 of bench/node_load.py: particle wrenches per second taken in through ~particle_wrenches while
the rate holds."""

import io
import threading
import time

import rospy
from rigid_body_sim.msg import ParticleWrench, ParticleWrenchArray

from generated_scene import make_scene
from node_harness import NS
from node_load_run import NodeRun


class Preserialized(ParticleWrenchArray):
    """A ParticleWrenchArray serialised once; publish() then only copies bytes."""

    __slots__ = ["_bytes"]

    def __init__(self, msg):
        super().__init__()
        buff = io.BytesIO()
        msg.serialize(buff)
        self._bytes = buff.getvalue()

    def serialize(self, buff):
        buff.write(self._bytes)


def wrench_array(k, n_bodies):
    """K entries: first a marker (particle out of range, rejected: counts arrays taken),
    then K-1 valid world-axes forces spread over all bodies' particles."""
    wrenches = [ParticleWrench(body="b0", particle=999)]
    for j in range(k - 1):
        w = ParticleWrench(body="b%d" % (j % n_bodies), particle=(j // n_bodies) % 8)
        w.wrench.force.x = 1e-3 * ((j % 7) - 3)
        w.wrench.force.z = 1e-3
        wrenches.append(w)
    return Preserialized(ParticleWrenchArray(wrenches=wrenches))


def publish_at(pub, msg, hz, duration_s, stop):
    """Publishes msg at hz for duration_s; returns (sent, elapsed, busy seconds)."""
    period = 1.0 / hz
    t_start = time.monotonic()
    t_next = t_start
    sent, busy = 0, 0.0
    while not stop.is_set():
        now = time.monotonic()
        if now - t_start >= duration_s:
            break
        if now < t_next:
            time.sleep(t_next - now)
            continue
        b0 = time.monotonic()
        pub.publish(msg)
        busy += time.monotonic() - b0
        sent += 1
        t_next += period
        if t_next < time.monotonic() - 10 * period:  # far behind: do not burst
            t_next = time.monotonic()
    return sent, time.monotonic() - t_start, busy


def intake_run(bench, n_bodies, k, hz, warmup, window):
    msg = wrench_array(k, n_bodies)
    pub = rospy.Publisher(NS + "/particle_wrenches", ParticleWrenchArray, queue_size=1000, tcp_nodelay=True)
    scene = make_scene(n_bodies, 1000, 100, bench.per_body_topics)
    with NodeRun(bench, scene, "intake_%d_%d" % (k, int(hz))) as run:
        deadline = time.monotonic() + 10
        while pub.get_num_connections() == 0 and time.monotonic() < deadline:
            time.sleep(0.05)
        time.sleep(0.3)
        stop = threading.Event()
        stats = {}
        total = warmup + window + 2.5

        def publisher():
            stats["sent"], stats["elapsed"], stats["busy"] = publish_at(pub, msg, hz, total, stop)

        thread = threading.Thread(target=publisher, daemon=True)
        thread.start()
        try:
            r = run.measure(warmup, window)
        finally:
            stop.set()
            thread.join()
    pub.unregister()
    arrays = r["rejected_marker"]
    # every entry not taken (marker, any past the node's per-array cap) is counted as rejected
    taken = arrays * k - r["rejected"]
    r["pub_msgs_per_s"] = stats["sent"] / stats["elapsed"]
    r["pub_busy_percent"] = 100.0 * stats["busy"] / stats["elapsed"]
    r["wrenches_sent_per_s"] = r["pub_msgs_per_s"] * (k - 1)
    r["wrenches_taken_per_s"] = taken / r["window_s"]
    arrays_per_s = arrays / r["window_s"]
    kept_up = arrays_per_s >= 0.97 * r["pub_msgs_per_s"]
    all_taken = taken >= 0.99 * arrays * (k - 1)
    held = r["rtf_min"] >= 0.99 and kept_up and all_taken
    notes = []
    if not kept_up:
        notes.append("node took %.0f of %.0f arrays/s" % (arrays_per_s, r["pub_msgs_per_s"]))
    if not all_taken:
        notes.append("entries past the per-array cap rejected")
    if r["pub_msgs_per_s"] < 0.97 * hz:
        notes.append("publisher reached only %.0f of %.0f Hz" % (r["pub_msgs_per_s"], hz))
    bench.log("intake K=%d at %.0f Hz: sent %.0f wrenches/s (publisher %.0f Hz, busy %.0f%%), node took %.0f/s, "
              "%d overruns, RTF min %.3f, step %.1f us, CPU %.0f%%, load %.2f -> %s"
              % (k, hz, r["wrenches_sent_per_s"], r["pub_msgs_per_s"], r["pub_busy_percent"],
                 r["wrenches_taken_per_s"], r["overruns"], r["rtf_min"], r["step_mean_us"], r["cpu_percent"],
                 r["loadavg1"], "held" if held else "NOT held"))
    return bench.record(part=3, label="wrench intake", n_bodies=n_bodies, rate_hz=1000, publish_rate_hz=100,
                        subscribers="none", entries_per_msg=k, msgs_hz=hz, passed=held,
                        note="; ".join(notes), **r)


def part_intake(bench, quick, budget_end):
    n_bodies = 100
    warmup, window = (1.0, 3.0) if quick else (2.0, 6.0)
    plan = [(1000, 100.0), (10000, 100.0)] if quick else [(1000, 100.0), (10000, 100.0), (3000, 1000.0)]
    rows = []
    for k, hz in plan:
        if rows and time.monotonic() > budget_end:
            bench.log("intake scan stopped: time budget")
            break
        rows.append(intake_run(bench, n_bodies, k, hz, warmup, window))
    return rows
