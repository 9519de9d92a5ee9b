#!/usr/bin/env bash
# Runs every benchmark program in BUILD/bench (Google Benchmark), medians of 5 repetitions.
set -euo pipefail
build=${1:-build}
export IBLKIT_ASSETS=${IBLKIT_ASSETS:-$(pwd)/assets}
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
shopt -s nullglob
for bench in "$build"/bench/*_bench; do
  echo "== $bench"
  "$bench" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
done
