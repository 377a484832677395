#!/bin/bash
# Builds rigid_body_sim and launches the node on the default scene:
#   bash scripts/run.sh [roslaunch args, e.g. integrator:=rk4 rviz:=true]
# roslaunch starts its own master when none is running. Without a display the
# node's status line, once a second, shows that it is alive.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ws="${RBS_WS:-$repo/.build_ws}"
bash "$repo/scripts/build.sh"
export PATH="/usr/bin:$PATH"
set +u; source "$ws/devel/setup.bash"; set -u
exec roslaunch rigid_body_sim rigid_body_sim.launch "$@"
