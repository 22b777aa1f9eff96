#!/usr/bin/env bash
# A bot's success rate on a level over seeds: plays LEVEL with BOT headless
# for seeds FIRST..LAST and prints one line per seed (seed, outcome, time,
# wall time, reason), then the rate, the median time of the won trials and
# the median wall time per trial. Anything after "--" is passed to
# `hemiroll run` (e.g. the human model's flags).
#   tools/bot-success.sh LEVEL BOT [FIRST LAST] [BUILD_DIR] [-- FLAGS...]
set -euo pipefail
cd "$(dirname "$0")/.."
usage="usage: tools/bot-success.sh LEVEL BOT [FIRST LAST] [BUILD_DIR] [-- FLAGS...]"
level=${1:?$usage}
bot=${2:?$usage}
shift 2
first=1 last=20 build=build
[ $# -gt 0 ] && [ "$1" != "--" ] && { first=$1; shift; }
[ $# -gt 0 ] && [ "$1" != "--" ] && { last=$1; shift; }
[ $# -gt 0 ] && [ "$1" != "--" ] && { build=$1; shift; }
[ $# -gt 0 ] && [ "$1" = "--" ] && shift
out=$(mktemp)
trap 'rm -f "$out"' EXIT
for seed in $(seq "$first" "$last"); do
  line=$("$build/hemiroll" run "$level" --bot "$bot" --seed "$seed" "$@" || true)
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
