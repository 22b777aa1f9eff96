#include "engine/record/ResultsFile.h"

#include <gtest/gtest.h>

#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::record {
namespace {

ResultsRow result(const std::string& trial, const std::string& reason) {
  return ResultsRow{.participant = "p01",
                     .session = "1",
                     .trialId = trial,
                     .level = "tutorial",
                     .levelHash = {},
                     .outcome = "success",
                     .reason = reason,
                     .duration = 12.5,
                     .score = 0.75,
                     .rows = 1250,
                     .droppedRows = 0,
                     .startTime = {},
                     .extra = {{"condition", "M3"}}};
}

TEST(ResultsFileTest, ACsvLineIsOneWholeRecordOrNothing) {
  using Fields = std::vector<std::string>;
  EXPECT_EQ(parseCsvLine("a,\"b,c\",\"d\"\"e\"\n"), (Fields{"a", "b,c", "d\"e"}));
  EXPECT_EQ(parseCsvLine("1,,2\r\n"), (Fields{"1", "", "2"}));
  EXPECT_FALSE(parseCsvLine("a,\"unterminated\n").has_value());  // the quote swallows the line end
  EXPECT_FALSE(parseCsvLine("no line end").has_value());
  EXPECT_FALSE(parseCsvLine("one\ntwo\n").has_value());         // two records
}

TEST(ResultsFileTest, AFolderInItsPlaceIsNamedNotReadAsEmpty) {
  // Read as empty, a session's resume took every finished trial for an
  // interrupted one and moved it aside (issue 19).
  test::TempDirectory dir;
  std::filesystem::create_directories(dir.path() / "results.csv");
  const ResultsFile file(dir.path() / "results.csv");
  for (int attempt = 0; attempt < 2; ++attempt) {
    try {
      if (attempt == 0) (void)file.read();
      else file.append(ResultsRow{});
      FAIL() << attempt;
    } catch (const RecordError& e) {
      EXPECT_NE(std::string(e.what()).find("results.csv: not a regular file"), std::string::npos) << e.what();
    }
  }
}

TEST(ResultsFileTest, HeaderOnceThenOneRowPerTrial) {
  hemiroll::test::TempDirectory dir;
  const ResultsFile file(dir.path() / "results.csv");
  file.append(result("t1", "goal"));
  file.append(result("t2", "said \"done\", then left"));
  const std::string text = hemiroll::test::TempDirectory::read(file.path());
  EXPECT_EQ(text,
            "participant,session,trial,level,level_hash,outcome,reason,duration_s,score,rows,dropped_rows,"
            "start_time,condition\n"
            "p01,1,t1,tutorial,,success,goal,12.5,0.75,1250,0,,M3\n"
            "p01,1,t2,tutorial,,success,\"said \"\"done\"\", then left\",12.5,0.75,1250,0,,M3\n");
}

TEST(ResultsFileTest, OtherColumnsThanTheFilesAreRefused) {
  hemiroll::test::TempDirectory dir;
  const ResultsFile file(dir.path() / "results.csv");
  file.append(result("t1", "goal"));
  ResultsRow other = result("t2", "goal");
  other.extra = {{"block", "2"}};
  try {
    file.append(other);
    FAIL() << "no error";
  } catch (const RecordError& e) {
    EXPECT_NE(std::string(e.what()).find("results.csv: line 1: the header differs"), std::string::npos) << e.what();
  }
  // The file is unchanged: one header, one row.
  const std::string text = hemiroll::test::TempDirectory::read(file.path());
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 2);
}

TEST(ResultsFileTest, AnUnwritablePlaceIsNamed) {
  hemiroll::test::TempDirectory dir;
  const ResultsFile file(dir.path() / "no-such-folder" / "results.csv");
  try {
    file.append(result("t1", "goal"));
    FAIL() << "no error";
  } catch (const RecordError& e) {
    EXPECT_NE(std::string(e.what()).find("no-such-folder/results.csv"), std::string::npos) << e.what();
  }
}

// What append() writes, read() gives back, quoting included.
TEST(ResultsFileTest, ReadGivesBackTheHeaderAndEveryFieldAsWritten) {
  hemiroll::test::TempDirectory dir;
  const ResultsFile file(dir.path() / "results.csv");
  EXPECT_TRUE(file.read().columns.empty()) << "a missing file is an empty table";
  file.append(result("t1", "goal"));
  file.append(result("t2", "said \"done\", then\nleft, \"twice\""));
  const ResultsTable table = file.read();
  EXPECT_EQ(table.columns, ResultsFile::columns(result("t1", "")));
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[0][2], "t1");
  EXPECT_EQ(table.rows[1][2], "t2");
  EXPECT_EQ(table.rows[1][6], "said \"done\", then\nleft, \"twice\"");
  EXPECT_EQ(table.rows[1][12], "M3");
}

TEST(ResultsFileTest, ReadRefusesACutRowAndAWrongFieldCountNamingTheLine) {
  hemiroll::test::TempDirectory dir;
  const auto path = dir.path() / "results.csv";
  const ResultsFile file(path);
  file.append(result("t1", "goal"));
  const std::string good = hemiroll::test::TempDirectory::read(path);
  dir.write("results.csv", good + "p01,1,t2,tut");
  try {
    file.read();
    FAIL() << "a cut row was read";
  } catch (const RecordError& e) {
    EXPECT_NE(std::string(e.what()).find("results.csv: line 3: the last row has no line end"), std::string::npos)
        << e.what();
  }
  dir.write("results.csv", good + "p01,1,t2\n");
  try {
    file.read();
    FAIL() << "a short row was read";
  } catch (const RecordError& e) {
    EXPECT_NE(std::string(e.what()).find("results.csv: line 3: 3 fields, the header has 13"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace hemiroll::record
