#!/usr/bin/env bash
# Runs every benchmark program in BUILD/bench (Google Benchmark), medians of 5 repetitions, then
# the reference tracer's sampling study (bench/sampling_study.cpp) with the scene's materials and
# with a glossy Phong lobe, which write docs/benchmarks/sampling_study{,_phong}.{md,svg} and their
# tables in docs/benchmarks.md (the references are cached in BUILD/sampling_study).
set -euo pipefail
build=${1:-build}
export IBLKIT_ASSETS=${IBLKIT_ASSETS:-$(pwd)/assets}
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
shopt -s nullglob
for bench in "$build"/bench/*_bench; do
  echo "== $bench"
  "$bench" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
done
if [ -x "$build/bench/sampling_study" ]; then
  echo "== $build/bench/sampling_study"
  mkdir -p docs/benchmarks
  study=("$build/bench/sampling_study" --cache "$build/sampling_study" --out-dir docs/benchmarks --update docs/benchmarks.md)
  "${study[@]}"
  "${study[@]}" --phong 20 --maps sky:sunny,venice:soft --name sampling_study_phong
fi
