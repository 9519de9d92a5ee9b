#!/usr/bin/env bash
# iblkit-report --scheduler slurm on a real one-node Slurm cluster (docs/cluster.md) started by
# one_node_slurm.sh, against the same small report run locally:
#   cluster_slurm_report_test.sh BIN_DIR SOURCE_DIR WORK_PARENT
# 1. Through Slurm (bakes, engine frames and reference waves as job arrays), report.json's numbers
#    and the reference thumbnails equal the local run's exactly; more than one wave was needed;
#    every stage folder in the cache is whole (has its stage.json).
# 2. A rerun submits nothing: every stage is cached.
# 3. A reference pass whose task is cancelled while it runs is detected (its log and exit code are
#    reported), resubmitted once, and the report still equals the local one, with no stage folder
#    missing its record and no temporary folder left.
# 4. A pass that fails on both tries ends the report with one line naming the case, exit 1, and
#    no report.json.
# Exit 77 (ctest's skip) only where Slurm or munge is not installed; everything else must pass.
set -euo pipefail
BIN=$(cd "${1:?usage: $0 BIN_DIR SOURCE_DIR WORK_PARENT}" && pwd)
SOURCE=$(cd "${2:?usage: $0 BIN_DIR SOURCE_DIR WORK_PARENT}" && pwd)
PARENT=${3:?usage: $0 BIN_DIR SOURCE_DIR WORK_PARENT}

TEST_NAME=cluster_slurm_report
# shellcheck source=one_node_slurm.sh
source "$(dirname "${BASH_SOURCE[0]}")/one_node_slurm.sh"

# --- the cases: a glossy sphere on a ground under two generated maps, one with a sun ---------------
mkdir -p "$D/scene"
python3 "$SOURCE/tests/programs/glossy_sphere_scene.py" "$D/scene" sun=400 soft=4
# Small, with reference waves: 2 passes first, then up to 6 (neither map converges at 1e-3).
report() {  # OUT CACHE BIN [options]
  local out=$1 cache=$2 bin=$3
  shift 3
  (cd "$D/scene" && "$BIN/iblkit-report" scene.json --envs sun.hdr,soft.hdr -o "$out" --cache "$cache" \
    --bin "$bin" --width 64 --height 36 --pass-spp 4 --min-passes 2 --max-passes 6 --bench 0 --modes sh,full "$@")
}
# report.json less what differs between any two runs: times, and the commands (which name the
# stage's temporary folder and the --bin folder).
# With a second argument, the stage counts (cached, run) too.
numbers() {
  python3 - "$@" <<'PY'
import json, sys
left_out = {"seconds", "bakeSeconds", "visibilitySeconds", "environmentSeconds", "traceSeconds", "frameMilliseconds", "commands"} | ({"stages"} if len(sys.argv) > 2 else set())
def strip(x):
    if isinstance(x, dict):
        return {k: strip(v) for k, v in x.items() if k not in left_out}
    if isinstance(x, list):
        return [strip(v) for v in x]
    return x
print(json.dumps(strip(json.load(open(sys.argv[1]))), indent=1, sort_keys=True))
PY
}
expect_same_report() {  # OUT [any-stage-counts]
  [ -f "$1/report.json" ] || fail "$1/report.json was not written"
  diff <(numbers "$D/local/report.json" ${2:+x}) <(numbers "$1/report.json" ${2:+x}) >"$D/diff.txt" ||
    fail "$1/report.json differs from the local run's: $(head -20 "$D/diff.txt")"
  for image in "$D"/local/images/*-reference.png; do
    cmp "$image" "$1/images/$(basename "$image")" || fail "$1: $(basename "$image") differs from the local run's"
  done
}
expect_whole_cache() {  # CACHE
  local folder
  for folder in "$1"/*-*; do
    [ -d "$folder" ] || continue
    case $(basename "$folder") in *.tmp-*) fail "a temporary folder was left in the cache: $folder" ;; esac
    [ -f "$folder/stage.json" ] || fail "stage folder $folder has no stage.json"
  done
}

# --- 0. the local run ----------------------------------------------------------------------------
t=$(date +%s%N)
report "$D/local" "$D/local-cache" "$BIN" 2>"$D/local.err" >/dev/null || fail "local report: $(tail -3 "$D/local.err")"
local_seconds=$(elapsed "$t")
echo "0. local report: $local_seconds s"

# --- 1. through Slurm ----------------------------------------------------------------------------
t=$(date +%s%N)
report "$D/slurm" "$D/slurm-cache" "$BIN" --scheduler slurm 2>"$D/slurm.err" >/dev/null ||
  fail "slurm report: $(tail -3 "$D/slurm.err")"
slurm_seconds=$(elapsed "$t")
expect_same_report "$D/slurm"
expect_whole_cache "$D/slurm-cache"
grep -q "slurm wave 2: submitted" "$D/slurm.err" || fail "one wave only: $(grep 'slurm' "$D/slurm.err" | tail -3)"
grep -q "running" "$D/slurm.err" || fail "no progress line: $(head -5 "$D/slurm.err")"
echo "1. through Slurm: the same numbers and reference thumbnails ($slurm_seconds s, local $local_seconds s;" \
  "$(grep -c "wave [0-9]*: submitted" "$D/slurm.err") waves)"

# --- 2. a rerun submits nothing --------------------------------------------------------------------
report "$D/slurm-again" "$D/slurm-cache" "$BIN" --scheduler slurm 2>"$D/again.err" >/dev/null ||
  fail "slurm rerun: $(tail -3 "$D/again.err")"
! grep -q "wave [0-9]*: submitted" "$D/again.err" || fail "the rerun submitted stages: $(grep submitted "$D/again.err")"
expect_same_report "$D/slurm-again" any-stage-counts
python3 -c 'import json, sys; s = json.load(open(sys.argv[1]))["stages"]; sys.exit(s["run"] != 0 or s["cached"] == 0)' \
  "$D/slurm-again/report.json" || fail "the rerun's stage counts: $(grep -A3 '"stages"' "$D/slurm-again/report.json")"
echo "2. a rerun submits nothing"

# --- 3. a task cancelled while it runs -------------------------------------------------------------
# iblkit-trace in a folder of its own, whose pass with seed 1 writes its Slurm task's id to
# $D/hanging and waits to be cancelled under the sun map, until the file $D/resubmitted exists
# (and with $D/fail-always, fails under both maps); the other programs are links to the real ones.
mkdir -p "$D/bin"
ln -s "$BIN/iblkit-bake" "$D/bin/iblkit-bake"
ln -s "$BIN/iblkit-view" "$D/bin/iblkit-view"
cat >"$D/bin/iblkit-trace" <<TRACE
#!/usr/bin/env bash
case " \$* " in
  *" --seed 1 "*)
    if [ -e "$D/fail-always" ]; then echo "iblkit-trace: made to fail" >&2; exit 4; fi ;;&
  *" --env sun.hdr "*" --seed 1 "*)
    if [ ! -e "$D/resubmitted" ]; then
      echo "\${SLURM_ARRAY_JOB_ID}_\${SLURM_ARRAY_TASK_ID}" >"$D/hanging.tmp" && mv "$D/hanging.tmp" "$D/hanging"
      sleep 300
    fi ;;
esac
exec "$BIN/iblkit-trace" "\$@"
TRACE
chmod +x "$D/bin/iblkit-trace"
t=$(date +%s%N)
report "$D/killed" "$D/killed-cache" "$D/bin" --scheduler slurm 2>"$D/killed.err" >/dev/null &
report_pid=$!
for _ in $(seq 600); do [ -e "$D/hanging" ] && break; sleep 0.1; done
[ -e "$D/hanging" ] || fail "no pass with seed 1 started: $(tail -3 "$D/killed.err")"
task=$(cat "$D/hanging")
[ "$(squeue -h -j "$task" -o %T)" = RUNNING ] || fail "task $task is not running: $(squeue -r 2>&1)"
[ -n "$task" ] || fail "the hanging task is not in the queue: $(squeue -r 2>&1)"
touch "$D/resubmitted"
scancel "$task"
wait "$report_pid" || fail "the report after a cancelled task: $(tail -3 "$D/killed.err")"
grep -q "failed; resubmitting it once" "$D/killed.err" || fail "the cancelled task was not reported: $(grep slurm "$D/killed.err" | tail -5)"
grep "failed; resubmitting it once" "$D/killed.err" | grep -q "ExitCode=" || fail "no exit code in: $(grep resubmitting "$D/killed.err")"
grep "failed; resubmitting it once" "$D/killed.err" | grep -q "log .*\.log" || fail "no log path in: $(grep resubmitting "$D/killed.err")"
expect_same_report "$D/killed"
expect_whole_cache "$D/killed-cache"
echo "3. task $task cancelled while running: reported, resubmitted, the same numbers ($(elapsed "$t") s)"
grep "resubmitting it once" "$D/killed.err" | head -1

# --- 4. a pass that fails twice --------------------------------------------------------------------
touch "$D/fail-always"
status=0
report "$D/failing" "$D/failing-cache" "$D/bin" --scheduler slurm 2>"$D/failing.err" >/dev/null || status=$?
[ "$status" -eq 1 ] || fail "a pass failing twice: exit status $status, expected 1"
last=$(tail -1 "$D/failing.err")
case $last in
  "iblkit-report: case scene-sun: stage trace-scene-sun-1 "*"failed twice") ;;
  "iblkit-report: case scene-soft: stage trace-scene-soft-1 "*"failed twice") ;;
  *) fail "the last line does not name the case and stage: $last" ;;
esac
[ ! -e "$D/failing/report.json" ] || fail "a failed report wrote report.json"
expect_whole_cache "$D/failing-cache"
echo "4. a pass failing twice: $last"
echo "$TEST_NAME: all passed in $(elapsed) s"
