"""What the plotting scripts next to this file share: waiting for a
condition with a deadline, and whether a ROS master answers."""
import os
import sys
import time


def wait_until(predicate, timeout_s, what, poll_s=0.05):
    """Polls predicate() every poll_s until it holds; exits the script naming
    `what` after timeout_s."""
    deadline = time.monotonic() + timeout_s
    while not predicate():
        if time.monotonic() > deadline:
            sys.exit('%s: no %s within %g s' % (os.path.basename(sys.argv[0]), what, timeout_s))
        time.sleep(poll_s)


def master_is_up(master):
    """Whether the rosgraph.Master `master` answers."""
    try:
        master.getPid()
        return True
    except Exception:  # the master is not up yet
        return False
