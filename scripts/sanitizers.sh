#!/bin/bash
# Builds the whole package (core, node, core gtests and rostests) with
# AddressSanitizer + UndefinedBehaviorSanitizer (gcc) in a workspace of its own
# (default /tmp/ws_asan; override with RBS_SANITIZER_WS=/path, not RBS_WS: the
# sanitizer flags stay in a workspace's CMake cache, so the workspace of
# scripts/test.sh must never be this one), runs every test and exits non-zero
# on a test failure or on any sanitizer report from any process.
#
#   bash scripts/sanitizers.sh            # build -j2, then all tests
#   RBS_JOBS=1 bash scripts/sanitizers.sh # build -j1
#
# All but two run here too. Stress.RandomParticleForcesKeepEveryStateFinite
# (10^5 steps of random forces on every scheme, the longest test by far under
# the sanitizers: doc/reliability.md) runs in scripts/test.sh only; the paths
# it takes are those of the shorter core tests, which run here. So does
# readme_examples.test, which checks the documents' commands against a node
# whose paths the other rostests take.
#
# Every instrumented process (gtest binaries, the node launched by rostest)
# writes its reports to $ws/sanitizer_logs/ (ASAN_OPTIONS/UBSAN_OPTIONS
# log_path), so a report is seen even when rostest keeps the node's stderr in
# its own log; the ROS logs of this run ($ws/ros_home/log) and the test output
# are searched for "runtime error" / "ERROR: AddressSanitizer" /
# "ERROR: LeakSanitizer" as well.
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ws="${RBS_SANITIZER_WS:-/tmp/ws_asan}"
start=$(date +%s)

bash "$repo/scripts/install_deps.sh"
san="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
# -O2: the timing rostests need a node that keeps up with its rate under
# ASan; -g1 gives the reports their line numbers, at less build time than
# full debug information. One build of the lane kernels instead of one per
# x86-64 level (RBS_SIMD_CLONES=OFF): the same source, instrumented once, at
# a fraction of the build time; the clones run in scripts/test.sh. The
# documents' commands (RBS_DOCUMENT_TESTS) check text, and run there too.
# The tests' own sources build at -Og (RBS_TEST_COMPILE_OPTIONS), much faster
# than at -O2 and still instrumented; the node and the core they test keep -O2.
rbs_catkin_make -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRBS_SIMD_CLONES=OFF -DRBS_DOCUMENT_TESTS=OFF \
  -DRBS_TEST_COMPILE_OPTIONS=-Og \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
  -DCMAKE_CXX_FLAGS="$san" -DCMAKE_C_FLAGS="$san" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
  -j"$jobs"
rbs_source_devel
# The test binaries build in parallel here; run_tests runs them one at a time.
catkin_make tests -j"$jobs"
build_done=$(date +%s)

logs="$ws/sanitizer_logs"
rm -rf "$logs" "$ws/ros_home" build/test_results
mkdir -p "$logs" "$ws/ros_home/log"
# This run's ROS logs only (the node's stderr under rostest ends up there).
export ROS_HOME="$ws/ros_home"
export ROS_LOG_DIR="$ws/ros_home/log"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:halt_on_error=1:log_path=$logs/asan:log_exe_name=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:log_path=$logs/ubsan:log_exe_name=1"
# Leaks inside the ROS libraries at exit (none of this package's code).
export LSAN_OPTIONS="suppressions=$repo/scripts/lsan.supp:print_suppressions=0"
export GTEST_FILTER="-Stress.RandomParticleForcesKeepEveryStateFinite"

status=0
# The gtests (the core's above all) are bound by one core and time nothing;
# the rostests mostly wait on the clock: the two groups run side by side,
# each group one test at a time. catkin's run_tests_<package>_<type> targets
# leave the results of the other group in place.
(cd build && make run_tests_rigid_body_sim_gtest >"$ws/run_gtests.log" 2>&1) &
gtests_pid=$!
(cd build && make run_tests_rigid_body_sim_rostest run_tests_rigid_body_sim_pyunit) 2>&1 |
  tee "$ws/run_tests.log" || status=1
wait "$gtests_pid" || status=1
cat "$ws/run_gtests.log" >>"$ws/run_tests.log"
catkin_test_results build/test_results || status=1
tests_done=$(date +%s)

reports=$(find "$logs" -type f | sort)
if [ -n "$reports" ]; then
  echo "sanitizers: REPORTS in $logs:"
  for f in $reports; do echo "==== $f"; head -60 "$f"; done
  status=1
fi
pattern='runtime error|ERROR: AddressSanitizer|ERROR: LeakSanitizer|SUMMARY: UndefinedBehaviorSanitizer'
hits=$( { grep -rlE "$pattern" "$ws/ros_home/log" build/test_results 2>/dev/null || true; \
          grep -lE "$pattern" "$ws/run_tests.log" 2>/dev/null || true; } )
if [ -n "$hits" ]; then
  echo "sanitizers: sanitizer output found in:"
  echo "$hits"
  for f in $hits; do grep -nE -A20 "$pattern" "$f" | head -40; done
  status=1
fi

echo "sanitizers: build $((build_done - start)) s, tests $((tests_done - build_done)) s," \
     "total $((tests_done - start)) s (workspace $ws, -j$jobs)"
if [ "$status" -eq 0 ]; then
  echo "sanitizers: OK: all tests passed, no ASan/UBSan/LSan report"
else
  echo "sanitizers: FAILED"
fi
exit "$status"
