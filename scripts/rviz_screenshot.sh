#!/bin/bash
# Renders the default scene in rviz on a virtual display (Xvfb) and saves a
# screenshot to doc/rviz_default_scene.png:
#   bash scripts/rviz_screenshot.sh [seconds to let the scene run, default 6]
# Runs on its own master port (RBS_SCREENSHOT_PORT, default 11399) so that it
# leaves any running simulation alone.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ws="${RBS_WS:-$repo/.build_ws}"
settle_s="${1:-6}"
port="${RBS_SCREENSHOT_PORT:-11399}"
display=":${RBS_SCREENSHOT_DISPLAY:-97}"
out="$repo/doc/rviz_default_scene.png"

needed=(xvfb rviz imagemagick libgl1-mesa-dri)
missing=()
for p in "${needed[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

bash "$repo/scripts/build.sh"
export PATH="/usr/bin:$PATH"
set +u; source "$ws/devel/setup.bash"; set -u
export ROS_MASTER_URI="http://localhost:$port"
export DISPLAY="$display"
export LIBGL_ALWAYS_SOFTWARE=1   # Xvfb has no GPU: Mesa's software renderer

pids=()
cleanup() { for pid in "${pids[@]}"; do kill -INT "$pid" 2>/dev/null || true; done; wait 2>/dev/null || true; }
trap cleanup EXIT

Xvfb "$display" -screen 0 1280x720x24 -nolisten tcp >/dev/null 2>&1 &
pids+=($!)
sleep 2
roslaunch -p "$port" rigid_body_sim rigid_body_sim.launch rviz:=true >/tmp/rviz_screenshot_launch.log 2>&1 &
pids+=($!)
sleep "$settle_s"
sleep 4   # rviz itself takes a few seconds to come up under software rendering

mkdir -p "$(dirname "$out")"
import -display "$display" -window root "$out"
echo "wrote $out"
