// A sweep as a user runs it (issue 32), against a plain RK4 anchor in the
// same run:
//   BM_NaiveRk4Anchor            the anchor (NaiveRk4Anchor.h, -O2): items
//                                are RK4 steps of one 12-state trajectory.
//   BM_WholeSweep/lanes:W        tools/bench/sweeps/rose_16_points_60s.lua
//                                (16 points x 60 s at 1 ms) through
//                                runSweepPart on one worker thread with W
//                                lanes, the manifest and the durable CSV
//                                included, as `hemiroll sweep --threads 1
//                                --maps none` runs it. Items are trajectory
//                                steps (960 000 per sweep). Process CPU time
//                                (the sweep's worker is not the bench's
//                                thread). The target: items_per_second at
//                                least 2.8x the anchor's; the counter
//                                x_anchor is that ratio, against the anchor
//                                timed in the same process (median of 5).
//                                The same as a user runs it, the whole
//                                process, two binaries alternating:
//                                tools/sweep-speed.sh.
//   BM_SweepPointAnalysis/s      the features of one sweep point (the
//                                paper's rose from the static tilt, 100 Hz
//                                rows) of 10, 60 and 600 s, as
//                                PointMeasurement analyses them; the rows are
//                                made outside the timed loop.
//   BM_PhysicsFingerprint        the manifest's physics fingerprint
//                                (PhysicsFingerprint.h): 4 s of the rose from
//                                rest with rk4 and with dop853, measured and
//                                hashed, a fixed cost of every `hemiroll
//                                sweep` (its FFT plans made in the first
//                                iteration only, as once per process).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <unistd.h>
#include <vector>

#include "engine/analysis/Analysis.h"
#include "engine/physics/BatchedRk4.h"
#include "engine/physics/StateLayout.h"
#include "engine/script/SweepLoader.h"
#include "game/research/sim/ScenarioRun.h"
#include "game/research/sweep/PhysicsFingerprint.h"
#include "game/research/sweep/PointMeasurement.h"
#include "game/research/sweep/SweepGrid.h"
#include "game/research/sweep/SweepPartRun.h"
#include "tools/bench/NaiveRk4Anchor.h"

namespace {

using namespace hemiroll;
namespace fs = std::filesystem;

void BM_NaiveRk4Anchor(benchmark::State& state) {
  constexpr long long kSteps = 100'000;
  for (auto _ : state) benchmark::DoNotOptimize(bench::naiveRk4Anchor(kSteps));
  state.SetItemsProcessed(state.iterations() * kSteps);
}
BENCHMARK(BM_NaiveRk4Anchor)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

double processCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The anchor's RK4 steps per CPU second in this process: the median of five
// runs of 100 000 steps (~25 ms each), measured once.
double anchorStepsPerCpuSecond() {
  static const double rate = [] {
    constexpr long long kSteps = 100'000;
    std::vector<double> rates;
    for (int run = 0; run < 5; ++run) {
      const double start = processCpuSeconds();
      benchmark::DoNotOptimize(bench::naiveRk4Anchor(kSteps));
      rates.push_back(static_cast<double>(kSteps) / (processCpuSeconds() - start));
    }
    std::nth_element(rates.begin(), rates.begin() + 2, rates.end());
    return rates[2];
  }();
  return rate;
}

const char* const kSpec = HEMIROLL_SOURCE_DIR "/tools/bench/sweeps/rose_16_points_60s.lua";

void BM_WholeSweep(benchmark::State& state) {
  const int lanes = static_cast<int>(state.range(0));
  if (!physics::laneWidthSupported(lanes)) {
    state.SkipWithError("this CPU does not run that lane width");
    return;
  }
  const task::SweepDef def = script::SweepLoader().loadFile(kSpec);
  const fs::path out = fs::temp_directory_path() / ("hemiroll-sweep-bench-" + std::to_string(::getpid()));
  const double anchor = anchorStepsPerCpuSecond();
  long long steps = 0;
  double cpu = 0.0;  // the sweeps' own, without the paused clean-ups
  for (auto _ : state) {
    state.PauseTiming();
    fs::remove_all(out);
    state.ResumeTiming();
    const double start = processCpuSeconds();
    game::SweepPartRequest request;
    request.def = def;
    request.specFile = kSpec;
    request.outDir = out;
    request.threads = 1;
    request.laneWidth = lanes;
    request.program = "hemiroll sweep_bench";
    const game::SweepPartReport report = game::runSweepPart(request);
    benchmark::DoNotOptimize(report.computed);
    steps += report.computed * static_cast<long long>(def.duration / def.timeStep + 0.5);
    cpu += processCpuSeconds() - start;
  }
  fs::remove_all(out);
  state.SetItemsProcessed(steps);
  state.counters["x_anchor"] = static_cast<double>(steps) / cpu / anchor;
}
BENCHMARK(BM_WholeSweep)->Arg(1)->Arg(8)->ArgName("lanes")->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

// One point's 100 Hz rows, the columns PointMeasurement keeps.
struct PointRows {
  std::vector<double> time, massX, massY, contactX, contactY, psi;
  analysis::TrialSamples samples() const { return {time, massX, massY, contactX, contactY, psi}; }
};

PointRows paperPointRows(double duration) {
  task::SweepDef def = script::SweepLoader().loadFile(kSpec);
  def.duration = duration;
  const game::SweepGrid grid(def);
  game::RunSettings settings;
  settings.duration = duration;
  settings.timeStep = def.timeStep;
  settings.every = game::sampleEvery(def.timeStep);
  // Point 6: k = 8, Omega = -pi/10, the paper's.
  const task::ScenarioDef scenario = grid.scenario(grid.point(6));
  PointRows rows;
  namespace slot = physics::force_slot;
  game::ScenarioRun(scenario, settings).run([&](const game::TrajectoryRow& row) {
    rows.time.push_back(row.time);
    rows.massX.push_back(row.state[slot::x_p]);
    rows.massY.push_back(row.state[slot::y_p]);
    rows.contactX.push_back(row.state[slot::u_a]);
    rows.contactY.push_back(row.state[slot::v_a]);
    rows.psi.push_back(row.state[slot::psi]);
  });
  return rows;
}

void BM_SweepPointAnalysis(benchmark::State& state) {
  const PointRows rows = paperPointRows(static_cast<double>(state.range(0)));
  for (auto _ : state) {
    const analysis::TrialFeatures features = analysis::analyzeTrial(rows.samples());
    benchmark::DoNotOptimize(features.rose.leaves);
  }
  state.counters["samples"] = static_cast<double>(rows.time.size());
}
BENCHMARK(BM_SweepPointAnalysis)->Arg(10)->Arg(60)->Arg(600)->ArgName("seconds")->Unit(benchmark::kMillisecond);

void BM_PhysicsFingerprint(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(game::physicsFingerprintOf(task::SweepDef{}));
}
BENCHMARK(BM_PhysicsFingerprint)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
