#include "engine/record/ReplayReader.h"

#include <gtest/gtest.h>

#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "engine/record/ReplayLogger.h"
#include "engine/record/TrialMeta.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::record {
namespace {

std::filesystem::path writeLog(const hemiroll::test::TempDirectory& dir, int ticks, bool finish = true) {
  const auto path = dir.path() / "log.replay";
  ReplayLogger logger(path, {});
  for (int k = 1; k <= ticks; ++k) {
    haptics::TickInput in;
    in.tick = static_cast<std::uint64_t>(k);
    in.position = {0.001 * k, -0.002 * k, 0.04};
    logger.push(in);
  }
  haptics::AppliedCommand engage;
  engage.tick = 2;
  engage.command.kind = haptics::ServoCommandKind::Engage;
  logger.push(engage);
  if (finish) logger.finish();
  return path;
}

std::string errorOf(const std::filesystem::path& path) {
  try {
    ReplayReader::load(path);
  } catch (const RecordError& e) {
    return e.what();
  }
  return "";
}

TEST(ReplayReaderTest, LoadsWhatTheLoggerWrote) {
  hemiroll::test::TempDirectory dir;
  const ReplayLog log = ReplayReader::load(writeLog(dir, 50));
  ASSERT_EQ(log.inputs.size(), 50u);
  EXPECT_EQ(log.inputs[9].tick, 10u);
  EXPECT_EQ(log.inputs[9].position[0], 0.001 * 10);
  EXPECT_EQ(log.header.softwareVersion, softwareVersion());
  ASSERT_EQ(log.commands.size(), 1u);
  EXPECT_EQ(log.commands[0].tick, 2u);
  EXPECT_EQ(log.commands[0].command.kind, haptics::ServoCommandKind::Engage);
}

TEST(ReplayReaderTest, BrokenLogsGiveClearErrors) {
  hemiroll::test::TempDirectory dir;
  const auto path = writeLog(dir, 50);
  const std::string good = hemiroll::test::TempDirectory::read(path);

  dir.write("log.replay", good.substr(0, good.size() - 10));
  EXPECT_NE(errorOf(path).find("log.replay: truncated"), std::string::npos) << errorOf(path);
  dir.write("log.replay", good.substr(0, 100));
  EXPECT_NE(errorOf(path).find("too short"), std::string::npos) << errorOf(path);
  std::string flipped = good;
  flipped[kReplayHeaderSize + 20 * kReplayRecordSize + 9] ^= 0x04;  // one bit of record 20's x
  dir.write("log.replay", flipped);
  EXPECT_NE(errorOf(path).find("checksum"), std::string::npos) << errorOf(path);
  // A command at a tick the log does not hold (checksum fixed up, so only
  // the command check can object).
  std::string outside = good;
  const std::size_t command = kReplayHeaderSize + 50 * kReplayRecordSize;
  outside[command] = 99;
  const auto* records = reinterpret_cast<const unsigned char*>(outside.data()) + kReplayHeaderSize;
  const std::uint64_t sum = fnv1a(records, outside.size() - kReplayHeaderSize, kFnvOffset);
  for (int i = 0; i < 8; ++i) outside[56 + static_cast<std::size_t>(i)] = static_cast<char>(sum >> (8 * i));
  dir.write("log.replay", outside);
  EXPECT_NE(errorOf(path).find("command 0 (byte " + std::to_string(command) + "): tick 99"), std::string::npos)
      << errorOf(path);
  std::string version = good;
  version[8] = 7;
  dir.write("log.replay", version);
  EXPECT_NE(errorOf(path).find("format version 7"), std::string::npos) << errorOf(path);
  dir.write("log.replay", "this is a text file, long enough to hold a header........" + std::string(300, '.'));
  EXPECT_NE(errorOf(path).find("not a hemiroll replay"), std::string::npos) << errorOf(path);
  EXPECT_NE(errorOf(dir.path() / "missing.replay").find("missing.replay: no such file"), std::string::npos);
}

TEST(ReplayReaderTest, AnUnfinishedLogIsRefused) {
  hemiroll::test::TempDirectory dir;
  const auto path = writeLog(dir, 10, false);
  EXPECT_NE(errorOf(path).find("never finished"), std::string::npos) << errorOf(path);
}

}  // namespace
}  // namespace hemiroll::record
