#!/bin/bash
# Builds and runs the libFuzzer targets in fuzz/ with clang-14 and
# ASan + UBSan, each for FUZZ_TIME seconds (default 60), starting from and
# growing its corpus in fuzz/corpus/<target>/ (minimized with -merge=1 at the
# end, inputs <= FUZZ_MAX_LEN bytes), with fuzz/<target>.dict as its
# dictionary when there is one. Prints execs/s, coverage and corpus size per
# target; a crash, hang (-timeout=10), leak, sanitizer report or memory past
# the target's limit (-rss_limit_mb and -malloc_limit_mb: 512 MB for
# service_text_fuzzer, whose aliases can expand a short text into gigabytes;
# 2048 MB for the others) is saved as fuzz/crashes/<target>-<kind>-... and
# makes the script exit non-zero. Inputs that crashed once and were fixed
# live in fuzz/regressions/ and run first, under the same limits, with the
# inputs too large to keep (fuzz/make_seeds.py --large).
#
#   bash scripts/fuzz.sh                     # every target, 60 s each
#   FUZZ_TIME=300 bash scripts/fuzz.sh wrench_fuzzer
#   FUZZ_MERGE=0 ...                         # leave fuzz/corpus untouched
#
# Targets: scene_parser_fuzzer (~bodies as a parameter tree), wrench_fuzzer
# (wrench messages, steps, resets, ~set_body_state), service_text_fuzzer
# (~spawn_body's YAML text).
#
# The generated headers and the list of sources come from a catkin
# workspace, RBS_WS (default /tmp/ws_fuzz): the script builds its message and
# dynamic_reconfigure targets, and the sources are those CMake compiles into
# the package's two libraries there (build/compile_commands.json). Objects,
# the library of them and the binaries go to FUZZ_BUILD (default
# /tmp/rbs_fuzz_build); FUZZ_JOBS (default 2) compile at a time.
set -euo pipefail
ws_default=/tmp/ws_fuzz
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
out="${FUZZ_BUILD:-/tmp/rbs_fuzz_build}"
fuzz_time="${FUZZ_TIME:-60}"
max_len="${FUZZ_MAX_LEN:-1024}"
merge="${FUZZ_MERGE:-1}"
jobs="${FUZZ_JOBS:-2}"
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(scene_parser_fuzzer wrench_fuzzer service_text_fuzzer)
t0=$(date +%s)

# ---- toolchain --------------------------------------------------------------
bash "$repo/scripts/install_deps.sh" clang-14 libclang-rt-14-dev
cxx=clang++-14

# ---- generated headers and the sources --------------------------------------
# Every run: a no-op when the workspace is current, else catkin_make runs
# CMake again, which brings compile_commands.json up to date with the lists
# in CMakeLists.txt and cmake/node.cmake.
mkdir -p "$out/obj"
echo "fuzz: the generated headers and the source list in $ws"
RBS_WS="$ws" bash "$repo/scripts/build.sh" -j1 rigid_body_sim_generate_messages_cpp rigid_body_sim_gencfg \
  >"$out/ws.log" 2>&1 || {
  tail -n 30 "$out/ws.log"
  echo "fuzz: the workspace build failed: see $out/ws.log"
  exit 1
}
# The sources of rigid_body_sim_core and rigid_body_sim_ros as CMake compiles
# them (every source but the node's main), relative to the checkout.
mapfile -t sources < <(/usr/bin/python3 -c '
import json, os, re, sys
for entry in json.load(open(sys.argv[1])):
    if re.search(r" -o CMakeFiles/rigid_body_sim_(core|ros)\.dir/", entry["command"]):
        print(os.path.relpath(entry["file"], sys.argv[2]))' \
  "$ws/build/compile_commands.json" "$ws/src/rigid_body_sim")
if [ ${#sources[@]} -eq 0 ]; then
  echo "fuzz: no sources of rigid_body_sim_core or rigid_body_sim_ros in $ws/build/compile_commands.json"
  exit 1
fi

# ---- build ------------------------------------------------------------------
# -O2: at -O1 Eigen's fixed-size products stay loops and calls, which the
# sanitizers and the coverage instrumentation then cost on every element.
cxxflags=(-std=c++17 -O2 -g -fno-omit-frame-pointer
  "-fsanitize=address,undefined" -fno-sanitize-recover=all
  -I"$repo/include" -I"$ws/devel/include" -isystem /usr/include/eigen3 -DNDEBUG)
# The core's integer comparisons are loop bounds and counts, not input
# checks: tracing them for the fuzzer's comparison hints cost most of the
# time of a step. Its edges are still covered. src/core holds its private
# headers (CMake's PRIVATE include directory).
core_flags=(-fno-sanitize-coverage=trace-cmp -I"$repo/src/core")
# Objects built with other flags are built again.
stamp="$cxx ${cxxflags[*]} ${core_flags[*]}"
if [ "$(cat "$out/obj/flags" 2>/dev/null)" != "$stamp" ]; then
  rm -f "$out"/obj/*.o
  echo "$stamp" >"$out/obj/flags"
fi
# The project's own code gets the coverage instrumentation.
export repo out cxx core_flags_text="${core_flags[*]}"
# shellcheck disable=SC2016  # expanded by the inner bash
printf '%s\n' "${sources[@]}" | xargs -P "$jobs" -I{} bash -c '
  src="$1"; shift
  obj="$out/obj/$(echo "$src" | tr / _).o"
  extra=()
  case "$src" in src/core/*) read -r -a extra <<<"$core_flags_text" ;; esac
  if [ ! -f "$obj" ] || [ "$repo/$src" -nt "$obj" ] || [ -n "$(find "$repo/include" "$repo/src" -newer "$obj" -name "*.h" | head -1)" ]; then
    "$cxx" "$@" -fsanitize=fuzzer-no-link "${extra[@]}" -c "$repo/$src" -o "$obj"
  fi' _ {} "${cxxflags[@]}"
objs=()
for s in "${sources[@]}"; do objs+=("$out/obj/$(echo "$s" | tr / _).o"); done
# A static library: a target links only the objects it reaches, so the
# node's parts that none reaches (publishers, services, the node itself)
# need none of their ROS libraries here.
rm -f "$out/librigid_body_sim_fuzz.a"
ar rcs "$out/librigid_body_sim_fuzz.a" "${objs[@]}"
ros_libs=(-L/usr/lib/x86_64-linux-gnu -lurdf -lurdfdom_model -lroslib -lroscpp -lxmlrpcpp -lrostime
  -lroscpp_serialization -lrosconsole -lcpp_common -lconsole_bridge -lboost_system -lyaml-cpp -lyaml
  -lpthread)
for t in "${targets[@]}"; do
  "$cxx" "${cxxflags[@]}" -fsanitize=fuzzer "$repo/fuzz/$t.cpp" "$out/librigid_body_sim_fuzz.a" \
    "${ros_libs[@]}" -o "$out/$t"
done
t_built=$(date +%s)
echo "fuzz: built ${targets[*]} in $((t_built - t0)) s"

# ---- run --------------------------------------------------------------------
asan_options="detect_leaks=1:abort_on_error=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
mkdir -p "$repo/fuzz/crashes"
large="$out/large"
rm -rf "$large"
/usr/bin/python3 "$repo/fuzz/make_seeds.py" --large "$large"
status=0
summary=()
for t in "${targets[@]}"; do
  corpus="$repo/fuzz/corpus/$t"
  work="$out/corpus_$t"
  mkdir -p "$corpus"
  rm -rf "$work"; mkdir -p "$work"
  cp -a "$corpus/." "$work/" 2>/dev/null || true
  log="$out/$t.log"
  # service_text_fuzzer's limit is a memory budget that an alias bomb
  # passes. The freed memory ASan holds back to catch a use after free (256
  # MB by default) is kept small there: recycled across the size classes, it
  # would raise the process's RSS past the budget within minutes.
  case "$t" in
    service_text_fuzzer) rss_mb=512; export ASAN_OPTIONS="$asan_options:quarantine_size_mb=16" ;;
    *) rss_mb=2048; export ASAN_OPTIONS="$asan_options" ;;
  esac
  limits=(-timeout=10 -rss_limit_mb="$rss_mb" -malloc_limit_mb="$rss_mb")
  dict=()
  [ -f "$repo/fuzz/$t.dict" ] && dict=(-dict="$repo/fuzz/$t.dict")
  # Every input that once crashed (fuzz/regressions/, fixed since) runs
  # first, and the large generated ones with them.
  regressions=()
  for f in "$repo"/fuzz/regressions/"$t"-* "$large/$t"-*; do [ -e "$f" ] && regressions+=("$f"); done
  if [ ${#regressions[@]} -gt 0 ]; then
    if ! "$out/$t" "${limits[@]}" "${regressions[@]}" >"$out/$t.regressions.log" 2>&1; then
      echo "fuzz: $t fails a regression input again: see $out/$t.regressions.log"
      status=1
    else
      echo "fuzz: $t passes its ${#regressions[@]} regression inputs"
    fi
  fi
  echo "fuzz: running $t for $fuzz_time s (log $log)"
  rc=0
  "$out/$t" "$work" -max_total_time="$fuzz_time" -max_len="$max_len" "${limits[@]}" "${dict[@]}" \
    -print_final_stats=1 \
    -artifact_prefix="$repo/fuzz/crashes/$t-" >"$log" 2>&1 || rc=$?
  grep -E '^#[0-9]+' "$log" | tail -n 3 || true
  grep -E '^(stat::|Done )' "$log" || true
  stats_line=$(grep -E '^#[0-9]+' "$log" | tail -1 || true)
  execs=$(grep -oE 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -oE '[0-9]+$' || echo '?')
  eps=$(grep -oE 'stat::average_exec_per_sec: *[0-9]+' "$log" | grep -oE '[0-9]+$' || echo '?')
  cov=$(echo "$stats_line" | grep -oE 'cov: [0-9]+' | grep -oE '[0-9]+' || echo '?')
  ft=$(echo "$stats_line" | grep -oE 'ft: [0-9]+' | grep -oE '[0-9]+' || echo '?')
  if [ "$rc" -ne 0 ]; then
    echo "fuzz: $t FAILED (exit $rc): see $log and fuzz/crashes/"
    grep -E 'ERROR: |runtime error|invariant broken|uncaught|Test unit written' "$log" | head -10 || true
    status=1
  fi
  if [ "$merge" = 1 ]; then
    # Keep only the inputs that add coverage: a small, reviewable corpus.
    merged="$out/merged_$t"
    rm -rf "$merged"; mkdir -p "$merged"
    "$out/$t" -merge=1 -max_len="$max_len" "${limits[@]}" "$merged" "$work" >"$out/$t.merge.log" 2>&1 || {
      echo "fuzz: merge of $t failed (see $out/$t.merge.log)"; status=1; }
    if [ -n "$(ls -A "$merged")" ]; then
      rm -rf "$corpus"; mkdir -p "$corpus"; cp -a "$merged/." "$corpus/"
    fi
  fi
  files=$(find "$corpus" -type f | wc -l)
  bytes=$(find "$corpus" -type f -printf '%s\n' | awk '{s += $1} END {print s + 0}')
  summary+=("$t: exit $rc, $execs execs, $eps execs/s, cov $cov edges, ft $ft features, corpus $files files / $bytes bytes")
done
t_end=$(date +%s)

echo "fuzz: ---- summary (build $((t_built - t0)) s, total $((t_end - t0)) s) ----"
for line in "${summary[@]}"; do echo "fuzz: $line"; done
total=$(find "$repo/fuzz/corpus" -type f -printf '%s\n' | awk '{s += $1} END {print s + 0}')
echo "fuzz: fuzz/corpus is $total bytes"
if [ "$total" -gt 1048576 ]; then echo "fuzz: corpus over 1 MB"; status=1; fi
exit "$status"
