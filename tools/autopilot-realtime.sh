#!/usr/bin/env bash
# The autopilot in real time (issue 13): plays LEVEL with `--realtime`
# (servo loop at 1 kHz on its own thread, the bot at 500 Hz, planning on a
# thread of its own) RUNS times and prints one line per run, then the
# success count and the median time of the won runs. Real time is not
# deterministic: each run is a new draw of the threads' timing. A run is
# stopped after LIMIT seconds of wall time (default 90) and counted as lost.
#   tools/autopilot-realtime.sh LEVEL [RUNS] [LIMIT] [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
level=${1:?usage: tools/autopilot-realtime.sh LEVEL [RUNS] [LIMIT] [BUILD_DIR]}
runs=${2:-8}
limit=${3:-90}
build=${4:-build}
out=$(mktemp)
trap 'rm -f "$out"' EXIT
for run in $(seq 1 "$runs"); do
  line=$(timeout "$limit" "$build/hemiroll" run "$level" --bot autopilot --realtime --seed "$run" || true)
  [ -n "$line" ] || line='{"outcome":"stopped","time":'"$limit"',"reason":"no result within the wall-time limit"}'
  python3 -c 'import json,sys; d=json.loads(sys.argv[2]); print(sys.argv[1], d["outcome"], round(d["time"],1), d["reason"])' "$run" "$line" | tee -a "$out"
done
python3 - "$out" <<'PY'
import statistics, sys
rows = [l.split(None, 3) for l in open(sys.argv[1])]
won = [float(r[2]) for r in rows if r[1] == "success"]
print(f"won {len(won)} of {len(rows)}; median time of the won: "
      f"{statistics.median(won) if won else float('nan'):.1f} s (min {min(won, default=float('nan')):.1f}, max {max(won, default=float('nan')):.1f})")
PY
