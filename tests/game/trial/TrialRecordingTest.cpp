// game/trial/TrialRecording: a trial recorded through engine/record. Here:
// that rows the record tap lost (TrialRig::tapLost, the ring full in a
// threaded trial) reach the sidecar's dropped_rows and results.csv, so that
// a recording with holes says so; and that a trial that lost none says 0.

#include "game/trial/TrialRecording.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>

#include "engine/files/CheckedFile.h"
#include "engine/files/FileKinds.h"
#include "engine/record/ResultsFile.h"
#include "engine/script/BotScript.h"
#include "engine/script/LevelLoader.h"
#include "game/trial/BotTrial.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

constexpr const char* kShortLevel = R"lua(
return { name = "short", task = { targets = { u_ca = { value = {0.5, 0.5}, tol = 0.004 } }, time_limit = 0.2 } }
)lua";

// A trial played headless and recorded; `lost` stands for rows the tap's
// ring refused (only a threaded trial can lose any; the count travels in the
// result, which is what is checked here).
nlohmann::json recordedSidecar(const test::TempDirectory& dir, const std::string& id, std::uint64_t lost,
                               std::uint64_t& resultsDropped) {
  script::LoadedLevel level = script::LevelLoader().loadSource(kShortLevel, "short.lua");
  script::BotScript bot(std::string(HEMIROLL_SOURCE_DIR) + "/scripts/bots/random.lua");
  BotTrial trial(level, bot, TrialSettings{});
  TrialRecordingDef def;
  def.dir = dir.path().string();
  def.ids = {"p", "1"};
  def.trialId = id;
  auto recording = std::make_unique<TrialRecording>(def, level.def, trial.rig().loopDef());
  trial.rig().record(recording->tap());
  TrialResult result = trial.run();
  EXPECT_EQ(result.recordRowsLost, 0u) << "a stepped trial's tap never loses a row";
  result.recordRowsLost = lost;
  recording->finish(result, TrialRecording::scoreFields(result));
  const record::ResultsTable table = record::ResultsFile(dir.path() / "results.csv").read();
  const auto column = std::find(table.columns.begin(), table.columns.end(), "dropped_rows") - table.columns.begin();
  EXPECT_LT(static_cast<std::size_t>(column), table.columns.size());
  resultsDropped = table.rows.empty() ? 99 : std::stoull(table.rows.back().at(static_cast<std::size_t>(column)));
  return nlohmann::json::parse(files::readCheckedFile(dir.path() / (id + ".json"), files::kSidecar));
}

TEST(TrialRecordingTest, RowsTheTapLostAreInTheSidecarAndTheResults) {
  const test::TempDirectory dir;
  std::uint64_t dropped = 0;
  nlohmann::json whole = recordedSidecar(dir, "whole", 0, dropped);
  EXPECT_EQ(whole["dropped_rows"], 0) << whole.dump();
  EXPECT_EQ(dropped, 0u);
  nlohmann::json holed = recordedSidecar(dir, "holed", 17, dropped);
  EXPECT_EQ(holed["dropped_rows"], 17) << holed.dump();
  EXPECT_EQ(dropped, 17u);
}

}  // namespace
}  // namespace hemiroll::game
