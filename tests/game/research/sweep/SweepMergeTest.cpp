// game/research/sweep/SweepMerge: shards joined into the byte-identical CSV of the
// unsharded run, from one folder or several; refused, with one sentence,
// when a shard is missing, given twice, incomplete, or of another spec or
// program.

#include "game/research/sweep/SweepMerge.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "game/research/sweep/SweepError.h"
#include "tests/game/support/TinySweep.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using test::TempDirectory;

std::string refusal(const std::vector<fs::path>& dirs) {
  try {
    mergeSweepParts(dirs);
  } catch (const SweepError& e) {
    EXPECT_EQ(e.kind(), SweepError::Kind::BadInput);
    return e.what();
  }
  return "merged";
}

class SweepMergeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    test::runSweepInto(test::kTinySweep, dir_.path() / "whole", {}, 2);
    for (long long i = 0; i < 3; ++i) test::runSweepInto(test::kTinySweep, dir_.path() / "parts", {i, 3});
  }
  fs::path at(const char* name) const { return dir_.path() / name; }
  TempDirectory dir_;
};

TEST_F(SweepMergeTest, ShardsMergeIntoTheUnshardedCsv) {
  const MergedSweep merged = mergeSweepParts({at("parts")});
  EXPECT_EQ(merged.parts, 3);
  EXPECT_EQ(merged.csv, TempDirectory::read(at("whole") / "sweep.csv"));
  EXPECT_TRUE(merged.manifest.shard.whole());
  EXPECT_EQ(merged.manifest.pointCount, 9);
  writeMergedSweep(merged, at("merged"));
  EXPECT_EQ(TempDirectory::read(at("merged") / "sweep.csv"), TempDirectory::read(at("whole") / "sweep.csv"));
  EXPECT_TRUE(readManifest(at("merged") / "sweep.json").complete);
  // The parts may lie in several folders, and a merged sweep merges again.
  fs::create_directories(at("split"));
  fs::rename(at("parts") / "part-2-of-3.csv", at("split") / "part-2-of-3.csv");
  fs::rename(at("parts") / "part-2-of-3.json", at("split") / "part-2-of-3.json");
  EXPECT_EQ(mergeSweepParts({at("parts"), at("split")}).csv, merged.csv);
  EXPECT_EQ(mergeSweepParts({at("merged")}).csv, merged.csv);
}

TEST_F(SweepMergeTest, RefusesAMissingShard) {
  fs::remove(at("parts") / "part-1-of-3.json");
  EXPECT_THAT(refusal({at("parts")}), HasSubstr("3 of 9 points are missing, the first is point 1 (shard 1/3 not given?)"));
}

TEST_F(SweepMergeTest, RefusesADuplicate) {
  EXPECT_THAT(refusal({at("parts"), at("whole")}), HasSubstr("point 0 is in both"));
}

TEST_F(SweepMergeTest, RefusesAnotherSpec) {
  test::runSweepInto(test::kTippingSweep, at("other"), {1, 3});
  fs::remove(at("parts") / "part-1-of-3.json");
  EXPECT_THAT(refusal({at("parts"), at("other")}), HasSubstr("part-1-of-3.json comes from another sweep spec"));
}

TEST_F(SweepMergeTest, RefusesAnIncompleteShard) {
  std::string manifest = TempDirectory::read(at("parts") / "part-2-of-3.json");
  manifest.replace(manifest.find("\"complete\": true"), 16, "\"complete\": false");
  dir_.write("parts/part-2-of-3.json", manifest);
  EXPECT_THAT(refusal({at("parts")}), HasSubstr("part-2-of-3.json: shard 2/3 is incomplete"));
}

TEST_F(SweepMergeTest, RefusesAnotherProgram) {
  std::string manifest = TempDirectory::read(at("parts") / "part-2-of-3.json");
  manifest.replace(manifest.find("hemiroll test"), 13, "hemiroll 0.0");
  dir_.write("parts/part-2-of-3.json", manifest);
  EXPECT_THAT(refusal({at("parts")}), HasSubstr("was written by hemiroll 0.0"));
}

TEST_F(SweepMergeTest, RefusesAFolderWithoutParts) {
  fs::create_directories(at("empty"));
  EXPECT_THAT(refusal({at("empty")}), HasSubstr("holds no sweep parts"));
  EXPECT_THAT(refusal({at("nothing")}), HasSubstr("is not a folder"));
}

TEST_F(SweepMergeTest, RefusesAPartWhoseRowsDisagreeWithItsManifest) {
  std::string csv = TempDirectory::read(at("parts") / "part-1-of-3.csv");
  csv.erase(csv.rfind('\n', csv.size() - 2) + 1);  // the last row gone
  dir_.write("parts/part-1-of-3.csv", csv);
  EXPECT_THAT(refusal({at("parts")}), HasSubstr("part-1-of-3.csv holds 2 rows; its manifest says 3"));
}

// A cell edited to NaN (issue 33) is refused as its row is read, naming the
// file, line and column: the merged CSV never says complete with a NaN.
TEST_F(SweepMergeTest, RefusesARowWithANonFiniteNumber) {
  std::string csv = TempDirectory::read(at("parts") / "part-1-of-3.csv");
  const std::size_t row = csv.find('\n') + 1;  // the first row, its second cell
  const std::size_t second = csv.find(',', row) + 1;
  csv = csv.substr(0, second) + "nan" + csv.substr(csv.find(',', second));
  dir_.write("parts/part-1-of-3.csv", csv);
  const std::string error = refusal({at("parts")});
  EXPECT_THAT(error, HasSubstr("part-1-of-3.csv: line 2: column "));
  EXPECT_THAT(error, HasSubstr(": 'nan' is not a finite number (the CSV never holds NaN)"));
}

// points_total is not covered by the spec hash. A part forged to be
// consistent with itself (shard 0 of 1e14, its 9 rows renumbered to match)
// once made the merge allocate 8e14 entries and abort (issue 19); it is
// refused before anything is sized.
TEST_F(SweepMergeTest, RefusesAPointsTotalNoSweepCanHave) {
  const long long step = 100'000'000'000'000;
  std::string manifest = TempDirectory::read(at("whole") / "sweep.json");
  const auto replaceValue = [&](const std::string& key, const std::string& value) {
    const std::size_t at = manifest.find(key);
    ASSERT_NE(at, std::string::npos) << key;
    const std::size_t start = manifest.find(':', at) + 2, end = manifest.find_first_of(",\n}", start);
    manifest.replace(start, end - start, value);
  };
  replaceValue("\"points_total\"", std::to_string(8 * step + 1));
  replaceValue("\"count\": 1", std::to_string(step));  // the shard's count
  replaceValue("\"step\"", std::to_string(step));
  dir_.write("whole/sweep.json", manifest);
  // The rows' point numbers as that shard would have them: 0, step, 2 step, ...
  std::string csv = TempDirectory::read(at("whole") / "sweep.csv");
  std::string forged = csv.substr(0, csv.find('\n') + 1);
  long long j = 0;
  for (std::size_t line = forged.size(); line < csv.size(); line = csv.find('\n', line) + 1, ++j)
    forged += std::to_string(j * step) + csv.substr(csv.find(',', line), csv.find('\n', line) - csv.find(',', line) + 1);
  dir_.write("whole/sweep.csv", forged);
  EXPECT_THAT(refusal({at("whole")}), HasSubstr("says points_total = 800000000000001; a sweep has 1 to 1000000 points"));
}

}  // namespace
}  // namespace hemiroll::game
