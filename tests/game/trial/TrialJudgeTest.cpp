#include "game/trial/TrialJudge.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "engine/physics/StateKinematics.h"
#include "engine/script/LevelLoader.h"
#include "game/trial/BotDevice.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::game {
namespace {

// Rows as the servo loop pushes them: time advancing 1 ms per tick, the
// level's initial state, no fault unless asked.
void pushRows(haptics::RecordRing& ring, const task::LevelDef& def, int from, int count,
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

// Judges every row the ring holds, as a threaded TrialRig's drain does;
// returns how many.
std::size_t drainInto(TrialJudge& judge, haptics::RecordRing& ring) {
  haptics::RecordRow row;
  std::size_t judged = 0;
  while (!judge.finished() && ring.pop(row)) {
    judge.judgeTick(row);
    ++judged;
  }
  return judged;
}

struct Fixture {
  script::LoadedLevel level =
      script::LevelLoader().loadFile(HEMIROLL_SOURCE_DIR "/levels/tutorial_01_tilt_and_return.lua");
  std::unique_ptr<haptics::RecordRing> ring = std::make_unique<haptics::RecordRing>();
};

TEST(TrialJudgeTest, JudgesEveryRow) {
  Fixture f;
  TrialJudge judge(f.level);
  judge.start(f.level.def.initial);
  pushRows(*f.ring, f.level.def, 1, 95);
  EXPECT_EQ(drainInto(judge, *f.ring), 95u);
  EXPECT_EQ(judge.judgedTicks(), 95);
  EXPECT_DOUBLE_EQ(judge.view().time, 0.095);
  EXPECT_FALSE(judge.finished());
}

TEST(TrialJudgeTest, ASafetyFaultEndsABotsTrialWithItsName) {
  Fixture f;
  TrialJudge judge(f.level);
  judge.start(f.level.def.initial);
  pushRows(*f.ring, f.level.def, 1, 5);
  pushRows(*f.ring, f.level.def, 6, 5, haptics::SafetyFault::LoopOverrun);
  drainInto(judge, *f.ring);
  ASSERT_TRUE(judge.finished());
  EXPECT_EQ(judge.judge().reason(), std::string("safety: ") + haptics::safetyFaultName(haptics::SafetyFault::LoopOverrun));
  EXPECT_EQ(judge.judgedTicks(), 6);  // judging stops with the trial
}

TEST(TrialJudgeTest, AHumansTrialGoesOnThroughAFaultAndEndsWhenAsked) {
  Fixture f;
  TrialJudge judge(f.level, /*faultsEndTrial=*/false);
  judge.start(f.level.def.initial);
  pushRows(*f.ring, f.level.def, 1, 5, haptics::SafetyFault::LoopOverrun);
  EXPECT_EQ(drainInto(judge, *f.ring), 5u);
  EXPECT_FALSE(judge.finished());
  judge.fail("quit by the player");
  EXPECT_TRUE(judge.finished());
  const TrialResult result = judge.result(f.level.def.initial);
  EXPECT_EQ(result.reason, "quit by the player");
  EXPECT_EQ(result.ticks, 5);
}

// Headless trials judge the loop's snapshot after each tick; real-time ones
// drain the record ring. The judge is one, so the two must agree bit for
// bit on the same ticks: here a real servo loop feeds both at once.
TEST(TrialJudgeTest, SnapshotsAndRingRowsOfTheSameTicksAreJudgedAlike) {
  Fixture f;
  haptics::ServoLoopDef def = trialLoopDef(f.level.def);
  def.recordRing = f.ring.get();
  def.recordEvery = 1;
  BotDevice device(botDeviceSpec(), def.mapping, def.period);
  haptics::ServoLoop loop(def, device);
  haptics::ServoCommand engage;
  engage.kind = haptics::ServoCommandKind::Engage;
  loop.post(engage);
  const physics::ForceDrivenState initial = physics::forceStateOf(def.initialState);
  const physics::Vec3 start = physics::massPointPosition(initial, f.level.def.params.radius);
  TrialJudge bySnapshot(f.level), byRing(f.level);
  bySnapshot.start(initial);
  byRing.start(initial);
  haptics::ServoSnapshot snapshot;
  for (int k = 0; k < 3000 && !bySnapshot.finished(); ++k) {
    // Take hold, then lean the proxy sideways at 10 mm/s (slow enough for
    // the velocity guard) so that the hemisphere tilts and rolls.
    device.setPose(start + physics::Vec3(std::clamp((k - 500) * 1e-5, 0.0, 0.01), 0.0, 0.0));
    loop.tick();
    loop.latest(snapshot);
    bySnapshot.judgeTick(snapshot);
    drainInto(byRing, *f.ring);
  }
  const TrialResult a = bySnapshot.result(initial), b = byRing.result(initial);
  EXPECT_EQ(a.ticks, 3000) << a.reason;
  EXPECT_GT(a.summary.contactPath, 0.0);  // the trial moved: the comparison is not of two idle runs
  EXPECT_EQ(a.outcome, b.outcome);
  EXPECT_EQ(a.reason, b.reason);
  EXPECT_EQ(a.ticks, b.ticks);
  EXPECT_EQ(a.summary.contactPath, b.summary.contactPath);
  EXPECT_EQ(a.summary.smoothness, b.summary.smoothness);
  EXPECT_EQ(a.summary.finalMargin, b.summary.finalMargin);
  EXPECT_EQ(a.summary.effort, b.summary.effort);
  EXPECT_EQ(a.maxRenderedForce, b.maxRenderedForce);
  EXPECT_EQ(a.maxProxyDistance, b.maxProxyDistance);
  for (int i = 0; i < 12; ++i) EXPECT_EQ(a.finalState[i], b.finalState[i]) << physics::kStateNames[i];
}

}  // namespace
}  // namespace hemiroll::game
