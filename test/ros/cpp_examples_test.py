#!/usr/bin/python3
"""The C++ client's example programs (src/examples/, quoted in
doc/testing.md) against the nodes of cpp_examples.test:

- step_client exits 0: the box gained exactly F t of momentum over the 100
  steps it pushed it;
- hold_controller, in lockstep with /hold_sim, brings the box's centre of
  mass to 1.5 m (its PD: 40 N/m, 12 N s/m on 2 kg) and holds it there:
  within 1e-4 m after 5 s of simulated time, with no lockstep timeout;
- doc/testing.md quotes both files whole."""
import os
import subprocess
import sys
import time
import unittest

import roslib.packages
import rospkg
import rospy
import rostest
from rigid_body_sim.testing import SimClient

TARGET_Z = 1.5       # m, the launch file's target_z
SETTLED_S = 5.0      # simulated time the PD takes to settle within TOLERANCE
TOLERANCE = 1e-4     # m


class CppExamples(unittest.TestCase):
    def test_step_client_checks_its_push(self):
        SimClient('/rigid_body_sim')  # the node is up
        program = roslib.packages.find_node('rigid_body_sim', 'step_client')
        self.assertTrue(program, 'step_client is not built')
        run = subprocess.run(program, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             universal_newlines=True, timeout=60.0)
        sys.stderr.write(run.stdout)
        self.assertEqual(run.returncode, 0, run.stdout)
        self.assertIn('box gained', run.stdout)

    def test_hold_controller_holds_the_box(self):
        sim = SimClient('/hold_sim')
        start = sim.stamp()
        deadline = time.monotonic() + 60.0
        while (sim.stamp() - start).to_sec() < SETTLED_S and time.monotonic() < deadline:
            time.sleep(0.1)
        self.assertGreaterEqual((sim.stamp() - start).to_sec(), SETTLED_S, 'the lockstep node stalled')
        self.assertAlmostEqual(sim.state('box').position[2], TARGET_Z, delta=TOLERANCE)
        self.assertEqual(sim.diagnostics()['lockstep_timeouts'], '0')

    def test_the_documentation_quotes_each_example_whole(self):
        root = rospkg.RosPack().get_path('rigid_body_sim')
        with open(os.path.join(root, 'doc', 'testing.md')) as f:
            document = f.read()
        for example in ('hold_controller.h', 'hold_controller.cpp', 'hold_controller_main.cpp',
                        'hold_controller_nodelet.cpp', 'controller_nodelet.h', 'step_client.cpp'):
            with open(os.path.join(root, 'src', 'examples', example)) as f:
                self.assertIn('```cpp\n' + f.read() + '```\n', document, example)


if __name__ == '__main__':
    rospy.init_node('cpp_examples_test')
    rostest.rosrun('rigid_body_sim', 'cpp_examples', CppExamples, sys.argv)
