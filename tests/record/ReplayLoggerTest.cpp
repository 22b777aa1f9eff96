#include "engine/record/ReplayLogger.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>

#include "engine/haptics/ReplayDevice.h"
#include "engine/haptics/ServoLoop.h"
#include "engine/haptics/SimulatedHandDevice.h"
#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "engine/record/RecordingReader.h"
#include "engine/record/ReplayReader.h"
#include "engine/record/TrialRecorder.h"
#include "tests/record/support/RecordRows.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::record {
namespace {

using haptics::Vec3;

constexpr double kRadius = 0.04;  // default hemisphere: the mass point rests at (0, 0, R)
constexpr double kPi = 3.141592653589793;
constexpr long kTicks = 3000;     // 3 s at 1 kHz: engagement, ramp, coupled motion

// The hand means to circle 5 mm about the mass point's rest position.
haptics::SimulatedHandDevice::Intent circling(double t) {
  const double w = 2.0 * kPi, r = 0.005;
  return {Vec3(r * std::sin(w * t), r * (1.0 - std::cos(w * t)), kRadius),
          Vec3(r * w * std::cos(w * t), r * w * std::sin(w * t), 0.0)};
}

struct RecordedRun {
  physics::ForceDrivenState state;
  std::filesystem::path csv;
  std::uint64_t dropped = 0;
};

// A headless run of the loop with `device`, recording every tick's row (and
// the inputs, when `replayPath` is given) by draining the rings between
// chunks of ticks, as a writer thread would.
RecordedRun record(haptics::HapticDevice& device, const std::filesystem::path& dir, const std::string& trialId,
           const std::filesystem::path& replayPath = {}) {
  auto rows = std::make_unique<haptics::RecordRing>();
  auto inputs = std::make_unique<haptics::InputRing>();
  haptics::ServoLoopDef def;
  def.requestRealtime = false;
  def.recordRing = rows.get();
  def.recordEvery = 1;
  def.inputRing = inputs.get();
  TrialMeta meta;
  meta.trialId = trialId;
  meta.recordEvery = 1;
  TrialRecorder rec(dir, meta);
  std::unique_ptr<ReplayLogger> logger;
  ReplayHeader header;
  header.levelHash = "test-level";
  header.seed = 99;
  if (!replayPath.empty()) logger = std::make_unique<ReplayLogger>(replayPath, header);
  haptics::ServoLoop loop(def, device);
  haptics::ServoCommand engage;
  engage.kind = haptics::ServoCommandKind::Engage;
  loop.post(engage);
  for (long done = 0; done < kTicks; done += 100) {
    loop.runHeadless(100);
    rec.drain(*rows);
    haptics::TickInput in;
    if (logger) logger->drain(*inputs);
    else
      while (inputs->pop(in)) {
      }
  }
  rec.finish(TrialEnd{});
  if (logger) logger->finish(loop.inputDropped());
  return {loop.state(), rec.csvPath(), loop.recordDropped() + loop.inputDropped()};
}

TEST(ReplayLoggerTest, AReplayReproducesTheRunBitForBit) {
  hemiroll::test::TempDirectory dir;
  haptics::SimulatedHandDevice hand(circling);
  const RecordedRun original = record(hand, dir.path(), "original", dir.path() / "original.replay");
  ASSERT_EQ(original.dropped, 0u);

  const ReplayLog log = ReplayReader::load(dir.path() / "original.replay");
  EXPECT_EQ(log.header.tickCount, static_cast<std::uint64_t>(kTicks));
  EXPECT_EQ(log.header.levelHash, "test-level");
  EXPECT_EQ(log.header.seed, 99u);
  haptics::ReplayDevice replay(log.inputs);
  const RecordedRun again = record(replay, dir.path(), "replayed");
  EXPECT_EQ(replay.position(), static_cast<std::size_t>(kTicks));
  EXPECT_EQ(replay.error(), nullptr);

  EXPECT_EQ(std::memcmp(original.state.data(), again.state.data(), sizeof(double) * 12), 0);
  const Recording a = RecordingReader::load(original.csv), b = RecordingReader::load(again.csv);
  ASSERT_EQ(a.rows.size(), static_cast<std::size_t>(kTicks));
  ASSERT_EQ(b.rows.size(), a.rows.size());
  for (std::size_t i = 0; i < a.rows.size(); ++i) ASSERT_TRUE(test::sameBits(a.rows[i], b.rows[i])) << "row " << i;
  // The run was not trivial: the hand engaged and the hemisphere rolled.
  EXPECT_EQ(a.rows.back().engagement, haptics::Engagement::Engaged) << haptics::safetyFaultName(a.rows.back().fault) << " " << a.rows.back().time;
  EXPECT_GT(std::hypot(a.rows.back().state[7], a.rows.back().state[8]), 1e-5);  // contact moved > 10 um

  // And the comparison can fail: one input 1 nm off changes the end state.
  // (One ulp, ~1e-18 m, can vanish in the rounding of the state's sums.)
  std::vector<haptics::TickInput> nudged = log.inputs;
  nudged[1500].position[0] += 1e-9;
  haptics::ReplayDevice off(nudged);
  const RecordedRun different = record(off, dir.path(), "nudged");
  EXPECT_NE(std::memcmp(original.state.data(), different.state.data(), sizeof(double) * 12), 0);
}

TEST(ReplayLoggerTest, LostInputsMakeTheLogUnusable) {
  hemiroll::test::TempDirectory dir;
  const auto path = dir.path() / "gap.replay";
  {
    ReplayLogger logger(path, {});
    haptics::TickInput in;
    in.tick = 1;
    logger.push(in);
    in.tick = 3;  // tick 2 lost
    logger.push(in);
    try {
      logger.finish();
      FAIL() << "no error";
    } catch (const RecordError& e) {
      EXPECT_NE(std::string(e.what()).find("tick 3 follows tick 1"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(ReplayReader::load(path), RecordError);
  ReplayLogger dropped(dir.path() / "dropped.replay", {});
  EXPECT_THROW(dropped.finish(5), RecordError);
}

}  // namespace
}  // namespace hemiroll::record
