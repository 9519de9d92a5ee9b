#!/usr/bin/env bash
# A split reference render on a real one-node Slurm cluster (docs/cluster.md) started here by
# one_node_slurm.sh.
#   cluster_slurm_trace_test.sh BIN_DIR SOURCE_DIR WORK_PARENT
# 1. A job array renders 4 passes (scripts/slurm/trace_array.sh, iblkit-trace --pass --sum), a
#    merge job (afterok, --kill-on-invalid-dep=yes) merges them: the EXR must be byte-identical
#    to one local run of all the samples.
# 2. Again with task 2 cancelled while it runs: it leaves no pass file (not even a partial one),
#    the merge that depends on it is cancelled and never runs, the missing pass is found by its
#    file and resubmitted alone, and the new merge is byte-identical too.
# 3. A job that depends (afterok, --kill-on-invalid-dep=yes) on a job that fails is cancelled
#    and never runs.
# Exit 77 (ctest's skip) only where Slurm or munge is not installed; everything else must pass.
set -euo pipefail
BIN=$(cd "${1:?usage: $0 BIN_DIR SOURCE_DIR WORK_PARENT}" && pwd)
SOURCE=$(cd "${2:?usage: $0 BIN_DIR SOURCE_DIR WORK_PARENT}" && pwd)
PARENT=${3:?usage: $0 BIN_DIR SOURCE_DIR WORK_PARENT}

TEST_NAME=cluster_slurm_trace
# shellcheck source=one_node_slurm.sh
source "$(dirname "${BASH_SOURCE[0]}")/one_node_slurm.sh"

# --- the scene: a glossy sphere on a ground under a generated map with a hot spot -------------------
mkdir -p "$D/scene"
python3 "$SOURCE/tests/programs/glossy_sphere_scene.py" "$D/scene" sky=400
TRACE_ARGS=("$D/scene/scene.json" --spp 12 --width 64 --height 36 --threads 1)
PASSES=4
"$BIN/iblkit-trace" "${TRACE_ARGS[@]}" -o "$D/single.exr" >/dev/null

# --- helpers ---------------------------------------------------------------------------------------
# The state of every task of job $1 (array tasks included), one per line.
states() { scontrol -o show job "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | cut -d= -f2; }
# Waits until no task of job $1 is pending or running (polling squeue is faster than sbatch --wait).
wait_done() {
  for _ in $(seq 600); do
    [ -z "$(squeue -h -j "$1" -o %T 2>/dev/null)" ] && return 0
    sleep 0.1
  done
  fail "job $1 still queued: $(squeue -j "$1" 2>&1)"
}
submit() { sbatch --parsable --chdir="$D" -o "$D/job-%A_%a.log" "$@"; }
submit_array() {  # OUTDIR ARRAY [sbatch options]: the trace tasks, through a wrapper that can hang
  local out=$1 array=$2
  shift 2
  IBLKIT_TRACE=$BIN/iblkit-trace submit --array="$array" "$@" "$D/task.sh" "$PASSES" "$out" "${TRACE_ARGS[@]}"
}
submit_merge() {  # DEPENDENCY OUT.exr OUTDIR
  submit --dependency="afterok:$1" --kill-on-invalid-dep=yes --wrap \
    "'$BIN/iblkit-trace' --merge $(for i in $(seq 0 $((PASSES - 1))); do printf "'%s' " "$3/pass_$i.sum"; done) -o '$2'"
}
# The array task: scripts/slurm/trace_array.sh, except that task $HANG_TASK waits to be cancelled
# while it runs (until the file $D/resubmitted exists).
cat >"$D/task.sh" <<TASK
#!/usr/bin/env bash
if [ "\${SLURM_ARRAY_TASK_ID}" = "\${HANG_TASK:-none}" ] && [ ! -e "$D/resubmitted" ]; then sleep 300; fi
exec "$SOURCE/scripts/slurm/trace_array.sh" "\$@"
TASK
chmod +x "$D/task.sh"
expect_identical() {
  [ -f "$1" ] || fail "$1 was not written (the job says COMPLETED: check outputs, not only states)"
  cmp "$D/single.exr" "$1" || fail "$1 differs from the single-process render"
}

# --- 1. a split render and its merge --------------------------------------------------------------
mkdir -p "$D/passes1"
t=$(date +%s%N)
array=$(submit_array "$D/passes1" "0-$((PASSES - 1))")
merge=$(submit_merge "$array" "$D/merged1.exr" "$D/passes1")
wait_done "$array"
wait_done "$merge"
[ "$(states "$array" | sort -u)" = COMPLETED ] || fail "array $array: $(states "$array" | tr '\n' ' ')"
[ "$(states "$merge")" = COMPLETED ] || fail "merge $merge: $(states "$merge")"
expect_identical "$D/merged1.exr"
echo "1. $PASSES passes + merge through Slurm: byte-identical to the single run ($(elapsed "$t") s)"

# --- 2. a task cancelled while it runs, found and resubmitted --------------------------------------
mkdir -p "$D/passes2"
t=$(date +%s%N)
array=$(HANG_TASK=2 submit_array "$D/passes2" "0-$((PASSES - 1))")
merge=$(submit_merge "$array" "$D/merged2.exr" "$D/passes2")
for _ in $(seq 300); do
  [ "$(squeue -h -j "${array}_2" -o %T 2>/dev/null)" = RUNNING ] && [ -f "$D/passes2/pass_0.sum" ] &&
    [ -f "$D/passes2/pass_1.sum" ] && [ -f "$D/passes2/pass_3.sum" ] && break
  sleep 0.1
done
[ "$(squeue -h -j "${array}_2" -o %T)" = RUNNING ] || fail "task ${array}_2 is not running"
scancel "${array}_2"
wait_done "$array"
wait_done "$merge"
[ "$(scontrol -o show job "${array}_2" | grep -o 'JobState=[A-Z]*')" = JobState=CANCELLED ] ||
  fail "task ${array}_2: $(scontrol -o show job "${array}_2")"
[ "$(states "$merge")" = CANCELLED ] || fail "the merge after a cancelled task is $(states "$merge"), not CANCELLED"
[ ! -e "$D/merged2.exr" ] || fail "the merge ran although a pass was cancelled"
missing=()
for i in $(seq 0 $((PASSES - 1))); do [ -f "$D/passes2/pass_$i.sum" ] || missing+=("$i"); done
[ "${missing[*]}" = 2 ] || fail "missing passes are '${missing[*]}', expected '2'"
leftovers=$(find "$D/passes2" -name '*.tmp-*')
[ -z "$leftovers" ] || fail "a cancelled task left $leftovers"
touch "$D/resubmitted"
again=$(submit_array "$D/passes2" "$(
  IFS=,
  echo "${missing[*]}"
)")
merge=$(submit_merge "$again" "$D/merged2.exr" "$D/passes2")
wait_done "$again"
wait_done "$merge"
[ "$(states "$merge")" = COMPLETED ] || fail "merge $merge after the resubmission: $(states "$merge")"
expect_identical "$D/merged2.exr"
echo "2. task 2 cancelled while running, merge cancelled, task 2 resubmitted: byte-identical ($(elapsed "$t") s)"

# --- 3. afterok on a failed job, with --kill-on-invalid-dep=yes ------------------------------------
failing=$(submit --wrap "exit 3")
dependent=$(submit --dependency="afterok:$failing" --kill-on-invalid-dep=yes --wrap "touch '$D/dependent-ran'")
wait_done "$failing"
wait_done "$dependent"
[ "$(states "$failing")" = FAILED ] || fail "job $failing: $(states "$failing")"
[ "$(states "$dependent")" = CANCELLED ] || fail "job $dependent after a failed job: $(states "$dependent")"
[ ! -e "$D/dependent-ran" ] || fail "job $dependent ran although the job it depends on failed"
echo "3. afterok on a failed job with --kill-on-invalid-dep=yes: cancelled, never ran"
echo "cluster_slurm_trace: all passed in $(elapsed) s"
