#!/bin/bash
# Runs clang-tidy with the checks of .clang-tidy on the C++ of src/ and
# include/ and exits non-zero on any finding. It reads the compile commands
# of the catkin workspace (scripts/common.sh: RBS_WS or .build_ws/), which
# scripts/build.sh writes: build first. Run by the test command after the
# build.
#
#   bash scripts/tidy_check.sh           # the files changed since main
#   bash scripts/tidy_check.sh --all     # every source of src/
#   bash scripts/tidy_check.sh FILE...   # these files
#
# The changed files are those that differ from the merge-base of HEAD and
# origin/main (else main), committed or not, plus new untracked ones. When
# there are none (main itself, as in CI on a clean clone), those the last
# commit changed against its first parent (a merge: the whole branch it
# brings); when that commit changed none either, nothing is checked. A
# changed header is checked through the source of the same name when there
# is one (else on its own); every source checks the package's headers it
# includes. Sources run RBS_TIDY_JOBS at a time (default RBS_JOBS, 2): a few
# files take seconds; --all (65 sources) about 7 minutes of CPU, so 3.5 to 4
# minutes on two idle cores (9 to 12 measured while other builds shared them).
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

# Every source of src/, relative to the checkout.
all_sources() { find src -name '*.cpp' | sort; }

files=()
mode="changed"
if [ "${1:-}" = "--all" ]; then
  mode="all"
elif [ $# -gt 0 ]; then
  mode="named"
  files=("$@")
else
  mapfile -t files < <(rbs_changed_cxx)
  if [ ${#files[@]} -eq 0 ] && git rev-parse --verify -q "HEAD^1" >/dev/null; then
    echo "tidy_check: no C++ changed since main: checking what the last commit changed"
    mapfile -t files < <(rbs_changed_cxx "HEAD^1")
  fi
  if [ ${#files[@]} -eq 0 ]; then
    echo "tidy_check: OK (no C++ changed; --all checks every source)"
    exit 0
  fi
fi
[ "$mode" = "all" ] && mapfile -t files < <(all_sources)

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
logs="$(mktemp -d)"
trap 'rm -rf "$logs"' EXIT
start=$(date +%s)
echo "tidy_check: ${#targets[@]} file(s), $tidy_jobs at a time"
export link logs
# shellcheck disable=SC2016  # expanded by the inner bash
printf '%s\n' "${targets[@]}" | xargs -P "$tidy_jobs" -I{} bash -c '
  out="$logs/$(echo "$1" | tr / _).log"
  if ! clang-tidy -p "$2" --quiet "$link/$1" >"$out" 2>&1; then touch "$out.failed"; fi
' _ {} "$ws/build"
failed=0
for f in "${targets[@]}"; do
  out="$logs/$(echo "$f" | tr / _).log"
  if [ -f "$out.failed" ]; then
    failed=1
    # clang-tidy's counts of suppressed warnings are noise here.
    grep -v -e '^[0-9]* warnings\{0,1\} generated' -e '^Suppressed [0-9]* warnings' \
      -e '^Use -header-filter' -e '^[0-9]* warnings\{0,1\} treated as errors' "$out" |
      sed "s|$link/||g" >&2 || true
  fi
done
elapsed=$(($(date +%s) - start))
if [ "$failed" -ne 0 ]; then
  echo "tidy_check: findings above (.clang-tidy; ${elapsed} s)" >&2
  exit 1
fi
echo "tidy_check: OK (${#targets[@]} file(s), ${elapsed} s)"
