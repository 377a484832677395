#!/bin/bash
# The one test command: installs what is missing, checks the C++ formatting
# of the whole tree (scripts/format_check.sh), lints every Python file and
# shell script (scripts/lint_check.sh: pyflakes, shellcheck), builds, runs
# clang-tidy on every source of src/ (scripts/tidy_check.sh), runs every test
# (gtest for the core, rostest for the node, the Python 3.8 / C++17 check,
# then the install space's test) and exits non-zero on any failure.
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
bash "$repo/scripts/install_deps.sh"
bash "$repo/scripts/format_check.sh"
bash "$repo/scripts/lint_check.sh"
bash "$repo/scripts/build.sh"
bash "$repo/scripts/tidy_check.sh"
cd "$ws"
rbs_source_devel
# The run command finds the launch file by package and name: it must resolve,
# and to exactly one file (a workspace visible inside the checkout once made
# roslaunch's search loop through the link back to it).
roslaunch --nodes rigid_body_sim rigid_body_sim.launch > /dev/null
rm -rf build/test_results
catkin_make run_tests -j1
catkin_test_results build/test_results
bash "$repo/test/install/install_space_test.sh" "$ws"
