#!/bin/bash
# Runs clang-tidy with the checks of .clang-tidy on every source of src/,
# and through them on the package's headers they include, and exits non-zero
# on any finding. It reads the compile commands of the catkin workspace
# (scripts/common.sh: RBS_WS or .build_ws/), which scripts/build.sh writes:
# build first. Run by the test command after the build.
#
#   bash scripts/tidy_check.sh           # every source of src/
#   bash scripts/tidy_check.sh FILE...   # these files
#
# A header named on the command line is checked through the source of the
# same name when there is one, else on its own. Sources run RBS_TIDY_JOBS at
# a time (default RBS_JOBS, 2).
#
# A source found clean is remembered in the workspace (build/tidy_cache/)
# under a key of everything clang-tidy's result depends on: its version,
# .clang-tidy, the compile command and the content of every file of the
# translation unit (scripts/tidy_keys.py). It is checked again only when
# that key changes; RBS_TIDY_CACHE=0 checks every source. A fresh workspace
# (as in CI) checks every source.
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$repo"
tidy_jobs="${RBS_TIDY_JOBS:-$jobs}"
db="$ws/build/compile_commands.json"
if [ ! -f "$db" ]; then
  echo "tidy_check: no $db: build first (bash scripts/build.sh)" >&2
  exit 1
fi
command -v clang-tidy >/dev/null || {
  echo "tidy_check: clang-tidy not found (bash scripts/install_deps.sh)" >&2
  exit 1
}

case "${1:-}" in
-*)
  echo "usage: tidy_check.sh [FILE...]" >&2
  exit 2
  ;;
esac
files=()
if [ $# -gt 0 ]; then
  files=("$@")
else
  mapfile -t files < <(find src -name '*.cpp' | sort)
fi

# A header stands for the source of its name (src/ros/x.cpp for
# include/rigid_body_sim/ros/x.h), else for itself; each once.
targets=()
for f in "${files[@]}"; do
  f="${f#./}"
  if [[ "$f" == *.h ]]; then
    stem="$(basename "$f" .h)"
    source_file="$(find src -name "$stem.cpp" | head -1)"
    [ -n "$source_file" ] && f="$source_file"
  fi
  targets+=("$f")
done
mapfile -t targets < <(printf '%s\n' "${targets[@]}" | sort -u)

# The compile commands name the sources through the workspace's link to the
# checkout: clang-tidy is given the same paths.
link="$ws/src/rigid_body_sim"
tidy_args="--quiet"
cache="$ws/build/tidy_cache"
mkdir -p "$cache"
declare -A key_of
if [ "${RBS_TIDY_CACHE:-1}" != 0 ]; then
  while read -r path key; do
    key_of["${path#"$link/"}"]="$key"
  done < <(/usr/bin/python3 "$repo/scripts/tidy_keys.py" "$db" "$repo/.clang-tidy" "$tidy_args" \
    "${targets[@]/#/$link/}")
fi
to_check=()
for f in "${targets[@]}"; do
  key="${key_of[$f]:--}"
  if [ "$key" != "-" ] && [ -f "$cache/$key" ]; then continue; fi
  to_check+=("$f ${key}")
done

logs="$(mktemp -d)"
trap 'rm -rf "$logs"' EXIT
start=$(date +%s)
cached=$((${#targets[@]} - ${#to_check[@]}))
echo "tidy_check: ${#targets[@]} file(s): ${#to_check[@]} to check, $tidy_jobs at a time; $cached clean as cached"
build_dir="$ws/build"
export link logs cache tidy_args build_dir
# Each line "<source> <key>" becomes the inner script's $1 and $2.
# RBS_TIDY_REVERSE=1 takes them last first, so that a second run started
# beside a first one meets it in the middle: each skips what the other has
# found clean by then.
order=(cat)
[ "${RBS_TIDY_REVERSE:-0}" = 1 ] && order=(tac)
# shellcheck disable=SC2016  # expanded by the inner bash
printf '%s\n' "${to_check[@]}" | "${order[@]}" | xargs -r -P "$tidy_jobs" -L 1 bash -c '
  [ "$2" != "-" ] && [ -f "$cache/$2" ] && exit 0
  out="$logs/$(echo "$1" | tr / _).log"
  # shellcheck disable=SC2086  # tidy_args: words
  if clang-tidy -p "$build_dir" $tidy_args "$link/$1" >"$out" 2>&1; then
    [ "$2" = "-" ] || touch "$cache/$2"
  else
    touch "$out.failed"
  fi
' _
failed=0
for entry in "${to_check[@]}"; do
  out="$logs/$(echo "${entry% *}" | tr / _).log"
  if [ -f "$out.failed" ]; then
    failed=1
    # clang-tidy's counts of suppressed warnings are noise here.
    grep -v -e '^[0-9]* warnings\{0,1\} generated' -e '^Suppressed [0-9]* warnings' \
      -e '^Use -header-filter' -e '^[0-9]* warnings\{0,1\} treated as errors' "$out" |
      sed "s|$link/||g" >&2 || true
  fi
done
# Keys no source has any more are dropped after a run over every source.
if [ $# -eq 0 ] && [ "${RBS_TIDY_CACHE:-1}" != 0 ]; then
  declare -A live
  for key in "${key_of[@]}"; do live["$key"]=1; done
  for entry in "$cache"/*; do
    [ -e "$entry" ] || continue
    [ -n "${live[$(basename "$entry")]:-}" ] || rm -f "$entry"
  done
fi
elapsed=$(($(date +%s) - start))
if [ "$failed" -ne 0 ]; then
  echo "tidy_check: findings above (.clang-tidy; ${elapsed} s)" >&2
  exit 1
fi
echo "tidy_check: OK (${#targets[@]} file(s), ${#to_check[@]} checked, ${elapsed} s)"
