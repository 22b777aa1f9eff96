#include "engine/record/ReplayLogger.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <thread>

#include "engine/haptics/devices/ReplayDevice.h"
#include "engine/haptics/ServoLoop.h"
#include "engine/haptics/devices/SimulatedHandDevice.h"
#include "engine/record/RecordError.h"
#include "engine/record/RecordingReader.h"
#include "engine/record/ReplayReader.h"
#include "engine/record/ReplayRunner.h"
#include "engine/record/TrialRecorder.h"
#include "tests/record/support/RecordRows.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::record {
namespace {

using haptics::Vec3;

constexpr double kRadius = 0.04;  // default hemisphere: the mass point rests at (0, 0, R)
constexpr double kPi = 3.141592653589793;

// The hand means to circle 5 mm about the mass point's rest position.
haptics::SimulatedHandDevice::Intent circling(double t) {
  const double w = 2.0 * kPi, r = 0.005;
  return {Vec3(r * std::sin(w * t), r * (1.0 - std::cos(w * t)), kRadius),
          Vec3(r * w * std::cos(w * t), r * w * std::sin(w * t), 0.0)};
}

haptics::ServoCommand command(haptics::ServoCommandKind kind) {
  haptics::ServoCommand c;
  c.kind = kind;
  return c;
}

// A gain change mid-run (M3, stiffer than the default 250 N/m; softer
// gains let this hand lose the mass point off the face).
haptics::ServoCommand stiffer() {
  haptics::ServoCommand c = command(haptics::ServoCommandKind::SetCoupling);
  c.coupling.stiffness = 300.0;
  return c;
}

// Rings for one loop; every row recorded (recordEvery = 1).
struct Rings {
  std::unique_ptr<haptics::RecordRing> rows = std::make_unique<haptics::RecordRing>();
  std::unique_ptr<haptics::InputRing> inputs = std::make_unique<haptics::InputRing>();
  std::unique_ptr<haptics::CommandRing> commands = std::make_unique<haptics::CommandRing>();

  haptics::ServoLoopDef def(bool logInputs) const {
    haptics::ServoLoopDef d;
    d.requestRealtime = false;
    d.recordRing = rows.get();
    d.recordEvery = 1;
    if (logInputs) {
      d.inputRing = inputs.get();
      d.commandRing = commands.get();
    }
    return d;
  }
};

TrialRecorder recorder(const std::filesystem::path& dir, const std::string& id) {
  TrialMeta meta;
  meta.trialId = id;
  meta.recordEvery = 1;
  return TrialRecorder(dir, meta);
}

ReplayHeader header() {
  ReplayHeader h;
  h.levelHash = "test-level";
  h.seed = 99;
  return h;
}

// Replays `log` headless into <dir>/<id>.csv; returns the end state.
physics::ForceDrivenState replay(const ReplayLog& log, const std::filesystem::path& dir, const std::string& id) {
  Rings rings;
  haptics::ReplayDevice device(log.inputs);
  haptics::ServoLoop loop(rings.def(false), device);
  TrialRecorder rec = recorder(dir, id);
  rec.startWriter(*rings.rows);
  EXPECT_EQ(ReplayRunner::run(loop, log), log.inputs.size());
  EXPECT_EQ(device.error(), nullptr);
  rec.finish(TrialEnd{});
  EXPECT_EQ(loop.recordDropped(), 0u);
  return loop.state();
}

void expectSameRows(const std::filesystem::path& a, const std::filesystem::path& b, std::size_t rows) {
  const Recording ra = RecordingReader::load(a), rb = RecordingReader::load(b);
  ASSERT_EQ(ra.rows.size(), rows);
  ASSERT_EQ(rb.rows.size(), rows);
  for (std::size_t i = 0; i < rows; ++i) ASSERT_TRUE(test::sameBits(ra.rows[i], rb.rows[i])) << "row " << i;
}

TEST(ReplayLoggerTest, AHeadlessRunReplaysBitForBit) {
  hemiroll::test::TempDirectory dir;
  constexpr long kTicks = 3000;  // 3 s at 1 kHz: engagement, ramp, coupled motion, a gain change
  Rings rings;
  haptics::SimulatedHandDevice hand(circling);
  haptics::ServoLoop loop(rings.def(true), hand);
  TrialRecorder rec = recorder(dir.path(), "original");
  ReplayLogger logger(dir.path() / "original.replay", header());
  loop.post(command(haptics::ServoCommandKind::Engage));
  for (long done = 0; done < kTicks; done += 100) {
    if (done == 1500) loop.post(stiffer());
    loop.runHeadless(100);
    rec.drain(*rings.rows);
    logger.drain(*rings.inputs, rings.commands.get());
  }
  rec.finish(TrialEnd{});
  logger.finish(loop.inputDropped());
  ASSERT_EQ(loop.recordDropped() + loop.inputDropped(), 0u);

  const ReplayLog log = ReplayReader::load(dir.path() / "original.replay");
  EXPECT_EQ(log.header.tickCount, static_cast<std::uint64_t>(kTicks));
  EXPECT_EQ(log.header.levelHash, "test-level");
  EXPECT_EQ(log.header.seed, 99u);
  ASSERT_EQ(log.commands.size(), 2u);
  EXPECT_EQ(log.commands[0].tick, 1u);
  EXPECT_EQ(log.commands[1].tick, 1501u);
  EXPECT_EQ(log.commands[1].command.coupling.stiffness, 300.0);

  const physics::ForceDrivenState again = replay(log, dir.path(), "replayed");
  EXPECT_EQ(std::memcmp(loop.state().data(), again.data(), sizeof(double) * 12), 0);
  expectSameRows(rec.csvPath(), dir.path() / "replayed.csv", kTicks);
  // The run was not trivial: the hand engaged and the hemisphere rolled.
  const Recording r = RecordingReader::load(rec.csvPath());
  EXPECT_EQ(r.rows.back().engagement, haptics::Engagement::Engaged) << haptics::safetyFaultName(r.rows.back().fault);
  EXPECT_GT(std::hypot(r.rows.back().state[7], r.rows.back().state[8]), 1e-5);  // contact moved > 10 um

  // And the comparison can fail: one input 1 nm off, or the gain change one
  // tick late, changes the end state. (One ulp of position, ~1e-18 m, can
  // vanish in the rounding of the state's sums.)
  ReplayLog nudged = log;
  nudged.inputs[1500].position[0] += 1e-9;
  EXPECT_NE(std::memcmp(loop.state().data(), replay(nudged, dir.path(), "nudged").data(), sizeof(double) * 12), 0);
  ReplayLog late = log;
  late.commands[1].tick += 1;
  EXPECT_NE(std::memcmp(loop.state().data(), replay(late, dir.path(), "late").data(), sizeof(double) * 12), 0);
}

// A run on the real clock, commands posted from another thread at whatever
// tick they land on, rings drained by writer threads: the replay, headless,
// still repeats every row bit for bit (lateness included).
TEST(ReplayLoggerTest, ARealTimeRunReplaysBitForBit) {
  hemiroll::test::TempDirectory dir;
  Rings rings;
  haptics::SimulatedHandDevice hand(circling);
  haptics::ServoLoop loop(rings.def(true), hand);
  TrialRecorder rec = recorder(dir.path(), "live");
  ReplayLogger logger(dir.path() / "live.replay", header());
  rec.startWriter(*rings.rows);
  logger.startWriter(*rings.inputs, rings.commands.get());
  loop.start();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  loop.post(command(haptics::ServoCommandKind::Engage));
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  loop.post(stiffer());
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  loop.stop();
  rec.finish(TrialEnd{});
  logger.finish(loop.inputDropped());
  ASSERT_EQ(loop.recordDropped() + loop.inputDropped(), 0u);

  const ReplayLog log = ReplayReader::load(dir.path() / "live.replay");
  ASSERT_EQ(log.inputs.size(), loop.ticks());
  ASSERT_EQ(log.commands.size(), 2u);
  const physics::ForceDrivenState again = replay(log, dir.path(), "replayed");
  EXPECT_EQ(std::memcmp(loop.state().data(), again.data(), sizeof(double) * 12), 0);
  expectSameRows(rec.csvPath(), dir.path() / "replayed.csv", static_cast<std::size_t>(loop.ticks()));
  const Recording r = RecordingReader::load(rec.csvPath());
  EXPECT_EQ(r.rows.back().engagement, haptics::Engagement::Engaged);  // engaged, the force ramping in
  EXPECT_GT(r.rows.back().rampScale, 0.0);
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
  EXPECT_THROW(ReplayLogger(path, {}), RecordError);  // never over an existing log
}

// A log made in hand: 300 ticks of the circling hand, Engage at tick 1 and
// a gain change at tick 50.
ReplayLog handMadeLog(double laterStiffness) {
  ReplayLog log;
  for (std::uint64_t tick = 1; tick <= 300; ++tick) {
    const haptics::SimulatedHandDevice::Intent at = circling(1e-3 * static_cast<double>(tick));
    haptics::TickInput in;
    in.tick = tick;
    in.position = {at.position.x(), at.position.y(), at.position.z()};
    in.velocity = {at.velocity.x(), at.velocity.y(), at.velocity.z()};
    log.inputs.push_back(in);
  }
  log.commands.push_back({1, command(haptics::ServoCommandKind::Engage)});
  haptics::ServoCommand gains = stiffer();
  gains.coupling.stiffness = laterStiffness;
  log.commands.push_back({50, gains});
  return log;
}

// Played in parts (a ghost, a frame's worth at a time) the log repeats the
// whole run bit for bit; a logged command the loop refuses (gains its device
// cannot render: a definition other than the logged run's) is named by its
// tick, by the part that met it and by ReplayRunner.
TEST(ReplayLoggerTest, ACursorPlaysInPartsAndNamesARefusedCommand) {
  const ReplayLog log = handMadeLog(300.0);
  Rings whole, parts;
  haptics::ReplayDevice wholeDevice(log.inputs), partsDevice(log.inputs);
  haptics::ServoLoop wholeLoop(whole.def(false), wholeDevice), partsLoop(parts.def(false), partsDevice);
  EXPECT_EQ(ReplayRunner::run(wholeLoop, log), 300u);
  ReplayCursor cursor;
  for (std::size_t due : {7u, 7u, 49u, 50u, 299u, 500u}) EXPECT_FALSE(cursor.playTo(partsLoop, log, due).has_value());
  EXPECT_EQ(cursor.next(), 300u);
  EXPECT_EQ(std::memcmp(wholeLoop.state().data(), partsLoop.state().data(), sizeof(double) * 12), 0);
  EXPECT_GT(std::hypot(partsLoop.state()[0], partsLoop.state()[1]), 1e-6);  // the point moved: not a trivial match

  const ReplayLog bad = handMadeLog(-1.0);  // a negative stiffness: refused
  Rings r1, r2;
  haptics::ReplayDevice d1(bad.inputs), d2(bad.inputs);
  haptics::ServoLoop l1(r1.def(false), d1), l2(r2.def(false), d2);
  ReplayCursor badCursor;
  EXPECT_FALSE(badCursor.playTo(l1, bad, 49).has_value());
  EXPECT_EQ(badCursor.playTo(l1, bad, 300), std::optional<std::uint64_t>(50));
  try {
    ReplayRunner::run(l2, bad);
    FAIL() << "no error";
  } catch (const RecordError& e) {
    EXPECT_NE(std::string(e.what()).find("logged at tick 50"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hemiroll::record
