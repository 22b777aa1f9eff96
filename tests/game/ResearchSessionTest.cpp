// game/research/ResearchSession: a protocol's plan turned into a session
// folder, trial by trial; resumed only with the same protocol, seed and
// levels; breaks that end a sitting.

#include "game/research/ResearchSession.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "engine/record/ContentHash.h"
#include "engine/record/DurableFile.h"
#include "engine/record/ResultsFile.h"
#include "game/research/SessionFolder.h"
#include "game/trial/ReplayCapture.h"
#include "game/trial/TrialSetup.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const std::string kLevels = std::string(HEMIROLL_SOURCE_DIR) + "/levels";

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Two blocks: the tutorial with the method overridden, then a stop break
// and a level copied beside the protocol (so that a test can change it).
constexpr const char* kProtocol = R"lua(
return {
  experiment = "unit",
  seed = 5,
  blocks = {
    { level = "tutorial_01_tilt_and_return.lua", method = "M1", time_limit = 12,
      break_after = { message = "see you tomorrow", stop = true } },
    { level = "own.lua", instructions = "roll", conditions = { { alpha = 1.5 }, { method = "visual" } } },
  },
}
)lua";

class ResearchSessionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_.write("own.lua", readFile(kLevels + "/tutorial_02_roll_a_short_distance.lua"));
    protocol_ = dir_.write("p.lua", kProtocol);
    request_.protocolPath = protocol_;
    request_.levelsDir = kLevels;
    request_.participant = "p01";
    request_.dataRoot = dir_.path() / "data";
  }
  fs::path folder() const { return dir_.path() / "data/unit/p01/1"; }

  // Records the next trial as a trial that ended at once, as the runners do.
  void finishOne(ResearchSession& s) const {
    const script::LoadedLevel level = s.loadNextLevel();
    const haptics::ServoLoopDef loop = trialLoopDef(level.def);
    auto recording = s.recordNext(level.def, loop, "bot", botDeviceSpec());
    TrialResult result;
    result.outcome = script::TrialOutcome::Success;
    result.reason = "target held";
    result.time = 1.5;
    result.ticks = 1500;
    s.finishNext(*recording, result);
  }
  std::string errorOf(SessionError::Kind expected) const {
    try {
      ResearchSession s(request_);
    } catch (const SessionError& e) {
      EXPECT_EQ(e.kind(), expected) << e.what();
      return e.what();
    }
    return "no error";
  }

  test::TempDirectory dir_;
  std::string protocol_;
  SessionRequest request_;
};

TEST_F(ResearchSessionTest, OpeningWritesNothingBeginWritesTheManifest) {
  ResearchSession s(request_);
  EXPECT_EQ(s.folder(), folder());
  EXPECT_FALSE(fs::exists(dir_.path() / "data"));
  EXPECT_FALSE(s.resumed());
  EXPECT_EQ(s.trialCount(), 3);
  s.begin("bot.lua");
  const SessionManifest m = SessionManifest::fromJson(hemiroll::test::TempDirectory::read(folder() / kManifestFile), "m");
  EXPECT_EQ(m.experiment, "unit");
  EXPECT_EQ(m.participant, "p01");
  EXPECT_EQ(m.seed, 5u);
  EXPECT_EQ(m.protocolHash, record::fileContentHash(protocol_));
  EXPECT_FALSE(m.startTime.empty());
  ASSERT_EQ(m.sittings.size(), 1u);
  EXPECT_EQ(m.sittings[0].firstTrial, 1);
  EXPECT_EQ(m.sittings[0].player, "bot.lua");
  ASSERT_EQ(m.plan.size(), 3u);
  // The effective coupling: the override over the level's (M3, 250, 10, 2).
  EXPECT_EQ(m.plan[0].method, "M1");
  EXPECT_EQ(m.plan[0].stiffness, 250.0);
  EXPECT_EQ(m.plan[0].timeLimit, 12.0);
  EXPECT_EQ(m.plan[0].levelHash, record::fileContentHash(kLevels + "/tutorial_01_tilt_and_return.lua"));
  ASSERT_TRUE(m.plan[1].breakBefore);
  EXPECT_TRUE(m.plan[1].breakBefore->stop);
  EXPECT_EQ(m.plan[1].timeLimit, 60.0);  // the level's own
}

TEST_F(ResearchSessionTest, TheNextLevelIsLoadedWithItsOverridesAndSeed) {
  ResearchSession s(request_);
  s.begin("bot.lua");
  const script::LoadedLevel level = s.loadNextLevel();
  EXPECT_EQ(level.def.coupling.method, physics::ForceMethod::M1);
  EXPECT_EQ(level.def.task.timeLimit, 12.0);
}

TEST_F(ResearchSessionTest, EachFinishedTrialHasItsFilesAndOneResultsRowWithThePlansColumns) {
  ResearchSession s(request_);
  s.begin("bot.lua");
  finishOne(s);
  EXPECT_EQ(s.done(), 1);
  EXPECT_TRUE(fs::exists(folder() / "trial-001.csv"));
  EXPECT_TRUE(fs::exists(folder() / "trial-001.json"));
  const record::ResultsTable table = record::ResultsFile(folder() / "results.csv").read();
  const std::vector<std::string> plan = {"trial_index", "block", "block_name", "trial_in_block", "repetition",
                                         "condition", "condition_label", "level_file", "method", "kr_N_per_m",
                                         "kv_N_s_per_m", "alpha", "time_limit_s", "seed", "guidance",
                                         "guidance_stiffness_N_per_m", "guidance_damping_N_s_per_m", "guidance_fade",
                                         "has_score", "medal", "stages_passed", "stage_count", "stage_times_s",
                                         "contact_path_m", "point_path_m", "effort_N2_s", "smoothness_m2_per_s6",
                                         "best_margin", "final_margin", "final_error_x_p_m", "final_error_y_p_m",
                                         "final_error_xd_p_m_per_s", "final_error_yd_p_m_per_s",
                                         "final_error_w_x_rad_per_s", "final_error_w_y_rad_per_s",
                                         "final_error_w_z_rad_per_s", "final_error_u_a_m", "final_error_v_a_m",
                                         "final_error_u_o_rad", "final_error_v_o_rad", "final_error_psi_rad",
                                         "final_error_omega_norm_rad_per_s", "ticks", "player", "device_profile",
                                         "device", "stop", "packets_received", "packets_lost",
                                         "packets_out_of_order", "packets_late", "packets_malformed"};
  ASSERT_EQ(table.columns.size(), 12u + plan.size());
  EXPECT_EQ(std::vector<std::string>(table.columns.begin() + 12, table.columns.end()), plan);
  ASSERT_EQ(table.rows.size(), 1u);
  const std::vector<std::string>& row = table.rows[0];
  EXPECT_EQ(row[2], "trial-001");
  EXPECT_EQ(row[5], "success");
  EXPECT_EQ(row[12], "1");      // trial_index
  EXPECT_EQ(row[20], "M1");     // method
  EXPECT_EQ(row[24], "12");     // time_limit_s
  EXPECT_EQ(row[26], "none");   // guidance
  EXPECT_EQ(row[29], "0");      // guidance_fade: none at all
  EXPECT_EQ(row[32], "0");      // stages_passed (a result made up here, with an empty summary)
  EXPECT_EQ(row[54], "1500");   // ticks
  EXPECT_EQ(row[55], "bot.lua");
}

// A results.csv whose header the next row cannot join was found only when
// the row was appended, after the participant had played the trial (issue
// 19). It is refused when the trial is set up, before any file is made.
TEST_F(ResearchSessionTest, AResultsHeaderTheRowCannotJoinIsRefusedBeforeTheTrial) {
  ResearchSession s(request_);
  s.begin("bot.lua");
  record::appendDurably(folder() / "results.csv", "participant,session,trial,other\n");
  const script::LoadedLevel level = s.loadNextLevel();
  try {
    (void)s.recordNext(level.def, trialLoopDef(level.def), "bot", botDeviceSpec());
    FAIL() << "no error";
  } catch (const SessionError& e) {
    EXPECT_EQ(e.kind(), SessionError::Kind::Environment);
    EXPECT_THAT(e.what(), HasSubstr("results.csv: line 1: the header differs"));
  }
  EXPECT_FALSE(fs::exists(folder() / "trial-001.csv"));
  EXPECT_FALSE(fs::exists(folder() / "trial-001.json"));
}

TEST_F(ResearchSessionTest, AStopBreakEndsTheSittingAndTheNextSittingStartsAfterIt) {
  {
    ResearchSession s(request_);
    s.begin("bot.lua");
    EXPECT_FALSE(s.stopsHere());
    finishOne(s);
    ASSERT_NE(s.pendingBreak(), nullptr);
    EXPECT_EQ(s.pendingBreak()->message, "see you tomorrow");
    EXPECT_TRUE(s.stopsHere());
  }
  ResearchSession again(request_);
  EXPECT_TRUE(again.resumed());
  EXPECT_EQ(again.keptFromEarlier(), 1);
  EXPECT_EQ(again.nextTrial().trialId, "trial-002");
  EXPECT_NE(again.pendingBreak(), nullptr);  // shown again,
  EXPECT_FALSE(again.stopsHere());           // but it does not stop a sitting that starts at it
  EXPECT_EQ(again.instructionsOf(again.nextTrial()), "roll");
  again.begin("mouse");
  finishOne(again);
  finishOne(again);
  EXPECT_TRUE(again.complete());
  const SessionManifest m = SessionManifest::fromJson(hemiroll::test::TempDirectory::read(folder() / kManifestFile), "m");
  ASSERT_EQ(m.sittings.size(), 2u);
  EXPECT_EQ(m.sittings[1].firstTrial, 2);
  EXPECT_EQ(m.sittings[1].player, "mouse");
  EXPECT_EQ(record::ResultsFile(folder() / "results.csv").read().rows.size(), 3u);
}

TEST_F(ResearchSessionTest, AChangedProtocolIsRefusedUnlessTheSessionIsNew) {
  ResearchSession(request_).begin("bot.lua");
  dir_.write("p.lua", std::string(kProtocol) + "-- a comment changes the content\n");
  EXPECT_THAT(errorOf(SessionError::Kind::BadInput),
              HasSubstr("p.lua changed since session '1' of participant 'p01' started (content hash fnv1a-"));
  request_.session = "2";
  EXPECT_NO_THROW(ResearchSession s(request_));
}

TEST_F(ResearchSessionTest, AChangedLevelIsRefusedNamingIt) {
  ResearchSession(request_).begin("bot.lua");
  dir_.write("own.lua", readFile(kLevels + "/tutorial_02_roll_a_short_distance.lua") + "\n-- edited\n");
  EXPECT_THAT(errorOf(SessionError::Kind::BadInput), HasSubstr("own.lua (trial-002) changed since session '1'"));
}

TEST_F(ResearchSessionTest, AnotherSeedIsRefusedForAStartedSession) {
  ResearchSession(request_).begin("bot.lua");
  request_.seed = 6;
  EXPECT_THAT(errorOf(SessionError::Kind::BadInput), HasSubstr("was started with seed 5, not 6"));
  request_.seed = 5;
  EXPECT_NO_THROW(ResearchSession s(request_));
}

TEST_F(ResearchSessionTest, BadIdsProtocolsAndFoldersAreOneSentence) {
  request_.participant = "../x";
  EXPECT_THAT(errorOf(SessionError::Kind::BadInput), HasSubstr("the participant id '../x' must be"));
  request_.participant = "p01";
  dir_.write("p.lua", "return { experiment = 'unit', blocks = {\n { level = 'nope.lua' } } }");
  EXPECT_THAT(errorOf(SessionError::Kind::BadInput), HasSubstr("p.lua:2: blocks[1].level: no level file 'nope.lua'"));
  dir_.write("p.lua", kProtocol);
  fs::create_directories(folder());
  dir_.write("data/unit/p01/1/notes.txt", "someone else's");
  EXPECT_THAT(errorOf(SessionError::Kind::Environment), HasSubstr("holds files but no session.json"));
}

}  // namespace
}  // namespace hemiroll::game
