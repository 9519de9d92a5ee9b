#!/bin/bash
# Alternates iblkit-view binaries on one bake and prints, per binary and mode, the median frame
# times of each run (full, lights, lights-shadowed at 1280 x 720), for comparing engine changes
# on a noisy machine (docs/benchmarks.md, issue 15's frame ratio).
#   scripts/frame_ratio.sh BAKE RUNS VIEW_BINARY...
# A binary may be a wrapper script that adds options to iblkit-view.
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: $0 BAKE RUNS VIEW_BINARY..." >&2
  exit 2
fi
bake=$1 runs=$2
shift 2
for ((k = 0; k < runs; ++k)); do
  for view in "$@"; do
    "$view" "$bake" --headless --width 1280 --height 720 --mode all --bench 10 2>&1 |
      awk -v b="$view" '$2 == "cpu" && ($1 == "full" || $1 == "lights" || $1 == "lights-shadowed") {print b, $1, $3}'
  done
done | awk '{k = $1 " " $2; v[k] = v[k] " " $3} END {for (k in v) print k ":" v[k] " ms"}' | sort
