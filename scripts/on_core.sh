#!/bin/bash
# The launch-prefix of launch/sharded.launch: runs the rest of the command line
# pinned (taskset) to core INDEX mod the number of cores, so that each shard
# has a core of its own where the machine has enough of them.
#   on_core.sh INDEX COMMAND [ARGS...]
set -euo pipefail
index="$1"
shift
exec taskset -c "$((index % $(nproc --all)))" "$@"
