#!/bin/bash
# The package as `catkin_make install` ships it, run from the install space
# alone. Installs the built workspace WS into a prefix of its own (the build
# directory reused, its install prefix put back afterwards), then, in a clean
# environment (env -i with PATH and HOME, only <prefix>/setup.bash sourced)
# and on a master of its own (the first free port from 11399):
#   - ROS_PACKAGE_PATH, PYTHONPATH, CMAKE_PREFIX_PATH, LD_LIBRARY_PATH,
#     PKG_CONFIG_PATH and PATH name nothing inside WS or the checkout; the
#     package, the node, rigid_body_sim.testing and the messages resolve into
#     the prefix;
#   - roslaunch rigid_body_sim rigid_body_sim.launch: /rigid_body_sim/bodies
#     publishes;
#   - roslaunch rigid_body_sim sharded.launch shards:=2: both shards publish,
#     shard k pinned to core k mod the cores (scripts/on_core.sh, installed);
#     with pin_cores:=false both keep this shell's CPU affinity;
#   - rigid_body_sim.testing.SimClient: pause(), then step(10) returns the
#     default scene's four bodies and a state hash;
#   - roslaunch rigid_body_sim quadrotor.launch: the URDF quadrotor, with
#     robot_state_publisher and the installed controller in lockstep, climbs
#     past 0.5 m; the same with in_process:=true, node and controller loaded
#     as nodelets from the prefix's libraries into one manager.
# Every wait is bounded and every process started is stopped on exit. The
# first failure prints one "install_space_test: FAIL: ..." line (then the
# log it concerns) and exits 1.
#   install_space_test.sh WS
set -Eeuo pipefail
self="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/$(basename "${BASH_SOURCE[0]}")"
repo="$(cd "$(dirname "$self")/../.." && pwd -P)"

fail() {
  echo "install_space_test: FAIL: $1" >&2
  if [ -n "${2:-}" ] && [ -f "$2" ]; then
    echo "--- last lines of $2:" >&2
    tail -n 40 "$2" >&2
  fi
  exit 1
}
# A failing command substitution reports once, in the shell that runs it.
trap '[ "$BASH_SUBSHELL" -gt 0 ] || fail "\"$BASH_COMMAND\" exited $? (line $LINENO)"' ERR

# ---- in the install space (the script runs itself under env -i) ----------
if [ "${1:-}" = "--in-install-space" ]; then
  prefix="$2" ws="$3" tmp="$4"
  groups=()     # process groups started here, the master first
  node_pids=()  # the nodes' PIDs, in case a roslaunch leaves one behind
  # Stops process group $1: SIGINT (roslaunch then stops its nodes), SIGKILL after 20 s.
  stop() {
    kill -INT -- "-$1" 2>/dev/null || return 0
    for _ in $(seq 200); do
      if ! kill -0 -- "-$1" 2>/dev/null; then return 0; fi
      sleep 0.1
    done
    kill -KILL -- "-$1" 2>/dev/null || true
  }
  # shellcheck disable=SC2317  # run by the EXIT trap
  stop_all() {
    local i pid
    for ((i = ${#groups[@]} - 1; i >= 0; i--)); do stop "${groups[$i]}"; done
    for pid in "${node_pids[@]}"; do kill -KILL "$pid" 2>/dev/null || true; done
  }
  trap stop_all EXIT
  # Starts "${@:2}" in a session of its own, output to $tmp/$1.log; its PID in $started.
  start() {
    setsid "${@:2}" > "$tmp/$1.log" 2>&1 < /dev/null &
    started=$!
    groups+=("$started")
  }

  set +u
  # shellcheck source=/dev/null
  source "$prefix/setup.bash"
  set -u
  port=$(/usr/bin/python3 -c '
import socket
for port in range(11399, 11499):
    s = socket.socket()
    try:
        s.bind(("", port))
    except OSError:
        continue
    finally:
        s.close()
    print(port)
    break')
  [ -n "$port" ] || fail "no free port in 11399-11498 for the master"
  export ROS_MASTER_URI="http://localhost:$port" ROS_LOG_DIR="$tmp/ros_log"

  # The environment: nothing of the workspace or the checkout.
  ws_real="$(cd "$ws" && pwd -P)"
  for var in ROS_PACKAGE_PATH PYTHONPATH CMAKE_PREFIX_PATH LD_LIBRARY_PATH PKG_CONFIG_PATH PATH; do
    IFS=: read -r -a entries <<< "${!var:-}"
    for entry in "${entries[@]}"; do
      [ -n "$entry" ] || continue
      real="$(realpath -m "$entry")"
      case "$real/" in
        "$ws_real"/*|"$repo"/*) fail "$var has $entry, inside the workspace or the checkout" ;;
      esac
    done
  done
  [[ ":$ROS_PACKAGE_PATH:" == *":$prefix/share:"* ]] \
    || fail "ROS_PACKAGE_PATH ($ROS_PACKAGE_PATH) lacks $prefix/share"
  found="$(rospack find rigid_body_sim)" || fail "rospack find rigid_body_sim"
  [ "$found" = "$prefix/share/rigid_body_sim" ] \
    || fail "rospack finds rigid_body_sim in $found, not in $prefix/share"
  /usr/bin/python3 - "$prefix" > "$tmp/resolve.log" 2>&1 <<'EOF' || fail "resolving the package's files from the install space" "$tmp/resolve.log"
import os, sys
import roslib.packages
import rigid_body_sim.msg, rigid_body_sim.srv, rigid_body_sim.testing
prefix = sys.argv[1] + os.sep
found = {'rigid_body_sim_node': roslib.packages.find_node('rigid_body_sim', 'rigid_body_sim_node'),
         'on_core.sh': roslib.packages.find_node('rigid_body_sim', 'on_core.sh'),
         'quadrotor_controller': roslib.packages.find_node('rigid_body_sim', 'quadrotor_controller')}
for name, paths in found.items():
    print(name, paths)
    assert paths and paths[0].startswith(prefix), '%s not in the install space' % name
for module in (rigid_body_sim.msg, rigid_body_sim.srv, rigid_body_sim.testing):
    print(module.__name__, module.__file__)
    assert module.__file__.startswith(prefix), '%s not in the install space' % module.__name__
EOF

  start roscore roscore -p "$port"
  for _ in $(seq 100); do
    if rostopic list > /dev/null 2>&1; then break; fi
    sleep 0.2
  done
  rostopic list > /dev/null 2>&1 || fail "no master on port $port within 20 s" "$tmp/roscore.log"

  # The PID of node $1, read over its XML-RPC API.
  node_pid() {
    /usr/bin/python3 -c '
import sys
from xmlrpc.client import ServerProxy
import rosgraph, rosnode
uri = rosnode.get_api_uri(rosgraph.Master("/install_space_test"), sys.argv[1], skip_cache=True)
code, _, pid = ServerProxy(uri).getPid("/install_space_test")
print(pid if code == 1 else "")' "$1"
  }
  # Waits (at most 20 s) for a message on topic $1; the log $2 on failure.
  wait_topic() {
    timeout -k 5 20 rostopic echo -n 1 "$1" > /dev/null 2>&1 \
      || fail "no message on $1 within 20 s" "$2"
  }
  launch() {
    start "$1" roslaunch --sigint-timeout 5 --sigterm-timeout 2 "${@:2}"
  }

  launch single rigid_body_sim rigid_body_sim.launch
  single=$started
  wait_topic /rigid_body_sim/bodies "$tmp/single.log"
  node_pids+=("$(node_pid /rigid_body_sim)")

  # The client, as a downstream test imports it.
  timeout -k 5 40 /usr/bin/python3 > "$tmp/client.log" 2>&1 - <<'EOF' || fail "SimClient().step(10) from the install space" "$tmp/client.log"
import rospy
from rigid_body_sim.testing import SimClient
rospy.init_node('install_space_test', anonymous=True)
sim = SimClient(timeout=20.0)
sim.pause()
result = sim.step(10)
print(result.sim_time, sorted(result.states), result.state_hash)
assert sorted(result.states) == ['box', 'rod', 't_handle', 'top'], sorted(result.states)
assert len(result.state_hash) == 16, result.state_hash
sim.resume()
EOF
  stop "$single"

  # Waits (at most 30 s) for base_link to climb past 0.5 m; the log $1 on failure.
  wait_climb() {
    timeout -k 5 40 /usr/bin/python3 > "$tmp/climb.log" 2>&1 - <<'EOF' || fail "quadrotor.launch: base_link did not climb past 0.5 m" "$1"
import threading
import rospy
from nav_msgs.msg import Odometry
rospy.init_node('install_space_test', anonymous=True)
climbed = threading.Event()
rospy.Subscriber('/rigid_body_sim/base_link/odom', Odometry,
                 lambda odom: odom.pose.pose.position.z > 0.5 and climbed.set())
assert climbed.wait(30.0), 'no odometry of base_link above 0.5 m within 30 s'
EOF
  }

  # The quadrotor example, its controller and URDF from the install space.
  launch quadrotor rigid_body_sim quadrotor.launch
  quadrotor=$started
  wait_climb "$tmp/quadrotor.log"
  node_pids+=("$(node_pid /rigid_body_sim)")
  stop "$quadrotor"

  # The same as nodelets of one manager, their libraries the prefix's.
  launch in_process rigid_body_sim quadrotor.launch in_process:=true
  in_process=$started
  wait_climb "$tmp/in_process.log"
  manager_pid="$(node_pid /rigid_body_sim_manager)"
  node_pids+=("$manager_pid")
  for library in librigid_body_sim_nodelets.so librigid_body_sim_example_nodelets.so; do
    grep -q " $prefix/lib/$library\$" "/proc/$manager_pid/maps" \
      || fail "the nodelet manager did not load $prefix/lib/$library" "$tmp/in_process.log"
  done
  stop "$in_process"

  # Shards, pinned (default) and not.
  cores=$(nproc --all)
  own_affinity="$(taskset -pc $$ | sed 's/.*: //')"
  for pin in true false; do
    launch "sharded_$pin" rigid_body_sim sharded.launch shards:=2 "pin_cores:=$pin"
    sharded=$started
    for k in 0 1; do
      wait_topic "/rigid_body_sim_$k/bodies" "$tmp/sharded_$pin.log"
      pid="$(node_pid "/rigid_body_sim_$k")"
      [ -n "$pid" ] || fail "no PID from /rigid_body_sim_$k" "$tmp/sharded_$pin.log"
      node_pids+=("$pid")
      affinity="$(taskset -pc "$pid" | sed 's/.*: //')"
      if [ "$pin" = true ]; then want=$((k % cores)); else want="$own_affinity"; fi
      [ "$affinity" = "$want" ] \
        || fail "sharded.launch pin_cores:=$pin: shard $k runs on CPUs $affinity, not $want" \
                "$tmp/sharded_$pin.log"
    done
    stop "$sharded"
  done
  exit 0
fi

# ---- install, then run the above in a clean environment ------------------
[ $# -eq 1 ] || { echo "usage: $0 WS" >&2; exit 2; }
ws="$(cd "$1" && pwd)"
[ -f "$ws/build/CMakeCache.txt" ] || fail "$ws/build is not a configured catkin build directory"
start_time=$(date +%s)
old_prefix="$(sed -n 's/^CMAKE_INSTALL_PREFIX:PATH=//p' "$ws/build/CMakeCache.txt")"
# Configured as the workspace was: without its own devel space in the prefix path.
cmake_prefix_path="$(tr ':' '\n' <<< "${CMAKE_PREFIX_PATH:-}" | { grep -v "^$ws/" || true; } | paste -sd: -)"
prefix="" tmp="" installing=""
restore() {
  if [ -n "$installing" ] && [ -n "$old_prefix" ]; then
    CMAKE_PREFIX_PATH="$cmake_prefix_path" cmake -DCMAKE_INSTALL_PREFIX="$old_prefix" \
      "$ws/build" > /dev/null 2>&1 \
      || echo "install_space_test: could not set $ws/build's install prefix back to $old_prefix" >&2
  fi
  for dir in "$prefix" "$tmp"; do [ -z "$dir" ] || rm -rf "$dir"; done
}
trap restore EXIT
prefix="$(mktemp -d "${TMPDIR:-/tmp}/rbs_install_space.XXXXXX")"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/rbs_install_space_logs.XXXXXX")"

installing=1
(cd "$ws" && CMAKE_PREFIX_PATH="$cmake_prefix_path" catkin_make install \
  -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_INSTALL_PREFIX="$prefix" -j"${RBS_JOBS:-2}") \
  > "$tmp/install.log" 2>&1 || fail "catkin_make install -DCMAKE_INSTALL_PREFIX=$prefix" "$tmp/install.log"
# It prints its own FAIL line.
env -i PATH=/usr/bin:/bin HOME="$HOME" bash "$self" --in-install-space "$prefix" "$ws" "$tmp" || exit 1
echo "install_space_test: OK in $(( $(date +%s) - start_time )) s (install space, node, Python client, quadrotor as programs and as nodelets, 2 shards pinned and not)"
