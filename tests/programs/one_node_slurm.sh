# Sourced by the Slurm tests: starts a one-node Slurm cluster (docs/cluster.md) without systemd:
# munged with a temporary key, slurmctld and slurmd with a generated slurm.conf (proctrack/linuxproc,
# task/none: no cgroups in a container), all in a new folder $D under $PARENT, each stopped by its
# PID when the test ends, however it ends. Before sourcing, set TEST_NAME (for messages) and PARENT.
# Exits 77 (ctest's skip) only where Slurm or munge is not installed. Defines fail and elapsed;
# exports SLURM_CONF and USER.
for program in munged slurmctld slurmd sbatch squeue scontrol scancel sinfo; do
  if ! command -v "$program" >/dev/null 2>&1 && [ ! -x "/usr/sbin/$program" ]; then
    echo "SKIP: $program is not installed (scripts/setup.sh installs slurm-wlm and munge)"
    exit 77
  fi
done
export PATH=$PATH:/usr/sbin
if [ "$(id -u)" -ne 0 ]; then
  echo "$TEST_NAME: must run as root (slurmd starts jobs as their user; CI runs as root)" >&2
  exit 1
fi
export USER=${USER:-$(id -un)}  # sbatch and slurmd want it; a container's shell may not set it

mkdir -p "$PARENT"
D=$(mktemp -d "$(cd "$PARENT" && pwd)/slurm.XXXXXX")
pids=()
M=
cleanup() {
  local status=$?
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  done
  if [ "$status" -ne 0 ]; then
    echo "--- logs in $D" >&2
    tail -n 20 "$D"/*.log >&2 2>/dev/null || true
  else
    rm -rf "$D"
  fi
  [ -z "$M" ] || [ "$M" = "$D/munge" ] || rm -rf "$M"
}
trap cleanup EXIT
trap 'exit 130' INT TERM
fail() {
  echo "$TEST_NAME: FAIL: $*" >&2
  exit 1
}
# Seconds since the start, or since the `date +%s%N` given.
start=$(date +%s%N)
elapsed() {
  local ms=$((($(date +%s%N) - ${1:-$start}) / 1000000))
  printf '%d.%03d' $((ms / 1000)) $((ms % 1000))
}

# --- munge, with a key of its own ------------------------------------------------------------------
# A Unix socket's path has at most 107 bytes: munge lives under /tmp when the work folder is deep.
M=$D/munge
[ ${#M} -lt 80 ] || M=$(mktemp -d /tmp/iblkit-munge.XXXXXX)
mkdir -p -m 700 "$M"
dd if=/dev/urandom of="$M/munge.key" bs=1024 count=1 status=none
chmod 400 "$M/munge.key"
munged -F --force --socket="$M/munge.socket" --key-file="$M/munge.key" \
  --pid-file="$M/munged.pid" --log-file="$D/munged.log" --seed-file="$M/munged.seed" 2>>"$D/munged.log" &
pids+=($!)
for _ in $(seq 50); do [ -S "$M/munge.socket" ] && break; sleep 0.1; done
[ -S "$M/munge.socket" ] || fail "munged did not start"

# --- slurm.conf, slurmctld and slurmd --------------------------------------------------------------
host=$(hostname -s)
port_free() { ! (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }
ctld_port=$((20000 + RANDOM % 20000))
until port_free "$ctld_port" && port_free $((ctld_port + 1)); do ctld_port=$((20000 + RANDOM % 20000)); done
mkdir -p "$D/state" "$D/spool"
export SLURM_CONF=$D/slurm.conf
cat >"$SLURM_CONF" <<CONF
ClusterName=iblkit
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$((ctld_port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$M/munge.socket
CredType=cred/munge
StateSaveLocation=$D/state
SlurmdSpoolDir=$D/spool
SlurmctldPidFile=$D/slurmctld.pid
SlurmdPidFile=$D/slurmd.pid
SlurmctldLogFile=$D/slurmctld.log
SlurmdLogFile=$D/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/builtin
SchedulerParameters=sched_interval=1
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MinJobAge=600
KillWait=2
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
slurmctld -D -i -f "$SLURM_CONF" >>"$D/slurmctld.log" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" -N "$host" >>"$D/slurmd.log" 2>&1 &
pids+=($!)
for _ in $(seq 150); do
  [ "$(sinfo -h -n "$host" -o %T 2>/dev/null)" = idle ] && break
  sleep 0.2
done
[ "$(sinfo -h -n "$host" -o %T 2>/dev/null)" = idle ] || fail "the node did not come up idle: $(sinfo 2>&1)"
echo "cluster up after $(elapsed) s"

