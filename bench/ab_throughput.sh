#!/bin/bash
# A/B comparison of throughput_bench between two commits: builds it for each
# (a detached git worktree and a catkin workspace of its own per commit,
# under $RBS_AB_DIR, default /tmp/rbs_ab, kept for the next call), then runs
# the two in turn, A B A B ..., and prints for every case the median time of
# each, the median of the pair-by-pair ratios B/A and their range, flagging
# the cases that B runs more than --threshold percent slower. Pairing the
# runs cancels most of the drift of a shared machine; the range of the
# ratios shows the noise that is left.
#
#   bench/ab_throughput.sh [options] [A [B]]
#     A   the base commit (default: the merge-base of HEAD and main, or HEAD~1
#         when HEAD is on main)
#     B   the commit compared with it (default: HEAD); "." is this checkout as
#         it is, uncommitted changes included
#   --pairs N         A/B pairs of runs (default 7)
#   --min-time S      --benchmark_min_time of each case in each run (default 0.1)
#   --filter REGEX    --benchmark_filter: only these cases (default: all)
#   --threshold PCT   flag a case whose B/A exceeds 1 + PCT/100 (default 3)
#   --pin CPUS        run both under taskset -c CPUS
#   --strict          exit 1 when a case is flagged (else 0 either way)
#   --report DIR      print the table of an earlier call's runs (the directory
#                     it names at the end) again, building and running nothing
#
# The whole suite at the defaults takes about 6 minutes for 7 pairs on two
# cores, after the builds (about 3 minutes each, once per commit).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export PATH="/usr/bin:$PATH"
pairs=7
min_time=0.1
filter=""
threshold=3
pin=""
strict=0
report=""
positional=()
while [ $# -gt 0 ]; do
  case "$1" in
    --pairs) pairs="$2"; shift 2 ;;
    --min-time) min_time="$2"; shift 2 ;;
    --filter) filter="$2"; shift 2 ;;
    --threshold) threshold="$2"; shift 2 ;;
    --pin) pin="$2"; shift 2 ;;
    --strict) strict=1; shift ;;
    --report) report="$2"; shift 2 ;;
    -h|--help) sed -n '2,28p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "ab_throughput: unknown option $1" >&2; exit 2 ;;
    *) positional+=("$1"); shift ;;
  esac
done
[ ${#positional[@]} -le 2 ] || { echo "ab_throughput: at most two commits" >&2; exit 2; }
[ "$pairs" -ge 1 ] 2>/dev/null || { echo "ab_throughput: --pairs takes a whole number >= 1" >&2; exit 2; }
dir="${RBS_AB_DIR:-/tmp/rbs_ab}"
mkdir -p "$dir"

# ---- the table ----------------------------------------------------------------
# Prints the table of the runs in $1 (a1.json, b1.json, ... and labels).
table() {
  cat "$1/labels"
  /usr/bin/python3 - "$1" "$threshold" "$strict" <<'PYTHON'
import glob
import json
import os
import statistics
import sys

runs, threshold, strict = sys.argv[1], float(sys.argv[2]), sys.argv[3] == "1"
pairs = len(glob.glob(os.path.join(runs, "b*.json")))
TO_NS = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}


def times(path):
    """Case name -> real time per iteration [ns] of one run."""
    with open(path) as f:
        report = json.load(f)
    return {
        b["name"]: b["real_time"] * TO_NS[b.get("time_unit", "ns")]
        for b in report["benchmarks"]
        if b.get("run_type", "iteration") == "iteration" and "error_occurred" not in b
    }


a_runs = [times(os.path.join(runs, "a%d.json" % i)) for i in range(1, pairs + 1)]
b_runs = [times(os.path.join(runs, "b%d.json" % i)) for i in range(1, pairs + 1)]
names = [n for n in a_runs[0] if all(n in r for r in a_runs + b_runs)]
only = sorted(set().union(*a_runs, *b_runs) - set(names))


def fmt(ns):
    for unit, scale in (("s", 1e9), ("ms", 1e6), ("us", 1e3)):
        if ns >= scale:
            return "%.3g %s" % (ns / scale, unit)
    return "%.3g ns" % ns


width = max([len(n) for n in names] + [4])
print("%-*s %9s %9s %6s %13s %7s" % (width, "case", "A median", "B median", "B/A",
                                     "B/A range", "B slower"))
flagged = []
for name in names:
    a = [r[name] for r in a_runs]
    b = [r[name] for r in b_runs]
    ratios = [y / x for x, y in zip(a, b)]
    ratio = statistics.median(ratios)
    flag = ratio > 1 + threshold / 100
    if flag:
        flagged.append(name)
    line = "%-*s %9s %9s %6.3f %6.3f-%-6.3f %4d/%-3d%s" % (
        width, name, fmt(statistics.median(a)), fmt(statistics.median(b)), ratio,
        min(ratios), max(ratios), sum(r > 1 for r in ratios), pairs,
        " SLOWER" if flag else "")
    print(line.rstrip())
for name in only:
    print("%-*s   in one side's runs only" % (width, name))
print("B/A: the median of the %d pair-by-pair ratios, and their range; B slower: in how many "
      "pairs;\nSLOWER: B/A above %.3g (B more than %g %% slower)" % (pairs, 1 + threshold / 100,
                                                                     threshold))
print("%d of %d cases slower by more than %g %%%s" % (
    len(flagged), len(names), threshold, (": " + ", ".join(flagged)) if flagged else ""))
sys.exit(1 if strict and flagged else 0)
PYTHON
}

if [ -n "$report" ]; then
  table "$report"
  exit
fi

# ---- the two commits --------------------------------------------------------
b_spec="${positional[1]:-HEAD}"
if [ ${#positional[@]} -ge 1 ]; then
  a_spec="${positional[0]}"
else
  a_spec="$(git -C "$repo" merge-base HEAD main 2>/dev/null || true)"
  if [ -z "$a_spec" ] || [ "$a_spec" = "$(git -C "$repo" rev-parse HEAD)" ]; then a_spec="HEAD~1"; fi
fi
a_sha="$(git -C "$repo" rev-parse --verify "$a_spec^{commit}")"
if [ "$b_spec" = "." ]; then
  b_sha="checkout"
else
  b_sha="$(git -C "$repo" rev-parse --verify "$b_spec^{commit}")"
fi

# Builds throughput_bench for a commit (or "checkout": this checkout as it is)
# and prints the binary's path.
build() {
  local sha="$1" src ws log
  if [ "$sha" = "checkout" ]; then
    src="$repo"
    ws="$dir/checkout_ws"
    log="$dir/checkout_build.log"
  else
    src="$dir/$sha/src"
    ws="$dir/$sha/ws"
    log="$dir/$sha/build.log"
    if [ ! -e "$src/.git" ]; then
      mkdir -p "$dir/$sha"
      git -C "$repo" worktree prune
      git -C "$repo" worktree add --detach "$src" "$sha" >/dev/null 2>&1
    fi
  fi
  echo "ab_throughput: building throughput_bench of $sha in $ws (log: $log)" >&2
  if ! RBS_WS="$ws" bash "$src/scripts/build.sh" -DRBS_BUILD_BENCH=ON throughput_bench >"$log" 2>&1; then
    tail -30 "$log" >&2
    echo "ab_throughput: the build of $sha failed" >&2
    exit 1
  fi
  echo "$ws/devel/lib/rigid_body_sim/throughput_bench"
}
bin_a="$(build "$a_sha")"
bin_b="$(build "$b_sha")"

# ---- the runs, A B A B ... --------------------------------------------------
runs="$(mktemp -d "$dir/runs.XXXXXX")"
printf 'A = %s (%s)\nB = %s (%s)\n' "$a_spec" "$a_sha" "$b_spec" "$b_sha" >"$runs/labels"
args=(--benchmark_repetitions=1 --benchmark_min_time="$min_time"
  --benchmark_format=json)
[ -n "$filter" ] && args+=(--benchmark_filter="$filter")
prefix=()
[ -n "$pin" ] && prefix=(taskset -c "$pin")
start=$(date +%s)
for ((i = 1; i <= pairs; i++)); do
  for side in a b; do
    bin="$bin_a"
    [ "$side" = b ] && bin="$bin_b"
    echo "ab_throughput: pair $i/$pairs, $side" >&2
    "${prefix[@]}" "$bin" "${args[@]}" >"$runs/$side$i.json" 2>"$runs/$side$i.log"
  done
done
echo "ab_throughput: $pairs pairs in $(($(date +%s) - start)) s; runs in $runs" >&2

table "$runs"
