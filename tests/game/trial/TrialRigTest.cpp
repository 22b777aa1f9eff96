// game/trial/TrialRig: the loop definition built once from the level and
// the rig's choices, the device's part of it, and the one record tap of
// both drivers (every judged tick at the tap's rate; stepping waits for the
// writer and loses nothing, threaded counts what a full ring refused).

#include "game/trial/TrialRig.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include "engine/physics/StateKinematics.h"
#include "engine/script/LevelLoader.h"
#include "game/trial/BotDevice.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::game {
namespace {

// A target out of reach: a trial runs until its time limit.
constexpr const char* kOpenLevel = R"lua(
return {
  name = "open field",
  task = { targets = { u_ca = { value = {0.5, 0.5}, tol = 0.004 } }, time_limit = 10 },
}
)lua";

script::LoadedLevel openLevel() { return script::LevelLoader().loadSource(kOpenLevel, "level.lua"); }

// A bot's desk device, kept by the rig; `out` names it for the test.
RigDeviceMaker botDevice(BotDevice*& out, haptics::DeviceSpec spec = botDeviceSpec()) {
  return [&out, spec](const haptics::ServoLoopDef& loop) {
    auto device = std::make_unique<BotDevice>(spec, loop.mapping, loop.period);
    out = device.get();
    return device;
  };
}

// The proxy held on the mass point's start, engaged: a quiet trial.
void hold(TrialRig& rig, BotDevice& device) {
  device.setPose(physics::massPointPosition(rig.initial(), rig.level().def.params.radius));
}

std::vector<haptics::RecordRow> popAll(haptics::RecordRing& ring) {
  std::vector<haptics::RecordRow> rows;
  haptics::RecordRow row;
  while (ring.pop(row)) rows.push_back(row);
  return rows;
}

TEST(TrialRigTest, TheLoopIsTheLevelsWithTheRigsChoicesAndTheDeviceGetsIt) {
  script::LoadedLevel level = openLevel();
  TrialRigDef def;
  physics::CouplingDef coupling = level.def.coupling;
  coupling.stiffness = 0.5 * coupling.stiffness;
  def.coupling = coupling;
  def.guidance.kind = haptics::GuidanceKind::Autopilot;
  def.guidance.stiffness = 50.0;
  haptics::ServoLoopDef seen;
  int made = 0;
  TrialRig rig(level, def, [&](const haptics::ServoLoopDef& loop) {
    seen = loop;
    ++made;
    return std::make_unique<BotDevice>(botDeviceSpec(), loop.mapping, loop.period);
  });
  EXPECT_EQ(made, 1);
  EXPECT_EQ(rig.loopDef().coupling.stiffness, coupling.stiffness);
  EXPECT_NE(rig.loopDef().coupling.stiffness, level.def.coupling.stiffness);
  EXPECT_EQ(rig.loopDef().guidance.kind, haptics::GuidanceKind::Autopilot);
  EXPECT_EQ(seen.mapping.scale, rig.loopDef().mapping.scale);
  EXPECT_TRUE(seen.mapping.offset == rig.loopDef().mapping.offset);
  EXPECT_FALSE(rig.loopDef().requestRealtime);   // stepping runs no thread
  EXPECT_EQ(rig.loopDef().recordRing, nullptr);  // stepping judges snapshots
  EXPECT_EQ(rig.loopDef().maxCatchUpTicks, haptics::ServoLoopDef{}.maxCatchUpTicks);
  for (int i = 0; i < 12; ++i) EXPECT_EQ(rig.initial()[i], level.def.initial[i]);
}

TEST(TrialRigTest, ADeviceWithoutForceOutputCatchesUpInsteadOfStopping) {
  script::LoadedLevel level = openLevel();
  haptics::DeviceSpec forceless = botDeviceSpec();
  forceless.hasForceOutput = false;
  BotDevice* device = nullptr;
  TrialRigDef def;
  def.threaded = true;
  TrialRig rig(level, def, botDevice(device, forceless));
  EXPECT_EQ(rig.loopDef().maxCatchUpTicks, kForcelessCatchUpTicks);
  EXPECT_NE(rig.loopDef().recordRing, nullptr);  // threaded: the judge's ring
  EXPECT_EQ(rig.loopDef().recordEvery, 1);       // of every tick, whatever the recording's rate
}

// A rig on the open level with a bot's device, its tap every `tapEvery`
// ticks into `ring`, engaged and started.
struct Bench {
  Bench(bool threaded, int tapEvery) : rig(level, defOf(threaded), botDevice(device)) {
    rig.record({ring.get(), tapEvery});
    rig.post(haptics::ServoCommandKind::Engage);
    rig.judging().start(rig.initial());
  }
  static TrialRigDef defOf(bool threaded) {
    TrialRigDef def;
    def.threaded = threaded;
    return def;
  }
  // One tick with the proxy held: the rig's step, or (threaded, its thread
  // not started) the loop's tick here, into the rig's ring.
  void tick() {
    hold(rig, *device);
    if (rig.loopDef().recordRing != nullptr)
      rig.loop().tick();
    else
      rig.step();
  }

  script::LoadedLevel level = openLevel();
  BotDevice* device = nullptr;
  std::unique_ptr<haptics::RecordRing> ring = std::make_unique<haptics::RecordRing>();
  TrialRig rig;
};

TEST(TrialRigTest, SteppingJudgesEachTickAndTapsEveryNthAsTheLoopPublishedIt) {
  Bench b(/*threaded=*/false, 10);
  std::vector<haptics::ServoSnapshot> snapshots;
  for (int k = 0; k < 95; ++k) {
    b.tick();
    snapshots.push_back(b.rig.snapshot());
  }
  EXPECT_EQ(b.rig.judging().judgedTicks(), 95);
  const std::vector<haptics::RecordRow> rows = popAll(*b.ring);
  ASSERT_EQ(rows.size(), 9u);  // ticks 10, 20, ..., 90
  for (const haptics::RecordRow& row : rows) {
    ASSERT_EQ(row.tick % 10, 0u);
    const haptics::ServoSnapshot& s = snapshots[static_cast<std::size_t>(row.tick - 1)];
    EXPECT_EQ(row.time, s.time);
    for (std::size_t i = 0; i < 12; ++i) EXPECT_EQ(row.state[i], s.state[i]);
    EXPECT_EQ(row.proxyPosition, s.proxyPosition);
  }
}

TEST(TrialRigTest, ThreadedDrainJudgesEveryRowAndTapsEveryNth) {
  Bench b(/*threaded=*/true, 10);
  for (int k = 0; k < 95; ++k) b.tick();
  EXPECT_EQ(b.rig.drain(), 95u);
  EXPECT_EQ(b.rig.judging().judgedTicks(), 95);
  EXPECT_FALSE(b.rig.judging().finished());
  const std::vector<haptics::RecordRow> rows = popAll(*b.ring);
  ASSERT_EQ(rows.size(), 9u);
  for (std::size_t i = 0; i < rows.size(); ++i) EXPECT_EQ(rows[i].tick, 10 * (i + 1));
  EXPECT_EQ(b.rig.tapLost(), 0u);
}

TEST(TrialRigTest, AThreadedTapCountsTheRowsAFullRingRefused) {
  Bench b(/*threaded=*/true, 1);
  while (b.ring->push(haptics::RecordRow{})) {
  }
  for (int k = 0; k < 5; ++k) b.tick();
  EXPECT_EQ(b.rig.drain(), 5u);  // the judge never waits for the recording
  EXPECT_EQ(b.rig.tapLost(), 5u);
}

// The stepping driver outruns any writer: with more rows than the ring
// holds (5000 > 4096) and a slow reader, every row still arrives, in order.
TEST(TrialRigTest, SteppingWaitsForTheWriterAndLosesNoRow) {
  Bench b(/*threaded=*/false, 1);
  std::atomic<bool> done{false};
  std::vector<std::uint64_t> ticks;
  std::thread writer([&] {
    haptics::RecordRow row;
    for (;;) {
      const bool finished = done.load();
      bool any = false;
      while (b.ring->pop(row)) {
        ticks.push_back(row.tick);
        any = true;
      }
      if (finished && !any) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  });
  constexpr int kTicks = 5000;
  for (int k = 0; k < kTicks && !b.rig.judging().finished(); ++k) b.tick();
  done = true;
  writer.join();
  EXPECT_FALSE(b.rig.judging().finished()) << b.rig.judging().judge().reason();
  ASSERT_EQ(ticks.size(), static_cast<std::size_t>(kTicks));
  for (std::size_t i = 0; i < ticks.size(); ++i) ASSERT_EQ(ticks[i], i + 1);
}

}  // namespace
}  // namespace hemiroll::game
