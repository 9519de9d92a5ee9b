#!/usr/bin/env bash
# Runs the libFuzzer targets of fuzz/ (docs/robustness.md), built into BUILD (make fuzz builds it).
#   scripts/fuzz.sh BUILD SECONDS [TARGET...]     default: every target
# For each target: first replays the committed corpus fuzz/corpus/<target>/ (-runs=0: every file
# once, a regression run of every past finding), then fuzzes for SECONDS from the committed
# corpus, the seeds of tests/data and assets/ (copied into BUILD/fuzz-seeds/<target>/ at run time)
# and what earlier runs found (BUILD/fuzz-corpus/<target>/, kept between runs). A finding (crash,
# sanitizer report, uncaught exception, an input running over 10 s, or over 2 GiB of memory) is
# saved as BUILD/fuzz-findings/<target>/<kind>-<sha1> and fails the script, after every target ran.
# Prints per target the executions and time, and writes them to BUILD/fuzz-summary.txt.
set -uo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:?usage: scripts/fuzz.sh BUILD SECONDS [TARGET...]}
SECONDS_PER_TARGET=${2:?usage: scripts/fuzz.sh BUILD SECONDS [TARGET...]}
shift 2
ALL_TARGETS=(exr hdr png gltf scene bake_record sh9 texture lights pass_sum)
[ $# -gt 0 ] && TARGETS=("$@") || TARGETS=("${ALL_TARGETS[@]}")

# Per target: the dictionary, the largest input, and the seeds taken at run time (globs).
declare -A DICT=([exr]=exr [hdr]=hdr [png]=png [gltf]=gltf [scene]=json [bake_record]=json [sh9]=json [texture]=texture
                  [lights]=json [pass_sum]=pass_sum)
declare -A MAX_LEN=([exr]=65536 [hdr]=65536 [png]=65536 [gltf]=65536 [scene]=8192 [bake_record]=4096 [sh9]=4096
                   [texture]=65536 [lights]=8192 [pass_sum]=4096)
declare -A SEEDS=(
  [exr]="tests/data/bad/*.exr tests/data/exr/*.exr assets/hdri/studio.exr assets/hdri/sky.exr"
  [hdr]="tests/data/bad/*.hdr assets/hdri/*.hdr"
  [png]="tests/data/bad/*.png tests/data/flip/*.png"
  [gltf]="tests/data/bad/*.gltf tests/data/bad/*.glb assets/models/*.glb"
  [scene]="assets/scenes/*.json"
  [bake_record]=""
  [sh9]=""
  [lights]=""
  [pass_sum]=""
  [texture]="tests/data/bad/*.png tests/data/flip/*.png assets/normals/*.webp assets/textures/*.webp"
)

# The targets hand each input to the loader as a file (fuzz/fuzz_loaders.h) in a scratch folder
# under $TMPDIR: in memory (/dev/shm) when there is one, which runs them 20 times faster than a disk.
scratch_parent=${FUZZ_TMPDIR:-${TMPDIR:-/tmp}}
if [ -z "${FUZZ_TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ]; then scratch_parent=/dev/shm; fi
export TMPDIR=$(mktemp -d "$scratch_parent/iblkit-fuzz.XXXXXX")
trap 'rm -rf "$TMPDIR"' EXIT

SUMMARY=$BUILD/fuzz-summary.txt
mkdir -p "$BUILD"
{
  echo "# scripts/fuzz.sh $BUILD $SECONDS_PER_TARGET ($(date -u +%Y-%m-%dT%H:%M:%SZ), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'))"
  printf '%-12s %10s %12s %8s %10s %s\n' target seconds executions exec/s peak_rss_mb result
} >"$SUMMARY"

failed=()
for target in "${TARGETS[@]}"; do
  program=$BUILD/bin/fuzz_$target
  if [ ! -x "$program" ]; then
    echo "fuzz: $program is not built (make fuzz builds it)" >&2
    exit 2
  fi
  committed=fuzz/corpus/$target
  seeds=$BUILD/fuzz-seeds/$target
  corpus=$BUILD/fuzz-corpus/$target
  findings=$BUILD/fuzz-findings/$target
  log=$BUILD/fuzz-logs/$target.log
  mkdir -p "$seeds" "$corpus" "$findings" "$(dirname "$log")"
  for pattern in ${SEEDS[$target]}; do
    for file in $pattern; do [ -f "$file" ] && cp -f "$file" "$seeds/"; done
  done
  options=(-timeout=10 -rss_limit_mb=2048 -max_len="${MAX_LEN[$target]}" -dict="fuzz/dict/${DICT[$target]}.dict"
           -artifact_prefix="$findings/" -print_final_stats=1)

  # 1. The committed corpus, every file once: past findings must stay fixed.
  result=ok
  if ! "$program" "${options[@]}" -runs=0 "$committed" >"$log.replay" 2>&1; then
    result="FINDING (replay of $committed)"
  fi
  # 2. Fuzzing for the given time.
  start=$(date +%s)
  if [ "$result" = ok ] && [ "$SECONDS_PER_TARGET" -gt 0 ]; then
    if ! "$program" "${options[@]}" -max_total_time="$SECONDS_PER_TARGET" "$corpus" "$committed" "$seeds" \
        >"$log" 2>&1; then
      artifact=$(grep -o "Test unit written to [^ ]*" "$log" | tail -1 | sed 's/Test unit written to //')
      result="FINDING ${artifact:-(see $log)}"
    fi
  fi
  elapsed=$(($(date +%s) - start))
  stats_log=$log
  [ -f "$log" ] && [ "$SECONDS_PER_TARGET" -gt 0 ] || stats_log=$log.replay
  executions=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$stats_log" | grep -o '[0-9]*$' | tail -1)
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$stats_log" | grep -o '[0-9]*$' | tail -1)
  rss=$(grep -o 'stat::peak_rss_mb: *[0-9]*' "$stats_log" | grep -o '[0-9]*$' | tail -1)
  printf '%-12s %10s %12s %8s %10s %s\n' "$target" "$elapsed" "${executions:-?}" "${rate:-?}" "${rss:-?}" "$result" \
    | tee -a "$SUMMARY"
  if [ "$result" != ok ]; then
    failed+=("$target")
    grep -m1 -B2 -A25 'ERROR: \|runtime error\|==ERROR\|IBLKIT_FUZZ_STRICT\|deadly signal\|timeout' "$log" "$log.replay" 2>/dev/null | head -40 >&2
  fi
done

echo "fuzz: summary in $SUMMARY"
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: findings in ${failed[*]} (inputs under $BUILD/fuzz-findings/; add each to fuzz/corpus/<target>/ with a test)" >&2
  exit 1
fi
