#!/bin/bash
# The one bench command: installs what the benchmarks need (Google Benchmark,
# matplotlib and the peer engines MuJoCo, Bullet, ODE, Simbody and DART from
# Debian; Boost.Odeint comes with Boost's headers), builds
# with -DRBS_BUILD_BENCH=ON and rewrites bench/results/ (CSVs and plots).
# Pass --quick for a two-dt smoke run that writes to /tmp instead.
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
quick=""
repetitions=5
results="$repo/bench/results"
if [ "${1:-}" = "--quick" ]; then
  quick="--quick"
  repetitions=1
  results="$(mktemp -d)"
fi
# The peer engines (MuJoCo 2.2.2, Bullet 3.24, ODE 0.16, Simbody 3.7, DART
# 6.12) and the plotting; the bench builds without the engines too, and skips
# their lines.
bash "$repo/scripts/install_deps.sh" libmujoco-dev libbullet-dev libode-dev libsimbody-dev libdart-dev \
  pkg-config python3-matplotlib
# The node, the bench programs and wrench_flood (all of them with the option on).
bash "$repo/scripts/build.sh" -DRBS_BUILD_BENCH=ON
bin="$ws/devel/lib/rigid_body_sim"
mkdir -p "$results"
cd "$repo"
# The stress bench asserts and times nothing that the others compare: it runs
# on core 0 while work_precision times on core 1.
echo "== work-precision (ours and peers, core 1) beside the stability stress (core 0) =="
taskset -c 0 "$bin/stability_stress" $quick "$results/stress.csv" > "$results/stress.md" &
stress=$!
trap 'kill "$stress" 2>/dev/null || true' EXIT
taskset -c 1 "$bin/work_precision" "$results/work_precision.csv" $quick
/usr/bin/python3 bench/plot_work_precision.py "$results/work_precision.csv" "$results/work_precision.png"
wait "$stress"
echo "== stability stress =="
cat "$results/stress.md"
echo "== throughput (Google Benchmark) =="
# 0.2 s a repetition (the library's default is 0.5): the medians of five
# move by less than the machine's run-to-run noise, in half the time.
"$bin/throughput_bench" --benchmark_repetitions=$repetitions --benchmark_min_time=0.2 \
  --benchmark_report_aggregates_only=true \
  --benchmark_out="$results/throughput.json" --benchmark_out_format=json
echo "== a URDF of N links loaded as one body =="
"$bin/urdf_load_bench" --benchmark_repetitions=$repetitions --benchmark_report_aggregates_only=true \
  --benchmark_out="$results/urdf_load.json" --benchmark_out_format=json
echo "== the node under load =="
/usr/bin/python3 bench/node_load.py --workspace "$ws" $quick --out "$results"
echo "results in $results"
