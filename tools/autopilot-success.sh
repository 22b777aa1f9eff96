#!/usr/bin/env bash
# The autopilot's success rate over generated reaching tasks (issue 13):
# plays levels/generated/random_reach.lua with seeds FIRST..LAST (default
# 1..100) headless and prints one line per seed (seed, outcome, time, wall
# time, reason), then the rate, the median time of the won tasks and the
# median wall time per trial (tools/bot-success.sh).
#   tools/autopilot-success.sh [FIRST LAST] [BUILD_DIR]
# A failed seed runs to the level's 4-minute limit: expect 20-40 s of wall
# time for each, well under a second for most won ones.
set -euo pipefail
cd "$(dirname "$0")/.."
exec tools/bot-success.sh levels/generated/random_reach.lua autopilot "${1:-1}" "${2:-100}" "${3:-build}"
