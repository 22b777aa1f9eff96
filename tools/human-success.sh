#!/usr/bin/env bash
# The human model's success on a level (issue 26, docs/HUMAN_MODEL.md):
# plays LEVEL with `--bot human` for seeds FIRST..LAST (default 1..20)
# headless; prints one line per seed, then the rate, the median time of the
# won trials and the median wall time (tools/bot-success.sh). Anything
# after "--" goes to `hemiroll run`: the human model's flags
# (--human-delay, --human-interval, --human-noise, --human-device,
# --human-aids).
#   tools/human-success.sh LEVEL [FIRST LAST] [BUILD_DIR] [-- FLAGS...]
# e.g. tools/human-success.sh levels/tutorial_04_stop_on_target.lua 1 20 build -- --human-aids
set -euo pipefail
cd "$(dirname "$0")/.."
level=${1:?usage: tools/human-success.sh LEVEL [FIRST LAST] [BUILD_DIR] [-- FLAGS...]}
shift
exec tools/bot-success.sh "$level" human "$@"
