#!/usr/bin/env bash
# The autopilot's success rate over generated reaching tasks (issue 13):
# plays levels/generated/random_reach.lua with seeds FIRST..LAST (default
# 1..100) headless and prints one line per seed, then the rate, the median
# time of the won tasks and the median wall time per trial.
#   tools/autopilot-success.sh [FIRST LAST] [BUILD_DIR]
# A failed seed runs to the level's 4-minute limit: expect 20-40 s of wall
# time for each, well under a second for most won ones.
set -euo pipefail
cd "$(dirname "$0")/.."
first=${1:-1}
last=${2:-100}
build=${3:-build}
out=$(mktemp)
trap 'rm -f "$out"' EXIT
for seed in $(seq "$first" "$last"); do
  line=$("$build/hemiroll" run levels/generated/random_reach.lua --bot autopilot --seed "$seed" || true)
  python3 -c 'import json,sys; d=json.loads(sys.argv[2]); print(sys.argv[1], d["outcome"], round(d["time"],1), round(d["wall_time"],2), d["reason"])' "$seed" "$line" | tee -a "$out"
done
python3 - "$out" <<'PY'
import statistics, sys
rows = [l.split(None, 4) for l in open(sys.argv[1])]
won = [r for r in rows if r[1] == "success"]
print(f"won {len(won)} of {len(rows)} ({100 * len(won) / len(rows):.0f} %); "
      f"median time of the won: {statistics.median(float(r[2]) for r in won) if won else float('nan'):.1f} s; "
      f"median wall per trial: {statistics.median(float(r[3]) for r in rows):.2f} s")
PY
