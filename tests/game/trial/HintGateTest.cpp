// game/trial/HintGate: the hint is shown exactly while the autopilot would
// have a plan (its first plan made once the coupling holds the mass point,
// none after a stage it can tell it will never reach), said without running
// the planner: checked against the autopilot itself, tick by tick.

#include "game/trial/HintGate.h"

#include <gtest/gtest.h>

#include "engine/autopilot/Autopilot.h"
#include "engine/script/ScriptError.h"
#include "game/trial/AutopilotBot.h"

namespace hemiroll::game {
namespace {

script::BotLevelInfo levelInfo() {
  script::BotLevelInfo info;
  info.workspaceRadius = 0.1;
  return info;
}

// Upright and still at the centre; the stage asks for the contact at (x, 0).
script::BotObservation observation(double time, bool engaged, double x, int stage) {
  script::BotObservation obs;
  obs.time = time;
  obs.engaged = engaged;
  obs.forceShare = engaged ? 1.0 : 0.0;
  obs.normal = {0.0, 0.0, 1.0};
  obs.mass = {0.0, 0.0, 0.04};
  obs.targetSet[7] = obs.targetSet[8] = true;
  obs.target[7] = x;
  obs.tolerance[7] = obs.tolerance[8] = 0.002;
  obs.stage = stage;
  return obs;
}

bool autopilotHasAPlan(const AutopilotBot& bot) {
  return bot.giveUpReason().empty() && bot.autopilot() != nullptr && bot.autopilot()->stats().decisions > 0;
}

TEST(HintGate, OpensAndClosesAsTheAutopilotsPlanDoes) {
  AutopilotBotOptions options;
  options.holdsProxy = false;  // as the hint's autopilot was
  AutopilotBot autopilot(options);
  autopilot.init(levelInfo(), 1);
  HintGate gate;
  gate.init(levelInfo());
  // Taking hold (not engaged), holding (engaged), a reachable second stage,
  // then a third beyond the device's reach, then a reachable one again.
  struct Step {
    double until;
    bool engaged;
    double x;
    int stage;
  };
  const Step steps[] = {{0.05, false, 0.02, 0}, {0.3, true, 0.02, 0}, {0.5, true, -0.03, 1}, {0.6, true, 0.5, 2}, {0.7, true, 0.0, 3}};
  double t = 0.0;
  int open = 0, closed = 0;
  for (const Step& s : steps) {
    for (; t < s.until; t += 0.001) {
      const script::BotObservation obs = observation(t, s.engaged, s.x, s.stage);
      autopilot.act(obs);
      const bool shown = gate.open(obs);
      ASSERT_EQ(shown, autopilotHasAPlan(autopilot)) << "at " << t << " s";
      (shown ? open : closed) += 1;
    }
  }
  EXPECT_GT(open, 100);    // both states were seen
  EXPECT_GT(closed, 100);
  EXPECT_FALSE(gate.reason().empty());
  EXPECT_EQ(gate.reason(), autopilot.giveUpReason());
}

TEST(HintGate, ALevelTheAutopilotCannotModelIsRefusedAsTheAutopilotRefusesIt) {
  script::BotLevelInfo info = levelInfo();
  info.coupling.visualOnly = true;
  HintGate gate;
  EXPECT_THROW(gate.init(info), script::ScriptError);
  AutopilotBot autopilot;
  EXPECT_THROW(autopilot.init(info, 1), script::ScriptError);
}

}  // namespace
}  // namespace hemiroll::game
