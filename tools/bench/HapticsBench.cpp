// Lateness of the 1 kHz servo loop on the real clock (issue 4): the loop runs
// the full tick (scripted device circling the mass point, engaged M3
// coupling, RK4 physics, safety, snapshot) on its own thread for kSeconds
// while a second thread keeps a core busy, as the renderer will. One
// iteration = one run; the counters are the loop's own statistics:
//   late_p50_us, late_p99_us, late_p999_us, late_max_us  lateness of a tick's
//     start after its deadline (upper bin edges of a 1 us histogram);
//   missed_ticks   ticks skipped by the catch-up policy;
//   ticks, fifo    ticks run; 1 when SCHED_FIFO was granted, else 0.
// The acceptance run is 60 s: HAPTICS_BENCH_SECONDS=60.
#include <benchmark/benchmark.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <thread>

#include "engine/haptics/Haptics.h"
#include "engine/haptics/devices/ScriptedDevice.h"

namespace {

using namespace hemiroll::haptics;

double benchSeconds() {
  const char* env = std::getenv("HAPTICS_BENCH_SECONDS");
  const double s = env ? std::atof(env) : 2.0;
  return s > 0.0 ? s : 2.0;
}

DeviceReading circling(double t) {
  constexpr double kPi = 3.141592653589793, r = 0.005, w = 2.0 * kPi;
  DeviceReading d;
  d.position = Vec3(r * std::sin(w * t), r * (1.0 - std::cos(w * t)), 0.04);
  d.velocity = Vec3(r * w * std::cos(w * t), r * w * std::sin(w * t), 0.0);
  return d;
}

void BM_ServoLoopLateness(benchmark::State& state) {
  const double seconds = benchSeconds();
  for (auto _ : state) {
    ScriptedDevice device(circling);
    ServoLoop loop(ServoLoopDef{}, device);
    ServoCommand engage;
    engage.kind = ServoCommandKind::Engage;
    loop.post(engage);

    // The busy second thread: a spinning consumer of snapshots (what a
    // renderer without vsync does).
    std::atomic<bool> stopBusy{false};
    std::atomic<std::uint64_t> busyReads{0};
    std::thread busy([&] {
      ServoSnapshot s;
      std::uint64_t n = 0;
      volatile double sink = 0.0;
      while (!stopBusy.load(std::memory_order_relaxed)) {
        if (loop.latest(s)) ++n;
        for (int i = 0; i < 1000; ++i) sink = sink + std::sqrt(static_cast<double>(i) + s.time);
      }
      busyReads.store(n);
    });
    loop.start();
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));  // the measurement window, not synchronisation
    loop.stop();
    stopBusy.store(true);
    busy.join();

    const LoopTimingSummary t = loop.timingSummary();
    state.counters["late_p50_us"] = t.latenessP50 * 1e6;
    state.counters["late_p99_us"] = t.latenessP99 * 1e6;
    state.counters["late_p999_us"] = t.latenessP999 * 1e6;
    state.counters["late_max_us"] = t.latenessMax * 1e6;
    state.counters["period_max_us"] = t.periodMax * 1e6;
    state.counters["missed_ticks"] = static_cast<double>(t.missedTicks);
    state.counters["ticks"] = static_cast<double>(t.ticks);
    state.counters["fifo"] = loop.realtime().status == RealtimeStatus::Fifo ? 1.0 : 0.0;
    state.counters["snapshots_read"] = static_cast<double>(busyReads.load());
    std::fprintf(stderr, "haptics_bench: %s\n", loop.realtime().note);
  }
}
BENCHMARK(BM_ServoLoopLateness)->Iterations(1)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
