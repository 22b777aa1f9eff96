// Headless playthroughs (issue 5): the paper's level (levels/paper_reaching.lua,
// 240 s time limit) played by a bot that calls Lua every tick, through the
// same tick code as `hemiroll run` (game/trial/BotTrial). One iteration
// is one whole trial; loading the level and the bot is not timed.
//   speedup_cpu   simulated seconds per second of CPU time on the one core
//                 that runs it: the figure (target >= 500);
//   speedup_wall  the same per wall second (lower on a loaded machine);
//   sim_s         simulated seconds per trial.
// Bots: circle (tools/bench/bots/circle.lua: the least a bot can do per
// tick, with the physics kept awake), tutorial_solver (feedback on ~15
// observation fields per tick), rose (the Sec. 5 actuation: trigonometry
// and ~20 fields per tick).
#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>
#include <string>

#include "engine/script/BotScript.h"
#include "engine/script/LevelLoader.h"
#include "game/trial/BotTrial.h"

namespace {

using namespace hemiroll;

const std::string kSource = HEMIROLL_SOURCE_DIR;

double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

void playPaperLevel(benchmark::State& state, const std::string& botPath) {
  double simulated = 0.0, cpu = 0.0, wall = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    script::LoadedLevel level = script::LevelLoader().loadFile(kSource + "/levels/paper_reaching.lua");
    script::BotScript bot(botPath);
    state.ResumeTiming();
    const double cpu0 = cpuSeconds();
    const auto wall0 = std::chrono::steady_clock::now();
    const game::TrialResult r = game::BotTrial(level, bot, game::TrialSettings{}).run();
    cpu += cpuSeconds() - cpu0;
    wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    simulated += r.time;
    benchmark::DoNotOptimize(r.finalState);
  }
  state.counters["speedup_cpu"] = simulated / cpu;
  state.counters["speedup_wall"] = simulated / wall;
  state.counters["sim_s"] = simulated / static_cast<double>(state.iterations());
}

void BM_PaperLevel_CircleBot(benchmark::State& state) { playPaperLevel(state, kSource + "/tools/bench/bots/circle.lua"); }
void BM_PaperLevel_TutorialSolver(benchmark::State& state) {
  playPaperLevel(state, kSource + "/scripts/bots/tutorial_solver.lua");
}
void BM_PaperLevel_RoseBot(benchmark::State& state) { playPaperLevel(state, kSource + "/scripts/bots/rose.lua"); }

BENCHMARK(BM_PaperLevel_CircleBot)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_PaperLevel_TutorialSolver)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_PaperLevel_RoseBot)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
