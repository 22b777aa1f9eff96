#include "game/play/ReplayPlayer.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>

#include "engine/script/LevelLoader.h"
#include "game/trial/ReplayCapture.h"
#include "tests/game/ui/support/StrokedTrial.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

using namespace std::chrono_literals;
using ::testing::HasSubstr;

const std::string kLevel = HEMIROLL_SOURCE_DIR "/levels/tutorial_01_tilt_and_return.lua";

class ReplayPlayerTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDirectory;
    const test::StrokedTrial trial = test::playStrokedTrial({kLevel, dir_->path() / "t.hrr", 600ms});
    EXPECT_EQ(trial.replayError, "");
    played_ = trial.last;
  }
  static void TearDownTestSuite() { delete dir_; }
  static test::TempDirectory* dir_;
  static haptics::ServoSnapshot played_;
  script::LoadedLevel level_ = script::LevelLoader().loadFile(kLevel);
};
test::TempDirectory* ReplayPlayerTest::dir_ = nullptr;
haptics::ServoSnapshot ReplayPlayerTest::played_;

TEST_F(ReplayPlayerTest, PlayingToTheEndReachesThePlayedStateBitForBit) {
  ReplayPlayer player(level_.def, kLevel, dir_->path() / "t.hrr");
  EXPECT_EQ(player.ticksPlayed(), 0u);
  EXPECT_EQ(player.ticksTotal(), played_.tick);
  player.playTo(player.ticksTotal() + 100);  // past the end: stops at it
  EXPECT_TRUE(player.done());
  for (std::size_t i = 0; i < 12; ++i) EXPECT_EQ(player.snapshot().state[i], played_.state[i]) << "slot " << i;
  EXPECT_NE(played_.state[physics::force_slot::u_o], 0.0);  // the strokes did move it
}

// A frame's worth at a time (as the ghost and the replay screen play it)
// gives the same run as one call.
TEST_F(ReplayPlayerTest, PlayingInChunksIsTheSameRun) {
  ReplayPlayer chunked(level_.def, kLevel, dir_->path() / "t.hrr");
  for (std::uint64_t t = 0; !chunked.done(); t += 17) {
    chunked.playTo(t);
    EXPECT_EQ(chunked.ticksPlayed(), std::min<std::uint64_t>(t, chunked.ticksTotal()));
  }
  for (std::size_t i = 0; i < 12; ++i) EXPECT_EQ(chunked.snapshot().state[i], played_.state[i]) << "slot " << i;
  chunked.playTo(3);  // never backwards
  EXPECT_TRUE(chunked.done());
}

TEST_F(ReplayPlayerTest, AnotherVersionOfTheLevelIsRefusedWithASentence) {
  std::ifstream in(kLevel);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string changed = dir_->write("changed.lua", text + "\n-- edited\n");
  try {
    ReplayPlayer player(level_.def, changed, dir_->path() / "t.hrr");
    FAIL() << "played a replay of another level version";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("another version of"));
  }
}

TEST_F(ReplayPlayerTest, AnUnknownDeviceKindIsRefusedWithASentence) {
  const std::filesystem::path copy = dir_->path() / "other-device.hrr";
  std::filesystem::copy_file(dir_->path() / "t.hrr", copy, std::filesystem::copy_options::overwrite_existing);
  {
    std::fstream f(copy, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(236);  // the header's device kind (docs/RECORDING.md); not in the records' checksum
    f.write("phantom9000\0", 12);
  }
  try {
    ReplayPlayer player(level_.def, kLevel, copy);
    FAIL() << "played a replay of an unknown device";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("does not know: 'phantom9000'"));
  }
  EXPECT_THROW(ReplayPlayer(level_.def, kLevel, dir_->path() / "missing.hrr"), std::runtime_error);
}

}  // namespace
}  // namespace hemiroll::game
