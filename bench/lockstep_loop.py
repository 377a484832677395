#!/usr/bin/python3
"""The cost of lockstep: a node in lockstep with a trivial controller at
real_time_factor 0, against the same node running free. The controllers:
this script through the Python client (rigid_body_sim.testing.
LockstepController), answering every cycle with no wrench or with one body
wrench, and the C++ client's hold controller example
(src/examples/hold_controller.h, a LockstepController answering every cycle
with one body wrench), all on ~lockstep_answers. The C++ controller runs as
the program hold_controller over TCP, answering from its callback queue
(cpp_queue_...) or on roscpp's network thread as the message arrives
(cpp_...), and as rigid_body_sim/HoldControllerNodelet in the node's own
nodelet manager (the node loaded as rigid_body_sim/SimulationNodelet),
answering on the node's stepping thread (nodelet_...).

Scene: --bodies generated boxes (8 particles each), rate 1000 Hz. Cases:

  free_every_step                 no lockstep, publish_rate 1000, ~bodies
                                  subscribed by this script (the same
                                  messages as the lockstep cases)
  python_empty_every_step         lockstep, publish_rate 1000 (one step per
                                  cycle), Python, empty answers
  python_body_wrench_every_step   the same, one body wrench per answer
  cpp_queue_body_wrench_every_step  the same from C++ over TCP, answered
                                  from the controller's callback queue
  cpp_body_wrench_every_step      the same, answered on arrival
  nodelet_body_wrench_every_step  the same in one nodelet manager
  python_empty_every_10           lockstep, publish_rate 100 (ten steps per
                                  cycle), Python, empty answers
  python_body_wrench_every_10     the same, one body wrench per answer
  cpp_body_wrench_every_10        the same from C++ over TCP
  nodelet_body_wrench_every_10    the same in one nodelet manager

For each: steps per second of simulation from the node's diagnostics
(`steps` over --window seconds of wall time), cycles per second (in
lockstep: steps per second over steps per cycle; free: the messages this
script received), wall µs per cycle, and the lockstep overhead per cycle = µs
per cycle in lockstep − µs per step free (both publishing every step). The
node runs on --node-cpu, the controller (this script or the C++ program)
and a private master on --bench-cpu; the nodelet manager, holding node and
controller, on --node-cpu.

Writes bench/results/lockstep_loop.md (also printed).

  bench/lockstep_loop.py [--bodies 1] [--window 5] [--workspace PATH] [--port 11398] [--out DIR]
"""

import argparse
import os
import sys
import tempfile
import time

from node_harness import NODE_NAME, NS, Processes, add_node_bench_arguments, devel_program


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bodies", type=int, default=1, help="generated boxes in the scene (default 1)")
    parser.add_argument("--window", type=float, default=5.0, help="measuring window [s] (default 5)")
    add_node_bench_arguments(parser, 11398, "lockstep_loop.md")
    return parser.parse_args()


ARGS = parse_args()
CPP_CONTROLLER = "hold_controller"  # its node name, as it runs it
MANAGER = "lockstep_bench_manager"  # the nodelet manager's node name
# (name, controller: None (free), "python", "cpp_queue", "cpp" or "nodelet",
#  body wrench in each answer, publish_rate)
CASES = [("free_every_step", None, False, 1000.0),
         ("python_empty_every_step", "python", False, 1000.0),
         ("python_body_wrench_every_step", "python", True, 1000.0),
         ("cpp_queue_body_wrench_every_step", "cpp_queue", True, 1000.0),
         ("cpp_body_wrench_every_step", "cpp", True, 1000.0),
         ("nodelet_body_wrench_every_step", "nodelet", True, 1000.0),
         ("python_empty_every_10", "python", False, 100.0),
         ("python_body_wrench_every_10", "python", True, 100.0),
         ("cpp_body_wrench_every_10", "cpp", True, 100.0),
         ("nodelet_body_wrench_every_10", "nodelet", True, 100.0)]
NODELET = "/usr/lib/nodelet/nodelet"  # Debian's nodelet program


def scene(lockstep, publish_rate, controller):
    bodies = [{"name": "b%d" % i, "shape": "box", "mass": 1.0, "size": [0.2, 0.15, 0.1], "resolution": 2,
               "position": [0.5 * i, 0.0, 0.0], "angular_velocity": [0.3, 2.0, -0.1]}
              for i in range(ARGS.bodies)]
    params = {"rate": 1000.0, "publish_rate": publish_rate, "real_time_factor": 0.0, "status_period": 0.0,
              "per_body_topics": False, "bodies": bodies}
    if lockstep:
        params.update({"lockstep": True, "lockstep_publishers": [controller], "lockstep_timeout": 5.0})
    return params


def measure(procs, log_dir, name, controller, body_wrench, publish_rate):
    import rospy
    from node_harness import Diagnostics
    from rigid_body_sim.testing import LockstepController
    from rigid_body_sim.testing import body_wrench as make_body_wrench
    lockstep = controller is not None
    # A nodelet's answers carry its manager's name.
    listed = {"cpp": "/" + CPP_CONTROLLER, "cpp_queue": "/" + CPP_CONTROLLER,
              "nodelet": "/" + MANAGER}.get(controller, rospy.get_name())
    rospy.set_param(NS, scene(lockstep, publish_rate, listed))
    diag = Diagnostics()
    cycles = [0]
    answer = [make_body_wrench("b0")] if body_wrench else []  # zero: b0 stays where it is

    def count(msg_or_states, _stamp=None):
        cycles[0] += 1
        return answer

    def log(suffix):
        return os.path.join(log_dir, name + suffix + ".log")

    # The hold controller holds b0 at z = 0, where it is: zero wrenches.
    hold_params = ["__name:=" + CPP_CONTROLLER, "_body:=b0", "_target_z:=0.0"]
    helper = None
    loaders = []
    if controller == "python":
        helper = LockstepController(count, NS)
    elif controller is None:
        helper = rospy.Subscriber(NS + "/bodies", rospy.AnyMsg, count, queue_size=100, tcp_nodelay=True)
    elif controller.startswith("cpp"):
        answer_thread = "queue" if controller == "cpp_queue" else "delivering"
        helper = procs.start(["taskset", "-c", str(ARGS.bench_cpu),
                              devel_program(os.environ["RBS_BENCH_WS"], CPP_CONTROLLER),
                              "_answer_thread:=" + answer_thread] + hold_params, log("_controller"))
    if controller == "nodelet":
        node = procs.start(["taskset", "-c", str(ARGS.node_cpu), NODELET, "manager",
                            "__name:=" + MANAGER], log(""))
        loaders = [procs.start([NODELET, "load", "rigid_body_sim/SimulationNodelet", MANAGER,
                                "__name:=" + NODE_NAME], log("_load_node")),
                   procs.start([NODELET, "load", "rigid_body_sim/HoldControllerNodelet", MANAGER]
                               + hold_params, log("_load_controller"))]
    else:
        node = procs.start(["taskset", "-c", str(ARGS.node_cpu),
                            devel_program(os.environ["RBS_BENCH_WS"], "rigid_body_sim_node"),
                            "__name:=" + NODE_NAME], log(""))

    def alive():
        return node.poll() is None

    first = diag.wait_next(30.0, alive)  # the first report: the node steps
    start = diag.wait_next(10.0, alive)
    cycles0 = cycles[0]
    time.sleep(ARGS.window)
    end = diag.wait_next(10.0, alive)
    cycles1 = cycles[0]
    if first is None or start is None or end is None:
        sys.exit("%s: no diagnostics from the node (log in %s)" % (name, log_dir))
    wall = end[0] - start[0]
    steps_per_s = (end[1]["steps"] - start[1]["steps"]) / wall
    cycles_per_s = steps_per_s * publish_rate / 1000.0 if lockstep else (cycles1 - cycles0) / wall
    for loader in loaders:
        procs.stop(loader)
    procs.stop(node)
    if controller == "python":
        helper.stop()
    elif controller is None:
        helper.unregister()
    elif helper is not None:
        procs.stop(helper)
    return {"case": name, "steps_per_s": steps_per_s, "cycles_per_s": cycles_per_s,
            "us_per_cycle": 1e6 / cycles_per_s if cycles_per_s > 0 else float("inf"),
            "timeouts": end[1].get("lockstep_timeouts", 0.0)}


def main():
    from node_harness import reexec_in_workspace, start_master
    reexec_in_workspace(ARGS.workspace, ARGS.port)
    os.sched_setaffinity(0, {ARGS.bench_cpu})
    log_dir = tempfile.mkdtemp(prefix="lockstep_loop_")
    procs = Processes()
    try:
        start_master(procs, ARGS.port, ARGS.bench_cpu, log_dir)
        import rospy
        rospy.init_node("lockstep_bench", disable_signals=True)
        rows = [measure(procs, log_dir, *case) for case in CASES]
    finally:
        procs.stop_all()
    free_us_per_step = 1e6 / rows[0]["steps_per_s"]
    lines = ["| case | steps/s | cycles/s | µs per cycle | overhead µs per cycle | lockstep timeouts |",
             "|---|---|---|---|---|---|"]
    for r in rows:
        every_step = r["case"].endswith("every_step") and r["case"] != "free_every_step"
        overhead = "%.1f" % (r["us_per_cycle"] - free_us_per_step) if every_step else ""
        lines.append("| %s | %.0f | %.0f | %.1f | %s | %d |" % (
            r["case"], r["steps_per_s"], r["cycles_per_s"], r["us_per_cycle"], overhead, r["timeouts"]))
    text = ("Lockstep at real_time_factor 0, %d bodies of 8 particles, rate 1000 Hz, window %.0f s, "
            "node on core %d, controller (Python: this script; C++: hold_controller) and master on "
            "core %d; nodelet cases: node and controller in one manager on core %d. Lockstep overhead per cycle = µs per cycle − µs per step in free_every_step "
            "(both publishing every step).\n\n%s\n" % (ARGS.bodies, ARGS.window, ARGS.node_cpu,
                                                       ARGS.bench_cpu, ARGS.node_cpu, "\n".join(lines)))
    print(text)
    os.makedirs(ARGS.out, exist_ok=True)
    with open(os.path.join(ARGS.out, "lockstep_loop.md"), "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
