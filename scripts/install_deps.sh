#!/bin/bash
# Installs Debian bookworm's ROS 1 packages and the tools rigid_body_sim needs,
# plus any package named on the command line (scripts/bench.sh adds the peer
# engines and matplotlib). Skips apt entirely when everything is already there.
set -euo pipefail
packages=(
  build-essential cmake clang-format clang-tidy pyflakes3 shellcheck catkin-lint catkin python3-catkin-pkg python3-rospkg
  iproute2
  ros-core-dev libroscpp-dev librostest-dev python3-rostest
  ros-message-generation ros-message-runtime
  libtf2-ros-dev libtf2-eigen-dev libtf2-msgs-dev libgeometry-msgs-dev
  libstd-srvs-dev libvisualization-msgs-dev libdiagnostic-updater-dev
  libdiagnostic-msgs-dev libros-rosgraph-msgs-dev libnav-msgs-dev libsensor-msgs-dev
  libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure
  libnodeletlib-dev libnodeletlib-tools pluginlib-dev
  rosbash python3-roslib libroslib-dev liburdf-dev liburdfdom-dev liburdfdom-headers-dev
  ros-robot-state-publisher librosbag-dev librosbag-storage-dev python3-rosbag
  python3-geometry-msgs python3-std-srvs python3-diagnostic-msgs
  python3-tf2-msgs python3-visualization-msgs python3-rosgraph-msgs
  python3-nav-msgs python3-sensor-msgs python3-rospy python3-numpy python3-yaml
  libeigen3-dev libboost-dev libgtest-dev googletest libbenchmark-dev libyaml-cpp-dev libyaml-dev
  "$@"
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  echo "install_deps: installing ${missing[*]}"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
