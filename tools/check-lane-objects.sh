#!/usr/bin/env bash
# The batched integrator's wide widths are compiled with -mavx2 / -mavx512f
# (engine/physics/BatchedRk4Lanes4.cpp, ...8.cpp). An inline function left
# out of line there would be a weak symbol that the linker may pick for the
# whole program, putting AVX instructions on the scalar path of a CPU without
# them. So those objects must define their entry points and nothing else.
#
#   tools/check-lane-objects.sh path/to/libhemiroll_physics.a
set -euo pipefail
archive=${1:?usage: tools/check-lane-objects.sh LIBHEMIROLL_PHYSICS_A}
status=0
for member in BatchedRk4Lanes4.cpp.o BatchedRk4Lanes8.cpp.o; do
  listing=$(nm -C --defined-only "$archive" 2>/dev/null | awk -v m="$member:" '$0 == m {on=1; next} /^$/ {on=0} on')
  if [ -z "$listing" ]; then
    echo "$archive has no member $member" >&2
    status=1
    continue
  fi
  # Local labels (r, t, b, d) are private to the object; only global or weak
  # code or data (T, W, V, D, B, R, u) could be shared with other objects.
  stray=$(echo "$listing" | awk '$2 ~ /^[TWVDBRu]$/' | grep -v -E 'hemiroll::physics::lanes::(rose|forceDriven)StepLanes[48]\(' || true)
  if [ -n "$stray" ]; then
    echo "$member defines more than its entry points (built for a wider instruction set):" >&2
    echo "$stray" >&2
    status=1
  fi
done
[ $status -eq 0 ] && echo "lane objects define only their entry points"
exit $status
