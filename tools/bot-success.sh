#!/usr/bin/env bash
# A bot's success rate on a level over seeds: plays LEVEL with BOT headless
# for seeds FIRST..LAST and prints one line per seed (seed, outcome, time
# [s], wall time [s], CPU time [s], the kind of task, reason), then the
# rate, the median time of the won trials, the median wall time per trial
# and the CPU per simulated second (median and largest). Where the level's
# name says which kind of task the seed drew ("Random task (coupling): ..."),
# the same per kind. Anything after "--" is passed to `hemiroll run` (e.g.
# the human model's flags).
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
  python3 -c '
import json, re, sys
try:
    d = json.loads(sys.argv[2])
except ValueError:
    d = {"outcome": "error", "time": 0, "wall_time": 0, "cpu_time": 0, "reason": "no result line", "level_name": ""}
m = re.search(r"\((\w+)\)", d.get("level_name", ""))
print(sys.argv[1], d["outcome"], round(d["time"], 2), round(d["wall_time"], 2), round(d.get("cpu_time", 0), 2),
      m[1] if m else "-", d["reason"])' "$seed" "$line" | tee -a "$out"
done
python3 - "$out" <<'PY'
import statistics, sys
rows = [l.rstrip("\n").split(None, 6) for l in open(sys.argv[1])]
def summary(rows):
    won = [r for r in rows if r[1] == "success"]
    per = [float(r[4]) / float(r[2]) for r in rows if float(r[2]) > 0]
    return (f"won {len(won)} of {len(rows)} ({100 * len(won) / len(rows):.0f} %); "
            f"median time of the won: {statistics.median(float(r[2]) for r in won) if won else float('nan'):.1f} s; "
            f"median wall per trial: {statistics.median(float(r[3]) for r in rows):.2f} s; "
            f"CPU per simulated second: median {statistics.median(per) if per else float('nan'):.3f}, "
            f"largest {max(per) if per else float('nan'):.3f}")
print(summary(rows))
kinds = sorted({r[5] for r in rows} - {"-"})
for kind in kinds:
    print(f"  {kind}: " + summary([r for r in rows if r[5] == kind]))
PY
