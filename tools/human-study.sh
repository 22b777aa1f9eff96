#!/usr/bin/env bash
# The human model's success table for docs/HUMAN_MODEL.md (issue 26): every
# tutorial and the paper's task, on a mouse with and without the game's aids
# at the visual delays 0.2 s and 0.25 s, and the paper's findings (the task
# on a force device with M3 at alpha 2 and 4, the arm co-contracted and
# relaxed, and by sight alone). SEEDS seeds each (default 20). Prints
# markdown tables; takes some minutes (an aided trial costs about what an
# unaided one does: HintGate, not the autopilot, gates the hint).
#   tools/human-study.sh [SEEDS] [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
seeds=${1:-20}
build=${2:-build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
rate() {  # LEVEL FLAGS... -> "won/seeds (median time s)"
  local level=$1; shift
  tools/human-success.sh "$level" 1 "$seeds" "$build" -- "$@" | tail -1 |
    python3 -c 'import re,sys; l=sys.stdin.read(); m=re.search(r"won (\d+) of (\d+).*?won: ([\d.na]+) s", l); print(f"{m.group(1)}/{m.group(2)}" + ("" if m.group(3)=="nan" else f" ({m.group(3)} s)"))'
}
echo "| level | mouse 0.2 s | mouse 0.25 s | mouse + aids 0.2 s | mouse + aids 0.25 s |"
echo "|---|---|---|---|---|"
for level in levels/tutorial_0*.lua levels/paper_reaching.lua; do
  row="| $(basename "$level" .lua)"
  for flags in "--human-delay 0.2" "--human-delay 0.25" "--human-delay 0.2 --human-aids" "--human-delay 0.25 --human-aids"; do
    # shellcheck disable=SC2086
    row="$row | $(rate "$level" $flags)"
  done
  echo "$row |"
done
sed 's/alpha = 2 }/alpha = 4 }/' levels/paper_reaching.lua > "$tmp/paper_reaching_alpha4.lua"
echo
echo "| the paper's task | won |"
echo "|---|---|"
echo "| force device, M3, alpha 2 | $(rate levels/paper_reaching.lua --human-device haptic) |"
echo "| force device, M3, alpha 4 | $(rate "$tmp/paper_reaching_alpha4.lua" --human-device haptic) |"
echo "| force device, alpha 2, relaxed arm | $(rate levels/paper_reaching.lua --human-device haptic --human-relaxed-arm) |"
echo "| force device, alpha 4, relaxed arm | $(rate "$tmp/paper_reaching_alpha4.lua" --human-device haptic --human-relaxed-arm) |"
echo "| by sight alone (mouse, no aids) | $(rate levels/paper_reaching.lua --human-device mouse) |"
