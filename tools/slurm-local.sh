#!/usr/bin/env bash
# A single-node Slurm cluster on this machine, for trying and testing
# `hemiroll sweep --slurm` (docs/SWEEP.md, "On a Slurm cluster"): munge,
# slurmctld and slurmd on localhost, every file of theirs under STATE_DIR.
#
#   tools/slurm-local.sh start STATE_DIR   installs slurm-wlm and munge when
#                                          missing (tools/install-deps.sh --slurm),
#                                          starts the daemons, waits for the node
#   tools/slurm-local.sh stop STATE_DIR    cancels every job, stops what start started
#
# After start, point Slurm's commands at it: export SLURM_CONF=STATE_DIR/slurm.conf
# Needs root (the daemons run as root here: a test machine, not a cluster).
set -euo pipefail

action=${1:-}
state=${2:-}
if [[ -z "$action" || -z "$state" ]]; then
  echo "usage: tools/slurm-local.sh start|stop STATE_DIR" >&2
  exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
state=$(mkdir -p "$state" && cd "$state" && pwd)
conf="$state/slurm.conf"
node=$(hostname -s)

start() {
  if ! command -v slurmctld > /dev/null || ! command -v munged > /dev/null; then
    "$here/install-deps.sh" --slurm
  fi
  mkdir -p "$state/spool" "$state/ctld" "$state/munge"
  chmod a+x "$state"  # munged runs as munge and must reach its folder in here
  # munge: its own socket under STATE_DIR, so a munged already running is left alone.
  local socket="$state/munge/munge.socket"
  if [[ ! -S "$socket" ]]; then
    chown munge:munge "$state/munge"
    runuser -u munge -- /usr/sbin/munged --socket="$socket" --pid-file="$state/munge/munged.pid" \
      --log-file="$state/munge/munged.log" --seed-file="$state/munge/munged.seed"
  fi
  local cpus memory
  cpus=$(nproc)
  # Nine tenths of the memory in MB, so that jobs asking --mem can start.
  memory=$(awk '/^MemTotal:/ { printf "%d", $2 / 1024 * 0.9 }' /proc/meminfo)
  cat > "$conf" <<CONF
ClusterName=hemiroll-local
SlurmctldHost=$node
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
StateSaveLocation=$state/ctld
SlurmdSpoolDir=$state/spool
SlurmctldPidFile=$state/slurmctld.pid
SlurmdPidFile=$state/slurmd.pid
SlurmctldLogFile=$state/slurmctld.log
SlurmdLogFile=$state/slurmd.log
SlurmctldPort=16817
SlurmdPort=16818
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SwitchType=switch/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
SlurmdTimeout=30
InactiveLimit=0
MinJobAge=300
KillWait=5
NodeName=$node CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF="$conf"
  /usr/sbin/slurmctld -f "$conf"
  /usr/sbin/slurmd -f "$conf"
  for _ in $(seq 1 60); do
    if sinfo -h -N -o "%T" 2>/dev/null | grep -qE "^(idle|mixed|allocated)"; then
      echo "slurm-local: node $node up; export SLURM_CONF=$conf"
      return 0
    fi
    sleep 1
  done
  echo "slurm-local: the node did not come up within 60 s; see $state/slurmctld.log and $state/slurmd.log" >&2
  exit 1
}

stop() {
  export SLURM_CONF="$conf"
  if [[ -f "$conf" ]]; then scancel --user=root > /dev/null 2>&1 || true; fi
  for pidfile in "$state/slurmd.pid" "$state/slurmctld.pid" "$state/munge/munged.pid"; do
    if [[ -f "$pidfile" ]]; then
      kill "$(cat "$pidfile")" 2> /dev/null || true
    fi
  done
  sleep 1
  echo "slurm-local: stopped"
}

case "$action" in
  start) start ;;
  stop) stop ;;
  *) echo "slurm-local: unknown action '$action' (start or stop)" >&2; exit 2 ;;
esac
