// game/research/session/ParticipantsFile: a lab's participants.tsv read and checked
// against the protocol - its own columns kept in order, n/a as missing,
// each group's rows ranked, and every mistake one sentence naming the file,
// the line and the column.

#include "game/research/session/ParticipantsFile.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "game/research/session/SessionError.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;

task::ProtocolDef protocol(task::Assignment assignment) {
  task::ProtocolDef p;
  p.assignment = assignment;
  for (const char* name : {"guided", "control"}) {
    task::GroupDef g;
    g.name = name;
    p.groups.push_back(g);
  }
  p.blocks.resize(3);
  p.counterbalanced = {1, 2};  // two orders
  return p;
}

class ParticipantsFileTest : public ::testing::Test {
 protected:
  std::string errorOf(const std::string& text, task::Assignment assignment = task::Assignment::ParticipantsFile) {
    const std::string path = dir_.write("participants.tsv", text);
    try {
      (void)readParticipantsFile(path, protocol(assignment));
    } catch (const SessionError& e) {
      EXPECT_EQ(e.kind(), SessionError::Kind::BadInput);
      return std::string(e.what()).substr(path.size());  // after the file's name
    }
    return "no error";
  }
  test::TempDirectory dir_;
};

TEST_F(ParticipantsFileTest, ReadsGroupsOrdersAndTheLabsOwnColumns) {
  const std::string path = dir_.write("participants.tsv",
                                      "participant_id\tage\tgroup\thandedness\torder\r\n"
                                      "p01\t24\tcontrol\tleft\t2\r\n"
                                      "p02\tn/a\tguided\tright\tn/a\n"
                                      "p03\t31\tcontrol\t\t\n\n");
  const ParticipantsTable t = readParticipantsFile(path, protocol(task::Assignment::ParticipantsFile));
  ASSERT_EQ(t.rows.size(), 3u);
  const ParticipantRow* p01 = t.find("p01");
  ASSERT_NE(p01, nullptr);
  EXPECT_EQ(p01->line, 2);
  EXPECT_EQ(p01->group, "control");
  EXPECT_EQ(p01->order, 2);
  EXPECT_EQ(p01->rankInGroup, 1);
  EXPECT_EQ(p01->columns, (record::Fields{{"age", "24"}, {"handedness", "left"}}));
  EXPECT_EQ(t.find("p02")->order, 0);  // n/a: none given
  EXPECT_EQ(t.find("p02")->columns, (record::Fields{{"age", ""}, {"handedness", "right"}}));
  EXPECT_EQ(t.find("p03")->rankInGroup, 2);  // the second control row
  EXPECT_EQ(t.find("p04"), nullptr);
}

TEST_F(ParticipantsFileTest, MistakesNameTheFileLineAndColumn) {
  EXPECT_EQ(errorOf(""), ": empty; the first line names the columns, starting with participant_id");
  EXPECT_EQ(errorOf("id\tgroup\n"), ":1: column 'id': the first column must be participant_id (tab-separated columns)");
  EXPECT_EQ(errorOf("participant_id\tgroup\tgroup\n"), ":1: column 'group': named twice");
  EXPECT_EQ(errorOf("participant_id\t\tgroup\n"), ":1: column 2 has no name");
  EXPECT_THAT(errorOf("participant_id\tage\n"), HasSubstr(":1: no 'group' column; the protocol assigns groups"));
  EXPECT_EQ(errorOf("participant_id\tgroup\np01\tguided\n\np02\tguided\n"), ":3: an empty line (remove it)");
  EXPECT_EQ(errorOf("participant_id\tgroup\np01 guided\n"), ":2: 1 columns, the header has 2 (columns are separated by tabs)");
  EXPECT_THAT(errorOf("participant_id\tgroup\np/01\tguided\n"),
              HasSubstr(":2: column 'participant_id': 'p/01' is not a participant id"));
  EXPECT_EQ(errorOf("participant_id\tgroup\np01\tguided\np01\tcontrol\n"),
            ":3: column 'participant_id': 'p01' is listed twice (also on line 2)");
  EXPECT_EQ(errorOf("participant_id\tgroup\np01\tn/a\n"), ":2: column 'group': missing; one of 'guided', 'control'");
  EXPECT_EQ(errorOf("participant_id\tgroup\np01\tguidd\n"),
            ":2: column 'group': no group 'guidd' in the protocol (its groups: 'guided', 'control')");
  EXPECT_EQ(errorOf("participant_id\tgroup\torder\np01\tguided\t1.5\n"),
            ":2: column 'order': '1.5' is not a block order: a whole number from 1 to 2 (the protocol's counterbalanced "
            "orders)");
  // With assignment by arrival the session decides: the file may not.
  EXPECT_THAT(errorOf("participant_id\tgroup\np01\tguided\n", task::Assignment::Balanced),
              HasSubstr(":1: column 'group': the protocol assigns groups and orders by arrival"));
  EXPECT_EQ(errorOf("participant_id\tage\np01\t24\n", task::Assignment::Balanced), "no error");
  // A lab column named as one hemiroll writes beside it would clash in BIDS and trials.csv.
  EXPECT_THAT(errorOf("participant_id\tgroup\tsession\np01\tguided\t3\n"),
              HasSubstr(":1: column 'session': a name hemiroll writes itself"));
  EXPECT_THAT(errorOf("participant_id\tgroup\tblock_order\np01\tguided\t2\n"), HasSubstr("'lab_block_order'"));
}

// A spreadsheet's byte-order mark is not part of the first column's name.
TEST_F(ParticipantsFileTest, AByteOrderMarkIsSkipped) {
  const std::string path = dir_.write("participants.tsv", "\xEF\xBB\xBFparticipant_id\tgroup\np01\tguided\n");
  const ParticipantsTable t = readParticipantsFile(path, protocol(task::Assignment::ParticipantsFile));
  ASSERT_NE(t.find("p01"), nullptr);
  EXPECT_EQ(t.header[0], "participant_id");
}

}  // namespace
}  // namespace hemiroll::game
