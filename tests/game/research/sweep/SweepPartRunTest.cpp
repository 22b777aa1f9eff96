// game/research/sweep/SweepPartRun: a shard into a folder - the CSV and a complete
// manifest; the same bytes for any thread count; a rerun after a crash keeps
// the whole rows already written and gives the same bytes; a complete shard
// is left alone; a folder holding another spec's shard is refused.

#include "game/research/sweep/SweepPartRun.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

#include "engine/physics/BatchedRk4.h"
#include "game/research/sweep/SweepError.h"
#include "game/research/sweep/SweepManifest.h"
#include "game/research/sweep/SweepTable.h"
#include "tests/game/support/TinySweep.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using test::TempDirectory;

TEST(SweepPartRun, WritesTheCsvAndACompleteManifest) {
  const TempDirectory dir;
  const SweepPartReport r = test::runSweepInto(test::kTippingSweep, dir.path() / "out");
  EXPECT_EQ(r.points, 4);
  EXPECT_EQ(r.computed, 4);
  EXPECT_EQ(r.resumed, 0);
  EXPECT_EQ(r.stopped, 2);  // k = 16 and k = 8 at Omega = -1 tip over from rest within 3 s
  EXPECT_FALSE(r.alreadyComplete);
  EXPECT_EQ(r.csv, dir.path() / "out" / "sweep.csv");
  EXPECT_FALSE(fs::exists(dir.path() / "out" / "sweep.csv.partial"));
  const SweepManifest m = readManifest(r.manifest);
  EXPECT_TRUE(m.complete);
  EXPECT_EQ(m.pointCount, 4);
  EXPECT_EQ(m.csv, "sweep.csv");
  EXPECT_EQ(readSweepRows(r.csv).size(), 4u);
}

TEST(SweepPartRun, TheCsvDoesNotDependOnTheThreadCount) {
  const TempDirectory dir;
  test::runSweepInto(test::kTinySweep, dir.path() / "one", {}, 1);
  test::runSweepInto(test::kTinySweep, dir.path() / "three", {}, 3);
  const std::string one = TempDirectory::read(dir.path() / "one" / "sweep.csv");
  EXPECT_EQ(readSweepRows(dir.path() / "one" / "sweep.csv").size(), 9u);
  EXPECT_EQ(one, TempDirectory::read(dir.path() / "three" / "sweep.csv"));
}

// Lanes that tip over (kTippingSweep) stop while the others go on, and the
// rows are the same bytes at every width this CPU runs.
TEST(SweepPartRun, TheCsvDoesNotDependOnTheLaneWidth) {
  for (const char* source : {test::kTinySweep, test::kTippingSweep}) {
    const TempDirectory dir;
    test::runSweepInto(source, dir.path() / "1", {}, 1, 1);
    const std::string scalar = TempDirectory::read(dir.path() / "1" / "sweep.csv");
    for (int width : {2, 4, 8}) {
      if (!physics::laneWidthSupported(width)) continue;
      const std::string name = std::to_string(width);
      test::runSweepInto(source, dir.path() / name, {}, 2, width);
      EXPECT_EQ(scalar, TempDirectory::read(dir.path() / name / "sweep.csv")) << "lanes " << width;
    }
  }
}

// What a crash leaves of a finished run of the tiny sweep in dir/out: the
// manifest saying incomplete, no CSV, and `partial` as the partial file.
// Returns the finished CSV.
std::string crashed(const TempDirectory& dir, const std::function<std::string(const std::string&)>& partial) {
  const fs::path out = dir.path() / "out";
  test::runSweepInto(test::kTinySweep, out);
  const std::string complete = TempDirectory::read(out / "sweep.csv");
  SweepManifest m = readManifest(out / "sweep.json");
  m.complete = false;
  dir.write("out/sweep.json", manifestJson(m));
  fs::remove(out / "sweep.csv");
  dir.write("out/sweep.csv.partial", partial(complete));
  return complete;
}

// The partial CSV with some whole rows and a cut one: the rerun keeps the
// whole ones.
TEST(SweepPartRun, ARerunAfterACrashKeepsTheWholeRows) {
  const TempDirectory dir;
  const fs::path out = dir.path() / "out";
  const std::string complete = crashed(dir, [](const std::string& csv) {
    // Header + points 0..3 whole + half of point 4.
    std::size_t at = 0;
    for (int line = 0; line < 5; ++line) at = csv.find('\n', at) + 1;
    return csv.substr(0, at + (csv.find('\n', at) - at) / 2);
  });

  const SweepPartReport r = test::runSweepInto(test::kTinySweep, out, {}, 2);
  EXPECT_EQ(r.resumed, 4);
  EXPECT_EQ(r.computed, 5);
  EXPECT_EQ(TempDirectory::read(out / "sweep.csv"), complete);
  EXPECT_EQ(readManifest(out / "sweep.json").resumedPoints, 4);

  const SweepPartReport again = test::runSweepInto(test::kTinySweep, out);
  EXPECT_TRUE(again.alreadyComplete);
  EXPECT_EQ(again.computed, 0);
  EXPECT_EQ(TempDirectory::read(out / "sweep.csv"), complete);
}

// A partial file whose rows are not the shard's first points (or of another
// header) is not trusted: the run starts clean.
TEST(SweepPartRun, APartialFileOfOtherRowsIsNotKept) {
  const TempDirectory dir;
  const fs::path out = dir.path() / "out";
  const std::string complete = crashed(dir, [](const std::string&) { return sweepHeader() + "5,garbage\n"; });
  const SweepPartReport r = test::runSweepInto(test::kTinySweep, out);
  EXPECT_EQ(r.resumed, 0);
  EXPECT_EQ(TempDirectory::read(out / "sweep.csv"), complete);
}

// Rows that start with the right point but are not what this program
// writes (a cell of garbage, a stray quote) were kept, copied into a part
// marked complete, and broke every later read for good (issue 19). They are
// recomputed: the rerun keeps only the whole, well-formed rows before them.
TEST(SweepPartRun, TamperedRowsAreRecomputedNotKept) {
  // "nan" and "inf" (issue 33): strtod reads them, so they were kept, and the
  // final CSV said complete with a NaN in it; the CSV never holds one.
  for (const char* damage : {"GARBAGE", "\"unterminated", "nan", "-inf", "1e999"}) {
    const TempDirectory dir;
    const fs::path out = dir.path() / "out";
    const std::string complete = crashed(dir, [&](const std::string& csv) {
      // Header + points 0, 1 whole, then point 2 with its second cell damaged.
      std::size_t at = 0;
      for (int line = 0; line < 3; ++line) at = csv.find('\n', at) + 1;
      const std::size_t second = csv.find(',', at) + 1;
      return csv.substr(0, second) + damage + csv.substr(csv.find(',', second));
    });
    const SweepPartReport r = test::runSweepInto(test::kTinySweep, out);
    EXPECT_EQ(r.resumed, 2) << damage;
    EXPECT_EQ(TempDirectory::read(out / "sweep.csv"), complete) << damage;
  }
}

TEST(SweepPartRun, AFolderWithAnotherSpecsShardIsRefused) {
  const TempDirectory dir;
  test::runSweepInto(test::kTinySweep, dir.path(), {0, 2});
  try {
    test::runSweepInto(test::kTippingSweep, dir.path(), {0, 2});
    FAIL();
  } catch (const SweepError& e) {
    EXPECT_EQ(e.kind(), SweepError::Kind::BadInput);
    EXPECT_THAT(e.what(), HasSubstr("already holds shard 0/2 of another sweep"));
  }
  // Another shard of another spec may share the folder (its own file names).
  EXPECT_NO_THROW(test::runSweepInto(test::kTippingSweep, dir.path(), {1, 2}));
}

}  // namespace
}  // namespace hemiroll::game
