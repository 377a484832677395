# shellcheck shell=bash
# Sourced (not run) by the scripts in scripts/: where the checkout and the
# catkin workspace are, ROS's environment, and the workspace helpers.
#
#   repo  the checkout (this file's parent directory)
#   ws    the catkin workspace: RBS_WS, else $ws_default if the script set it
#         before sourcing this file, else .build_ws/ inside the checkout. The
#         workspace links back to the checkout, so one inside it must be a
#         hidden directory: roslaunch's search for launch files skips those
#         instead of looping through the link.
#   jobs  parallel build jobs: RBS_JOBS, default 2
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ws="${RBS_WS:-${ws_default:-$repo/.build_ws}}"
# shellcheck disable=SC2034  # read by the scripts that source this file
jobs="${RBS_JOBS:-2}"
# Debian's ROS lives in /usr; its Python is /usr/bin/python3, not whatever is first on PATH.
export PATH="/usr/bin:$PATH"

# Creates $ws with the checkout linked into its src/, then runs catkin_make
# there with ROS's Python and the given arguments; leaves the shell in $ws.
# The build writes build/compile_commands.json (scripts/tidy_check.sh).
rbs_catkin_make() {
  if ! command -v catkin_make >/dev/null; then
    echo "catkin_make not found: install the dependencies first (bash scripts/install_deps.sh)" >&2
    return 1
  fi
  mkdir -p "$ws/src"
  # A workspace kept from another checkout builds this one: the link follows.
  if [ -L "$ws/src/rigid_body_sim" ] && [ "$(readlink "$ws/src/rigid_body_sim")" != "$repo" ]; then
    ln -sfn "$repo" "$ws/src/rigid_body_sim"
  fi
  [ -e "$ws/src/rigid_body_sim" ] || ln -s "$repo" "$ws/src/rigid_body_sim"
  cd "$ws" || return 1
  catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_EXPORT_COMPILE_COMMANDS=ON "$@"
}

# Sources the workspace's devel/setup.bash (which reads unset variables).
rbs_source_devel() {
  set +u
  # shellcheck source=/dev/null
  source "$ws/devel/setup.bash"
  set -u
}

# Prints the merge-base of HEAD and origin/main, else of HEAD and main;
# nothing when there is neither.
rbs_main_base() {
  local ref
  for ref in origin/main main; do
    if git -C "$repo" rev-parse --verify -q "$ref^{commit}" >/dev/null; then
      git -C "$repo" merge-base HEAD "$ref"
      return 0
    fi
  done
}

# Prints the C++ files of src/, include/, test/, bench/ and fuzz/ (relative
# to the checkout, one a line) that differ from the commit BASE ($1),
# committed or not, and the new untracked ones; prints nothing when BASE is
# empty. format_check.sh --changed and tidy_check.sh use it.
rbs_changed_cxx() {
  local base="$1"
  [ -n "$base" ] || return 0
  {
    git -C "$repo" diff --name-only --diff-filter=ACMR "$base" -- src include test bench fuzz
    git -C "$repo" ls-files --others --exclude-standard -- src include test bench fuzz
  } | sort -u | while IFS= read -r f; do
    case "$f" in *.cpp | *.h) [ -f "$repo/$f" ] && echo "$f" ;; esac
  done
}
