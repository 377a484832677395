"""Part 7 of bench/node_load.py: what ~record costs a node stepping at 1 kHz. The quadrotor of
config/quadrotor.yaml (falling: no controller) and 1,000 boxes each pushed as in part 5, at rate
1000 Hz with publish_rate 100 (each publish cycle's ~bodies and state hash recorded), once without
and once with ~record to a bag in the run's log directory."""

import os

import rospy
import yaml

from generated_scene import make_scene
from node_harness import REPO
from node_load_push import push_every_body
from node_load_run import NodeRun, machine_floor

RECORD_RATE_HZ = 1000
RECORD_PUBLISH_RATE_HZ = 100
RECORD_BODIES = 1000


def quadrotor_scene():
    """config/quadrotor.yaml at rate 1000 Hz, publish_rate 100; its URDF in /robot_description, where
    the node (in the root namespace) reads it."""
    with open(os.path.join(REPO, "config", "quadrotor.urdf")) as f:
        rospy.set_param("/robot_description", f.read())
    with open(os.path.join(REPO, "config", "quadrotor.yaml")) as f:
        scene = yaml.safe_load(f)
    scene.update({"rate": float(RECORD_RATE_HZ), "publish_rate": float(RECORD_PUBLISH_RATE_HZ),
                  "real_time_factor": 1.0, "status_period": 0.0})
    return scene


def record_run(bench, name, scene, pushed, bag, warmup, window):
    label = "%s_%s" % (name, "recorded" if bag else "unrecorded")
    if bag:
        scene = dict(scene, record=bag)
    n = len(scene["bodies"])
    with NodeRun(bench, scene, label) as run:
        held = push_every_body(bench, run, n) if pushed else {}
        r = run.measure(warmup, window)
        last = bench.diag.reports[-1][1]
    r.update(held)
    r["record_dropped"] = int(last.get("record_dropped", 0))
    r["note"] = str(last.get("record_error", ""))
    r["bag_mbyte"] = os.path.getsize(bag) / 1e6 if bag else 0.0
    if bag:
        os.remove(bag)
    r["floor_overruns"], r["floor_worst_us"] = machine_floor(bench, r["window_s"], r["step_mean_us"])
    passed = r["rtf_min"] >= 0.995 and r["record_dropped"] == 0 and not r["note"]
    bench.log("%s: RTF window %.4f, min %.3f, %d overruns in %.1f s (bare loop %d), step %.1f us, CPU %.0f%%, "
              "bag %.1f MB, %d dropped%s -> %s"
              % (label, r["rtf_window"], r["rtf_min"], r["overruns"], r["window_s"], r["floor_overruns"],
                 r["step_mean_us"], r["cpu_percent"], r["bag_mbyte"], r["record_dropped"],
                 ", " + r["note"] if r["note"] else "", "pass" if passed else "FAIL"))
    return bench.record(part=7, label=label, n_bodies=n, rate_hz=RECORD_RATE_HZ,
                        publish_rate_hz=RECORD_PUBLISH_RATE_HZ, subscribers="none", record=bool(bag),
                        passed=passed, load_ok=passed, **r)


def part_record(bench, quick):
    """Each scene without, then with ~record."""
    warmup, window = (1.0, 3.0) if quick else (3.0, 10.0)
    scenes = [("quadrotor", quadrotor_scene(), False),
              ("pushed_%d" % RECORD_BODIES,
               make_scene(RECORD_BODIES, RECORD_RATE_HZ, RECORD_PUBLISH_RATE_HZ, bench.per_body_topics), True)]
    rows = []
    for name, scene, pushed in scenes:
        for bag in (None, os.path.join(bench.log_dir, name + ".bag")):
            rows.append(record_run(bench, name, scene, pushed, bag, warmup, window))
    return rows
