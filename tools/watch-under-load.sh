#!/usr/bin/env bash
# The window under load (issue 27): `hemiroll play LEVEL --watch` under Xvfb
# with one core kept busy by another process (a spin loop), RUNS times for
# the paper's task and for tutorial 04, and what each run did: the outcome,
# the safety stops, the servo loop's lateness (p99, max) and the stalls it
# rode out, the frame rate and the CPU the game took. Beside each level, the
# same autopilot without the window (`hemiroll run --bot autopilot
# --realtime`, same load), so that what the window causes is told from what
# the autopilot's own planning causes.
#
# Then the stops that fit the device, with a stall made on purpose (the
# game process stopped for STALL_MS with SIGSTOP, then continued: every
# thread, the servo thread too, comes back late): the mouse rides it out
# (no safety stop, the stall counted), a force device (the UDP bridge with
# the reference client, hemiroll-haptic-client) stops with "servo loop
# stalled".
#
# The servo thread runs under the normal scheduler, as on most players'
# machines (no rtprio limit): the program is started without CAP_SYS_NICE
# (setpriv), so its request for SCHED_FIFO is refused even as root. --fifo
# lets it have SCHED_FIFO where the machine grants it.
#
#   tools/watch-under-load.sh [--runs N] [--build DIR] [--limit S] [--no-load] [--no-baseline] [--fifo]
#                             [--level FILE]... [--frame-cap FPS] [--out FILE]
# (--level: these levels instead of the two; --frame-cap: the game's setting, default 60.)
# Prints a markdown table (also written to FILE, default out/watch-under-load.md;
# each run's own output beside it, in out/watch-under-load/).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=10 build=build limit=120 load=1 baseline=1 fifo=0 out=out/watch-under-load.md stall_ms=60 cap=60
levels=()
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    --limit) limit=$2; shift 2 ;;
    --no-load) load=0; shift ;;
    --no-baseline) baseline=0; shift ;;
    --fifo) fifo=1; shift ;;
    --level) levels+=("$2"); shift 2 ;;
    --frame-cap) cap=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    -h|--help) sed -n '2,29p' "$0"; exit 0 ;;
    *) echo "watch-under-load: unknown option '$1' (--help lists them)" >&2; exit 2 ;;
  esac
done
for tool in xvfb-run python3 awk; do
  command -v "$tool" >/dev/null || { echo "watch-under-load: needs $tool (tools/install-deps.sh installs it)" >&2; exit 2; }
done
[ -x "$build/hemiroll" ] || { echo "watch-under-load: no $build/hemiroll: run 'make build' first" >&2; exit 2; }
mkdir -p "$(dirname "$out")"
work=$(mktemp -d)
busy=""
cleanup() {
  [ -n "$busy" ] && kill "$busy" 2>/dev/null || true
  rm -rf "${out%.md}" && mkdir -p "${out%.md}" && cp "$work"/*.txt "$work"/*.json "${out%.md}/" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
if [ "$load" = 1 ]; then
  # One core kept busy by another process, as another program on a
  # player's 2-core machine would.
  awk 'BEGIN { for (;;) x++ }' &
  busy=$!
fi
export LIBGL_ALWAYS_SOFTWARE=1 SDL_AUDIODRIVER=dummy
# The program as a player's machine runs it: no CAP_SYS_NICE, so no SCHED_FIFO.
nofifo=()
if [ "$fifo" = 0 ]; then
  command -v setpriv >/dev/null || { echo "watch-under-load: needs setpriv (util-linux) to run without SCHED_FIFO; or --fifo" >&2; exit 2; }
  nofifo=(setpriv --bounding-set=-sys_nice)
fi

# The machine's busy CPU since a /proc/stat sample, in cores (this machine
# may be shared: what else ran shows here, beside the spin loop's one core).
cpu_sample() { awk '/^cpu / { print $2 + $3 + $4 + $7 + $8 + $9, $2 + $3 + $4 + $5 + $6 + $7 + $8 + $9 }' /proc/stat; }
busy_cores() {  # before-sample after-sample
  awk -v n="$(nproc)" -v b="$1" -v t="$2" -v B="$3" -v T="$4" 'BEGIN { if (T > t) printf "%.2f", (B - b) / (T - t) * n; else print "-" }'
}

# One watched run: its autoplay summary into $work/<name>.txt.
# Settings and data in a folder of its own (never the user's).
watch() {  # name level [settings-json] [stall-after-seconds]
  local name=$1 level=$2 settings=${3:-} stall=${4:-}
  local home="$work/$name.home"
  mkdir -p "$home/config" "$home/data"
  printf '%s\n' "${settings:-{\"frame_cap_fps\": $cap\}}" > "$home/config/settings.json"
  HEMIROLL_CONFIG_DIR="$home/config" HEMIROLL_DATA_DIR="$home/data" \
    xvfb-run -a -s "-screen 0 1280x720x24" "${nofifo[@]}" "$build/hemiroll" play "$level" --watch --autoplay "$limit" \
    > "$work/$name.txt" 2>&1 &
  local runner=$! before
  before=$(cpu_sample)
  if [ -n "$stall" ]; then
    sleep "$stall"
    local pid
    pid=$(pgrep -n -f "^$build/hemiroll play $level" || true)
    if [ -n "$pid" ]; then
      kill -STOP "$pid"
      sleep "$(awk "BEGIN { print $stall_ms / 1000 }")"
      kill -CONT "$pid"
    fi
  fi
  wait "$runner" || true
  echo "machine busy: $(busy_cores $before $(cpu_sample)) cores" >> "$work/$name.txt"
}

baseline_run() {  # name level seed
  local line
  line=$(timeout "$limit" "${nofifo[@]}" "$build/hemiroll" run "$2" --bot autopilot --realtime --seed "$3" 2>/dev/null || true)
  [ -n "$line" ] || line='{"outcome":"stopped","time":'"$limit"',"reason":"no result within the wall-time limit"}'
  printf '%s\n' "$line" > "$work/$1.json"
}

[ ${#levels[@]} -gt 0 ] || levels=(levels/paper_reaching.lua levels/tutorial_04_stop_on_target.lua)
for level in "${levels[@]}"; do
  tag=$(basename "$level" .lua)
  for run in $(seq 1 "$runs"); do
    watch "$tag-watch-$run" "$level"
    [ "$baseline" = 1 ] && baseline_run "$tag-run-$run" "$level" "$run"
    echo "watch-under-load: $tag run $run done" >&2
  done
done
# The stall on purpose, 3 s into tutorial 04: the mouse, then the bridge.
watch stall-mouse levels/tutorial_04_stop_on_target.lua "" 3
port=47131
# The client stands for a device's driver, which runs at real-time priority:
# under the normal scheduler its 1 kHz sends starve under load and the
# bridge's own watchdog stops the game before the stall this is about.
if [ -x "$build/hemiroll-haptic-client" ]; then
  "$build/hemiroll-haptic-client" --port "$port" --duration 60 --realtime-priority 90 > "$work/client.txt" 2>&1 &
  client=$!
  watch stall-udp levels/tutorial_04_stop_on_target.lua "{\"device\": \"udp\", \"udp_port\": $port, \"frame_cap_fps\": $cap}" 3
  kill "$client" 2>/dev/null || true
  wait "$client" 2>/dev/null || true
else
  echo "no $build/hemiroll-haptic-client: the bridge's stall not measured" > "$work/stall-udp.txt"
fi

python3 - "$work" "$runs" "$load" "$baseline" "$stall_ms" "$cap" "${levels[@]}" <<'PY' | tee "$out"
import json, os, re, statistics, sys
work, runs, load, baseline, stall_ms, cap = sys.argv[1], int(sys.argv[2]), sys.argv[3] == "1", sys.argv[4] == "1", sys.argv[5], sys.argv[6]
levels = sys.argv[7:]

def parse(path):
    text = open(path).read() if os.path.exists(path) else ""
    r = {"text": text}
    m = re.search(r"trial: (\w+) at ([\d.]+) s \(([^)]*)\)", text)
    if m: r.update(outcome=m[1], time=float(m[2]), reason=m[3])
    elif "stopped for safety" in text:
        m = re.search(r"trial: stopped for safety \((.*)\)", text); r.update(outcome="safety stop", time=None, reason=m[1] if m else "")
    else:
        m = re.search(r"trial: the trial was still running at ([\d.]+) s \((.*)\)", text)
        r.update(outcome="unfinished", time=None,
                 reason=f"at {m[1]} s, {m[2]}" if m else ("still running at the limit" if "autoplay" in text else text.strip()[-200:]))
    m = re.search(r"autopilot: \d+ plans \((\d+) per second\)", text); r["plans"] = int(m[1]) if m else None
    m = re.search(r"decisions applied (\d+), dropped late (\d+)", text); r["decided"] = f"{m[1]} / {m[2]}" if m else None
    m = re.search(r"machine busy: ([\d.]+) cores", text); r["busy"] = float(m[1]) if m else None
    m = re.search(r"safety stops: (\d+)", text); r["stops"] = int(m[1]) if m else None
    m = re.search(r"lateness p50 (\d+) us, p99 (\d+) us, p99.9 (\d+) us, max (\d+) us, missed ticks (\d+), stalls over the overrun limit (\d+)", text)
    if m: r.update(p99=int(m[2]), max=int(m[4]), missed=int(m[5]), stalls=int(m[6]))
    m = re.search(r"median ([\d.]+) fps", text); r["fps"] = float(m[1]) if m else None
    m = re.search(r"cpu: ([\d.]+) s in ([\d.]+) s of wall time \((\d+) %", text); r["cpu"] = int(m[3]) if m else None
    m = re.search(r"servo thread: (.*)", text); r["sched"] = m[1] if m else ""
    return r

def fmt(v, f="{}"):
    return "-" if v is None else f.format(v)

print(f"# `play --watch` under load ({'one core kept busy by a spin loop' if load else 'no extra load'}), Xvfb 1280x720, llvmpipe, frame cap {cap} fps\n")
sched = ""
for level in levels:
    tag = os.path.basename(level)[:-4]
    rows = [parse(f"{work}/{tag}-watch-{i}.txt") for i in range(1, runs + 1)]
    base = []
    if baseline:
        for i in range(1, runs + 1):
            try: base.append(json.load(open(f"{work}/{tag}-run-{i}.json")))
            except Exception: base.append({"outcome": "?", "time": None, "reason": "unreadable"})
    sched = sched or next((r["sched"] for r in rows if r["sched"]), "")
    print(f"## {level}\n")
    head = ("| run | watched: outcome | time [s] | safety stops | lateness p99 / max [ms] | stalls ridden | missed ticks "
            "| fps | CPU [% of a core] | plans/s | decisions applied / dropped late | machine busy [cores] |")
    sep = "|---|---|---|---|---|---|---|---|---|---|---|---|"
    if baseline: head += " no window (`run --realtime`) |"; sep += "---|"
    print(head); print(sep)
    for i, r in enumerate(rows):
        line = (f"| {i+1} | {r['outcome']}{' (' + r['reason'] + ')' if r['outcome'] != 'success' else ''} | {fmt(r['time'], '{:.1f}')} "
                f"| {fmt(r['stops'])} | {fmt(r.get('p99') and r['p99']/1000, '{:.2f}')} / {fmt(r.get('max') and r['max']/1000, '{:.1f}')} "
                f"| {fmt(r.get('stalls'))} | {fmt(r.get('missed'))} | {fmt(r['fps'], '{:.0f}')} | {fmt(r['cpu'])} | {fmt(r['plans'])} "
                f"| {fmt(r['decided'])} "
                f"| {fmt(r['busy'], '{:.2f}')} |")
        if baseline:
            b = base[i]
            line += f" {b['outcome']}{'' if b['outcome'] == 'success' else ' (' + str(b.get('reason','')) + ')'} {fmt(b.get('time'), '{:.1f}')} s |"
        print(line)
    won = sum(r["outcome"] == "success" for r in rows)
    stops = sum(r["stops"] or 0 for r in rows)
    p99 = [r["p99"] / 1000 for r in rows if r.get("p99") is not None]
    mx = [r["max"] / 1000 for r in rows if r.get("max") is not None]
    summary = (f"\nwatched: won {won} of {len(rows)}, safety stops {stops}, lateness p99 median "
               f"{statistics.median(p99) if p99 else float('nan'):.2f} ms, worst max {max(mx) if mx else float('nan'):.1f} ms, "
               f"stalls ridden {sum(r.get('stalls') or 0 for r in rows)}")
    if baseline:
        summary += f"; without the window: won {sum(b['outcome'] == 'success' for b in base)} of {len(base)}"
    print(summary + "\n")
print(f"servo thread: {sched}\n")
print(f"## A {stall_ms} ms stall on purpose (SIGSTOP of the game, 3 s into tutorial 04, watched)\n")
print("| device | safety stops | stalls ridden | lateness max [ms] | outcome |")
print("|---|---|---|---|---|")
for name, label in (("stall-mouse", "mouse (no force output)"), ("stall-udp", "UDP bridge + reference client (renders force)")):
    r = parse(f"{work}/{name}.txt")
    print(f"| {label} | {fmt(r['stops'])} | {fmt(r.get('stalls'))} | {fmt(r.get('max') and r['max']/1000, '{:.1f}')} | {r['outcome']} ({r['reason']}) |")
PY
