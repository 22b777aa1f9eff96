#!/usr/bin/env bash
# Checks `hemiroll sweep --slurm` on a real (single-node) Slurm cluster:
# starts one on this machine (tools/slurm-local.sh), runs a small sweep as a
# job array and its merge, and checks that
#   1. the merged sweep.csv equals the same sweep run on one machine, byte
#      for byte;
#   2. the job asks the cluster for the time, partition and memory given,
#      its logs land in a folder whose name has a space and a quote, and an
#      #SBATCH line added by hand survives writing the job again;
#   3. with one array task killed, the merge does not run, the other parts
#      are kept, and submitting again computes only the missing part and
#      merges to the same bytes.
# Stops the cluster after, whatever happened. Needs root (the daemons).
#
#   tools/slurm-sweep-check.sh [HEMIROLL_BINARY]   (default: build/hemiroll)
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
hemiroll=$(realpath "${1:-$root/build/hemiroll}")
if [[ $(id -u) -ne 0 ]]; then
  echo "slurm-sweep-check: needs root, to start slurmctld, slurmd and munge on this machine" >&2
  exit 1
fi
work=$(mktemp -d /tmp/hemiroll-slurm-check.XXXXXX)
chmod 755 "$work"  # munge (its own user) keeps its socket inside
state="$work/slurm"
cleanup() {
  "$root/tools/slurm-local.sh" stop "$state" > /dev/null 2>&1 || true
  rm -rf "$work"
}
trap cleanup EXIT
fail() {
  echo "slurm-sweep-check: FAILED: $*" >&2
  for log in "$work"/out*/slurm/*.log "$work"/write1.err "$state"/slurmctld.log; do
    [[ -f "$log" ]] && { echo "--- $log" >&2; tail -5 "$log" >&2; }
  done
  exit 1
}

"$root/tools/slurm-local.sh" start "$state"
export SLURM_CONF="$state/slurm.conf"

# Six points of the rose drive, 5 s each: seconds of work, three shards.
cat > "$work/spec.lua" <<'SPEC'
return {
  description = "k x Omega, small: the Slurm check",
  params = { R = 0.04, m_s = 0.1, m_p = 1.0, g = 9.81 },
  drive = { r1 = 0.015, r2 = 0.008, k = 8, Omega = -math.pi / 10 },
  duration = 5,
  axes = {
    { param = "k", values = { 6, 8, 10 } },
    { param = "Omega", values = { -0.4, -0.3 } },
  },
}
SPEC
"$hemiroll" sweep "$work/spec.lua" --out "$work/whole" --maps none > /dev/null 2>&1 || fail "the one-machine run"

# Waits until job $1 has left the queue (done, failed or cancelled).
wait_for() {
  for _ in $(seq 1 300); do
    [[ -z $(squeue -h -j "$1" 2> /dev/null) ]] && return 0
    sleep 0.5
  done
  fail "job $1 still queued after 150 s"
}
submit() {  # prints the array job's id and the merge job's id
  "$1/slurm/submit.sh" | sed -E 's/.*array job ([0-9]+) .*merge job ([0-9]+).*/\1 \2/'
}

# 1. The whole job, into a folder sbatch would split at the space; asked for
# resources, with a line added by hand and the job written again.
out1="$work/out 1 \"q\""
write1() {
  "$hemiroll" sweep "$work/spec.lua" --out "$out1" --slurm 3 --maps none --slurm-time 10 \
    --slurm-partition local --slurm-mem 100M > /dev/null 2> "$work/write1.err" || fail "writing the job: $(cat "$work/write1.err")"
}
write1
sed -i 's/^set -euo pipefail$/#SBATCH --comment=added-by-hand\nset -euo pipefail/' "$out1/slurm/sweep-array.sbatch"
write1
grep -q "kept the #SBATCH lines added to it: #SBATCH --comment=added-by-hand" "$work/write1.err" ||
  fail "writing the job again did not say it kept the hand-added line"
read -r array merge < <(submit "$out1")
job=$(scontrol show job "${array}_0")
grep -q "TimeLimit=00:10:00" <<< "$job" || fail "the array task does not have the 10-minute limit"
grep -q "Partition=local" <<< "$job" || fail "the array task is not in partition local"
grep -qE "MinMemoryNode=100M|mem=100M" <<< "$job" || fail "the array task does not ask 100M"
grep -q "Comment=added-by-hand" <<< "$job" || fail "the hand-added #SBATCH line was lost"
wait_for "$merge"
cmp -s "$out1/sweep.csv" "$work/whole/sweep.csv" || fail "the merged sweep.csv differs from the one-machine run"
for log in task-0 task-1 task-2 merge; do
  [[ -f "$out1/slurm/$log.log" ]] || fail "no $log.log in the folder with a space and a quote"
done
echo "slurm-sweep-check: 3 array tasks and the merge give the one-machine sweep.csv, byte for byte;"
echo "slurm-sweep-check: time, partition, memory and a hand-added line reach the cluster; logs under a spaced name"

# 3. One task killed: nothing runs until it is cancelled, so the kill is sure.
"$hemiroll" sweep "$work/spec.lua" --out "$work/out2" --slurm 3 --maps none > /dev/null 2>&1 || fail "writing the job"
scontrol update PartitionName=local State=DOWN
read -r array merge < <(submit "$work/out2")
scancel "${array}_1"
scontrol update PartitionName=local State=UP
wait_for "$array"
wait_for "$merge"
[[ ! -e "$work/out2/sweep.csv" ]] || fail "the merge ran although a task was killed"
[[ -f "$work/out2/parts/part-0-of-3.csv" && -f "$work/out2/parts/part-2-of-3.csv" ]] || fail "a finished part is missing"
[[ ! -e "$work/out2/parts/part-1-of-3.csv" ]] || fail "the killed task left a part"
before=$(md5sum "$work/out2/parts/part-0-of-3.csv" "$work/out2/parts/part-2-of-3.csv")
read -r array merge < <(submit "$work/out2")
wait_for "$merge"
cmp -s "$work/out2/sweep.csv" "$work/whole/sweep.csv" || fail "after resubmitting, sweep.csv differs from the one-machine run"
[[ $(md5sum "$work/out2/parts/part-0-of-3.csv" "$work/out2/parts/part-2-of-3.csv") == "$before" ]] ||
  fail "resubmitting changed a finished part"
grep -q "already complete" "$work/out2/slurm/task-0.log" || fail "task 0 computed its finished part again"
echo "slurm-sweep-check: a killed task stops the merge; resubmitting computes only its part and merges the same bytes"
