#!/bin/bash
# Renders a scene in rviz on a virtual display (Xvfb) and saves a 1280x720
# screenshot; rviz shows the scene's own config full screen, without its
# Displays panel:
#   bash scripts/rviz_screenshot.sh             # doc/rviz_default_scene.png
#   bash scripts/rviz_screenshot.sh quadrotor   # doc/rviz_quadrotor.png
# Both scenes start paused (paused:=true), so the picture shows a state fixed
# by simulation time, however slowly rviz comes up:
# - default: config/rigid_body_sim.rviz on the default scene, the box pushed
#   by a held wrench and then stepped 1 s, so that its wrench display has
#   arrows to draw while every body stays in view;
# - quadrotor: config/quadrotor.rviz on launch/quadrotor.launch, run from
#   rest once rviz is up and paused after 4 s of simulation time, hovering,
#   with its odometry trail from the take-off and its rotors' thrust arrows.
# Runs on its own master port (RBS_SCREENSHOT_PORT, default 11399) so that it
# leaves any running simulation alone.
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
scene="${1:-default}"
case "$scene" in
  default) launch=rigid_body_sim.launch config=rigid_body_sim.rviz out=rviz_default_scene.png ;;
  quadrotor) launch=quadrotor.launch config=quadrotor.rviz out=rviz_quadrotor.png ;;
  *) echo "usage: $0 [default|quadrotor]" >&2; exit 2 ;;
esac
out="$repo/doc/$out"
port="${RBS_SCREENSHOT_PORT:-11399}"
display=":${RBS_SCREENSHOT_DISPLAY:-97}"

# The virtual display, rviz and the screenshot tool on top of the usual packages.
bash "$repo/scripts/install_deps.sh" xvfb rviz imagemagick libgl1-mesa-dri
bash "$repo/scripts/build.sh" rigid_body_sim_node quadrotor_controller
rbs_source_devel
export ROS_MASTER_URI="http://localhost:$port"
export DISPLAY="$display"
export LIBGL_ALWAYS_SOFTWARE=1   # Xvfb has no GPU: Mesa's software renderer

tmp="$(mktemp -d)"
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill -INT "$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true
  rm -rf "$tmp"
}
trap cleanup EXIT

# Waits (at most 60 s) until the ROS service $1 is advertised.
wait_for_service() {
  for _ in $(seq 120); do
    rosservice list 2>/dev/null | grep -qx "$1" && return 0
    sleep 0.5
  done
  echo "rviz_screenshot: $1 did not come up" >&2
  tail -n 20 "$tmp"/*.log >&2
  return 1
}

Xvfb "$display" -screen 0 1280x720x24 -nolisten tcp >/dev/null 2>&1 &
pids+=($!)
sleep 2
roslaunch -p "$port" rigid_body_sim "$launch" paused:=true >"$tmp/launch.log" 2>&1 &
pids+=($!)
# The scene's config without its panels: the 3D view fills the screen.
/usr/bin/python3 - "$repo/config/$config" "$tmp/screenshot.rviz" <<'EOF'
import sys
import yaml
with open(sys.argv[1]) as f:
    config = yaml.safe_load(f)
config.pop("Panels", None)
with open(sys.argv[2], "w") as f:
    yaml.safe_dump(config, f)
EOF
rosrun rviz rviz -d "$tmp/screenshot.rviz" --fullscreen __name:=rviz >"$tmp/rviz.log" 2>&1 &
pids+=($!)
wait_for_service /rigid_body_sim/step
if [ "$scene" = quadrotor ]; then
  # The rotors' thrust arrows, as quadrotor.launch draws them with rviz:=true.
  /usr/bin/python3 "$repo/scripts/thrust_markers.py" __name:=thrust_markers \
    _actuator_states:=/rigid_body_sim/base_link/actuator_states >"$tmp/markers.log" 2>&1 &
  pids+=($!)
fi
wait_for_service /rviz/load_config   # advertised once the window is shown
sleep 3                              # rviz's first frames under software rendering

if [ "$scene" = quadrotor ]; then
  rosservice call /rigid_body_sim/set_paused "data: false" >/dev/null
  for _ in $(seq 240); do   # at most 2 min of wall time
    [ "$(rostopic echo -n 1 /clock/clock/secs | head -n 1)" -ge 4 ] && break
    sleep 0.5
  done
  rosservice call /rigid_body_sim/set_paused "data: true" >/dev/null
else
  # A held push on the box, off its centre: a force and a torque to draw.
  rosservice call /rigid_body_sim/apply_body_wrench \
    "{body: box, reference_frame: box, reference_point: {x: 0.15, y: 0.1, z: 0.05}, wrench: {force: {z: 0.2}}, duration: {secs: -1, nsecs: 0}}" >/dev/null
  rosservice call /rigid_body_sim/step "steps: 1000" >/dev/null
fi
sleep 3   # rviz draws what the last messages carry

mkdir -p "$(dirname "$out")"
import -display "$display" -window root "$tmp/screenshot.png"
# 256 colours keep the picture small for the repository.
convert "$tmp/screenshot.png" -colors 256 "$out"
echo "wrote $out ($(stat -c %s "$out") bytes)"
