#!/usr/bin/env bash
# The autopilot's success rate over generated tasks (issues 13, 28): plays
# levels/generated/random_task.lua (bodies, couplings, two stages with a psi
# band, tolerances from the paper's to twice them, all mixed; the seed picks
# the kind) with seeds FIRST..LAST (default 0..199) headless and prints one
# line per seed (seed, outcome, time, wall time, CPU time, kind, reason),
# then the rate, the median time of the won tasks, the median wall time
# and the CPU per simulated second, over all and per kind
# (tools/bot-success.sh). --level FILE plays another generator (e.g.
# levels/generated/random_reach.lua, the paper's body reaching anywhere, or
# levels/generated/random_hold.lua, the paper's task moved with a hold of
# 0.1-1 s and bands 1-2x the paper's: kind "hold").
#   tools/autopilot-success.sh [--level FILE] [FIRST LAST] [BUILD_DIR]
# A failed seed runs to the level's time limit: expect 20-40 s of wall time
# for each, about a second for most won ones.
set -euo pipefail
cd "$(dirname "$0")/.."
level=levels/generated/random_task.lua
if [ "${1:-}" = "--level" ]; then level=${2:?"--level needs a file"}; shift 2; fi
exec tools/bot-success.sh "$level" autopilot "${1:-0}" "${2:-199}" "${3:-build}"
