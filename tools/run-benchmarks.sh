#!/usr/bin/env bash
# `make bench`: runs every benchmark with repetitions and reports medians
# (the machine is shared and noisy). Results also go to out/bench/*.json.
set -euo pipefail
build=${1:-build}
mkdir -p out/bench
for b in "$build"/bench/*_bench; do
  name=$(basename "$b")
  [ "$name" = peer_bench ] && continue  # not Google Benchmark: its own section below
  echo "== $name (median of 7 repetitions)"
  # render_bench opens a window: a virtual display and Mesa's software GL.
  wrap=()
  [ "$name" = render_bench ] && wrap=(xvfb-run -a env LIBGL_ALWAYS_SOFTWARE=1)
  "${wrap[@]}" "$b" --benchmark_repetitions=7 --benchmark_report_aggregates_only=true \
       --benchmark_display_aggregates_only=true \
       --benchmark_out="out/bench/$name.json" --benchmark_out_format=json 2>/dev/null |
    grep -E 'Benchmark|_median'
done

# Work-precision study and the tether's invariant table (~1-2 min): regenerates
# docs/WORK_PRECISION.md and docs/work-precision/*.csv, *.png.
echo "== work_precision (docs/WORK_PRECISION.md)"
mkdir -p docs/work-precision
"$build"/bench/work_precision --out docs/work-precision --doc docs/WORK_PRECISION.md
gnuplot docs/work-precision/work_precision.gp

# hemiroll against MuJoCo, Bullet and ODE on the same scenes (issue 15, a few
# minutes): regenerates docs/PEERS.md and docs/peers/*.
if [ -x "$build"/bench/peer_bench ]; then
  echo "== peer_bench (docs/PEERS.md)"
  mkdir -p docs/peers
  "$build"/bench/peer_bench --out docs/peers --doc docs/PEERS.md
  gnuplot docs/peers/peers.gp
else
  echo "== peer_bench not built (tools/install-deps.sh --peers, then configure again)"
fi
