"""Parts 1 and 5 of bench/node_load.py: the largest number of bodies stepped at rate 1000 with no
overruns beyond this machine's noise, free (1) and each pushed by one held force (5)."""

import math
import time

from generated_scene import make_scene
from node_load_push import push_every_body
from node_load_run import NOISE_OVERRUNS_PER_S, NodeRun, machine_floor


def capacity_run(bench, n, warmup, window, pushed=False):
    label = "pushed" if pushed else "capacity"
    with NodeRun(bench, make_scene(n, 1000, 10, bench.per_body_topics), "%s_%d" % (label, n)) as run:
        held = push_every_body(bench, run, n) if pushed else {}
        r = run.measure(warmup, window)
    r.update(held)
    r["floor_overruns"], r["floor_worst_us"] = machine_floor(bench, r["window_s"], r["step_mean_us"])
    passed = r["overruns"] == 0 and r["rtf_min"] >= 0.99
    # Within noise: no more than 1/s, or than twice what the bare loop got in the same time.
    load_ok = (r["overruns"] <= max(NOISE_OVERRUNS_PER_S * r["window_s"], 2 * r["floor_overruns"])
               and r["catch_up_limit_hits"] == 0 and r["rtf_min"] >= 0.99)
    bench.log("%s N=%d: %d overruns in %.1f s (bare loop, same step time: %d), step %.1f us (max %.0f), "
              "RTF min %.3f, CPU %.0f%%, core %d other %.0f%%, load %.2f, first report %.1f s -> %s"
              % (label, n, r["overruns"], r["window_s"], r["floor_overruns"], r["step_mean_us"], r["step_max_us"],
                 r["rtf_min"], r["cpu_percent"], bench.args.node_cpu, r["core_other_percent"], r["loadavg1"],
                 r["startup_s"], "pass" if passed else ("pass within noise" if load_ok else "FAIL")))
    return bench.record(part=5 if pushed else 1, label=label, n_bodies=n, rate_hz=1000, publish_rate_hz=10,
                        subscribers="none", passed=passed, load_ok=load_ok, **r)


def part_capacity(bench, quick, budget_end, pushed=False):
    """Scans N until a run fails beyond noise, then bisects. Returns
    (largest strict pass, largest pass within noise, smallest failure beyond noise)."""
    if pushed:
        scan = bench.args.sizes or ([100, 1000] if quick else [1000, 10000])
    else:
        scan = bench.args.sizes or ([1, 100, 1000] if quick else [1, 1000, 10000])
    warmup, window = (1.0, 3.0) if quick else (3.0, 10.0)
    strict = {}

    def run_n(n):
        row = capacity_run(bench, n, warmup, window, pushed)
        strict[n] = row["passed"]
        return row["load_ok"]

    best, first_fail = None, None
    for n in scan:
        if time.monotonic() > budget_end and best is not None:
            bench.log("capacity scan stopped: time budget")
            break
        if run_n(n):
            best = n
        else:
            first_fail = n
            break
    if not quick and best is not None and first_fail is not None:
        lo, hi = best, first_fail
        for _ in range(3):
            if time.monotonic() > budget_end:
                bench.log("capacity bisection stopped: time budget")
                break
            mid = int(float("%.2g" % math.sqrt(lo * hi)))
            if mid <= lo or mid >= hi:
                break
            if run_n(mid):
                lo = mid
            else:
                hi = mid
        best, first_fail = lo, hi
    strict_best = max([n for n, ok in strict.items() if ok and (first_fail is None or n < first_fail)],
                      default=None)
    return strict_best, best, first_fail
