#!/bin/bash
# Builds rigid_body_sim (Release) in the catkin workspace: .build_ws/ inside the
# checkout, or RBS_WS=/path (see scripts/common.sh). Installs nothing: run
# scripts/install_deps.sh first (run.sh and test.sh do). Extra arguments go to
# catkin_make, e.g. -DRBS_BUILD_BENCH=ON or a target name; -j$RBS_JOBS (2) unless
# they give their own -j.
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
rbs_catkin_make -DCMAKE_BUILD_TYPE=Release -j"$jobs" "$@"
