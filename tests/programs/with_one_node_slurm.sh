#!/usr/bin/env bash
# Runs a command on a one-node Slurm cluster started for it (one_node_slurm.sh), for trying
# `iblkit-report --scheduler slurm` and measuring it (docs/cluster.md "Measured"):
#   tests/programs/with_one_node_slurm.sh WORK_PARENT COMMAND [ARG...]
# The cluster's folder is a new one under WORK_PARENT; SLURM_CONF points the command's sbatch,
# squeue and scontrol at it. The daemons are stopped when the command ends. As root.
set -euo pipefail
PARENT=${1:?usage: $0 WORK_PARENT COMMAND [ARG...]}
shift
TEST_NAME=with_one_node_slurm
# shellcheck source=one_node_slurm.sh
source "$(dirname "${BASH_SOURCE[0]}")/one_node_slurm.sh"
"$@"
