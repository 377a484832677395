"""The held push of bench/node_load.py's parts 5 and 6: one world-axes particle force on every
body, sent once, checked held and acting."""

import time

import rospy
from rigid_body_sim.msg import BodyStateArray, ParticleWrench, ParticleWrenchArray

from node_harness import NS

# World z at particle 0, a corner, so each body gets a force and a torque (~3e-4 N m);
# small enough that after a minute's push no box leaves the lanes' range or needs a substep.
PUSH_FORCE_N = 0.005
# Entries per ParticleWrenchArray: the node reads at most 10,000 of one array (doc/node.md).
PUSH_ENTRIES_PER_ARRAY = 1000


def push_array(first, count):
    wrenches = []
    for i in range(first, first + count):
        w = ParticleWrench(body="b%d" % i, particle=0)  # zero stamp: from the next step; no timeout
        w.header.frame_id = "world"
        w.wrench.force.z = PUSH_FORCE_N
        wrenches.append(w)
    return ParticleWrenchArray(wrenches=wrenches)


def z_velocity_rates(bodies, span_s=1.0):
    """d(v_z)/dt of the bodies at these indices over about span_s of simulation time, from two
    ~bodies messages (the bodies' own topics may not be advertised yet in a large scene)."""
    topic = NS + "/bodies"
    first = rospy.wait_for_message(topic, BodyStateArray, timeout=10)
    time.sleep(span_s)
    last = rospy.wait_for_message(topic, BodyStateArray, timeout=10)
    dt = (last.header.stamp - first.header.stamp).to_sec()
    # Boxes of 1 kg: v_z = p_z.
    return [(last.bodies[i].linear_momentum.z - first.bodies[i].linear_momentum.z) / dt
            if dt > 0 else float("nan") for i in bodies]


def push_every_body(bench, run, n):
    """Holds one world-axes particle force on each of the n bodies, sent once, and checks that every
    one is held (diagnostics) and acts (the first and last body speed up at F/m, boxes of 1 kg)."""
    pub = rospy.Publisher(NS + "/particle_wrenches", ParticleWrenchArray, queue_size=100)
    deadline = time.monotonic() + 10
    while pub.get_num_connections() == 0 and time.monotonic() < deadline:
        time.sleep(0.05)
    for first in range(0, n, PUSH_ENTRIES_PER_ARRAY):
        pub.publish(push_array(first, min(PUSH_ENTRIES_PER_ARRAY, n - first)))
    # While the node advertises its bodies' topics the master is busy and
    # reports can come late: keep the latest one.
    report = None
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        report = run.diag.wait_next(2, run.alive) or report
        if report is not None and report[1].get("held_wrenches", 0) >= n:
            break
    pub.unregister()
    held = int(report[1].get("held_wrenches", 0)) if report else 0
    rejected = int(report[1].get("rejected_messages", 0)) if report else -1
    if held != n or rejected != 0:
        raise RuntimeError("pushed N=%d: %d wrenches held, %d rejected" % (n, held, rejected))
    rates = z_velocity_rates([0, n - 1])
    if any(not abs(rate - PUSH_FORCE_N) <= 0.01 * PUSH_FORCE_N for rate in rates):
        raise RuntimeError("pushed N=%d: dv_z/dt %s m/s^2, expected %g" % (n, rates, PUSH_FORCE_N))
    bench.log("pushed N=%d: %d wrenches held, dv_z/dt of the first and last body %.6f, %.6f m/s^2 (F/m = %g)"
              % (n, held, rates[0], rates[1], PUSH_FORCE_N))
    return {"held_wrenches": held, "push_dv_dt_mps2": min(rates)}
