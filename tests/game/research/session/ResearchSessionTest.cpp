// game/research/session/ResearchSession: a protocol's plan turned into a session
// folder, trial by trial; resumed only with the same protocol, seed and
// levels; breaks that end a sitting.

#include "game/research/session/ResearchSession.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "engine/record/ContentHash.h"
#include "engine/record/DurableFile.h"
#include "engine/record/ResultsFile.h"
#include "game/research/session/SessionFolder.h"
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
    result.outcome = task::TrialOutcome::Success;
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
  const std::vector<std::string> plan = {"group", "block_order", "trial_index", "block", "block_name", "trial_in_block", "repetition",
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
  EXPECT_EQ(row[12], "");       // group: the protocol has none
  EXPECT_EQ(row[13], "1");      // block_order
  EXPECT_EQ(row[14], "1");      // trial_index
  EXPECT_EQ(row[22], "M1");     // method
  EXPECT_EQ(row[26], "12");     // time_limit_s
  EXPECT_EQ(row[28], "none");   // guidance
  EXPECT_EQ(row[31], "0");      // guidance_fade: none at all
  EXPECT_EQ(row[34], "0");      // stages_passed (a result made up here, with an empty summary)
  EXPECT_EQ(row[56], "1500");   // ticks
  EXPECT_EQ(row[57], "bot.lua");
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

// A session begun by a version whose results.csv had fewer columns cannot
// be resumed by this one: refused before anything is touched, saying which
// columns differ and what to do.
TEST_F(ResearchSessionTest, AnOldResultsHeaderIsRefusedOnResumeSayingWhyAndWhatToDo) {
  {
    ResearchSession s(request_);
    s.begin("bot.lua");
    finishOne(s);
  }
  const fs::path results = folder() / "results.csv";
  std::string text = hemiroll::test::TempDirectory::read(results);
  // As the version before groups wrote it: no group, block_order columns.
  const std::size_t cut = text.find(",group,block_order");
  ASSERT_NE(cut, std::string::npos);
  text.erase(cut, std::string(",group,block_order").size());
  const std::size_t rowCut = text.find(",,1,1,");
  ASSERT_NE(rowCut, std::string::npos);
  text.erase(rowCut + 1, 3);  // ",1," of ",,1,1,": group and block_order go
  fs::remove(results);
  record::appendDurably(results, text);
  const std::string error = errorOf(SessionError::Kind::BadInput);
  EXPECT_THAT(error, HasSubstr("results.csv of session '1' of participant 'p01' was started by hemiroll"));
  EXPECT_THAT(error, HasSubstr("it lacks group, block_order"));
  EXPECT_THAT(error, HasSubstr("Finish the session with the version that started it, or start a new session"));
  EXPECT_EQ(hemiroll::test::TempDirectory::read(results), text);
}

// Three groups, assigned by arrival; a counterbalanced pair of blocks.
constexpr const char* kGroups = R"lua(
return {
  experiment = "groups",
  seed = 3,
  groups = {
    { name = "guided", changes = { { block = "training", guidance = { kind = "autopilot", stiffness = 300 } } } },
    { name = "augmented", changes = { { block = "training", guidance = { kind = "error_augmentation", gain = 100 } } } },
    { name = "control" },
  },
  counterbalance = { "retention", "transfer" },
  blocks = {
    { name = "training", level = "tutorial_01_tilt_and_return.lua", repetitions = 2 },
    { name = "retention", level = "tutorial_01_tilt_and_return.lua" },
    { name = "transfer", level = "own.lua" },
  },
}
)lua";

TEST_F(ResearchSessionTest, ParticipantsArrivingInTurnFillTheGroupsAndOrdersInTurn) {
  request_.protocolPath = dir_.write("g.lua", kGroups);
  std::vector<std::pair<std::string, int>> assigned;
  for (int k = 0; k < 6; ++k) {
    request_.participant = "p" + std::to_string(k);
    ResearchSession s(request_);
    s.begin("bot.lua");
    assigned.emplace_back(s.manifest().group, s.manifest().blockOrder);
    const std::vector<ManifestTrial>& plan = s.manifest().plan;
    ASSERT_EQ(plan.size(), 4u);
    // Training first, then retention and transfer in the participant's order.
    EXPECT_EQ(plan[0].blockName, "training");
    EXPECT_EQ(plan[2].blockName, s.manifest().blockOrder == 1 ? "retention" : "transfer");
    EXPECT_EQ(plan[3].blockName, s.manifest().blockOrder == 1 ? "transfer" : "retention");
    EXPECT_EQ(plan[3].block, 3);
    const std::string kind = haptics::guidanceKindName(plan[0].guidance.kind);
    EXPECT_EQ(kind, s.manifest().group == "guided" ? "autopilot"
                    : s.manifest().group == "augmented" ? "error_augmentation" : "none");
    EXPECT_EQ(haptics::guidanceKindName(plan[2].guidance.kind), std::string("none"));  // only training changes
    finishOne(s);
  }
  // The k-th: group k mod 3, order (k div 3) mod 2 + 1.
  const std::vector<std::pair<std::string, int>> expected = {{"guided", 1},    {"augmented", 1}, {"control", 1},
                                                             {"guided", 2},    {"augmented", 2}, {"control", 2}};
  EXPECT_EQ(assigned, expected);
  // Group and order are in every results row and sidecar.
  const fs::path p4 = dir_.path() / "data/groups/p4/1";
  const record::ResultsTable table = record::ResultsFile(p4 / "results.csv").read();
  ASSERT_EQ(table.rows.size(), 1u);
  EXPECT_EQ(table.columns[12], "group");
  EXPECT_EQ(table.rows[0][12], "augmented");
  EXPECT_EQ(table.rows[0][13], "2");
  const std::string sidecar = hemiroll::test::TempDirectory::read(p4 / "trial-001.json");
  EXPECT_THAT(sidecar, HasSubstr("\"group\": \"augmented\""));
  EXPECT_THAT(sidecar, HasSubstr("\"block_order\": \"2\""));
  // A second session of a participant keeps their group and order.
  request_.participant = "p4";
  request_.session = "2";
  ResearchSession again(request_);
  EXPECT_EQ(again.manifest().group, "augmented");
  EXPECT_EQ(again.manifest().blockOrder, 2);
}

TEST_F(ResearchSessionTest, TheParticipantsFileAssignsAndIsCheckedNamingFileLineAndColumn) {
  std::string protocol = kGroups;
  protocol.replace(protocol.find("seed = 3,"), 9, "seed = 3, assignment = \"participants_file\", participants = \"participants.tsv\",");
  request_.protocolPath = dir_.write("g.lua", protocol);
  const std::string file = dir_.write("participants.tsv",
                                      "participant_id\tgroup\torder\tage\thandedness\n"
                                      "p01\tcontrol\t2\t24\tleft\n"
                                      "p02\tguided\tn/a\t31\tright\n");
  ResearchSession s(request_);
  EXPECT_EQ(s.manifest().group, "control");
  EXPECT_EQ(s.manifest().blockOrder, 2);
  EXPECT_EQ(s.manifest().participantInfo,
            (std::vector<std::pair<std::string, std::string>>{{"age", "24"}, {"handedness", "left"}}));
  request_.participant = "p02";
  EXPECT_EQ(ResearchSession(request_).manifest().blockOrder, 1);  // the first guided row: order 1
  request_.participant = "p03";
  EXPECT_EQ(errorOf(SessionError::Kind::BadInput),
            "participant 'p03' is not in " + (dir_.path() / "participants.tsv").lexically_normal().string() +
                "; add a line for them (participant_id first, tab-separated) before their first session");
  const std::string shown = (dir_.path() / "participants.tsv").lexically_normal().string();
  dir_.write("participants.tsv", "participant_id\tgroup\nop01\tcontrl\n");
  EXPECT_EQ(errorOf(SessionError::Kind::BadInput),
            shown + ":2: column 'group': no group 'contrl' in the protocol (its groups: 'guided', 'augmented', 'control')");
  dir_.write("participants.tsv", "participant_id\tgroup\torder\np03\tcontrol\t3\n");
  EXPECT_EQ(errorOf(SessionError::Kind::BadInput),
            shown + ":2: column 'order': '3' is not a block order: a whole number from 1 to 2 (the protocol's "
                    "counterbalanced orders)");
  dir_.write("participants.tsv", "participant_id\tgroup\np03\tcontrol\textra\n");
  EXPECT_EQ(errorOf(SessionError::Kind::BadInput),
            shown + ":2: 3 columns, the header has 2 (columns are separated by tabs)");
  dir_.write("participants.tsv", "participant_id\tgroup\np03\tcontrol\np03\tguided\n");
  EXPECT_EQ(errorOf(SessionError::Kind::BadInput),
            shown + ":3: column 'participant_id': 'p03' is listed twice (also on line 2)");
  dir_.write("participants.tsv", "id\tgroup\n");
  EXPECT_EQ(errorOf(SessionError::Kind::BadInput),
            shown + ":1: column 'id': the first column must be participant_id (tab-separated columns)");
  dir_.write("participants.tsv", "participant_id\tage\n");
  EXPECT_THAT(errorOf(SessionError::Kind::BadInput), HasSubstr(shown + ":1: no 'group' column"));
  (void)file;
}

}  // namespace
}  // namespace hemiroll::game
