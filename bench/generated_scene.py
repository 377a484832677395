"""The scenes bench/node_load.py and bench/startup.py set on the parameter server: N generated
boxes."""

import math
import random


def make_scene(n_bodies, rate, publish_rate, per_body_topics, moving=True):
    """N boxes of 2x2x2 particles (8 each) on a grid, all turning and drifting unless not `moving`,
    gravity off. No status line (status_period 0): each log message costs roscpp O(topics); the
    benches read /diagnostics instead."""
    bodies = []
    side = max(1, int(math.ceil(n_bodies ** (1.0 / 3.0))))
    rng = random.Random(n_bodies)
    for i in range(n_bodies):
        x, y, z = i % side, (i // side) % side, i // (side * side)
        body = {"name": "b%d" % i, "shape": "box", "mass": 1.0, "size": [0.2, 0.15, 0.1],
                "resolution": 2, "position": [0.5 * x, 0.5 * y, 0.5 * z]}
        if moving:
            body["linear_velocity"] = [0.01, 0.0, 0.0]
            body["angular_velocity"] = [rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(1, 3)]
        bodies.append(body)
    return {"rate": float(rate), "publish_rate": float(publish_rate), "real_time_factor": 1.0,
            "gravity": [0.0, 0.0, 0.0], "status_period": 0.0, "per_body_topics": per_body_topics,
            "bodies": bodies}
