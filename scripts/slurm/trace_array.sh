#!/usr/bin/env bash
#SBATCH --job-name=iblkit-trace
#SBATCH --cpus-per-task=1
# One task of a split reference render (docs/cluster.md): task I of a Slurm array renders pass I
# of PASSES, its share of the --spp samples, into OUTDIR/pass_I.sum (iblkit-trace --sum, written
# to a temporary name and renamed, so a killed task leaves no pass_I.sum at all).
#   sbatch --array=0-$((PASSES - 1)) scripts/slurm/trace_array.sh PASSES OUTDIR SCENE [iblkit-trace options]
# PASSES is an argument, not $SLURM_ARRAY_TASK_COUNT, so that one task resubmitted alone
# (sbatch --array=2 ...) renders the same samples as in the whole array. IBLKIT_TRACE names the
# program (default: iblkit-trace on the PATH); give every task the same options, --spp included.
# Merge when all are done: sbatch --dependency=afterok:JOB --kill-on-invalid-dep=yes
#   --wrap "iblkit-trace --merge OUTDIR/pass_{0..N-1}.sum -o OUT.exr".
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: sbatch --array=0-N-1 $0 PASSES OUTDIR SCENE [iblkit-trace options]" >&2
  exit 2
fi
passes=$1 outdir=$2
shift 2
task=${SLURM_ARRAY_TASK_ID:?trace_array.sh: not an array task (submit with sbatch --array=0-$((passes - 1)))}
exec "${IBLKIT_TRACE:-iblkit-trace}" "$@" --pass "$task" --passes "$passes" --sum "$outdir/pass_$task.sum"
