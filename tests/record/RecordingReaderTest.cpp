#include "engine/record/RecordingReader.h"

#include <gtest/gtest.h>

#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "engine/record/TrialRecorder.h"
#include "tests/record/support/RecordRows.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::record {
namespace {

struct Written {
  std::filesystem::path csv;
  std::vector<haptics::RecordRow> rows;
};

Written writeTrial(const hemiroll::test::TempDirectory& dir, std::size_t n, bool finish = true) {
  TrialMeta meta;
  meta.trialId = "r";
  Written w{{}, test::randomRows(n, 11)};
  TrialRecorder rec(dir.path(), meta);
  for (const auto& row : w.rows) rec.push(row);
  if (finish) rec.finish(TrialEnd{});
  w.csv = rec.csvPath();
  return w;
}

std::string errorOf(const std::filesystem::path& csv, const ReadOptions& options = {}) {
  try {
    RecordingReader::load(csv, options);
  } catch (const RecordError& e) {
    return e.what();
  }
  return "";
}

TEST(RecordingReaderTest, RoundTripIsBitIdentical) {
  hemiroll::test::TempDirectory dir;
  const Written w = writeTrial(dir, 500);
  const Recording r = RecordingReader::load(w.csv);
  EXPECT_TRUE(r.status.complete);
  EXPECT_FALSE(r.truncatedTail);
  ASSERT_EQ(r.rows.size(), w.rows.size());
  for (std::size_t i = 0; i < w.rows.size(); ++i) ASSERT_TRUE(test::sameBits(w.rows[i], r.rows[i])) << i;
}

TEST(RecordingReaderTest, ACorruptLineIsNamedByFileLineAndColumn) {
  hemiroll::test::TempDirectory dir;
  const Written w = writeTrial(dir, 20);
  std::string text = hemiroll::test::TempDirectory::read(w.csv);
  // Line 5 (the 4th row): its first field becomes garbage.
  std::size_t pos = 0;
  for (int k = 0; k < 4; ++k) pos = text.find('\n', pos) + 1;
  dir.write("r.csv", text.substr(0, pos) + '#' + text.substr(pos));
  const std::string e = errorOf(w.csv);
  EXPECT_NE(e.find(w.csv.string() + ": line 5: column 1 (time_s)"), std::string::npos) << e;
}

TEST(RecordingReaderTest, ATruncatedTailIsAnErrorUnlessAllowed) {
  hemiroll::test::TempDirectory dir;
  const Written w = writeTrial(dir, 20, false);  // an interrupted trial: sidecar incomplete
  const std::string text = hemiroll::test::TempDirectory::read(w.csv);
  dir.write("r.csv", text.substr(0, text.size() - 7));  // cut inside the last row
  EXPECT_NE(errorOf(w.csv).find("line 21: incomplete last line"), std::string::npos) << errorOf(w.csv);
  ReadOptions lenient;
  lenient.allowTruncatedTail = true;
  const Recording r = RecordingReader::load(w.csv, lenient);
  EXPECT_TRUE(r.truncatedTail);
  EXPECT_FALSE(r.status.complete);
  ASSERT_EQ(r.rows.size(), 19u);
  for (std::size_t i = 0; i < r.rows.size(); ++i) ASSERT_TRUE(test::sameBits(w.rows[i], r.rows[i]));
}

TEST(RecordingReaderTest, BrokenFilesGiveClearErrors) {
  hemiroll::test::TempDirectory dir;
  const Written w = writeTrial(dir, 5);
  const std::string text = hemiroll::test::TempDirectory::read(w.csv);
  // A finished trial missing a row disagrees with its sidecar.
  dir.write("r.csv", text.substr(0, text.rfind('\n', text.size() - 2) + 1));
  EXPECT_NE(errorOf(w.csv).find("holds 4 rows, its sidecar says 5"), std::string::npos) << errorOf(w.csv);
  dir.write("r.csv", "");
  EXPECT_NE(errorOf(w.csv).find("line 1: missing or incomplete header"), std::string::npos) << errorOf(w.csv);
  dir.write("r.csv", "a,b,c\n");
  EXPECT_NE(errorOf(w.csv).find("line 1: the header"), std::string::npos) << errorOf(w.csv);
  std::filesystem::remove(dir.path() / "r.json");
  EXPECT_NE(errorOf(w.csv).find("r.json: no such file"), std::string::npos) << errorOf(w.csv);
  EXPECT_NE(errorOf(dir.path() / "none.csv").find("none.json"), std::string::npos);
}

}  // namespace
}  // namespace hemiroll::record
