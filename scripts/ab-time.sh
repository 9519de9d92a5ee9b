#!/usr/bin/env bash
# Times two commands in turn and prints the ratio of their CPU times pair by pair: the method of
# every "N alternated pairs" figure in docs/benchmarks.md. On a shared, noisy machine the two
# commands see the same load only when they run close together, so B then A, N times (after one
# warm-up of each), and the median of the N ratios A / B with their range.
#
#   scripts/ab-time.sh [-n N] 'B command' 'A command'
#
# CPU time is user + system of the whole process (GNU time); wall time is printed beside it.
# Exits non-zero if either command fails.
set -euo pipefail

pairs=7
if [[ "${1:-}" == "-n" ]]; then
  pairs="${2:-}"
  shift $(($# < 2 ? $# : 2))
fi
# 1 to 999 pairs (a larger count is a typo, and bash's arithmetic would wrap it).
if [[ $# -ne 2 || ! "$pairs" =~ ^[1-9][0-9]{0,2}$ ]]; then
  echo "usage: scripts/ab-time.sh [-n N] 'B command' 'A command'" >&2
  exit 2
fi
baseline="$1" candidate="$2"
timer=/usr/bin/time
[[ -x "$timer" ]] || { echo "ab-time: $timer not found (apt-get install time)" >&2; exit 1; }
log="$(mktemp)"
trap 'rm -f "$log"' EXIT

# Prints "cpu wall" in seconds for one run of command $1.
run() {
  if ! "$timer" -f '%U %S %e' -o "$log" bash -c "$1" >/dev/null 2>&1; then
    echo "ab-time: command failed: $1" >&2
    exit 1
  fi
  awk 'END { printf "%.3f %.3f\n", $1 + $2, $3 }' "$log"
}

run "$baseline" >/dev/null
run "$candidate" >/dev/null
ratios=()
for ((i = 1; i <= pairs; ++i)); do
  read -r cpuB wallB < <(run "$baseline")
  read -r cpuA wallA < <(run "$candidate")
  if awk -v b="$cpuB" 'BEGIN { exit !(b > 0) }'; then
    ratio=$(awk -v a="$cpuA" -v b="$cpuB" 'BEGIN { printf "%.3f", a / b }')
    ratios+=("$ratio")
  else
    ratio="none (B used no measurable CPU time)"
  fi
  echo "pair $i: A cpu ${cpuA} s (wall ${wallA}), B cpu ${cpuB} s (wall ${wallB}), A/B ${ratio}"
done
if [[ ${#ratios[@]} -eq 0 ]]; then
  echo "ab-time: no pair had a measurable CPU time for B (GNU time counts 10 ms steps)" >&2
  exit 1
fi
printf '%s\n' "${ratios[@]}" | sort -g | awk '
  { r[NR] = $1 }
  END {
    median = NR % 2 ? r[(NR + 1) / 2] : (r[NR / 2] + r[NR / 2 + 1]) / 2
    printf "A/B cpu median %.3f (range %.3f-%.3f, %d pairs)\n", median, r[1], r[NR], NR
  }'
