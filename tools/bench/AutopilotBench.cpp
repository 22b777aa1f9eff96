// The autopilot (issue 13) through the real trial loop, as `hemiroll run
// LEVEL --bot autopilot` plays it. One iteration is one whole trial; loading
// the level is not timed. Counters:
//   task_s        simulated time to success [s] (0 if the trial failed);
//   success       1 when the trial was won;
//   wall_s        wall time of the trial [s] (target: paper task < 30 s);
//   decision_median_ms, decision_p99_ms, decision_max_ms
//                 wall time of one planning decision (most decisions only
//                 check; the landing searches make the tail);
//   decisions, rollout_s  plans made and simulated seconds rolled out.
//   BM_HelixPolicyTick*: the feedback law's cost per servo tick.
// The success rate over generated tasks is tools/autopilot-success.sh (it
// takes minutes: failed seeds run to the 240 s time limit).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "engine/script/LevelLoader.h"
#include "game/trial/AutopilotBot.h"
#include "game/trial/BotTrial.h"

namespace {

using namespace hemiroll;

const std::string kSource = HEMIROLL_SOURCE_DIR;

void playLevel(benchmark::State& state, const std::string& level) {
  std::vector<double> decisions;
  double task = 0.0, wall = 0.0, rolled = 0.0, won = 0.0, count = 0.0;
  long long decisionCount = 0;
  for (auto _ : state) {
    state.PauseTiming();
    script::LoadedLevel loaded = script::LevelLoader().loadFile(kSource + "/levels/" + level);
    game::AutopilotBot bot;
    state.ResumeTiming();
    const auto wall0 = std::chrono::steady_clock::now();
    const game::TrialResult r = game::BotTrial(loaded, bot, game::TrialSettings{}).run();
    wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    const bool success = r.outcome == task::TrialOutcome::Success;
    won += success ? 1.0 : 0.0;
    task += success ? r.time : 0.0;
    count += 1.0;
    const autopilot::PlannerStats& stats = bot.autopilot()->stats();
    decisions.insert(decisions.end(), stats.decisionWall.begin(), stats.decisionWall.end());
    decisionCount += stats.decisions;
    rolled += stats.rolloutSeconds;
  }
  std::sort(decisions.begin(), decisions.end());
  const auto at = [&](double q) {
    return decisions.empty() ? 0.0 : 1e3 * decisions[static_cast<std::size_t>(q * static_cast<double>(decisions.size() - 1))];
  };
  state.counters["task_s"] = task / count;
  state.counters["success"] = won / count;
  state.counters["wall_s"] = wall / count;
  state.counters["decision_median_ms"] = at(0.5);
  state.counters["decision_p99_ms"] = at(0.99);
  state.counters["decision_max_ms"] = at(1.0);
  state.counters["decisions"] = static_cast<double>(decisionCount) / count;
  state.counters["rollout_s"] = rolled / count;
}

// The work the autopilot adds to every servo tick: one step of its feedback
// law (the proxy for the next tick), on a tilted, turning state of the
// paper's task. Planning is not in it (it runs every 0.1 s, off the tick).
void policyTick(benchmark::State& state, bool settling) {
  const physics::HemisphereParams params;
  const physics::ModelConstants constants(params);
  autopilot::Goal goal;
  for (int slot : {7, 8}) {
    goal.set[static_cast<std::size_t>(slot)] = true;
    goal.target[static_cast<std::size_t>(slot)] = -0.04;
    goal.tolerance[static_cast<std::size_t>(slot)] = 0.004;
  }
  autopilot::HelixPolicy policy(constants, autopilot::HelixParams{}, 0.001);
  policy.setGoal(goal);
  if (settling) policy.land(0.003);
  physics::ForceDrivenState x = physics::ForceDrivenState::Zero();
  x << 0.005, 0.002, 0.01, 0.0, 0.3, -0.2, 0.7, -0.01, 0.02, 0.2, -0.1, 0.5;
  for (auto _ : state) {
    x[11] += 1e-9;  // a new state each tick, as the loop gives
    benchmark::DoNotOptimize(policy.proxyFor(x));
  }
}

// The regulated settle's tick (SettleRegulator): near rest, where it holds
// the proxy.
void BM_HelixPolicyTickRegulated(benchmark::State& state) {
  const physics::HemisphereParams params;
  const physics::ModelConstants constants(params);
  autopilot::Goal goal;
  for (int slot : {7, 8}) {
    goal.set[static_cast<std::size_t>(slot)] = true;
    goal.target[static_cast<std::size_t>(slot)] = -0.04;
    goal.tolerance[static_cast<std::size_t>(slot)] = 0.004;
  }
  autopilot::HelixPolicy policy(constants, autopilot::HelixParams{}, 0.001);
  policy.setGoal(goal);
  policy.setSettleGain(autopilot::settleGainFor(params, physics::CouplingDef{}, 0.001));
  policy.settleNow();
  physics::ForceDrivenState x = physics::ForceDrivenState::Zero();
  x << 0.0017, 0.0, 0.0, 0.0, 0.01, -0.01, 0.005, -0.039, -0.039, -0.04, 0.0, 0.3;
  for (auto _ : state) {
    x[11] += 1e-9;  // a new state each tick, as the loop gives
    benchmark::DoNotOptimize(policy.proxyFor(x));
  }
}

void BM_HelixPolicyTickTravelling(benchmark::State& state) { policyTick(state, false); }
void BM_HelixPolicyTickSettling(benchmark::State& state) { policyTick(state, true); }

void BM_AutopilotPaperTask(benchmark::State& state) { playLevel(state, "paper_reaching.lua"); }
void BM_AutopilotTutorial04(benchmark::State& state) { playLevel(state, "tutorial_04_stop_on_target.lua"); }
void BM_AutopilotFullOrientation(benchmark::State& state) { playLevel(state, "challenge_full_orientation.lua"); }

}  // namespace

BENCHMARK(BM_HelixPolicyTickTravelling);
BENCHMARK(BM_HelixPolicyTickSettling);
BENCHMARK(BM_HelixPolicyTickRegulated);
BENCHMARK(BM_AutopilotPaperTask)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_AutopilotTutorial04)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_AutopilotFullOrientation)->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK_MAIN();
