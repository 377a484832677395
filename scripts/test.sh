#!/bin/bash
# The one test command: installs what is missing, checks the C++ formatting
# of the whole tree (scripts/format_check.sh), lints every Python file and
# shell script (scripts/lint_check.sh: pyflakes, shellcheck, catkin_lint),
# builds the package and its test binaries, runs every test (gtest for the
# core, rostest for the node, the Python 3.8 / C++17 check, then the install
# space's test) with clang-tidy over every source of src/
# (scripts/tidy_check.sh) beside them, and exits non-zero on any failure.
#
# clang-tidy runs one source at a time at the lowest priority while the tests
# run: the rostests mostly wait on the clock, so it takes the idle core
# instead of minutes of its own. If it is not done when the tests are, a
# second run takes the sources from the other end (tidy_check.sh,
# RBS_TIDY_REVERSE). Its report is printed after the tests.
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

tidy_log="$ws/build/tidy_check.log"
RBS_TIDY_JOBS=1 nice -n 19 bash "$repo/scripts/tidy_check.sh" >"$tidy_log" 2>&1 &
tidy_pid=$!
status=0
# The run command finds the launch file by package and name: it must resolve,
# and to exactly one file (a workspace visible inside the checkout once made
# roslaunch's search loop through the link back to it).
roslaunch --nodes rigid_body_sim rigid_body_sim.launch >/dev/null || status=1
rm -rf build/test_results
catkin_make run_tests -j1 || status=1
catkin_test_results build/test_results || status=1
bash "$repo/test/install/install_space_test.sh" "$ws" || status=1
tests_done=$(date +%s)
if kill -0 "$tidy_pid" 2>/dev/null; then
  RBS_TIDY_JOBS=1 RBS_TIDY_REVERSE=1 bash "$repo/scripts/tidy_check.sh" >"$tidy_log.reverse" 2>&1 ||
    status=1
  cat "$tidy_log.reverse"
fi
wait "$tidy_pid" || status=1
cat "$tidy_log"
echo "test: build $((build_done - start)) s, tests $((tests_done - build_done)) s," \
  "clang-tidy done $(($(date +%s) - tests_done)) s after them"
exit "$status"
