#!/bin/bash
# Installs what is missing, builds rigid_body_sim and launches the node on the
# default scene:
#   bash scripts/run.sh [roslaunch args, e.g. integrator:=rk4 rviz:=true]
# roslaunch starts its own master when none is running. Without a display the
# node's status line, once a second, shows that it is alive.
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
bash "$repo/scripts/install_deps.sh"
bash "$repo/scripts/build.sh"
rbs_source_devel
exec roslaunch rigid_body_sim rigid_body_sim.launch "$@"
