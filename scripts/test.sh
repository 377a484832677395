#!/bin/bash
# The one test command: installs what is missing, checks the C++ formatting
# of the whole tree (scripts/format_check.sh), lints every Python file and
# shell script (scripts/lint_check.sh: pyflakes, shellcheck, catkin_lint),
# builds the package and its test binaries, runs clang-tidy over every source
# of src/ (scripts/tidy_check.sh), then every test (gtest for the core,
# rostest for the node, the Python 3.8 / C++17 check, then the install
# space's test), and exits non-zero on any failure.
#
# clang-tidy runs before the tests, not beside them: beside them it took the
# idle core, but a rostest that counts the node's late wake-ups then saw one.
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
start=$(date +%s)
bash "$repo/scripts/install_deps.sh"
bash "$repo/scripts/format_check.sh"
bash "$repo/scripts/lint_check.sh"
bash "$repo/scripts/build.sh"
cd "$ws"
rbs_source_devel
# The test binaries build in parallel here; run_tests below runs them one at
# a time, and would build them one at a time too.
catkin_make tests -j"$jobs"
build_done=$(date +%s)

tidy_start=$(date +%s)
bash "$repo/scripts/tidy_check.sh"
tidy_done=$(date +%s)
# The run command finds the launch file by package and name: it must resolve,
# and to exactly one file (a workspace visible inside the checkout once made
# roslaunch's search loop through the link back to it).
roslaunch --nodes rigid_body_sim rigid_body_sim.launch >/dev/null
rm -rf build/test_results
status=0
catkin_make run_tests -j1 || status=1
catkin_test_results build/test_results || status=1
bash "$repo/test/install/install_space_test.sh" "$ws" || status=1
echo "test: build $((build_done - start)) s, clang-tidy $((tidy_done - tidy_start)) s," \
  "tests $(($(date +%s) - tidy_done)) s"
exit "$status"
