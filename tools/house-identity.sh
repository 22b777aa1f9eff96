#!/usr/bin/env bash
# Writes every output of hemiroll sim, run and session on the shipped
# scenarios, levels and protocols into DIR, with the fields that measure the
# wall clock or the date masked, and prints one sha256 per file. A
# refactoring that changes no behaviour leaves this list unchanged: run it
# before and after and diff the two lists (issue 17 did so).
#
#   tools/house-identity.sh BUILD_DIR OUT_DIR > hashes.txt
set -euo pipefail
build=${1:?usage: tools/house-identity.sh BUILD_DIR OUT_DIR}
out=${2:?usage: tools/house-identity.sh BUILD_DIR OUT_DIR}
hemiroll="$build/hemiroll"
root="$(cd "$(dirname "$0")/.." && pwd)"
rm -rf "$out"; mkdir -p "$out"

# Wall times, dates and machine names are not behaviour.
mask() {
  sed -E -e "s#$out#<out>#g" -e "s#$root#<root>#g" \
        -e 's/[0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9:.]+Z/<date>/g' \
        -e 's/wall [0-9.]+ s/wall - s/g' \
        -e 's/"(wall_time|cpu_time|wall_time_s|wall_s|started|finished|created|date|recorded_at|host|hostname|started_at|finished_at|time_utc|written_at)": ?("[^"]*"|[0-9.eE+-]+)/"\1":"-"/g' "$@"
}

for scenario in "$root"/levels/scenarios/*.lua; do
  name=$(basename "$scenario" .lua)
  "$hemiroll" sim "$scenario" --duration 2 --out "$out/sim_$name.csv" 2> "$out/sim_$name.err" || echo "exit $?" >> "$out/sim_$name.err"
  "$hemiroll" sim "$scenario" --duration 1 --integrator dopri5 --every 10 --out "$out/sim_${name}_dopri5.csv" 2>> "$out/sim_$name.err" || true
done

for level in "$root"/levels/*.lua "$root"/levels/generated/*.lua; do
  name=$(basename "$level" .lua)
  for bot in "$root"/scripts/bots/*.lua autopilot; do
    botname=$(basename "$bot" .lua)
    # Every shipped bot on every level; the autopilot (seconds a run) on a few.
    case "$botname:$name" in
      autopilot:paper_reaching|autopilot:tutorial_04*|autopilot:challenge_slalom|autopilot:challenge_time_trial|autopilot:random_reach) ;;
      autopilot:*) continue ;;
    esac
    for seed in 0 7; do
      tag="run_${name}_${botname}_$seed"
      rec="$out/$tag.rec"
      "$hemiroll" run "$level" --bot "$bot" --seed "$seed" --record "$rec" 2> "$out/$tag.err" | mask > "$out/$tag.json" || true
    done
  done
done

for protocol in "$root"/levels/protocols/*.lua; do
  name=$(basename "$protocol" .lua)
  "$hemiroll" session "$protocol" --participant p01 --data "$out/session_$name" \
    --bot "$root/scripts/bots/tutorial_solver.lua" --seed 3 2> "$out/session_$name.err" | mask > "$out/session_$name.jsonl" || true
done

# Mask the recordings' own clock fields, then hash everything.
find "$out" -type f \( -name '*.json' -o -name '*.jsonl' -o -name '*.csv' -o -name '*.tsv' -o -name '*.err' \) -print0 |
  while IFS= read -r -d '' f; do mask "$f" > "$f.masked" && mv "$f.masked" "$f"; done
(cd "$out" && find . -type f -print0 | sort -z | xargs -0 sha256sum)
