// game/research/session/GroupAssignment: the least filled group then its least used
// order, by arrival; the participants file's group and order (or rank);
// a participant's earlier session keeps its assignment.

#include "game/research/session/GroupAssignment.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "game/research/session/SessionError.h"
#include "game/research/session/SessionManifest.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

task::ProtocolDef protocol() {
  task::ProtocolDef p;
  for (const char* name : {"a", "b", "c"}) {
    task::GroupDef g;
    g.name = name;
    p.groups.push_back(g);
  }
  p.blocks.resize(2);
  p.counterbalanced = {0, 1};  // two orders
  return p;
}

// A session of `participant` in `group`, order `order`, as a session leaves it.
void arrived(const fs::path& experiment, const std::string& participant, const std::string& group, int order,
             const std::string& session = "1") {
  SessionManifest m;
  m.participant = participant;
  m.session = session;
  m.group = group;
  m.blockOrder = order;
  fs::create_directories(experiment / participant / session);
  std::ofstream(experiment / participant / session / "session.json") << m.toJson();
}

TEST(GroupAssignmentTest, ByArrivalTheLeastFilledGroupThenItsLeastUsedOrder) {
  test::TempDirectory dir;
  const fs::path experiment = dir.path() / "e";
  const task::ProtocolDef p = protocol();
  std::vector<std::pair<std::string, int>> got;
  for (int k = 0; k < 6; ++k) {
    // Appended, not "p" + to_string(k): GCC 12 warns on the latter (-Wrestrict, a false positive).
    std::string id = "p";
    id += std::to_string(k);
    const ParticipantAssignment a = assignParticipant(p, experiment, id, "1");
    got.emplace_back(a.group, a.order);
    arrived(experiment, id, a.group, a.order);
  }
  EXPECT_EQ(got, (std::vector<std::pair<std::string, int>>{{"a", 1}, {"b", 1}, {"c", 1}, {"a", 2}, {"b", 2}, {"c", 2}}));
  // A drop-out's place is filled first: with b's order-1 participant gone, b and its order 1 are the least used.
  fs::remove_all(experiment / "p1");
  const ParticipantAssignment next = assignParticipant(p, experiment, "p9", "1");
  EXPECT_EQ(next.group, "b");
  EXPECT_EQ(next.order, 1);
  EXPECT_THAT(next.how, HasSubstr("balanced by arrival: participant 6 of the experiment"));
  // A second session keeps the first's assignment.
  const ParticipantAssignment again = assignParticipant(p, experiment, "p4", "2");
  EXPECT_EQ(again.group, "b");
  EXPECT_EQ(again.order, 2);
  EXPECT_EQ(again.how, "kept from the participant's earlier session");
}

TEST(GroupAssignmentTest, FromTheParticipantsFileItsGroupAndOrderOrTheRankWithinTheGroup) {
  test::TempDirectory dir;
  task::ProtocolDef p = protocol();
  p.assignment = task::Assignment::ParticipantsFile;
  p.participantsFile = dir.write("participants.tsv",
                                 "participant_id\tgroup\torder\tage\n"
                                 "x1\tc\t2\t30\n"
                                 "x2\tc\tn/a\t31\n"
                                 "x3\tc\tn/a\t32\n");
  const ParticipantAssignment x1 = assignParticipant(p, dir.path() / "e", "x1", "1");
  EXPECT_EQ(x1.group, "c");
  EXPECT_EQ(x1.order, 2);
  EXPECT_EQ(x1.info, (record::Fields{{"age", "30"}}));
  EXPECT_EQ(x1.how, p.participantsFile + ", line 2");
  EXPECT_EQ(assignParticipant(p, dir.path() / "e", "x2", "1").order, 2);  // the second of group c: order 2
  EXPECT_EQ(assignParticipant(p, dir.path() / "e", "x3", "1").order, 1);  // the third: round again
  try {
    (void)assignParticipant(p, dir.path() / "e", "x4", "1");
    FAIL() << "no error";
  } catch (const SessionError& e) {
    EXPECT_THAT(e.what(), HasSubstr("participant 'x4' is not in " + p.participantsFile));
  }
}

// A file edited after a participant's first session does not move them: their
// second session in another group would split them across two groups.
TEST(GroupAssignmentTest, AParticipantsFileEditedSinceTheFirstSessionIsRefused) {
  test::TempDirectory dir;
  task::ProtocolDef p = protocol();
  p.assignment = task::Assignment::ParticipantsFile;
  p.participantsFile = dir.write("participants.tsv", "participant_id\tgroup\torder\nx1\tc\t2\n");
  const fs::path experiment = dir.path() / "e";
  arrived(experiment, "x1", "c", 2);
  EXPECT_EQ(assignParticipant(p, experiment, "x1", "2").group, "c");  // the same line: session 2 as session 1
  dir.write("participants.tsv", "participant_id\tgroup\torder\nx1\ta\t2\n");
  try {
    (void)assignParticipant(p, experiment, "x1", "2");
    FAIL() << "no error";
  } catch (const SessionError& e) {
    EXPECT_EQ(e.kind(), SessionError::Kind::BadInput);
    EXPECT_THAT(e.what(), HasSubstr(":2: participant 'x1' is in group 'a' with block order 2 there, but an earlier "
                                    "session of theirs ran in group 'c'"));
  }
}

TEST(GroupAssignmentTest, WithoutGroupsOrOrdersThereIsNothingToAssign) {
  test::TempDirectory dir;
  task::ProtocolDef p;
  p.blocks.resize(2);
  const ParticipantAssignment a = assignParticipant(p, dir.path(), "p", "1");
  EXPECT_EQ(a.group, "");
  EXPECT_EQ(a.order, 1);
}

}  // namespace
}  // namespace hemiroll::game
