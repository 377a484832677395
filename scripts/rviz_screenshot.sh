#!/bin/bash
# Renders the default scene in rviz on a virtual display (Xvfb), the box
# pushed so that its applied wrench shows, and saves a screenshot to
# doc/rviz_default_scene.png:
#   bash scripts/rviz_screenshot.sh [seconds to let the scene run, default 6]
# or the quadrotor example (launch/quadrotor.launch) taking off, at 1/20 of
# real time so that the picture catches it climbing and turning with its
# applied wrench drawn, to doc/rviz_quadrotor.png:
#   bash scripts/rviz_screenshot.sh quadrotor [seconds to let it run, default 12]
# Runs on its own master port (RBS_SCREENSHOT_PORT, default 11399) so that it
# leaves any running simulation alone.
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
scene=default
if [ "${1:-}" = quadrotor ]; then
  scene=quadrotor
  shift
fi
port="${RBS_SCREENSHOT_PORT:-11399}"
display=":${RBS_SCREENSHOT_DISPLAY:-97}"

# The virtual display, rviz and the screenshot tool on top of the usual packages.
bash "$repo/scripts/install_deps.sh" xvfb rviz imagemagick libgl1-mesa-dri
bash "$repo/scripts/build.sh"
rbs_source_devel
export ROS_MASTER_URI="http://localhost:$port"
export DISPLAY="$display"
export LIBGL_ALWAYS_SOFTWARE=1   # Xvfb has no GPU: Mesa's software renderer

pids=()
cleanup() { for pid in "${pids[@]}"; do kill -INT "$pid" 2>/dev/null || true; done; wait 2>/dev/null || true; }
trap cleanup EXIT

Xvfb "$display" -screen 0 1280x720x24 -nolisten tcp >/dev/null 2>&1 &
pids+=($!)
sleep 2
if [ "$scene" = quadrotor ]; then
  out="$repo/doc/rviz_quadrotor.png"
  roslaunch -p "$port" rigid_body_sim quadrotor.launch rviz:=true real_time_factor:=0.05 \
    >/tmp/rviz_screenshot_launch.log 2>&1 &
  pids+=($!)
  sleep "${1:-12}"
else
  out="$repo/doc/rviz_default_scene.png"
  roslaunch -p "$port" rigid_body_sim rigid_body_sim.launch rviz:=true >/tmp/rviz_screenshot_launch.log 2>&1 &
  pids+=($!)
  sleep "${1:-6}"
  # A held push on the box, so that the applied-wrench display has arrows to draw.
  rosservice call /rigid_body_sim/apply_body_wrench \
    "{body: box, reference_frame: box, reference_point: {x: 0.15, y: 0.1, z: 0.05}, wrench: {force: {z: 0.2}}, duration: {secs: -1, nsecs: 0}}" >/dev/null
  sleep 4   # rviz itself takes a few seconds to come up under software rendering
fi

mkdir -p "$(dirname "$out")"
import -display "$display" -window root "$out"
echo "wrote $out"
