#!/usr/bin/env bash
# The issue 32 figures of this build against an earlier commit, measured in
# the same run (`make bench` ends with it; BENCH_AGAINST=none skips it).
# REV's hemiroll and benchmarks are built in a detached worktree under
# out/against/ (kept, so a second run only rebuilds what changed), then each
# round runs REV's binary and this build's, one after the other, so that the
# load of a shared machine falls on both alike. Reported: the median over the
# rounds of each side's figure (each benchmark figure is itself a median of
# 5 repetitions):
#   - the whole sweep as a user runs it: `hemiroll sweep` of
#     tools/bench/sweeps/rose_16_points_60s.lua, --threads 1 --maps none, in
#     steps per CPU second over the naive RK4 anchor (tools/sweep-speed.sh);
#   - one sweep point's analysis of 10, 60 and 600 s (sweep_bench);
#   - the RK4 step, 12-state with the M3 coupling, and the 8-lane rose
#     kernel (physics_bench);
#   - the servo loop's lateness p99.9 over 10 s (haptics_bench).
#
#   tools/bench-against.sh REV [BUILD] [ROUNDS]
set -euo pipefail
usage="usage: tools/bench-against.sh REV [BUILD] [ROUNDS]"
rev=${1:?$usage}
build=${2:-build}
rounds=${3:-3}
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
[[ "$rounds" =~ ^[1-9][0-9]*$ ]] || { echo "bench-against.sh: ROUNDS must be a positive whole number, got '$rounds'" >&2; exit 2; }
sha=$(git rev-parse --verify --quiet "$rev^{commit}") ||
  { echo "bench-against.sh: '$rev' names no commit of this repository" >&2; exit 2; }
for b in hemiroll bench/sweep_bench bench/physics_bench bench/haptics_bench; do
  [ -x "$build/$b" ] || { echo "bench-against.sh: $build/$b is missing: build this tree first (make build)" >&2; exit 2; }
done

# REV's binaries. The worktree is git's own, so `git worktree prune` tidies it
# once out/ is removed.
tree="$root/out/against/${sha:0:12}"
if [ ! -d "$tree" ]; then
  mkdir -p "$root/out/against"
  git worktree add --detach --quiet "$tree" "$sha"
fi
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
echo "== building ${sha:0:12} in $tree/build (its targets only; a first build takes minutes)"
(cd "$tree" && cmake --preset release -Wno-dev "${launcher[@]}" > /dev/null &&
  cmake --build build -j "$(nproc)" --target hemiroll sweep_bench physics_bench haptics_bench > /dev/null) ||
  { echo "bench-against.sh: ${sha:0:12} did not build (run the build in $tree by hand to see why)" >&2; exit 1; }
old="$tree/build"

median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

# One benchmark's median of 5 repetitions: COLUMN is cpu_time or a counter.
bench_median() {
  local bin=$1 filter=$2 column=$3
  "$bin" --benchmark_filter="$filter" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
         --benchmark_format=csv 2> /dev/null |
    awk -F, -v col="$column" 'NR == 1 {for (i = 1; i <= NF; ++i) {h = $i; gsub(/"/, "", h); if (h == col) c = i}}
                              /_median"/ && c {print $c}'
}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
figures=(
  "sweep_bench|BM_SweepPointAnalysis/seconds:10$|cpu_time|analysis of a 10 s point [ms]"
  "sweep_bench|BM_SweepPointAnalysis/seconds:60$|cpu_time|analysis of a 60 s point [ms]"
  "sweep_bench|BM_SweepPointAnalysis/seconds:600$|cpu_time|analysis of a 600 s point [ms]"
  "physics_bench|BM_ForceDrivenRk4Step/coupledM3:1$|cpu_time|RK4 step, 12-state, M3 [ns]"
  "physics_bench|BM_PrescribedLockstepRk4/lanes:8$|items_per_second|rose kernel, 8 lanes [steps/s]"
)
echo "== ${rounds} alternating rounds, load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for ((r = 1; r <= rounds; ++r)); do
  for i in "${!figures[@]}"; do
    IFS='|' read -r bin filter column _ <<< "${figures[$i]}"
    bench_median "$old/bench/$bin" "$filter" "$column" >> "$work/old.$i"
    bench_median "$build/bench/$bin" "$filter" "$column" >> "$work/new.$i"
  done
  for side in old new; do
    dir=$old; [ $side = new ] && dir=$build
    HAPTICS_BENCH_SECONDS=10 "$dir/bench/haptics_bench" --benchmark_filter=BM_ServoLoopLateness --benchmark_format=csv 2> /dev/null |
      awk -F, 'NR == 1 {for (i = 1; i <= NF; ++i) {h = $i; gsub(/"/, "", h); if (h == "late_p999_us") c = i}}
               NR > 1 && c {print $c}' >> "$work/$side.servo"
  done
done
echo "== load after: $(cut -d' ' -f1-3 /proc/loadavg)"

printf '\n| figure (median of %d rounds) | %s | this build |\n|---|---|---|\n' "$rounds" "${sha:0:12}"
for i in "${!figures[@]}"; do
  IFS='|' read -r _ _ column label <<< "${figures[$i]}"
  scale=1; [ "$column" = items_per_second ] && scale=1e-6 && label=${label/steps\/s/M steps\/s}
  printf '| %s | %.4g | %.4g |\n' "$label" "$(median < "$work/old.$i" | awk -v s=$scale '{print $1 * s}')" \
    "$(median < "$work/new.$i" | awk -v s=$scale '{print $1 * s}')"
done
printf '| servo lateness p99.9, 10 s [us] | %s | %s |\n\n' "$(median < "$work/old.servo")" "$(median < "$work/new.servo")"

echo "== the whole sweep against the anchor"
tools/sweep-speed.sh "$rounds" "$build/bench/sweep_bench" "$old/hemiroll" "$build/hemiroll"
