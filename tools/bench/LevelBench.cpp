// Costs of the level machinery per tick and per load: the native judge and
// summary (which may run inside the 1 kHz servo tick), the Lua callbacks at
// a level's rate, and loading a level file. Medians via make bench.

#include <benchmark/benchmark.h>

#include <string>

#include "engine/script/LevelLoader.h"
#include "engine/task/TaskJudge.h"
#include "engine/task/TrialSummaryAccumulator.h"

namespace {

using namespace hemiroll;
using namespace hemiroll::script;

const std::string kPaperLevel = std::string(HEMIROLL_SOURCE_DIR) + "/levels/paper_reaching.lua";

// A state that drifts, so the judge sees changing margins (never inside).
physics::ForceDrivenState drifting(long long tick) {
  physics::ForceDrivenState x = physics::ForceDrivenState::Zero();
  const double t = static_cast<double>(tick % 100000) * 1e-3;
  x[physics::force_slot::u_a] = -1e-4 * t;
  x[physics::force_slot::v_a] = -2e-4 * t;
  x[physics::force_slot::x_p] = 0.01;
  x[physics::force_slot::w_z] = 0.02;
  return x;
}

// The paper's 11 judged components + the summary, per tick.
void BM_JudgeAndSummaryPerTick(benchmark::State& state) {
  const LoadedLevel level = LevelLoader().loadFile(kPaperLevel);
  TaskJudge judge(level.def.task);
  TrialSummaryAccumulator summary;
  JudgeInput in;
  EffortInput effort;
  long long tick = 0;
  for (auto _ : state) {
    in.time = static_cast<double>(tick % 100000) * 1e-3;
    in.state = drifting(tick);
    effort.proxyPosition.x() = in.state[0];
    judge.judge(in);
    summary.add(in, effort, judge);
    benchmark::DoNotOptimize(judge.worstNormalizedMargin());
    if (++tick % 100000 == 0) {
      judge.reset();
      summary.reset();
    }
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_JudgeAndSummaryPerTick);

// LevelScript::update every tick with on_update at 100 Hz (the highest
// rate): the amortized Lua cost per 1 ms tick.
void BM_CallbacksAt100HzPerTick(benchmark::State& state) {
  LoadedLevel level = LevelLoader().loadSource(
      "local n = 0\nreturn { name = 'b', task = { targets = { x_p = { value = 1, tol = 0.001 } }, time_limit = 1e9 },\n"
      "callbacks = { rate = 100, on_update = function(s) if s.u_a < -1 then n = n + s.t end end } }",
      "bench.lua");
  TaskJudge judge(level.def.task);
  TrialObservation obs;
  long long tick = 0;
  for (auto _ : state) {
    obs.time = static_cast<double>(tick++) * 1e-3;
    level.script->update(obs, judge);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["lua_calls"] = static_cast<double>(level.script->callbackCalls());
}
BENCHMARK(BM_CallbacksAt100HzPerTick);

// Loading the paper's level: sandbox, chunk, every field read and checked.
void BM_LoadPaperLevel(benchmark::State& state) {
  const LevelLoader loader;
  for (auto _ : state) benchmark::DoNotOptimize(loader.loadFile(kPaperLevel).def.task.stages.size());
}
BENCHMARK(BM_LoadPaperLevel)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
