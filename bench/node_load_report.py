"""The report of bench/node_load.py: its Markdown (summary, then a section per part that ran) and
the columns of its CSV."""

import os

from bench_report import commit_described, cpu_model, md_table
from node_load_push import PUSH_ENTRIES_PER_ARRAY, PUSH_FORCE_N
from node_load_record import RECORD_BODIES, RECORD_PUBLISH_RATE_HZ, RECORD_RATE_HZ
from node_load_run import NOISE_OVERRUNS_PER_S
from node_load_step_cost import CORE_STEP_BENCHMARKS, STEP_COST_BODIES, STEP_COST_STEPS

CSV_FIELDS = ["part", "label", "n_bodies", "rate_hz", "publish_rate_hz", "subscribers", "entries_per_msg",
              "msgs_hz", "window_s", "integrator", "startup_s", "overruns", "overruns_per_s",
              "floor_overruns", "floor_worst_us", "catch_up_limit_hits", "rtf_window", "rtf_min", "step_mean_us",
              "step_max_us", "cpu_percent",
              "core_other_percent", "loadavg1", "tf_msgs_per_s", "bodies_msgs_per_s", "rx_mbyte_per_s",
              "pub_msgs_per_s", "pub_busy_percent", "wrenches_sent_per_s", "wrenches_taken_per_s",
              "latency_median_ms", "latency_p90_ms", "latency_min_ms", "latency_max_ms",
              "stamp_lag_median_ms", "trials", "held_wrenches", "push_dv_dt_mps2", "ns_per_body_step",
              "cpu_ns_per_body_step", "core_ns_per_body_step", "node_to_core", "record", "bag_mbyte",
              "record_dropped", "passed", "load_ok", "note"]


def capacity_summary(kind, capacity):
    strict_best, best, first_fail = capacity
    return [("%s at rate 1000 Hz, zero overruns in the window (publish_rate 10, one core)" % kind,
             "%s" % (strict_best if strict_best is not None else "none of the sizes tried")),
            ("%s at rate 1000 Hz, overruns within this machine's noise (<= %.0f/s or <= 2x a bare loop's), "
             "RTF >= 0.99" % (kind, NOISE_OVERRUNS_PER_S),
             "%s (%s)" % (best if best is not None else "none",
                          "fails at %s" % first_fail if first_fail else "no size tried failed"))]


def capacity_table(rows, part):
    rows = [r for r in rows if r["part"] == part]
    return md_table(
        ["N bodies", "window s", "overruns", "bare loop overruns", "overruns per publish cycle",
         "catch-up hits",
         "step mean us", "ns per body-step", "step max us", "RTF min", "node CPU %", "core other %", "load avg",
         "first report s", "pass"],
        [[r["n_bodies"], r["window_s"], r["overruns"], r["floor_overruns"],
          "%.2f" % (r["overruns"] / (10.0 * r["window_s"])),
          r["catch_up_limit_hits"], r["step_mean_us"], 1e3 * r["step_mean_us"] / r["n_bodies"],
          r["step_max_us"], "%.3f" % r["rtf_min"], r["cpu_percent"], r["core_other_percent"],
          "%.2f" % r["loadavg1"], r["startup_s"],
          "yes" if r["passed"] else ("within noise" if r["load_ok"] else "no")] for r in rows])


def write_report(bench, results, quick, elapsed):
    """The Markdown report; results: what each part that ran returned, by name."""
    capacity, pushed = results.get("capacity"), results.get("pushed")
    cpu_rows, intake_rows = results.get("cpu", []), results.get("intake", [])
    latency_rows, step_cost = results.get("latency", []), results.get("step_cost")
    record_rows = results.get("record", [])
    loads = [r["loadavg1"] for r in bench.rows if "loadavg1" in r]
    integrator = next((r.get("integrator") for r in bench.rows if r.get("integrator")), "")
    md = ["# The node under load (`bench/node_load.py`%s)" % (" --quick" if quick else ""), ""]
    md.append("Commit %s, %s, %d cores; node pinned to core %d (`taskset`) with scheduling `%s`, this script "
              "and the master on core %d. Integrator: %s (the node's default). Scenes: N generated boxes, `resolution: 2` "
              "(8 particles each), all moving (idle bodies are skipped by the integrator). "
              "Load average (1 min) during the runs: %.2f to %.2f. Run time %.0f s."
              % (commit_described(), cpu_model(), os.cpu_count(), bench.args.node_cpu, bench.args.sched,
                 bench.args.bench_cpu, integrator, min(loads) if loads else float("nan"),
                 max(loads) if loads else float("nan"), elapsed))
    md.append("")
    md.append("## Summary")
    md.append("")
    summary = capacity_summary("bodies", capacity) if capacity else []
    for r in cpu_rows:
        summary.append(("node CPU, %d bodies, /tf + ~bodies at 100 Hz subscribed" % r["n_bodies"],
                        "%.1f %% of one core" % r["cpu_percent"]))
    held = [r for r in intake_rows if r["passed"]]
    held0 = [r for r in held if r["overruns"] == 0]
    if intake_rows:
        summary.append(("particle wrenches/s taken, rate held (RTF >= 0.99, all arrays taken)",
                        "%.0f" % max(r["wrenches_taken_per_s"] for r in held) if held else "none held"))
        summary.append(("... of those with zero overruns",
                        "%.0f" % max(r["wrenches_taken_per_s"] for r in held0) if held0 else "none"))
    for r in latency_rows:
        summary.append(("wrench -> ~bodies latency, publish_rate %d (median of %d)"
                        % (r["publish_rate_hz"], r["trials"]),
                        "%.2f ms (1/publish_rate = %.1f ms)" % (r["latency_median_ms"], 1e3 / r["publish_rate_hz"])))
    if pushed:
        summary += capacity_summary("pushed bodies (one held particle force each)", pushed)
    for r in step_cost or []:
        summary.append(("~step %d while paused, %d %s bodies: node / core ns per body-step"
                        % (STEP_COST_STEPS, STEP_COST_BODIES, "pushed" if "pushed" in r["label"] else "free"),
                        "%.1f / %.1f (%.2fx)" % (r["ns_per_body_step"], r["core_ns_per_body_step"],
                                                 r["node_to_core"])))
    if step_cost and len(step_cost) == 2:
        free, pushed_cost = step_cost
        summary.append(("~step, pushed / free ns per body-step: node, core",
                        "%.2fx, %.2fx" % (pushed_cost["ns_per_body_step"] / free["ns_per_body_step"],
                                          pushed_cost["core_ns_per_body_step"] / free["core_ns_per_body_step"])))
    for r in record_rows:
        summary.append(("%s at %d Hz, publish_rate %d, %s: RTF in the window (min)"
                        % (r["label"].split("_")[0] if r["n_bodies"] == 1 else "%d pushed bodies" % r["n_bodies"],
                           r["rate_hz"], r["publish_rate_hz"], "recorded" if r["record"] else "not recorded"),
                        "%.4f (%.3f), %d dropped" % (r["rtf_window"], r["rtf_min"], r["record_dropped"])))
    md.append(md_table(["figure", "value"], summary))
    md.append("")

    if capacity:
        md.append("## 1. Capacity: rate 1000 Hz, publish_rate 10, no /tf or ~bodies subscriber")
        md.append("")
        md.append("Each run: node started on a fresh scene, %s s warm-up, then the window between two "
                  "diagnostics reports. Overruns = increase of the cumulative `overruns` key (a wake-up late by "
                  "more than one step). RTF min = lowest `real_time_factor_achieved` in the window. "
                  "Pass = zero overruns and RTF min >= 0.99; \"within noise\" = at most %.0f overrun/s or at most "
                  "twice the bare loop's count, no catch-up-limit hit and RTF min >= 0.99. \"bare loop\" = "
                  "`bench/wake_jitter` right after the run, on the node's core with its scheduling: sleep to each "
                  "1 ms boundary, then busy for the run's mean step time, overruns counted as the node counts "
                  "them; it is what this shared virtual machine gives with no node at all. The scan stops at the "
                  "first size that fails beyond noise and "
                  "bisects. "
                  "\"core other\" = busy time of the node's core not used by the node (disturbance)."
                  % ("1" if quick else "3", NOISE_OVERRUNS_PER_S))
        md.append("")
        md.append(capacity_table(bench.rows, 1))
        md.append("")

    if cpu_rows:
        md.append("## 2. CPU use: rate 1000 Hz, /tf and ~bodies at 100 Hz, both subscribed")
        md.append("")
        md.append("Node CPU = (utime + stime) from /proc/<pid>/stat over the window, per wall second, in % of one "
                  "core. The script subscribes to /tf and ~bodies as raw bytes (rospy.AnyMsg), so both messages "
                  "are built, serialised and sent.")
        md.append("")
        md.append(md_table(
            ["N bodies", "window s", "node CPU %", "step mean us", "/tf msg/s", "~bodies msg/s", "received MB/s",
             "overruns", "core other %", "load avg"],
            [[r["n_bodies"], r["window_s"], r["cpu_percent"], r["step_mean_us"], r["tf_msgs_per_s"],
              r["bodies_msgs_per_s"], "%.2f" % r["rx_mbyte_per_s"], r["overruns"], r["core_other_percent"],
              "%.2f" % r["loadavg1"]] for r in cpu_rows]))
        md.append("")

    if intake_rows:
        md.append("## 3. Particle wrench intake through ~particle_wrenches (100 bodies, 800 particles, publish_rate 100)")
        md.append("")
        md.append("Arrays of K entries published at R Hz by this script (rospy, each array serialised once and "
                  "re-sent as bytes). The first entry of each array is deliberately invalid (particle 999), so the "
                  "increase of `rejected_particle_out_of_range` counts the arrays the node processed; taken = "
                  "arrays x K - all rejected entries. Held = RTF min >= 0.99, the node processed >= 97 % of the "
                  "arrays sent and took >= 99 % of their valid entries. Publisher busy = time inside "
                  "publish() / wall time.")
        md.append("")
        md.append(md_table(
            ["K", "R Hz", "publisher Hz", "publisher busy %", "sent wrenches/s", "taken wrenches/s", "overruns",
             "RTF min", "step mean us", "node CPU %", "load avg", "held", "note"],
            [[r["entries_per_msg"], "%.0f" % r["msgs_hz"], r["pub_msgs_per_s"], r["pub_busy_percent"],
              "%.0f" % r["wrenches_sent_per_s"], "%.0f" % r["wrenches_taken_per_s"], r["overruns"],
              "%.3f" % r["rtf_min"], r["step_mean_us"], r["cpu_percent"], "%.2f" % r["loadavg1"],
              "yes" if r["passed"] else "no", r.get("note", "")] for r in intake_rows]))
        md.append("")

    if latency_rows:
        md.append("## 4. Latency: ParticleWrench (zero stamp) -> first ~bodies message reflecting it")
        md.append("")
        md.append("One box at rest, rate 1000 Hz. Each trial: wall time before publish(); the first ~bodies message "
                  "(tcp_nodelay, deserialised by rospy) whose linear momentum differs from the one before the "
                  "send; latency = wall time at its callback - send time; then a zero force replaces the push and "
                  "the next trial waits for a constant momentum plus a random 20-50 ms. Includes rospy publish "
                  "and callback overhead on both ends. Expected bound: up to one step (1 ms) until the wrench "
                  "is used, up to 1/publish_rate until the next publish cycle, plus transport. stamp - send = "
                  "the message's stamp (simulation time) minus the send time.")
        md.append("")
        md.append(md_table(
            ["publish_rate Hz", "trials", "median ms", "p90 ms", "min ms", "max ms", "1/publish_rate ms",
             "stamp - send median ms", "node CPU %", "load avg"],
            [[r["publish_rate_hz"], r["trials"], "%.2f" % r["latency_median_ms"], "%.2f" % r["latency_p90_ms"],
              "%.2f" % r["latency_min_ms"], "%.2f" % r["latency_max_ms"], 1e3 / r["publish_rate_hz"],
              "%.2f" % r["stamp_lag_median_ms"], r["cpu_percent"], "%.2f" % r["loadavg1"]] for r in latency_rows]))
        md.append("")

    if pushed:
        md.append("## 5. Pushed capacity: part 1 with one held particle force on every body")
        md.append("")
        md.append("As part 1, except that before the warm-up every body gets one held force of %g N along world "
                  "z at its particle 0 (a corner, so a torque too), sent once as ParticleWrenchArray messages of "
                  "%d entries on ~particle_wrenches (zero stamp, no `wrench_timeout`: held until replaced). "
                  "Before timing, the script waits for the diagnostics key `held_wrenches` = N with no rejected "
                  "message, and checks on two ~bodies messages that the first and last body's dv_z/dt = F/m (1 kg boxes) within "
                  "1 %%; the bodies therefore take the loaded SIMD lanes every step."
                  % (PUSH_FORCE_N, PUSH_ENTRIES_PER_ARRAY))
        md.append("")
        md.append(capacity_table(bench.rows, 5))
        md.append("")

    if step_cost:
        md.append("## 6. ~step through the node against the core's World::Step")
        md.append("")
        md.append("The node paused on %d tumbling boxes (the part 1 scene), free, then in a second run each pushed "
                  "as in part 5; ~step %d called %d times from one persistent rospy service client after a "
                  "warm-up ~step 1000; ns per body-step = wall time of the call / (bodies x steps), median over "
                  "the calls; node CPU = the node's utime + stime over each call (10 ms ticks). Core: "
                  "`throughput_bench --benchmark_filter=^<benchmark>$` on the node's core with its scheduling "
                  "right after each run, median of as many repetitions: %s for free boxes, %s for boxes with one "
                  "held world-axes particle force each. A `rosservice call` timed from the shell would add the "
                  "command's own start-up (0.7-1.2 s on this machine, 35-60 ns per body-step at this size)."
                  % (STEP_COST_BODIES, STEP_COST_STEPS, step_cost[0]["trials"], CORE_STEP_BENCHMARKS[False],
                     CORE_STEP_BENCHMARKS[True]))
        md.append("")
        md.append(md_table(
            ["bodies", "kind", "steps per call", "calls", "node ns per body-step", "node CPU ns per body-step",
             "core ns per body-step", "node / core", "load avg"],
            [[r["n_bodies"], "pushed" if "pushed" in r["label"] else "free", STEP_COST_STEPS, r["trials"],
              r["ns_per_body_step"], r["cpu_ns_per_body_step"], r["core_ns_per_body_step"],
              "%.2f" % r["node_to_core"], "%.2f" % r["loadavg1"]] for r in step_cost]))
        md.append("")

    if record_rows:
        md.append("## 7. ~record: rate %d Hz, publish_rate %d, without and with a bag"
                  % (RECORD_RATE_HZ, RECORD_PUBLISH_RATE_HZ))
        md.append("")
        md.append("The quadrotor of config/quadrotor.yaml (no controller: it falls, with drag) and %d boxes "
                  "pushed as in part 5, each run once without and once with `~record` to a bag in the run's log "
                  "directory (each publish cycle's ~bodies and state hash, and the pushes), nobody subscribed. "
                  "Window and bare loop as in part 1. Pass = RTF min >= 0.995, nothing dropped "
                  "(`record_dropped`) and no `record_error`."
                  % RECORD_BODIES)
        md.append("")
        md.append(md_table(
            ["run", "bodies", "window s", "RTF window", "RTF min", "overruns", "bare loop overruns",
             "step mean us", "step max us", "node CPU %", "bag MB", "dropped", "load avg", "pass"],
            [[r["label"], r["n_bodies"], r["window_s"], "%.4f" % r["rtf_window"], "%.3f" % r["rtf_min"],
              r["overruns"], r["floor_overruns"], r["step_mean_us"], r["step_max_us"], r["cpu_percent"],
              "%.1f" % r["bag_mbyte"], r["record_dropped"], "%.2f" % r["loadavg1"],
              "yes" if r["passed"] else "no"] for r in record_rows]))
        md.append("")
    return "\n".join(md)
