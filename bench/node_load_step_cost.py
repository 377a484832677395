"""Part 6 of bench/node_load.py: the cost of ~step through the node against the core's World::Step."""

import json
import os
import statistics
import subprocess
import time

import rospy
from rigid_body_sim.srv import Step
from std_srvs.srv import SetBool

from generated_scene import make_scene
from node_harness import CLK_TCK, NS, devel_program, proc_cpu_ticks
from node_load_push import push_every_body
from node_load_run import NodeRun


STEP_COST_BODIES = 1000
STEP_COST_STEPS = 20000
# The core's counterpart of each node scene: free tumbling boxes, and boxes
# each pushed by one held world-axes particle force.
CORE_STEP_BENCHMARKS = {False: "BM_WorldStep/casimir_splitting4/free/1000",
                        True: "BM_WorldStepLoaded/world_force/1000"}


def core_ns_per_body_step(bench, benchmark, repetitions):
    """Median ns per body-step of the core's `benchmark`, on the node's core with its scheduling."""
    program = devel_program(bench.workspace, "throughput_bench")
    out = subprocess.run(bench.node_prefix + ["taskset", "-c", str(bench.args.node_cpu), program,
                                              "--benchmark_filter=^%s$" % benchmark,
                                              "--benchmark_repetitions=%d" % repetitions,
                                              "--benchmark_report_aggregates_only=true", "--benchmark_format=json"],
                         stdout=subprocess.PIPE, universal_newlines=True, check=True).stdout
    median = next(b for b in json.loads(out)["benchmarks"] if b.get("aggregate_name") == "median")
    return 1e9 * median["per_body_step"]


def step_cost_run(bench, pushed, repetitions):
    """~step STEP_COST_STEPS on the paused node (its bodies free, or each pushed as in part 5), timed from a
    persistent client (no per-call connection set-up), and the node's own CPU time over each call; then the
    core's figure for the same kind of bodies."""
    label = "step cost, pushed" if pushed else "step cost"
    body_steps = float(STEP_COST_BODIES * STEP_COST_STEPS)
    walls, cpus = [], []
    scene = make_scene(STEP_COST_BODIES, 1000, 10, bench.per_body_topics)
    with NodeRun(bench, scene, label.replace(", ", "_").replace(" ", "_")) as run:
        held = push_every_body(bench, run, STEP_COST_BODIES) if pushed else {}
        rospy.ServiceProxy(NS + "/set_paused", SetBool)(True)
        step = rospy.ServiceProxy(NS + "/step", Step, persistent=True)
        step(1000)  # warm-up: caches and first-touch page faults
        for _ in range(repetitions):
            ticks0, t0 = proc_cpu_ticks(run.proc.pid), time.monotonic()
            response = step(STEP_COST_STEPS)
            t1, ticks1 = time.monotonic(), proc_cpu_ticks(run.proc.pid)
            if not response.success:
                raise RuntimeError("~step failed: %s" % response.message)
            walls.append(1e9 * (t1 - t0) / body_steps)
            cpus.append(1e9 * (ticks1 - ticks0) / CLK_TCK / body_steps)
        step.close()
        startup_s, integrator = run.startup_s, run.first[1].get("integrator", "")
    benchmark = CORE_STEP_BENCHMARKS[pushed]
    core = core_ns_per_body_step(bench, benchmark, repetitions)
    node = statistics.median(walls)
    r = {"ns_per_body_step": node, "cpu_ns_per_body_step": statistics.median(cpus), "core_ns_per_body_step": core,
         "node_to_core": node / core, "trials": repetitions, "loadavg1": os.getloadavg()[0],
         "startup_s": startup_s, "integrator": integrator}
    r.update(held)
    bench.log("%s: ~step %d on %d bodies: node %.1f ns per body-step (its CPU %.1f; each call %s), "
              "core %s %.1f -> %.2fx, load %.2f"
              % (label, STEP_COST_STEPS, STEP_COST_BODIES, node, r["cpu_ns_per_body_step"],
                 ", ".join("%.1f" % w for w in walls), benchmark, core, r["node_to_core"], r["loadavg1"]))
    return bench.record(part=6, label=label, n_bodies=STEP_COST_BODIES, rate_hz=1000, publish_rate_hz=10,
                        subscribers="none", passed=r["node_to_core"] <= 1.2, note=benchmark, **r)


def part_step_cost(bench, quick):
    """step_cost_run on free bodies, then on pushed ones: the node against the core for each, and pushed
    against free through the node and in the core."""
    repetitions = 3 if quick else 5
    return [step_cost_run(bench, pushed, repetitions) for pushed in (False, True)]
