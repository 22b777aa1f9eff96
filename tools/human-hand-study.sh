#!/usr/bin/env bash
# The human model on the mouse against the mouse with the game's simulated
# hand (issue 26, `--human-device mouse-hand`: the person's hand moves the
# mouse, the game's hand between the mouse and the proxy is pushed by the
# coupling force), every tutorial and the paper's task, SEEDS seeds each
# (default 20), at visual delay DELAY (default 0.2 s), each level to its own
# time limit. Anything after "--" goes to `hemiroll run` for both columns
# (e.g. --human-aids). Prints a markdown table for docs/HUMAN_MODEL.md.
#   tools/human-hand-study.sh [SEEDS] [DELAY] [BUILD_DIR] [-- FLAGS...]
set -euo pipefail
cd "$(dirname "$0")/.."
seeds=20 delay=0.2 build=build
[ $# -gt 0 ] && [ "$1" != "--" ] && { seeds=$1; shift; }
[ $# -gt 0 ] && [ "$1" != "--" ] && { delay=$1; shift; }
[ $# -gt 0 ] && [ "$1" != "--" ] && { build=$1; shift; }
[ $# -gt 0 ] && [ "$1" = "--" ] && shift
rate() {  # LEVEL FLAGS... -> "won/seeds (median time s)"
  local level=$1; shift
  tools/human-success.sh "$level" 1 "$seeds" "$build" -- "$@" | tail -1 |
    python3 -c 'import re,sys; l=sys.stdin.read(); m=re.search(r"won (\d+) of (\d+).*?won: ([\d.na]+) s", l); print(f"{m.group(1)}/{m.group(2)}" + ("" if m.group(3)=="nan" else f" ({m.group(3)} s)"))'
}
echo "| level | mouse $delay s | mouse-hand $delay s |"
echo "|---|---|---|"
for level in levels/tutorial_0[1-5]*.lua levels/paper_reaching.lua; do
  echo "| $(basename "$level" .lua) | $(rate "$level" --human-delay "$delay" --human-device mouse "$@") | $(rate "$level" --human-delay "$delay" --human-device mouse-hand "$@") |"
done
