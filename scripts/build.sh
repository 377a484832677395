#!/bin/bash
# Installs what is missing, then builds rigid_body_sim in a catkin workspace
# (default: .build_ws/ inside the checkout; override with RBS_WS=/path). The
# workspace links back to the checkout, so it must be a hidden directory:
# roslaunch's search for launch files skips those instead of looping.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ws="${RBS_WS:-$repo/.build_ws}"
bash "$repo/scripts/install_deps.sh"
mkdir -p "$ws/src"
[ -e "$ws/src/rigid_body_sim" ] || ln -s "$repo" "$ws/src/rigid_body_sim"
cd "$ws"
# Debian's ROS lives in /usr; its Python is /usr/bin/python3, not whatever is first on PATH.
export PATH="/usr/bin:$PATH"
catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=Release "$@"
