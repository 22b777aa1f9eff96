#!/usr/bin/env bash
# Compares what two hemiroll binaries write where the sweep and the analysis
# are concerned (issue 32): the shipped sweeps with their maps (one also with
# --lanes 1), the benchmark sweep, `hemiroll figures` and `hemiroll analyze`
# of a simulated rose. Every file must be the same bytes (the manifests'
# wall times aside, so they are left out). Exit 0 when all are identical.
#
#   tools/sweep-identity.sh OLD_HEMIROLL NEW_HEMIROLL OUT_DIR
set -euo pipefail
old=$(realpath "${1:?usage: tools/sweep-identity.sh OLD_HEMIROLL NEW_HEMIROLL OUT_DIR}")
new=$(realpath "${2:?usage: tools/sweep-identity.sh OLD_HEMIROLL NEW_HEMIROLL OUT_DIR}")
out=${3:?usage: tools/sweep-identity.sh OLD_HEMIROLL NEW_HEMIROLL OUT_DIR}
root="$(cd "$(dirname "$0")/.." && pwd)"
rm -rf "$out"; mkdir -p "$out"
for who in old new; do
  bin=$old; [ $who = new ] && bin=$new
  dir="$out/$who"; mkdir -p "$dir"
  for spec in "$root"/levels/sweeps/*.lua; do
    "$bin" sweep "$spec" --out "$dir/$(basename "$spec" .lua)" --maps svg > /dev/null 2>&1
  done
  "$bin" sweep "$root/levels/sweeps/rose_k_omega_rest.lua" --out "$dir/rest_lanes_1" --lanes 1 --threads 1 --maps none > /dev/null 2>&1
  "$bin" sweep "$root/tools/bench/sweeps/rose_16_points_60s.lua" --out "$dir/bench16" --threads 1 --maps svg > /dev/null 2>&1
  "$bin" figures --out "$dir/figures" --scenario "$root/levels/scenarios/rose_paper.lua" > /dev/null 2>&1
  mkdir -p "$dir/analyze"
  "$bin" sim "$root/levels/scenarios/rose_paper.lua" --duration 600 --every 10 --out "$dir/analyze/rose.csv" > /dev/null 2>&1
  (cd "$dir/analyze" && "$bin" analyze rose.csv --out out --plots svg > analyze.md 2>&1)
  find "$dir" -name 'sweep.json' -delete
done
files=$(find "$out/new" -type f | wc -l)
if diff -r "$out/old" "$out/new" > "$out/diff.txt"; then
  echo "identical: $files files"
else
  echo "different (see $out/diff.txt):" >&2; head -20 "$out/diff.txt" >&2; exit 1
fi
