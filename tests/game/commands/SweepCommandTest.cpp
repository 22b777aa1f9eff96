// `hemiroll sweep`, end to end: the real binary in a child process. A tiny
// sweep's CSV (rows, columns, finite or empty cells, a known tip-over), the
// same bytes for 1 and 2 threads and for shards merged, merge's refusals,
// the map, bad input, and a run killed mid-way and rerun.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <signal.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <thread>

#include "engine/record/CsvRowFormat.h"
#include "engine/record/ResultsFile.h"
#include "tests/game/support/TinySweep.h"
#include "tests/support/ChildProcess.h"
#include "tests/support/ProcessRunner.h"
#include "tests/support/TempDirectory.h"
#include "tests/support/XmlCheck.h"

namespace hemiroll::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

const std::string kBinary = HEMIROLL_BINARY;

ProcessResult hemiroll(const std::vector<std::string>& args) { return runProcess(kBinary, args); }

class SweepCommandTest : public ::testing::Test {
 protected:
  std::string at(const std::string& name) const { return (dir_.path() / name).string(); }
  std::string csv(const std::string& folder, const std::string& name = "sweep.csv") const {
    return TempDirectory::read(dir_.path() / folder / name);
  }
  TempDirectory dir_;
};

TEST_F(SweepCommandTest, WritesRowsColumnsAndAMapAndReportsTheTipOver) {
  const std::string spec = dir_.write("tip.lua", kTippingSweep);
  const ProcessResult r = hemiroll({"sweep", spec, "--out", at("out"), "--threads", "2"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_THAT(r.out, StartsWith("{\"csv\":"));
  EXPECT_THAT(r.out, HasSubstr("\"points\":4,\"computed\":4,\"resumed\":0,\"stopped\":2,\"threads\":2"));
  // Not a terminal: no bar, one line at the end.
  EXPECT_THAT(r.err, Not(HasSubstr("\r")));
  EXPECT_THAT(r.err, StartsWith("hemiroll sweep: 4 points (shard 0/1"));

  const record::ResultsTable table = record::ResultsFile(dir_.path() / "out" / "sweep.csv").read();
  ASSERT_EQ(table.rows.size(), 4u);
  auto column = [&](const char* name) {
    return static_cast<std::size_t>(std::find(table.columns.begin(), table.columns.end(), name) - table.columns.begin());
  };
  const std::set<std::string> text = {"event", "helix_window", "notes"};
  for (const auto& row : table.rows) {
    ASSERT_EQ(row.size(), table.columns.size());
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (text.count(table.columns[c]) || row[c].empty()) continue;  // empty: not found (or no event)
      double v = 0.0;
      EXPECT_TRUE(record::parseDouble(row[c], v) && std::isfinite(v)) << table.columns[c] << " = " << row[c];
    }
  }
  // Point 3: k = 16, Omega = -1 rad/s from rest tips over at 0.39 s; point 0 (the paper's) runs to the end.
  const auto& tipped = table.rows[3];
  EXPECT_EQ(tipped[column("k")], "16");
  EXPECT_EQ(tipped[column("event")], "tipped_over");
  EXPECT_NEAR(std::stod(tipped[column("event_time_s")]), 0.39, 0.05);
  EXPECT_EQ(tipped[column("paper_like")], "0");
  EXPECT_THAT(tipped[column("notes")], StartsWith("stopped by tipped_over"));
  EXPECT_EQ(table.rows[0][column("event")], "none");
  EXPECT_EQ(table.rows[0][column("event_time_s")], "");
  EXPECT_EQ(table.rows[0][column("simulated_s")], "3");

  const std::string map = csv("out", "map-k-Omega.svg");
  EXPECT_EQ(xmlProblem(map), "");
  EXPECT_THAT(map, Not(HasSubstr("nan")));
  EXPECT_THAT(map, HasSubstr("T: tipped over"));
}

TEST_F(SweepCommandTest, ThreadsAndShardsGiveTheSameBytes) {
  const std::string spec = dir_.write("tiny.lua", kTinySweep);
  ASSERT_EQ(hemiroll({"sweep", spec, "--out", at("one"), "--threads", "1", "--maps", "none"}).exitCode, 0);
  ASSERT_EQ(hemiroll({"sweep", spec, "--out", at("two"), "--threads", "2", "--maps", "none"}).exitCode, 0);
  EXPECT_EQ(csv("one").size(), csv("two").size());
  EXPECT_EQ(csv("one"), csv("two"));
  for (const char* shard : {"0/2", "1/2"}) {
    const ProcessResult r = hemiroll({"sweep", spec, "--out", at("parts"), "--shard", shard});
    ASSERT_EQ(r.exitCode, 0) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir_.path() / "parts" / "map-k-Omega.svg"));  // a shard draws no maps
  const ProcessResult merged = hemiroll({"sweep", "merge", at("parts"), "--out", at("merged")});
  ASSERT_EQ(merged.exitCode, 0) << merged.err;
  EXPECT_THAT(merged.out, HasSubstr("\"parts\":2,\"points\":9"));
  EXPECT_EQ(csv("merged"), csv("one"));
  EXPECT_EQ(xmlProblem(csv("merged", "map-k-Omega.svg")), "");

  const ProcessResult map = hemiroll({"sweep", "map", at("merged"), "--x", "Omega", "--y", "k", "--metric", "paper_like",
                                      "--out", at("paper_like.svg")});
  ASSERT_EQ(map.exitCode, 0) << map.err;
  const std::string svg = TempDirectory::read(at("paper_like.svg"));
  EXPECT_EQ(xmlProblem(svg), "");
  EXPECT_THAT(svg, Not(HasSubstr("nan")));
  EXPECT_THAT(svg, HasSubstr("paper-like"));
}

TEST_F(SweepCommandTest, MergeRefusesWithOneSentence) {
  const std::string spec = dir_.write("tiny.lua", kTinySweep);
  const std::string other = dir_.write("tip.lua", kTippingSweep);
  ASSERT_EQ(hemiroll({"sweep", spec, "--out", at("a"), "--shard", "0/2"}).exitCode, 0);
  ASSERT_EQ(hemiroll({"sweep", spec, "--out", at("b"), "--shard", "0/2"}).exitCode, 0);
  ASSERT_EQ(hemiroll({"sweep", other, "--out", at("c"), "--shard", "1/2"}).exitCode, 0);
  struct Case {
    std::vector<std::string> dirs;
    std::string sentence;
  };
  for (const Case& c : {Case{{at("a")}, "4 of 9 points are missing, the first is point 1 (shard 1/2 not given?)"},
                        Case{{at("a"), at("b")}, "point 0 is in both"},
                        Case{{at("a"), at("c")}, "comes from another sweep spec"}}) {
    std::vector<std::string> args = {"sweep", "merge"};
    args.insert(args.end(), c.dirs.begin(), c.dirs.end());
    args.insert(args.end(), {"--out", at("m")});
    const ProcessResult r = hemiroll(args);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_THAT(r.err, HasSubstr(c.sentence));
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;  // one sentence, one line
    EXPECT_FALSE(fs::exists(dir_.path() / "m"));
  }
}

TEST_F(SweepCommandTest, BadInputIsOneSentenceAndWritesNothing) {
  const std::string spec = dir_.write("bad.lua", "return {\n  axes = {\n    { param = 'omega', values = { 1 } } } }");
  ProcessResult r = hemiroll({"sweep", spec, "--out", at("o")});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.err, HasSubstr("bad.lua:3: axes[1].param: unknown parameter 'omega' (did you mean 'Omega'?)"));
  EXPECT_FALSE(fs::exists(dir_.path() / "o"));
  r = hemiroll({"sweep", spec});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.err, HasSubstr("missing --out DIR"));
  r = hemiroll({"sweep", "map", at("nothing"), "--x", "k", "--y", "Omega", "--metric", "loops"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.err, HasSubstr("holds no finished sweep"));
  r = hemiroll({"sweep", "--help"});
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_THAT(r.out, HasSubstr("hemiroll sweep merge DIR..."));
}

// SIGKILL mid-run, then the same command again: the finished points are
// kept, the rest computed, and the CSV is the uninterrupted run's.
TEST_F(SweepCommandTest, AKilledRunRerunGivesTheSameCsv) {
  const std::string spec = dir_.write("long.lua", R"(return { axes = {
      { param = "k", range = { from = 6, to = 12, count = 7 } }, { param = "Omega", values = { -0.5, -0.3, -0.7 } } } })");
  const fs::path partial = dir_.path() / "killed" / "sweep.csv.partial";
  {
    ChildProcess child(kBinary, {"sweep", spec, "--out", at("killed"), "--threads", "1", "--maps", "none"});
    // Wait for some rows (the header and at least two points), then kill.
    auto lines = [&] {
      const std::string text = TempDirectory::read(partial);
      return std::count(text.begin(), text.end(), '\n');
    };
    for (int i = 0; i < 2000 && lines() < 3; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    child.signal(SIGKILL);
    child.wait();
  }
  ASSERT_FALSE(fs::exists(dir_.path() / "killed" / "sweep.csv")) << "the run finished before the kill";
  const ProcessResult rerun = hemiroll({"sweep", spec, "--out", at("killed"), "--threads", "2", "--maps", "none"});
  ASSERT_EQ(rerun.exitCode, 0) << rerun.err;
  EXPECT_THAT(rerun.out, Not(HasSubstr("\"resumed\":0,")));
  ASSERT_EQ(hemiroll({"sweep", spec, "--out", at("clean"), "--threads", "2", "--maps", "none"}).exitCode, 0);
  EXPECT_EQ(csv("killed"), csv("clean"));
}

}  // namespace
}  // namespace hemiroll::test
