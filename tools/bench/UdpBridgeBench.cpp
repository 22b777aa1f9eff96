// Round trip through the UDP bridge on loopback (issue 4): the servo loop on
// its own thread with a UdpBridgeDevice, and the reference client's loop
// (tools/hapticclient, a spring-mass hand) on a second thread of this
// process, both at 1 kHz. One iteration = one run of kSeconds. Counters, from
// the client's books (times in microseconds):
//   rtt_min_us, rtt_p50_us, rtt_p99_us, rtt_max_us  from sending a state to
//     receiving the first force computed from it. The force waits for the
//     loop's next tick, so these depend on the phase between the client's
//     and the loop's 1 ms grids: with the client at 1000 Hz the phase is
//     fixed (an arbitrary value per run); at 990 Hz it sweeps the whole
//     period, the median is about half a period and the minimum is the
//     bridge's own cost (two socket hops, decode, one tick, encode).
//   lost, out_of_order  state datagrams the bridge never got or got late;
//     forces_lost, forces_out_of_order  the same for forces at the client.
// UDP_BRIDGE_BENCH_SECONDS sets the run length (default 2).
#include <benchmark/benchmark.h>

#include <atomic>
#include <cstdlib>
#include <optional>
#include <thread>

#include "engine/haptics/ServoLoop.h"
#include "engine/haptics/devices/UdpBridgeDevice.h"
#include "tools/hapticclient/HapticClient.h"

namespace {

using namespace hemiroll;
using namespace hemiroll::haptics;

double benchSeconds() {
  const char* env = std::getenv("UDP_BRIDGE_BENCH_SECONDS");
  const double s = env ? std::atof(env) : 2.0;
  return s > 0.0 ? s : 2.0;
}

// What both benchmarks' clients share: the bridge's port, the run's length
// and rate, real-time priority as a real device's client would run (the
// hand starts on the mass point at rest by default, so the coupling engages).
hapticclient::ClientOptions clientOptions(std::uint16_t port, double rate) {
  hapticclient::ClientOptions options;
  options.port = port;
  options.duration = benchSeconds();
  options.rate = rate;
  options.realtimePriority = 70;
  return options;
}

// One run of both benchmarks: a bridge on a free port, the client shaped by
// `shape` on its own thread, the servo loop engaged until the client ends.
// Empty (with the state skipped) when the bridge cannot open or no client
// state arrives.
struct BridgeRun {
  hapticclient::ClientSummary summary;
  UdpBridgeCounters counters;
};

template <class Shape>
std::optional<BridgeRun> runBridge(benchmark::State& state, double clientRate, Shape shape) {
  UdpBridgeDef bridgeDef;
  bridgeDef.port = 0;
  UdpBridgeDevice bridge(bridgeDef);
  if (!bridge.open()) {
    state.SkipWithError(bridge.error());
    return std::nullopt;
  }
  hapticclient::ClientOptions options = clientOptions(bridge.port(), clientRate);
  shape(options);
  std::atomic<bool> stopClient{false};
  BridgeRun run;
  std::thread client([&] { run.summary = hapticclient::runClient(options, stopClient); });
  if (!bridge.waitForClient(2.0)) {
    stopClient = true;
    client.join();
    state.SkipWithError("the client sent nothing");
    return std::nullopt;
  }
  ServoLoop loop(ServoLoopDef{}, bridge);
  ServoCommand engage;
  engage.kind = ServoCommandKind::Engage;
  loop.post(engage);
  loop.start();
  client.join();
  loop.stop();
  run.counters = bridge.counters();
  return run;
}

void BM_UdpBridgeRoundTrip(benchmark::State& state) {
  const double clientRate = static_cast<double>(state.range(0));
  for (auto _ : state) {
    const auto run = runBridge(state, clientRate, [](hapticclient::ClientOptions& options) {
      options.circleRadius = 0.005;
      options.circleFrequency = 1.0;
    });
    if (!run) return;
    const hapticclient::ClientSummary& summary = run->summary;
    const UdpBridgeCounters& c = run->counters;
    state.counters["rtt_min_us"] = summary.rttMin * 1e6;
    state.counters["rtt_p50_us"] = summary.rttMedian * 1e6;
    state.counters["rtt_p99_us"] = summary.rttP99 * 1e6;
    state.counters["rtt_max_us"] = summary.rttMax * 1e6;
    state.counters["lost"] = static_cast<double>(c.lost);
    state.counters["out_of_order"] = static_cast<double>(c.outOfOrder);
    state.counters["forces_lost"] = static_cast<double>(summary.forcesLost);
    state.counters["forces_out_of_order"] = static_cast<double>(summary.forcesOutOfOrder);
    state.counters["states"] = static_cast<double>(summary.statesSent);
  }
}
BENCHMARK(BM_UdpBridgeRoundTrip)->Arg(1000)->Arg(990)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

// End to end, a step of the hand to the force's response (issue 31): the
// simulated device (a Touch's figures: 3.3 N clamp, 50 g handle, 0.02 N
// friction, 0.055 mm encoder counts) reports a 2 mm square wave on x, an
// edge every 47 ms (at 990 Hz the client's phase to the loop's grid moves
// 0.47 of a period between edges, so the edges sample every phase; every
// 50 ms would sample two); the latency runs from sending the first state after an edge to the
// client receiving the first force computed from it that differs by more
// than 0.02 N. The path: socket, the bridge's receiver, the servo loop's
// next tick (physics, coupling, safety with its rate limit), socket back.
// Counters (us): step_p50_us, step_p10_us, step_p90_us, step_max_us, steps.
void BM_UdpBridgeStepResponse(benchmark::State& state) {
  const double clientRate = static_cast<double>(state.range(0));
  for (auto _ : state) {
    const auto run = runBridge(state, clientRate, [](hapticclient::ClientOptions& options) {
      options.peakForce = 3.3;
      options.handleMass = 0.05;
      options.friction = 0.02;
      options.resolution = 0.000055;
      options.step = 0.002;
      options.stepPeriod = 0.094;
    });
    if (!run) return;
    const hapticclient::ClientSummary& summary = run->summary;
    state.counters["step_p50_us"] = summary.stepMedian * 1e6;
    state.counters["step_p10_us"] = summary.stepP10 * 1e6;
    state.counters["step_p90_us"] = summary.stepP90 * 1e6;
    state.counters["step_max_us"] = summary.stepMax * 1e6;
    state.counters["steps"] = static_cast<double>(summary.steps);
    state.counters["lost"] = static_cast<double>(run->counters.lost);
  }
}
BENCHMARK(BM_UdpBridgeStepResponse)->Arg(1000)->Arg(990)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
