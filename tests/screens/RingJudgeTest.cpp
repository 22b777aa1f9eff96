#include "game/play/RingJudge.h"

#include <gtest/gtest.h>

#include <memory>

#include "engine/script/LevelLoader.h"

namespace hemiroll::game {
namespace {

// Rows as the servo loop pushes them: time advancing 1 ms per tick, the
// level's initial state, no fault unless asked.
void pushRows(haptics::RecordRing& ring, const script::LevelDef& def, int from, int count,
              haptics::SafetyFault fault = haptics::SafetyFault::None) {
  for (int k = from; k < from + count; ++k) {
    haptics::RecordRow row;
    row.tick = static_cast<std::uint64_t>(k);
    row.time = k * 0.001;
    for (int i = 0; i < 12; ++i) row.state[static_cast<std::size_t>(i)] = def.initial[i];
    row.fault = fault;
    ASSERT_TRUE(ring.push(row));
  }
}

struct Fixture {
  script::LoadedLevel level =
      script::LevelLoader().loadFile(HEMIROLL_SOURCE_DIR "/levels/tutorial_01_tilt_and_return.lua");
  std::unique_ptr<haptics::RecordRing> ring = std::make_unique<haptics::RecordRing>();
};

TEST(RingJudgeTest, JudgesEveryRowAndForwardsEveryNth) {
  Fixture f;
  auto forward = std::make_unique<haptics::RecordRing>();
  RingJudge judge(f.level, forward.get(), 10);
  judge.start(f.level.def.initial);
  pushRows(*f.ring, f.level.def, 1, 95);
  EXPECT_EQ(judge.drain(*f.ring), 95u);
  EXPECT_EQ(judge.judgedTicks(), 95);
  EXPECT_DOUBLE_EQ(judge.view().time, 0.095);
  haptics::RecordRow row;
  int forwarded = 0;
  while (forward->pop(row)) {
    EXPECT_EQ(row.tick % 10, 0u);
    ++forwarded;
  }
  EXPECT_EQ(forwarded, 9);  // ticks 10, 20, ..., 90
  EXPECT_FALSE(judge.finished());
}

TEST(RingJudgeTest, ASafetyFaultEndsABotsTrialWithItsName) {
  Fixture f;
  RingJudge judge(f.level);
  judge.start(f.level.def.initial);
  pushRows(*f.ring, f.level.def, 1, 5);
  pushRows(*f.ring, f.level.def, 6, 5, haptics::SafetyFault::LoopOverrun);
  judge.drain(*f.ring);
  ASSERT_TRUE(judge.finished());
  EXPECT_EQ(judge.judge().reason(), std::string("safety: ") + haptics::safetyFaultName(haptics::SafetyFault::LoopOverrun));
  EXPECT_EQ(judge.judgedTicks(), 6);  // judging stops with the trial
}

TEST(RingJudgeTest, AHumansTrialGoesOnThroughAFaultAndEndsWhenAsked) {
  Fixture f;
  RingJudge judge(f.level, nullptr, 10, /*faultsEndTrial=*/false);
  judge.start(f.level.def.initial);
  pushRows(*f.ring, f.level.def, 1, 5, haptics::SafetyFault::LoopOverrun);
  EXPECT_EQ(judge.drain(*f.ring), 5u);
  EXPECT_FALSE(judge.finished());
  judge.fail("quit by the player");
  EXPECT_TRUE(judge.finished());
  const TrialResult result = judge.result(f.level.def.initial);
  EXPECT_EQ(result.reason, "quit by the player");
  EXPECT_EQ(result.ticks, 5);
}

}  // namespace
}  // namespace hemiroll::game
