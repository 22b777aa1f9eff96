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
}

TEST(ReplayReaderTest, BrokenLogsGiveClearErrors) {
  hemiroll::test::TempDirectory dir;
  const auto path = writeLog(dir, 50);
  const std::string good = readWholeFile(path);

  dir.write("log.replay", good.substr(0, good.size() - 10));
  EXPECT_NE(errorOf(path).find("log.replay: truncated"), std::string::npos) << errorOf(path);
  dir.write("log.replay", good.substr(0, 100));
  EXPECT_NE(errorOf(path).find("too short"), std::string::npos) << errorOf(path);
  std::string flipped = good;
  flipped[kReplayHeaderSize + 20 * kReplayRecordSize + 9] ^= 0x04;  // one bit of record 20's x
  dir.write("log.replay", flipped);
  EXPECT_NE(errorOf(path).find("checksum"), std::string::npos) << errorOf(path);
  std::string version = good;
  version[8] = 7;
  dir.write("log.replay", version);
  EXPECT_NE(errorOf(path).find("format version 7"), std::string::npos) << errorOf(path);
  dir.write("log.replay", "this is a text file, long enough to hold a header........" + std::string(300, '.'));
  EXPECT_NE(errorOf(path).find("not a hemiroll replay"), std::string::npos) << errorOf(path);
  EXPECT_NE(errorOf(dir.path() / "missing.replay").find("missing.replay: cannot open"), std::string::npos);
}

TEST(ReplayReaderTest, AnUnfinishedLogIsRefused) {
  hemiroll::test::TempDirectory dir;
  const auto path = writeLog(dir, 10, false);
  EXPECT_NE(errorOf(path).find("never finished"), std::string::npos) << errorOf(path);
}

}  // namespace
}  // namespace hemiroll::record
