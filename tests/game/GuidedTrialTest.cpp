// Haptic guidance in a whole trial (game/trial): the autopilot's plan as a
// spring-damper on the device, felt by the built-in passive hand, which
// moves only where the device pushes it. Headless and deterministic.

#include <gtest/gtest.h>

#include <string>

#include "engine/script/LevelLoader.h"
#include "game/trial/HeadlessTrial.h"
#include "game/trial/PassiveHandBot.h"

namespace hemiroll::game {
namespace {

const std::string kLevels = std::string(HEMIROLL_SOURCE_DIR) + "/levels/";

TrialResult passiveHandOn(const std::string& level, haptics::GuidanceKind kind, double stiffness = 300.0) {
  script::LoadedLevel loaded = script::LevelLoader().loadFile(kLevels + level);
  PassiveHandBot hand;
  TrialSettings settings;
  settings.guidance.kind = kind;
  settings.guidance.stiffness = stiffness;
  settings.guidance.damping = 10.0;
  return HeadlessTrial(loaded, hand, settings).run();
}

// The paper's task in miniature (tutorial 04): a hand that only yields to
// the device reaches the target and stops there when the autopilot guides
// it, and not without guidance or with the error pushed up.
TEST(GuidedTrialTest, AutopilotGuidanceLeadsAPassiveHandToTheTarget) {
  const TrialResult guided = passiveHandOn("tutorial_04_stop_on_target.lua", haptics::GuidanceKind::Autopilot);
  EXPECT_EQ(guided.outcome, script::TrialOutcome::Success) << guided.reason;
  const TrialResult alone = passiveHandOn("tutorial_04_stop_on_target.lua", haptics::GuidanceKind::None);
  EXPECT_EQ(alone.outcome, script::TrialOutcome::Failure);
  EXPECT_EQ(alone.reason, "time limit reached");
  const TrialResult augmented =
      passiveHandOn("tutorial_04_stop_on_target.lua", haptics::GuidanceKind::ErrorAugmentation);
  EXPECT_EQ(augmented.outcome, script::TrialOutcome::Failure);
}

TEST(GuidedTrialTest, AGuidedTrialIsDeterministic) {
  const TrialResult a = passiveHandOn("tutorial_02_roll_a_short_distance.lua", haptics::GuidanceKind::Autopilot);
  const TrialResult b = passiveHandOn("tutorial_02_roll_a_short_distance.lua", haptics::GuidanceKind::Autopilot);
  EXPECT_EQ(a.outcome, script::TrialOutcome::Success) << a.reason;
  EXPECT_EQ(a.ticks, b.ticks);
  EXPECT_EQ(a.time, b.time);
}

}  // namespace
}  // namespace hemiroll::game
