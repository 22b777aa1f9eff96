#!/usr/bin/env bash
# Issue 32's measure as a user meets it: the whole process of
#   hemiroll sweep tools/bench/sweeps/rose_16_points_60s.lua --threads 1 --maps none
# in trajectory steps per CPU second (user + system, from the shell's `time`,
# whose figures come from getrusage to the millisecond), against the naive
# RK4 anchor's RK4 steps per CPU second (sweep_bench's BM_NaiveRk4Anchor),
# measured in the same run. Each round runs every binary once and the
# anchor once, alternating, so that load on a shared machine falls on all of
# them alike; the report gives the medians over the rounds.
#
#   tools/sweep-speed.sh ROUNDS SWEEP_BENCH HEMIROLL [HEMIROLL ...]
#
# e.g. the binary of the previous commit against this one:
#   tools/sweep-speed.sh 7 build/bench/sweep_bench old/hemiroll build/hemiroll
# SWEEP_ARGS adds options to every sweep (e.g. SWEEP_ARGS="--lanes 1").
set -euo pipefail
usage="usage: tools/sweep-speed.sh ROUNDS SWEEP_BENCH HEMIROLL [HEMIROLL ...]"
rounds=${1:?$usage}
bench=${2:?$usage}
shift 2
[ $# -ge 1 ] || { echo "$usage" >&2; exit 2; }
[[ "$rounds" =~ ^[1-9][0-9]*$ ]] || { echo "sweep-speed.sh: ROUNDS must be a positive whole number, got '$rounds'" >&2; exit 2; }
for b in "$bench" "$@"; do
  [ -x "$b" ] || { echo "sweep-speed.sh: '$b' is not an executable file" >&2; exit 2; }
done
root="$(cd "$(dirname "$0")/.." && pwd)"
spec="$root/tools/bench/sweeps/rose_16_points_60s.lua"
steps=960000  # 16 points x 60 s / 1 ms
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

echo "sweep options: --threads 1 --maps none ${SWEEP_ARGS:-}"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for ((r = 1; r <= rounds; ++r)); do
  "$bench" --benchmark_filter=BM_NaiveRk4Anchor --benchmark_format=csv 2>/dev/null |
    awk -F, '/BM_NaiveRk4Anchor/ {print $7}' >> "$work/anchor"
  i=0
  for bin in "$@"; do
    i=$((i + 1))
    rm -rf "$work/out"
    TIMEFORMAT='%3U %3S'
    # shellcheck disable=SC2086  # SWEEP_ARGS is a list of options
    if ! { time "$bin" sweep "$spec" --out "$work/out" --threads 1 --maps none ${SWEEP_ARGS:-} > /dev/null 2>&1; } 2>> "$work/cpu.$i"; then
      echo "sweep-speed.sh: '$bin sweep $spec' failed (run it by hand to see why)" >&2
      exit 1
    fi
  done
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"

anchor=$(median < "$work/anchor")
awk -v a="$anchor" -v n="$rounds" 'BEGIN {printf "anchor (naive RK4): %.3g M steps per CPU second, median of %d\n", a / 1e6, n}'
i=0
for bin in "$@"; do
  i=$((i + 1))
  cpu=$(awk '{print $1 + $2}' "$work/cpu.$i" | median)
  awk -v bin="$bin" -v cpu="$cpu" -v n="$rounds" -v steps="$steps" -v a="$anchor" 'BEGIN {
    rate = steps / cpu
    printf "%s: %.3f s CPU (median of %d), %.3g M steps per CPU second, %.2fx the anchor\n", bin, cpu, n, rate / 1e6, rate / a
  }'
done
